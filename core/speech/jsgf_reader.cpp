#include <algorithm>
#include <charconv>
#include <cmath>
#include <set>

#include "speech/jsgf.h"

namespace thespis::core::speech {
namespace {

// Deeper nesting than any grammar a person writes; it keeps hostile text off the stack's end.
constexpr int kMaxDepth = 200;

struct Lexeme {
    enum class Kind { End, Word, Quoted, RuleName, Tag, Weight, Symbol };
    Kind kind = Kind::End;
    std::string text; // Word, Quoted (unescaped), RuleName and Tag (without brackets), Symbol
    double weight = 0;
    int line = 1, column = 1;
};

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }
bool isSymbol(char c) { return c == '=' || c == ';' || c == '|' || c == '*' || c == '+' || c == '(' || c == ')' || c == '[' || c == ']'; }
bool endsWord(char c) { return isSpace(c) || isSymbol(c) || c == '<' || c == '>' || c == '{' || c == '}' || c == '/' || c == '"'; }

// The length of the valid UTF-8 sequence at `text`'s start, or 0.
std::size_t utf8Length(std::string_view text)
{
    const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
    const unsigned char lead = byte(0);
    std::size_t length = lead < 0x80 ? 1 : lead >= 0xC2 && lead < 0xE0 ? 2 : lead >= 0xE0 && lead < 0xF0 ? 3 : lead >= 0xF0 && lead < 0xF5 ? 4 : 0;
    if (length == 0 || length > text.size())
        return 0;
    for (std::size_t i = 1; i < length; ++i)
        if ((byte(i) & 0xC0) != 0x80)
            return 0;
    // Overlong three- and four-byte forms, surrogates, and code points beyond U+10FFFF.
    if ((lead == 0xE0 && byte(1) < 0xA0) || (lead == 0xED && byte(1) >= 0xA0) || (lead == 0xF0 && byte(1) < 0x90)
        || (lead == 0xF4 && byte(1) >= 0x90))
        return 0;
    return length;
}

Error syntaxError(int line, int column, const std::string& what)
{
    return makeError(ErrorCode::CorruptData,
                     "JSGF line " + std::to_string(line) + ", column " + std::to_string(column) + ": " + what + ".");
}

class Lexer {
public:
    explicit Lexer(std::string_view text) : m_text(text) {}

    Result<Lexeme> next()
    {
        if (auto skipped = skipSpaceAndComments(); !skipped)
            return skipped.error();
        Lexeme lexeme;
        lexeme.line = m_line;
        lexeme.column = m_column;
        if (m_at >= m_text.size())
            return lexeme;
        const char c = m_text[m_at];
        if (isSymbol(c)) {
            lexeme.kind = Lexeme::Kind::Symbol;
            lexeme.text = std::string(1, c);
            advance(1);
            return lexeme;
        }
        switch (c) {
        case '<': return enclosed(lexeme, Lexeme::Kind::RuleName, '>', "a rule name <…>");
        case '{': return enclosed(lexeme, Lexeme::Kind::Tag, '}', "a tag {…}");
        case '"': return enclosed(lexeme, Lexeme::Kind::Quoted, '"', "a quoted token");
        case '/': return weight(lexeme);
        case '>':
        case '}': return syntaxError(m_line, m_column, std::string("a stray '") + c + "'");
        default: break;
        }
        std::size_t end = m_at;
        while (end < m_text.size() && !endsWord(m_text[end]))
            ++end;
        lexeme.kind = Lexeme::Kind::Word;
        lexeme.text = std::string(m_text.substr(m_at, end - m_at));
        advance(end - m_at);
        return lexeme;
    }

private:
    void advance(std::size_t count)
    {
        for (std::size_t i = 0; i < count && m_at < m_text.size(); ++i, ++m_at) {
            if (m_text[m_at] == '\n') {
                ++m_line;
                m_column = 1;
            } else if ((static_cast<unsigned char>(m_text[m_at]) & 0xC0) != 0x80) {
                ++m_column; // columns count characters, not the bytes of one
            }
        }
    }

