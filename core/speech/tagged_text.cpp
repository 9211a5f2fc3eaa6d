#include "speech/tagged_text.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <optional>

#include "util/text.h"

namespace thespis::core::speech {
namespace {

struct ParseError {
    int line, column;
    std::string message;
};

class Reader {
public:
    explicit Reader(std::string_view input) : m_input(input) {}

    bool atEnd() const { return m_pos >= m_input.size(); }
    char peek(std::size_t ahead = 0) const { return m_pos + ahead < m_input.size() ? m_input[m_pos + ahead] : '\0'; }
    std::size_t position() const { return m_pos; }
    int line() const { return m_line; }
    int column() const { return m_column; }

    char take()
    {
        const char c = m_input[m_pos++];
        if (c == '\n') {
            ++m_line;
            m_column = 1;
        } else if ((static_cast<unsigned char>(c) & 0xC0) != 0x80) {
            // A column is a character: UTF-8 continuation bytes do not start one.
            ++m_column;
        }
        return c;
    }

    [[noreturn]] void fail(std::string message) const { throw ParseError{m_line, m_column, std::move(message)}; }
    [[noreturn]] static void failAt(int line, int column, std::string message)
    {
        throw ParseError{line, column, std::move(message)};
    }

    void skipSpace()
    {
        while (!atEnd() && (peek() == ' ' || peek() == '\t' || peek() == '\n' || peek() == '\r'))
            take();
    }

    std::string name()
    {
        std::string out;
        while (!atEnd() && (std::isalnum(static_cast<unsigned char>(peek())) || peek() == '_' || peek() == '-'
                            || peek() == ':' || peek() == '.'))
            out += take();
        return out;
    }

