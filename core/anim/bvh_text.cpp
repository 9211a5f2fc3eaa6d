// BVH text scanning helpers (bvh_text.h).

#include "anim/bvh_text.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>

namespace thespis::core::anim::bvh {

std::string_view nextWord(std::string_view line, std::size_t& pos)
{
    while (pos < line.size() && isInlineSpace(line[pos]))
        ++pos;
    const std::size_t start = pos;
    while (pos < line.size() && !isInlineSpace(line[pos]))
        ++pos;
    return line.substr(start, pos - start);
}

bool equalsNoCase(std::string_view a, std::string_view b)
{
    return a.size() == b.size()
           && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
                  return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
              });
}

bool startsWithNoCase(std::string_view s, std::string_view prefix)
{
    return s.size() >= prefix.size() && equalsNoCase(s.substr(0, prefix.size()), prefix);
}

std::string quote(std::string_view token)
{
    std::string out = "'";
    const std::size_t shown = std::min<std::size_t>(token.size(), 40);
    for (std::size_t i = 0; i < shown; ++i) {
        const auto c = static_cast<unsigned char>(token[i]);
        if (c >= 0x20 && c < 0x7f) {
            out += char(c);
        } else {
            char buffer[8];
            std::snprintf(buffer, sizeof buffer, "\\x%02x", unsigned(c));
            out += buffer;
        }
    }
    if (shown < token.size())
        out += "…";
    return out + "'";
}

Error corrupt(int line, const std::string& message)
{
    return makeError(ErrorCode::CorruptData, "line " + std::to_string(line) + ": " + message);
}

bool parseNumber(std::string_view token, double& value)
{
    if (token.starts_with('+')) {
        token.remove_prefix(1);
        if (token.starts_with('-'))
            return false;
    }
    const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    return !token.empty() && ec == std::errc() && end == token.data() + token.size() && std::isfinite(value);
}

bool parseInteger(std::string_view token, long long& value)
{
    if (token.starts_with('+')) {
        token.remove_prefix(1);
        if (token.starts_with('-'))
            return false;
    }
    const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    return !token.empty() && ec == std::errc() && end == token.data() + token.size();
}

Error inFile(const std::filesystem::path& path, Error error)
{
    error.message = path.filename().string() + ", " + error.message;
    error.detail = path.string();
    return error;
}

} // namespace thespis::core::anim::bvh