    Result<void> skipSpaceAndComments()
    {
        while (m_at < m_text.size()) {
            if (isSpace(m_text[m_at])) {
                advance(1);
            } else if (m_text.substr(m_at, 2) == "//") {
                advance(std::min(m_text.find('\n', m_at), m_text.size()) - m_at);
            } else if (m_text.substr(m_at, 2) == "/*") {
                const std::size_t close = m_text.find("*/", m_at + 2);
                if (close == std::string_view::npos)
                    return syntaxError(m_line, m_column, "a comment /* is never closed");
                advance(close + 2 - m_at);
            } else {
                break;
            }
        }
        return {};
    }

    // Text up to `close` (a backslash escapes it), on one line for rule names.
    Result<Lexeme> enclosed(Lexeme lexeme, Lexeme::Kind kind, char close, const char* what)
    {
        std::string content;
        std::size_t i = m_at + 1;
        for (; i < m_text.size() && m_text[i] != close; ++i) {
            if (kind == Lexeme::Kind::RuleName && (isSpace(m_text[i]) || m_text[i] == '<'))
                return syntaxError(lexeme.line, lexeme.column, std::string(what) + " holds a space or '<'");
            if (m_text[i] == '\\' && kind != Lexeme::Kind::RuleName && i + 1 < m_text.size())
                ++i;
            content += m_text[i];
        }
        if (i >= m_text.size())
            return syntaxError(lexeme.line, lexeme.column, std::string(what) + " is never closed");
        if (kind == Lexeme::Kind::RuleName && content.empty())
            return syntaxError(lexeme.line, lexeme.column, "a rule name <> is empty");
        lexeme.kind = kind;
        lexeme.text = std::move(content);
        advance(i + 1 - m_at);
        return lexeme;
    }

    Result<Lexeme> weight(Lexeme lexeme)
    {
        const std::size_t close = m_text.find('/', m_at + 1);
        const std::string_view number =
            close == std::string_view::npos ? std::string_view{} : m_text.substr(m_at + 1, close - m_at - 1);
        const auto [end, ec] = std::from_chars(number.data(), number.data() + number.size(), lexeme.weight);
        if (close == std::string_view::npos || number.empty() || ec != std::errc() || end != number.data() + number.size()
            || !std::isfinite(lexeme.weight) || lexeme.weight < 0)
            return syntaxError(lexeme.line, lexeme.column, "a weight must be a number ≥ 0 between slashes (/2.5/)");
        lexeme.kind = Lexeme::Kind::Weight;
        advance(close + 1 - m_at);
        return lexeme;
    }

    std::string_view m_text;
    std::size_t m_at = 0;
    int m_line = 1, m_column = 1;
};

// Grammar names and the parts of rule names: letters, digits and _ $ - (ASCII).
bool isName(std::string_view name)
{
    return !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '$'
               || c == '-';
    });
}

bool isDottedName(std::string_view name)
{
    while (true) {
        const std::size_t dot = name.find('.');
        if (!isName(name.substr(0, dot)))
            return false;
        if (dot == std::string_view::npos)
            return true;
        name.remove_prefix(dot + 1);
    }
}

class Parser {
public:
    explicit Parser(std::string_view text) : m_lexer(text) {}

    Result<JsgfGrammar> parse()
    {
        if (auto first = advance(); !first)
            return first.error();
        if (m_next.kind != Lexeme::Kind::Word || m_next.text != "#JSGF")
            return makeError(ErrorCode::NotOurFormat, "This is not a JSGF grammar: it does not start with \"#JSGF\".");
        if (auto header = parseHeader(); !header)
            return header.error();
        if (auto name = parseGrammarName(); !name)
            return name.error();
        while (m_next.kind != Lexeme::Kind::End) {
            auto statement = m_next.kind == Lexeme::Kind::Word && m_next.text == "import" ? parseImport() : parseRule();
            if (!statement)
                return statement.error();
        }
        return std::move(m_grammar);
    }

private:
    Result<void> advance()
    {
        auto lexeme = m_lexer.next();
        if (!lexeme)
            return lexeme.error();
        m_next = std::move(*lexeme);
        return {};
    }

