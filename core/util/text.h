#pragma once
// Small text helpers shared across core.

#include <string>
#include <string_view>

namespace thespis::core {

/// A name as messages show it: in double quotes.
inline std::string inQuotes(std::string_view text)
{
    std::string quoted;
    quoted.reserve(text.size() + 2);
    quoted += '"';
    quoted += text;
    quoted += '"';
    return quoted;
}

/// ASCII lower case (file extensions, names compared without case).
inline std::string lowercase(std::string_view text)
{
    std::string out(text);
    for (char& c : out)
        if (c >= 'A' && c <= 'Z')
            c = char(c - 'A' + 'a');
    return out;
}

} // namespace thespis::core
