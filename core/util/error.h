#pragma once
// Error values returned by every core API that can fail on bad input, I/O or cancellation.
// Bugs are asserted; expected failures travel as Result<T> (no exception crosses core).

#include <cassert>
#include <string>
#include <utility>
#include <variant>

namespace thespis::core {

enum class ErrorCode {
    FileNotFound,   ///< the file does not exist or cannot be opened
    NotOurFormat,   ///< the file is not of the format the reader handles
    CorruptData,    ///< our format, but malformed (message names line or field)
    NewerVersion,   ///< written by a newer Thespis
    NotFound,       ///< a named thing (character, action, asset) does not exist; the message lists what does
    InvalidArgument,///< a caller passed values that break a documented rule
    InvalidSchedule,///< a schedule or action cannot be built as asked
    IoError,        ///< reading or writing failed part way
    Cancelled,      ///< the user stopped the job
    Internal,       ///< should not happen: a bug
};

/// Short English name of an error code ("corrupt data"), for messages and logs.
const char* errorCodeName(ErrorCode code);

struct Error {
    ErrorCode code = ErrorCode::Internal;
    std::string message; ///< one sentence for the user: what happened, and where
    std::string detail;  ///< technical context for logs and a "Details..." button
};

/// Formats an error as "corrupt data: message (detail)" for terminals and logs.
std::string describe(const Error& error);

/// A value or an Error. Minimal on purpose: std::expected is not usable with clang 14, which
/// builds the fuzz targets.
template <class T>
class [[nodiscard]] Result {
public:
    Result(T value) : m_state(std::in_place_index<0>, std::move(value)) {}
    Result(Error error) : m_state(std::in_place_index<1>, std::move(error)) {}

    bool ok() const { return m_state.index() == 0; }
    explicit operator bool() const { return ok(); }

    T& value() & { assert(ok()); return std::get<0>(m_state); }
    const T& value() const& { assert(ok()); return std::get<0>(m_state); }
    T&& value() && { assert(ok()); return std::get<0>(std::move(m_state)); }
    T* operator->() { return &value(); }
    const T* operator->() const { return &value(); }
    T& operator*() & { return value(); }
    const T& operator*() const& { return value(); }

    const Error& error() const { assert(!ok()); return std::get<1>(m_state); }

private:
    std::variant<T, Error> m_state;
};

template <>
class [[nodiscard]] Result<void> {
public:
    Result() = default;
    Result(Error error) : m_error(std::move(error)), m_ok(false) {}
    bool ok() const { return m_ok; }
    explicit operator bool() const { return m_ok; }
    const Error& error() const { assert(!m_ok); return m_error; }

private:
    Error m_error;
    bool m_ok = true;
};

inline Error makeError(ErrorCode code, std::string message, std::string detail = {})
{
    return Error{code, std::move(message), std::move(detail)};
}

} // namespace thespis::core