    Error expected(const std::string& what) const
    {
        const std::string found = m_next.kind == Lexeme::Kind::End ? "the end of the text"
                                                                   : "\"" + m_next.text + "\"";
        return syntaxError(m_next.line, m_next.column, "expected " + what + ", found " + found);
    }

    bool atSymbol(char symbol) const { return m_next.kind == Lexeme::Kind::Symbol && m_next.text[0] == symbol; }

    Result<void> expectSymbol(char symbol, const std::string& what)
    {
        if (!atSymbol(symbol))
            return expected(what);
        return advance();
    }

    Result<void> parseHeader()
    {
        if (auto moved = advance(); !moved)
            return moved.error();
        std::vector<std::string> fields;
        while (m_next.kind == Lexeme::Kind::Word && fields.size() < 3) {
            fields.push_back(m_next.text);
            if (auto moved = advance(); !moved)
                return moved.error();
        }
        if (fields.empty())
            return expected("a version after #JSGF (V1.0)");
        std::string version = fields[0];
        for (char& c : version)
            c = char(std::toupper(static_cast<unsigned char>(c)));
        if (version != "V1.0")
            return syntaxError(1, 1, "JSGF version " + fields[0] + " is not V1.0, the one read here");
        m_grammar.version = "V1.0";
        m_grammar.charset = fields.size() > 1 ? fields[1] : "";
        m_grammar.locale = fields.size() > 2 ? fields[2] : "";
        return expectSymbol(';', "';' after the #JSGF header");
    }

    Result<void> parseGrammarName()
    {
        if (m_next.kind != Lexeme::Kind::Word || m_next.text != "grammar")
            return expected("\"grammar name;\" after the header");
        if (auto moved = advance(); !moved)
            return moved.error();
        if (m_next.kind != Lexeme::Kind::Word || !isDottedName(m_next.text))
            return expected("a grammar name (letters, digits, _ $ - and dots)");
        m_grammar.name = m_next.text;
        if (auto moved = advance(); !moved)
            return moved.error();
        return expectSymbol(';', "';' after the grammar's name");
    }

    Result<void> parseImport()
    {
        if (auto moved = advance(); !moved)
            return moved.error();
        const Lexeme at = m_next;
        const std::size_t dot = at.text.rfind('.');
        if (at.kind != Lexeme::Kind::RuleName || dot == std::string::npos || !isDottedName(at.text.substr(0, dot))
            || !(at.text.substr(dot + 1) == "*" || isName(at.text.substr(dot + 1))))
            return expected("an imported rule <grammar.rule> or <grammar.*>");
        JsgfImport imported{at.text.substr(0, dot), at.text.substr(dot + 1), at.line, at.column};
        for (const JsgfImport& earlier : m_grammar.imports)
            if (earlier.grammar == imported.grammar && earlier.rule == imported.rule)
                return syntaxError(at.line, at.column,
                                   "<" + at.text + "> is imported twice (first on line " + std::to_string(earlier.line) + ")");
        m_grammar.imports.push_back(std::move(imported));
        if (auto moved = advance(); !moved)
            return moved.error();
        return expectSymbol(';', "';' after the import");
    }