    // An entity after its "&": the character it stands for, or nullopt (then "&" is text).
    std::optional<char> entity()
    {
        static constexpr std::pair<std::string_view, char> kEntities[] = {
            {"lt;", '<'}, {"gt;", '>'}, {"amp;", '&'}, {"quot;", '"'}, {"apos;", '\''}};
        for (const auto& [name, character] : kEntities)
            if (m_input.substr(m_pos, name.size()) == name) {
                for (std::size_t i = 0; i < name.size(); ++i)
                    take();
                return character;
            }
        return std::nullopt;
    }

private:
    std::string_view m_input;
    std::size_t m_pos = 0;
    int m_line = 1, m_column = 1;
};

struct Tag {
    std::string name;
    std::map<std::string, std::string> attributes;
    int line = 0, column = 0;
};

// A tag after its "<": name, attributes, "/>".
Tag readTag(Reader& r, int line, int column)
{
    Tag tag;
    tag.line = line;
    tag.column = column;
    tag.name = r.name();
    if (tag.name.empty())
        r.fail("expected a tag name after \"<\"");
    for (;;) {
        r.skipSpace();
        if (r.atEnd())
            r.failAt(line, column, "the tag <" + tag.name + "> is not closed with \"/>\"");
        if (r.peek() == '/' && r.peek(1) == '>') {
            r.take();
            r.take();
            return tag;
        }
        if (r.peek() == '>')
            r.fail("<" + tag.name + "> must end with \"/>\": gesture tags are empty elements");
        const int attributeLine = r.line(), attributeColumn = r.column();
        const std::string key = r.name();
        if (key.empty())
            r.fail(std::string("unexpected ") + inQuotes(std::string(1, r.peek())) + " in <" + tag.name + ">");
        r.skipSpace();
        if (r.peek() != '=')
            r.fail("expected \"=\" after the attribute " + key);
        r.take();
        r.skipSpace();
        const char quote = r.peek();
        if (quote != '"' && quote != '\'')
            r.fail("the value of " + key + " must be in quotes");
        r.take();
        std::string value;
        for (;;) {
            if (r.atEnd())
                r.failAt(attributeLine, attributeColumn, "the value of " + key + " is not closed");
            const char c = r.take();
            if (c == quote)
                break;
            if (c == '<')
                r.fail("\"<\" in the value of " + key);
            if (c == '&') {
                if (const auto e = r.entity()) {
                    value += *e;
                    continue;
                }
            }
            value += c;
        }
        if (!tag.attributes.emplace(key, value).second)
            r.failAt(attributeLine, attributeColumn, "the attribute " + key + " is given twice");
    }
}

std::string attribute(const Tag& tag, const std::string& key)
{
    const auto it = tag.attributes.find(key);
    if (it == tag.attributes.end() || it->second.empty())
        Reader::failAt(tag.line, tag.column, "<" + tag.name + "> needs a " + key + " attribute");
    return it->second;
}

void refuseOthers(const Tag& tag, std::initializer_list<std::string_view> known)
{
    for (const auto& [key, value] : tag.attributes)
        if (std::find(known.begin(), known.end(), key) == known.end())
            Reader::failAt(tag.line, tag.column, "<" + tag.name + "> has no attribute " + key);
}

TaggedText parse(std::string_view input)
{
    Reader r(input);
    TaggedText out;
    std::map<std::string, std::size_t> open; // id → index in out.gestures
    while (!r.atEnd()) {
        const char c = r.peek();
        if (c == '&') {
            r.take();
            out.text += r.entity().value_or('&');
            continue;
        }
        const char next = r.peek(1);
        if (c != '<' || !(std::isalpha(static_cast<unsigned char>(next)) || next == '/' || next == '_')) {
            out.text += r.take();
            continue;
        }
        const int line = r.line(), column = r.column();
        r.take();
        if (r.peek() == '/')
            r.fail("closing tags are not used: end a gesture with <end_gesture id=\"…\"/>");
        const Tag tag = readTag(r, line, column);
        if (tag.name == "begin_gesture") {
            refuseOthers(tag, {"id", "anim"});
            TaggedGesture gesture;
            gesture.id = attribute(tag, "id");
            gesture.animation = attribute(tag, "anim");
            gesture.begin = gesture.end = out.text.size();
            gesture.line = line;
            gesture.column = column;
            const bool used = std::any_of(out.gestures.begin(), out.gestures.end(),
                                          [&](const TaggedGesture& g) { return g.id == gesture.id; });
            if (used)
                Reader::failAt(line, column, "the gesture id " + inQuotes(gesture.id) + " is used twice");
            open.emplace(gesture.id, out.gestures.size());
            out.gestures.push_back(std::move(gesture));
        } else if (tag.name == "end_gesture") {
            refuseOthers(tag, {"id"});
            const std::string id = attribute(tag, "id");
            const auto it = open.find(id);
            if (it == open.end())
                Reader::failAt(line, column, "<end_gesture id=" + inQuotes(id) + "/> has no <begin_gesture> before it");
            out.gestures[it->second].end = out.text.size();
            open.erase(it);
        } else {
            Reader::failAt(line, column, "unknown tag <" + tag.name + ">: expected begin_gesture or end_gesture");
        }
    }
    if (!open.empty()) {
        const TaggedGesture& g = out.gestures[open.begin()->second];
        Reader::failAt(g.line, g.column, "the gesture " + inQuotes(g.id) + " is never ended with <end_gesture id="
                                             + inQuotes(g.id) + "/>");
    }
    return out;
}

std::string escaped(std::string_view text, bool attribute)
{
    std::string out;
    for (char c : text)
        appendEscaped(out, c, attribute);
    return out;
}

} // namespace

Result<TaggedText> parseTaggedText(std::string_view input)
{
    try {
        return parse(input);
    } catch (const ParseError& e) {
        return makeError(ErrorCode::CorruptData, "line " + std::to_string(e.line) + ", column "
                                                     + std::to_string(e.column) + ": " + e.message + ".");
    }
}

std::string taggedTextString(const TaggedText& tagged)
{
    // Tags at each offset: ends first (a gesture ending where another begins), then begins in order.
    std::string out;
    for (std::size_t i = 0; i <= tagged.text.size(); ++i) {
        for (const TaggedGesture& g : tagged.gestures)
            if (g.end == i && g.begin != i)
                out += "<end_gesture id=\"" + escaped(g.id, true) + "\"/>";
        for (const TaggedGesture& g : tagged.gestures)
            if (g.begin == i)
                out += "<begin_gesture id=\"" + escaped(g.id, true) + "\" anim=\"" + escaped(g.animation, true) + "\"/>";
        for (const TaggedGesture& g : tagged.gestures)
            if (g.end == i && g.begin == i)
                out += "<end_gesture id=\"" + escaped(g.id, true) + "\"/>";
        if (i < tagged.text.size())
            out += escaped(std::string_view(tagged.text).substr(i, 1), false);
    }
    return out;
}

} // namespace thespis::core::speech
