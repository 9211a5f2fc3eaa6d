#pragma once
// Small text helpers shared across core.

#include <string>
#include <string_view>

namespace thespis::core {

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
