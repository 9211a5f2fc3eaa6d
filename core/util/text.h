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

/// A sentence to go after a colon: its first letter in lower case ("The file …" → "the file …").
inline std::string lowerFirst(std::string sentence)
{
    if (!sentence.empty() && sentence[0] >= 'A' && sentence[0] <= 'Z')
        sentence[0] = char(sentence[0] - 'A' + 'a');
    return sentence;
}

} // namespace thespis::core
