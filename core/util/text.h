#pragma once
// Small text helpers shared across core.

#include <span>
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

/// The text with its ASCII letters in one case.
inline std::string asciiCase(std::string_view text, bool upper)
{
    const char from = upper ? 'a' : 'A', to = upper ? 'A' : 'a';
    std::string out(text);
    for (char& c : out)
        if (c >= from && c <= from + 25)
            c = char(c - from + to);
    return out;
}

/// The parts one after another, with `separator` between them ("AH L", "go forward").
inline std::string joined(std::span<const std::string> parts, std::string_view separator = " ")
{
    std::string text;
    for (std::size_t i = 0; i < parts.size(); ++i) {
        if (i > 0)
            text += separator;
        text += parts[i];
    }
    return text;
}

/// ASCII lower case (file extensions, names compared without case).
inline std::string lowercase(std::string_view text) { return asciiCase(text, false); }

/// ASCII upper case (BML's lexemes and enumerations, compared without case).
inline std::string uppercase(std::string_view text) { return asciiCase(text, true); }

/// The text without the spaces, tabs and line ends around it.
inline std::string_view trimmed(std::string_view text)
{
    const auto space = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
    while (!text.empty() && space(text.front()))
        text.remove_prefix(1);
    while (!text.empty() && space(text.back()))
        text.remove_suffix(1);
    return text;
}

/// Appends `c` as markup text holds it: <, > and & as references, and " too when `quote` (in a
/// quoted attribute value).
inline void appendEscaped(std::string& out, char c, bool quote)
{
    switch (c) {
    case '<': out += "&lt;"; break;
    case '>': out += "&gt;"; break;
    case '&': out += "&amp;"; break;
    case '"': out += quote ? "&quot;" : "\""; break;
    default: out += c;
    }
}

/// A sentence to go after a colon: its first letter in lower case ("The file …" → "the file …").
inline std::string lowerFirst(std::string sentence)
{
    if (!sentence.empty() && sentence[0] >= 'A' && sentence[0] <= 'Z')
        sentence[0] = char(sentence[0] - 'A' + 'a');
    return sentence;
}

} // namespace thespis::core
