#include "util/json_document.h"

#include <algorithm>
#include <cstdint>
#include <limits>

namespace thespis::core::json_document {

namespace {

// Scans the text once for nesting depth (outside strings), so that nothing recursive ever sees
// a hostile file nested thousands of levels deep. Returns the byte offset where the limit is
// crossed, or npos.
std::size_t findExcessiveNesting(std::string_view text)
{
    int depth = 0;
    bool inString = false, escaped = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (inString) {
            if (escaped)
                escaped = false;
            else if (c == '\\')
                escaped = true;
            else if (c == '"')
                inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '{' || c == '[') {
            if (++depth > kMaxDepth)
                return i;
        } else if (c == '}' || c == ']') {
            --depth;
        }
    }
    return std::string_view::npos;
}

std::string lineAndColumn(std::string_view text, std::size_t offset)
{
    offset = std::min(offset, text.size());
    std::size_t line = 1, column = 1;
    for (std::size_t i = 0; i < offset; ++i) {
        if (text[i] == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
    return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

Result<json> parseObject(std::string_view text, const Kind& kind)
{
    const std::string noun(kind.noun);
    const std::string notOurs = "This is not a Thespis " + noun;
    // A UTF-8 byte order mark is harmless: some editors add one.
    if (text.starts_with("\xEF\xBB\xBF"))
        text.remove_prefix(3);
    const std::size_t first = text.find_first_not_of(" \t\r\n");
    if (first == std::string_view::npos || text[first] != '{')
        return makeError(ErrorCode::NotOurFormat, notOurs + ": it does not start with a JSON object.");
    if (const std::size_t at = findExcessiveNesting(text); at != std::string_view::npos)
        return makeError(ErrorCode::CorruptData, lineAndColumn(text, at) + ": the " + noun + " nests deeper than "
                                                     + std::to_string(kMaxDepth) + " levels.");
    json document;
    try {
        document = json::parse(text);
    } catch (const json::parse_error& e) {
        // nlohmann's text is "[json.exception.parse_error.101] parse error at line L, column C: why".
        std::string why = e.what();
        if (const std::size_t colon = why.find(": "); colon != std::string::npos)
            why = why.substr(colon + 2);
        const std::size_t offset = e.byte > 0 ? e.byte - 1 : 0;
        return makeError(ErrorCode::CorruptData,
                         lineAndColumn(text, offset) + ": the " + noun + " is not valid JSON (" + why + ").", e.what());
    } catch (const json::out_of_range& e) {
        // "number overflow parsing '1e999'": point at the number when it can be found.
        const std::string why = e.what();
        const std::size_t open = why.find('\''), close = why.rfind('\'');
        std::string where;
        if (open != std::string::npos && close > open + 1)
            if (const std::size_t at = text.find(why.substr(open + 1, close - open - 1)); at != std::string_view::npos)
                where = lineAndColumn(text, at) + ": ";
        return makeError(ErrorCode::CorruptData, where + "the " + noun + " holds a number too large to read.", why);
    } catch (const std::exception& e) {
        return makeError(ErrorCode::CorruptData, "The " + noun + " could not be read as JSON.", e.what());
    }
    if (!document.is_object())
        return makeError(ErrorCode::NotOurFormat, notOurs + ": it is not a JSON object.");
    return document;
}

} // namespace

Result<Versioned> parseVersioned(std::string_view text, const Kind& kind)
{
    auto parsed = parseObject(text, kind);
    if (!parsed)
        return parsed.error();
    json& document = *parsed;
    const std::string noun(kind.noun);
    const auto format = document.find("format");
    if (format == document.end())
        return makeError(ErrorCode::NotOurFormat, "This is not a Thespis " + noun + ": it has no \"format\" field.");
    if (!format->is_string() || format->get_ref<const std::string&>() != kind.formatName)
        return makeError(ErrorCode::NotOurFormat, "This is not a Thespis " + noun + ": its format is "
                                                      + describeValue(*format) + ", not \"" + std::string(kind.formatName)
                                                      + "\".");
    const auto version = document.find("version");
    if (version == document.end())
        return makeError(ErrorCode::CorruptData, "version: this field is required but missing.");
    if (!version->is_number_integer())
        return makeError(ErrorCode::CorruptData, "version: expected a whole number, found " + describeValue(*version) + ".");
    const std::string newer = "This " + noun + " was saved by a newer Thespis (format ";
    if (version->is_number_unsigned() && version->get<std::uint64_t>() > std::uint64_t(std::numeric_limits<int>::max()))
        return makeError(ErrorCode::NewerVersion, newer + version->dump() + "). Update Thespis to open it.");
    const std::int64_t number = version->get<std::int64_t>();
    if (number < kind.firstVersion)
        return makeError(ErrorCode::CorruptData, "version: " + std::to_string(number) + " is not a " + noun
                                                     + " format version (the first is "
                                                     + std::to_string(kind.firstVersion) + ").");
    if (number > kind.currentVersion)
        return makeError(ErrorCode::NewerVersion, newer + std::to_string(number) + "). Update Thespis to open it.",
                         "this build reads formats " + std::to_string(kind.firstVersion) + " to "
                             + std::to_string(kind.currentVersion));
    return Versioned{std::move(document), int(number)};
}

std::string quote(std::string_view text)
{
    return json(std::string(text)).dump(-1, ' ', false, json::error_handler_t::replace);
}

std::string describeValue(const json& value)
{
    switch (value.type()) {
    case json::value_t::null: return "null";
    case json::value_t::boolean: return value.get<bool>() ? "true" : "false";
    case json::value_t::string: {
        const auto& s = value.get_ref<const std::string&>();
        return s.size() <= 40 ? "the text " + quote(s) : "a text";
    }
    case json::value_t::number_integer:
    case json::value_t::number_unsigned:
    case json::value_t::number_float: return value.dump();
    case json::value_t::object: return "an object";
    case json::value_t::array: return "a list";
    default: return "an unsupported value";
    }
}

} // namespace thespis::core::json_document
