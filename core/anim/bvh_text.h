#pragma once
// Private to the BVH reader, writer and mapping files: scanning BVH text with line numbers,
// and the error and number parsing rules they share. A line ends at LF, CRLF or a lone CR, so
// LF, CRLF and mixed files (the cgspeed releases mix them) count lines the same way as an
// editor does.

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

#include "util/error.h"

namespace thespis::core::anim::bvh {

inline bool isInlineSpace(char c) { return c == ' ' || c == '\t' || c == '\v' || c == '\f'; }
inline bool isBreak(char c) { return c == '\n' || c == '\r'; }
inline bool isSpace(char c) { return isInlineSpace(c) || isBreak(c); }

/// The next whitespace-separated word of `line` from `pos` (moved past it); empty at the end.
std::string_view nextWord(std::string_view line, std::size_t& pos);

bool equalsNoCase(std::string_view a, std::string_view b);
bool startsWithNoCase(std::string_view s, std::string_view prefix);

/// A token as it appears in an error message: quoted, at most 40 characters, control and
/// non-ASCII bytes escaped (the fuzzer feeds anything; messages must stay readable).
std::string quote(std::string_view token);

struct Token {
    std::string_view text; // empty at the end of the text
    int line = 0;
};

class Scanner {
public:
    explicit Scanner(std::string_view text) : m_text(text)
    {
        if (m_text.starts_with("\xEF\xBB\xBF")) // UTF-8 byte order mark
            m_pos = 3;
    }

    std::size_t remaining() const { return m_text.size() - m_pos; }

    /// The next whitespace-separated token, across lines. At the end of the text: an empty
    /// token on the line of the last token, so that errors name a line the file has.
    Token next()
    {
        while (m_pos < m_text.size() && isSpace(m_text[m_pos]))
            advanceOne();
        if (m_pos >= m_text.size())
            return {{}, m_lastTokenLine};
        return word();
    }

    /// The next token on the current line, or an empty token at the end of the line.
    Token nextOnLine()
    {
        while (m_pos < m_text.size() && isInlineSpace(m_text[m_pos]))
            ++m_pos;
        if (m_pos < m_text.size() && isBreak(m_text[m_pos]))
            return {{}, m_line};
        return word();
    }

    /// The rest of the current line (without its line break) and its number; moves to the next
    /// line. False at the end of the text.
    bool nextLine(std::string_view& text, int& number)
    {
        if (m_pos >= m_text.size())
            return false;
        const std::size_t start = m_pos;
        while (m_pos < m_text.size() && !isBreak(m_text[m_pos]))
            ++m_pos;
        text = m_text.substr(start, m_pos - start);
        number = m_line;
        if (m_pos < m_text.size())
            advanceOne(); // LF or CR
        if (m_pos < m_text.size() && m_text[m_pos] == '\n' && m_text[m_pos - 1] == '\r')
            advanceOne(); // the LF of a CRLF
        return true;
    }

    /// Skips the rest of the current line; false if it held anything but spaces.
    bool restOfLineIsEmpty(Token& found)
    {
        found = nextOnLine();
        return found.text.empty();
    }

private:
    Token word()
    {
        const std::size_t start = m_pos;
        while (m_pos < m_text.size() && !isSpace(m_text[m_pos]))
            ++m_pos;
        if (m_pos > start)
            m_lastTokenLine = m_line;
        return {m_text.substr(start, m_pos - start), m_line};
    }

    void advanceOne()
    {
        const char c = m_text[m_pos++];
        if (c == '\n' || (c == '\r' && (m_pos >= m_text.size() || m_text[m_pos] != '\n')))
            ++m_line;
    }

    std::string_view m_text;
    std::size_t m_pos = 0;
    int m_line = 1;
    int m_lastTokenLine = 1;
};

/// CorruptData naming the line: "line 42: <message>".
Error corrupt(int line, const std::string& message);

/// An error parsing the text of `path`, told of the file: "walk.bvh, line 42: …", the path as
/// detail.
Error inFile(const std::filesystem::path& path, Error error);

/// Parses a whole token as a finite double ("+1.5", "-.25", "1e-05"). from_chars does not
/// accept a leading '+', which some exporters write.
bool parseNumber(std::string_view token, double& value);
bool parseInteger(std::string_view token, long long& value);

} // namespace thespis::core::anim::bvh
