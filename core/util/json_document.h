#pragma once
// Reading Thespis' versioned JSON documents (the scenario today; package manifests and motion
// databases next): the text checked and parsed with errors that say where (line and column, or
// the field path), the "format" and "version" header checked, and the helpers readers use to name
// fields and values in their messages. A reader throws FieldError inside; its entry point turns
// it into a CorruptData error naming the field.

#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "util/error.h"

namespace thespis::core::json_document {

using json = nlohmann::json;

// Documents nest a handful of levels; unknown fields could nest deeper, but a limit keeps the
// recursive parts (comparison, writing, destruction) safe from hostile files.
inline constexpr int kMaxDepth = 64;

/// What a reader checks the header against, and names the document by in messages.
struct Kind {
    std::string_view noun;       ///< "scenario"
    std::string_view formatName; ///< the "format" field's value
    int firstVersion = 1;
    int currentVersion = 1;
};

struct Versioned {
    json document;
    int version = 0;
};

/// Parses `text` (a UTF-8 byte order mark allowed) as a JSON object of `kind` with its "format"
/// and "version": NotOurFormat when it is not such a document, NewerVersion when its version is
/// above the current one, CorruptData naming the line and column or the field otherwise.
Result<Versioned> parseVersioned(std::string_view text, const Kind& kind);

// Thrown inside a reader only: a field path and what is wrong.
struct FieldError {
    std::string path;
    std::string message;
};

[[noreturn]] inline void fail(const std::string& path, std::string message)
{
    throw FieldError{path, std::move(message)};
}

inline std::string join(const std::string& path, std::string_view key)
{
    return path.empty() ? std::string(key) : path + "." + std::string(key);
}

inline std::string indexed(const std::string& path, std::size_t index)
{
    return path + "[" + std::to_string(index) + "]";
}

/// `text` as a JSON string, for messages.
std::string quote(std::string_view text);
/// What a JSON value is, for "expected X, found Y" messages: short, with the value if small.
std::string describeValue(const json& value);

} // namespace thespis::core::json_document