    Result<void> parseRule()
    {
        JsgfRule rule;
        rule.line = m_next.line;
        rule.column = m_next.column;
        if (m_next.kind == Lexeme::Kind::Word && m_next.text == "public") {
            rule.isPublic = true;
            if (auto moved = advance(); !moved)
                return moved.error();
        }
        if (m_next.kind != Lexeme::Kind::RuleName || !isName(m_next.text))
            return expected("a rule definition <name> = …; (or import, at a statement's start)");
        rule.name = m_next.text;
        if (rule.name == "NULL" || rule.name == "VOID")
            return syntaxError(m_next.line, m_next.column, "<" + rule.name + "> is JSGF's own and cannot be defined");
        if (const JsgfRule* earlier = m_grammar.findRule(rule.name))
            return syntaxError(m_next.line, m_next.column,
                               "<" + rule.name + "> is defined twice (first on line " + std::to_string(earlier->line) + ")");
        if (auto moved = advance(); !moved)
            return moved.error();
        if (auto equals = expectSymbol('=', "'=' after the rule's name"); !equals)
            return equals.error();
        auto expansion = parseAlternatives(0);
        if (!expansion)
            return expansion.error();
        rule.expansion = std::move(*expansion);
        if (auto end = expectSymbol(';', "';' or '|' after the rule's expansion"); !end)
            return end.error();
        m_grammar.rules.push_back(std::move(rule));
        return {};
    }

    Result<JsgfExpansion> parseAlternatives(int depth)
    {
        if (depth > kMaxDepth)
            return syntaxError(m_next.line, m_next.column, "groups nest deeper than " + std::to_string(kMaxDepth));
        JsgfExpansion alternatives;
        alternatives.kind = JsgfExpansion::Kind::Alternatives;
        alternatives.line = m_next.line;
        alternatives.column = m_next.column;
        bool weighted = false;
        do {
            if (!alternatives.children.empty())
                if (auto moved = advance(); !moved)
                    return moved.error();
            const bool hasWeight = m_next.kind == Lexeme::Kind::Weight;
            if (!alternatives.children.empty() && hasWeight != weighted)
                return syntaxError(m_next.line, m_next.column, "either every alternative has a weight or none has");
            weighted = hasWeight;
            if (hasWeight) {
                alternatives.weights.push_back(m_next.weight);
                if (auto moved = advance(); !moved)
                    return moved.error();
            }
            auto sequence = parseSequence(depth);
            if (!sequence)
                return sequence.error();
            alternatives.children.push_back(std::move(*sequence));
        } while (atSymbol('|'));
        if (alternatives.children.size() == 1 && !weighted)
            return std::move(alternatives.children.front());
        return alternatives;
    }

    bool startsItem() const
    {
        using K = Lexeme::Kind;
        return m_next.kind == K::Word || m_next.kind == K::Quoted || m_next.kind == K::RuleName || atSymbol('(')
               || atSymbol('[');
    }

    Result<JsgfExpansion> parseSequence(int depth)
    {
        JsgfExpansion sequence;
        sequence.line = m_next.line;
        sequence.column = m_next.column;
        if (!startsItem())
            return expected("a word, a <rule>, '(' or '['");
        while (startsItem()) {
            auto item = parseItem(depth);
            if (!item)
                return item.error();
            sequence.children.push_back(std::move(*item));
        }
        if (sequence.children.size() == 1)
            return std::move(sequence.children.front());
        return sequence;
    }

    Result<JsgfExpansion> parseItem(int depth)
    {
        auto item = parsePrimary(depth);
        if (!item)
            return item;
        bool repeated = false;
        while (atSymbol('*') || atSymbol('+') || m_next.kind == Lexeme::Kind::Tag) {
            if (m_next.kind == Lexeme::Kind::Tag) {
                item->tags.push_back(m_next.text);
            } else if (repeated) {
                return syntaxError(m_next.line, m_next.column, "a second '*' or '+' after one item");
            } else {
                repeated = true;
                JsgfExpansion repeat;
                repeat.kind = atSymbol('*') ? JsgfExpansion::Kind::ZeroOrMore : JsgfExpansion::Kind::OneOrMore;
                repeat.line = item->line;
                repeat.column = item->column;
                repeat.children.push_back(std::move(*item));
                *item = std::move(repeat);
            }
            if (auto moved = advance(); !moved)
                return moved.error();
        }
        return item;
    }

