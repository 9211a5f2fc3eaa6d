#include "dialogue/bot_files.h"

#include <algorithm>

#include "dialogue/normalise.h"
#include "util/text.h"

namespace thespis::core::dialogue {
namespace {

struct Entry {
    int line = 0;
    std::vector<std::string> values;
};

// Reads the JSON-ish form, an array of arrays of strings, keeping each inner array's line. A
// hand-written scanner rather than a JSON library: it must report the line of a bad entry and
// go on after it, and the largest files (a set of 24 000 names) load on every start.
class ArrayScanner {
public:
    ArrayScanner(std::string_view text, const std::string& file, std::vector<LoadProblem>& problems)
        : m_text(text), m_file(file), m_problems(problems)
    {
    }

    std::vector<Entry> entries()
    {
        std::vector<Entry> out;
        skipSpace();
        if (!take('['))
            return fail("the file starts with neither \"[\" nor an entry"), out;
        for (;;) {
            skipSpace();
            if (take(']'))
                return out;
            if (!take('['))
                return fail("an entry must be a list such as [\"a\", \"b\"]"), out;
            Entry entry{m_line, {}};
            for (;;) {
                skipSpace();
                if (take(']'))
                    break;
                std::string value;
                if (!string(value))
                    return fail("a list holds only quoted strings"), out;
                entry.values.push_back(std::move(value));
                skipSpace();
                if (take(','))
                    continue;
                if (!take(']'))
                    return fail("\",\" or \"]\" expected after a string"), out;
                break;
            }
            out.push_back(std::move(entry));
            skipSpace();
            if (!take(',') && (m_at >= m_text.size() || m_text[m_at] != ']'))
                return fail("\",\" or \"]\" expected after an entry"), out;
        }
    }

    // "a", "b", ... up to the first thing that is not a string.
    std::vector<std::string> quotedList()
    {
        std::vector<std::string> values;
        for (std::string value; string(value); value.clear()) {
            values.push_back(std::move(value));
            skipSpace();
            if (!take(','))
                break;
            skipSpace();
        }
        return values;
    }

    // A JSON string at the cursor; false (cursor unchanged on the opening quote) when there is none.
    bool string(std::string& out)
    {
        if (!take('"'))
            return false;
        while (m_at < m_text.size()) {
            const char c = m_text[m_at++];
            if (c == '"')
                return true;
            if (c == '\n')
                ++m_line;
            if (c != '\\' || m_at >= m_text.size()) {
                out += c;
                continue;
            }
            const char escaped = m_text[m_at++];
            switch (escaped) {
            case 'n': out += '\n'; break;
            case 't': out += '\t'; break;
            case 'r': out += '\r'; break;
            case 'b': out += '\b'; break;
            case 'f': out += '\f'; break;
            case 'u': appendCodePoint(out); break;
            default: out += escaped; // \" \\ \/
            }
        }
        return false;
    }

private:
    void appendCodePoint(std::string& out)
    {
        unsigned code = 0;
        for (int i = 0; i < 4 && m_at < m_text.size(); ++i, ++m_at) {
            const char h = m_text[m_at];
            code = code * 16 + unsigned(h >= '0' && h <= '9' ? h - '0' : (h | 0x20) >= 'a' && (h | 0x20) <= 'f' ? (h | 0x20) - 'a' + 10 : 0);
        }
        if (code < 0x80) {
            out += char(code);
        } else if (code < 0x800) {
            out += char(0xC0 | (code >> 6));
            out += char(0x80 | (code & 0x3F));
        } else {
            out += char(0xE0 | (code >> 12));
            out += char(0x80 | ((code >> 6) & 0x3F));
            out += char(0x80 | (code & 0x3F));
        }
    }
    void skipSpace()
    {
        while (m_at < m_text.size() && (m_text[m_at] == ' ' || m_text[m_at] == '\t' || m_text[m_at] == '\n' || m_text[m_at] == '\r')) {
            if (m_text[m_at] == '\n')
                ++m_line;
            ++m_at;
        }
    }
    bool take(char c)
    {
        if (m_at < m_text.size() && m_text[m_at] == c) {
            ++m_at;
            return true;
        }
        return false;
    }
    void fail(std::string message)
    {
        m_problems.push_back(LoadProblem{m_file, m_line, 0, std::move(message) + "; the rest of the file is skipped"});
    }

    std::string_view m_text;
    const std::string& m_file;
    std::vector<LoadProblem>& m_problems;
    std::size_t m_at = 0;
    int m_line = 1;
};

bool isJsonForm(std::string_view text) { return trimmed(text).starts_with('['); }

// The line form: one entry a line, its values split at the first ":" when `pairs` (or written as
// quoted strings separated by commas); blank lines and "#" comments skipped.
std::vector<Entry> lineEntries(std::string_view text, bool pairs, const std::string& file, std::vector<LoadProblem>& problems)
{
    std::vector<Entry> out;
    int lineNumber = 0;
    while (!text.empty()) {
        const std::size_t end = std::min(text.find('\n'), text.size());
        const std::string_view line = trimmed(text.substr(0, end));
        text.remove_prefix(std::min(end + 1, text.size()));
        ++lineNumber;
        if (line.empty() || line.starts_with('#'))
            continue;
        Entry entry{lineNumber, {}};
        if (line.starts_with('"')) {
            std::vector<LoadProblem> unused; // a bad line is reported below by its count of values
            entry.values = ArrayScanner(line, file, unused).quotedList();
        } else if (!pairs) {
            entry.values.emplace_back(line);
        } else if (const std::size_t colon = line.find(':'); colon != std::string_view::npos) {
            entry.values.emplace_back(trimmed(line.substr(0, colon)));
            entry.values.emplace_back(trimmed(line.substr(colon + 1)));
        }
        if (pairs && entry.values.size() != 2) {
            problems.push_back(LoadProblem{file, lineNumber, 0, "expected \"key:value\"; the line is skipped"});
            continue;
        }
        out.push_back(std::move(entry));
    }
    return out;
}

std::vector<Entry> entries(std::string_view text, bool pairs, const std::string& file, std::vector<LoadProblem>& problems)
{
    return isJsonForm(text) ? ArrayScanner(text, file, problems).entries() : lineEntries(text, pairs, file, problems);
}

} // namespace

void PhraseSet::add(std::string phrase)
{
    std::string key = matchForm(phrase);
    if (key.empty())
        return;
    longestWords = std::max(longestWords, int(std::count(key.begin(), key.end(), ' ')) + 1);
    matchKeys.insert(std::move(key));
    phrases.push_back(std::move(phrase));
}

PhraseSet readSet(std::string_view text, const std::string& file, std::vector<LoadProblem>& problems)
{
    PhraseSet set;
    for (Entry& entry : entries(text, false, file, problems)) {
        std::string phrase;
        for (const std::string& word : entry.values)
            phrase += (phrase.empty() ? "" : " ") + word;
        set.add(std::move(phrase));
    }
    return set;
}

Pairs readPairs(std::string_view text, const std::string& file, std::vector<LoadProblem>& problems)
{
    Pairs pairs;
    for (Entry& entry : entries(text, true, file, problems)) {
        if (entry.values.size() != 2) {
            problems.push_back(LoadProblem{file, entry.line, 0, "an entry must hold two strings, found "
                                                                    + std::to_string(entry.values.size())});
            continue;
        }
        pairs.emplace_back(std::move(entry.values[0]), std::move(entry.values[1]));
    }
    return pairs;
}

} // namespace thespis::core::dialogue
