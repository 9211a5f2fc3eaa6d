#pragma once
// The one place where core's Result errors become Python exceptions (STYLE.md §9):
//   FileNotFound                             → FileNotFoundError
//   NotOurFormat, CorruptData, NewerVersion  → thespis.FormatError (a ValueError)
//   NotFound                                 → KeyError
//   InvalidArgument, InvalidSchedule         → ValueError
//   IoError                                  → OSError
//   Cancelled                                → thespis.Cancelled (a KeyboardInterrupt)
//   Internal                                 → RuntimeError
// Every raised exception carries `code` (thespis.ErrorCode) and `detail` (str) attributes.

#include <utility>

#include "bind_common.h"
#include "util/error.h"

namespace thespis::python {

/// Raises the Python exception for `error` (throws pybind11::error_already_set).
[[noreturn]] void throwError(const core::Error& error);

/// The value of a Result, or the matching Python exception.
template <class T>
T unwrap(core::Result<T>&& result)
{
    if (!result)
        throwError(result.error());
    return std::move(result).value();
}

inline void unwrap(core::Result<void>&& result)
{
    if (!result)
        throwError(result.error());
}

} // namespace thespis::python