    Result<JsgfExpansion> parsePrimary(int depth)
    {
        JsgfExpansion primary;
        primary.line = m_next.line;
        primary.column = m_next.column;
        if (atSymbol('(') || atSymbol('[')) {
            const bool optional = atSymbol('[');
            if (auto moved = advance(); !moved)
                return moved.error();
            auto inner = parseAlternatives(depth + 1);
            if (!inner)
                return inner;
            if (auto closed = expectSymbol(optional ? ']' : ')', optional ? "']'" : "')'"); !closed)
                return closed.error();
            if (!optional)
                return inner;
            primary.kind = JsgfExpansion::Kind::Optional;
            primary.children.push_back(std::move(*inner));
            return primary;
        }
        if (m_next.kind == Lexeme::Kind::RuleName) {
            if (m_next.text == "NULL" || m_next.text == "VOID") {
                primary.kind = m_next.text == "NULL" ? JsgfExpansion::Kind::Null : JsgfExpansion::Kind::Void;
            } else if (isDottedName(m_next.text)) {
                primary.kind = JsgfExpansion::Kind::RuleRef;
                primary.text = m_next.text;
            } else {
                return syntaxError(m_next.line, m_next.column,
                                   "<" + m_next.text + "> is not a rule name (letters, digits, _ $ - and dots)");
            }
        } else {
            primary.kind = JsgfExpansion::Kind::Token;
            primary.text = m_next.text;
        }
        if (auto moved = advance(); !moved)
            return moved.error();
        return primary;
    }

    Lexer m_lexer;
    Lexeme m_next;
    JsgfGrammar m_grammar;
};

// Each rule reference names a rule of this grammar or one that may come from an import.
Result<void> checkReferences(const JsgfGrammar& grammar, const JsgfExpansion& expansion)
{
    if (expansion.kind == JsgfExpansion::Kind::RuleRef) {
        const std::string& name = expansion.text;
        const std::size_t dot = name.rfind('.');
        bool known = false;
        if (dot == std::string::npos) {
            known = grammar.findRule(name) != nullptr
                    || std::any_of(grammar.imports.begin(), grammar.imports.end(),
                                   [&](const JsgfImport& i) { return i.rule == name || i.rule == "*"; });
        } else {
            const std::string owner = name.substr(0, dot);
            known = owner == grammar.name ? grammar.findRule(name.substr(dot + 1)) != nullptr
                                          : std::any_of(grammar.imports.begin(), grammar.imports.end(),
                                                        [&](const JsgfImport& i) { return i.grammar == owner; });
        }
        if (!known)
            return syntaxError(expansion.line, expansion.column, "<" + name + "> is neither defined nor imported");
    }
    for (const JsgfExpansion& child : expansion.children)
        if (auto checked = checkReferences(grammar, child); !checked)
            return checked;
    return {};
}

} // namespace

const JsgfRule* JsgfGrammar::findRule(std::string_view ruleName) const
{
    for (const JsgfRule& rule : rules)
        if (rule.name == ruleName)
            return &rule;
    return nullptr;
}

std::vector<const JsgfRule*> JsgfGrammar::publicRules() const
{
    std::vector<const JsgfRule*> found;
    for (const JsgfRule& rule : rules)
        if (rule.isPublic)
            found.push_back(&rule);
    return found;
}

Result<JsgfGrammar> parseJsgf(std::string_view text)
{
    if (text.substr(0, 3) == "\xEF\xBB\xBF") // a UTF-8 byte order mark
        text.remove_prefix(3);
    int line = 1, column = 1;
    for (std::size_t at = 0; at < text.size();) {
        const std::size_t length = utf8Length(text.substr(at));
        if (length == 0)
            return syntaxError(line, column, "the text is not UTF-8");
        line += text[at] == '\n';
        column = text[at] == '\n' ? 1 : column + 1;
        at += length;
    }
    auto grammar = Parser(text).parse();
    if (!grammar)
        return grammar;
    for (const JsgfRule& rule : grammar->rules)
        if (auto checked = checkReferences(*grammar, rule.expansion); !checked)
            return checked.error();
    return grammar;
}

} // namespace thespis::core::speech
