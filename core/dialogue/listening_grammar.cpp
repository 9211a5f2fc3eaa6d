#include "dialogue/listening_grammar.h"

#include <algorithm>
#include <array>
#include <memory>
#include <set>
#include <span>
#include <unordered_map>

#include "dialogue/listening_tree.h"
#include "util/text.h"

namespace thespis::core::dialogue {
namespace {

constexpr std::array<std::string_view, 20> kOnes = {
    "zero",    "one",     "two",       "three",    "four",     "five",    "six",
    "seven",   "eight",   "nine",      "ten",      "eleven",   "twelve",  "thirteen",
    "fourteen", "fifteen", "sixteen",  "seventeen", "eighteen", "nineteen"};
constexpr std::array<std::string_view, 10> kTens = {"",      "",      "twenty",  "thirty", "forty",
                                                    "fifty", "sixty", "seventy", "eighty", "ninety"};

void spellBelowThousand(int n, std::vector<std::string>& out)
{
    if (n >= 100) {
        out.emplace_back(kOnes[std::size_t(n / 100)]);
        out.emplace_back("hundred");
        n %= 100;
        if (n == 0)
            return;
    }
    if (n < 20) {
        out.emplace_back(kOnes[std::size_t(n)]);
        return;
    }
    out.emplace_back(kTens[std::size_t(n / 10)]);
    if (n % 10)
        out.emplace_back(kOnes[std::size_t(n % 10)]);
}

// "42" → forty two; up to six digits as a number, longer runs (and "007") digit by digit, as
// people read codes.
std::vector<std::string> spelledDigits(std::string_view digits)
{
    std::vector<std::string> out;
    if (digits.size() > 6 || (digits.size() > 1 && digits.front() == '0')) {
        for (char d : digits)
            out.emplace_back(kOnes[std::size_t(d - '0')]);
        return out;
    }
    int value = 0;
    for (char d : digits)
        value = value * 10 + (d - '0');
    if (value >= 1000) {
        spellBelowThousand(value / 1000, out);
        out.emplace_back("thousand");
        if (value % 1000 == 0)
            return out;
    }
    if (value % 1000 != 0 || value == 0)
        spellBelowThousand(value % 1000, out);
    return out;
}

// The ASCII letters of a Latin letter with a diacritic (U+00C0 … U+00FF, œ), or "".
std::string_view latinBase(char32_t c)
{
    static constexpr std::string_view kLatin1 = // U+00C0 … U+00FF; '.' for the two signs
        "aaaaaaaceeeeiiiidnooooo.ouuuuyts"
        "aaaaaaaceeeeiiiidnooooo.ouuuuyty";
    if (c == 0xC6 || c == 0xE6)
        return "ae";
    if (c == 0xDF)
        return "ss";
    if (c == 0x152 || c == 0x153)
        return "oe";
    if (c >= 0xC0 && c <= 0xFF && kLatin1[c - 0xC0] != '.')
        return kLatin1.substr(c - 0xC0, 1);
    return {};
}

// The code point at the start of `text` and its length in bytes (a stray byte stands for itself).
std::pair<char32_t, std::size_t> decode(std::string_view text)
{
    const auto byte = [&](std::size_t i) { return char32_t(static_cast<unsigned char>(text[i])); };
    const char32_t lead = byte(0);
    const std::size_t length = lead >= 0xF0 ? 4 : lead >= 0xE0 ? 3 : lead >= 0xC0 ? 2 : 1;
    if (length > text.size() || length == 1)
        return {lead, 1};
    char32_t c = lead & (0x3F >> (length - 1));
    for (std::size_t i = 1; i < length; ++i) {
        if ((byte(i) & 0xC0) != 0x80)
            return {lead, 1};
        c = (c << 6) | (byte(i) & 0x3F);
    }
    return {c, length};
}

using listening::Forest;
using listening::Key;
using listening::Node;
using listening::Step;

std::string stepText(const Key& key)
{
    switch (key.first) {
    case Step::Word: return key.second;
    case Step::Set: return "<" + key.second + ">";
    case Step::Any: return "<any>";
    case Step::MaybeAny: return "[<any>]";
    }
    return {};
}

// What may follow `node`: its children's steps and what follows them; optional when a pattern
// also ends at `node`.
void writeRest(const Node& node, std::string& out)
{
    const bool grouped = node.end || node.children.size() > 1;
    out += node.end ? "[" : grouped ? "(" : "";
    bool first = true;
    for (const auto& [key, child] : node.children) {
        out += first ? "" : " | ";
        first = false;
        out += stepText(key);
        if (!child->children.empty()) {
            out += ' ';
            writeRest(*child, out);
        }
    }
    out += node.end ? "]" : grouped ? ")" : "";
}

bool isGrammarName(std::string_view name)
{
    return !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '.';
    });
}

class Builder {
public:
    Builder(const GrammarSource& source, const ListeningOptions& options) : m_source(source), m_options(options) {}

    Result<ListeningGrammar> build()
    {
        if (!isGrammarName(m_options.grammarName))
            return makeError(ErrorCode::InvalidArgument, "A grammar's name is letters, digits, _ and dots, not "
                                                             + inQuotes(m_options.grammarName) + ".");
        if (!(m_options.wildcardWordWeight > 0 && m_options.wildcardWordWeight <= 1))
            return makeError(ErrorCode::InvalidArgument, "A wildcard word's weight is a probability in (0, 1], not "
                                                             + std::to_string(m_options.wildcardWordWeight) + ".");
        makeSets();
        makeWildcardWords();
        for (std::size_t p = 0; p < m_source.patterns.size(); ++p)
            addPattern(p);
        if (m_grammar.patternsUsed == 0)
            return makeError(ErrorCode::InvalidArgument, "Nothing to listen for: none of the "
                                                             + std::to_string(m_source.patterns.size())
                                                             + " patterns has a word that can be said.");
        return write();
    }

private:
    std::vector<std::string> words(std::string_view token)
    {
        std::string dropped;
        std::vector<std::string> said = speakableWords(token, &dropped);
        if (joined(said) != lowercase(token) && m_noted.insert(std::string(token)).second) {
            if (said.empty())
                m_grammar.notes.push_back(inQuotes(token) + " is left out: nothing in it can be said.");
            else
                m_grammar.notes.push_back(inQuotes(token) + " is listened for as " + inQuotes(joined(said))
                                          + (dropped.empty() ? "." : " (" + inQuotes(dropped) + " left out)."));
        }
        return said;
    }

    void makeSets()
    {
        std::set<std::string> ruleNames;
        for (const auto& [name, phrases] : m_source.sets) {
            std::vector<std::string> said;
            for (const auto& phrase : phrases) {
                std::vector<std::string> phraseWords;
                for (const std::string& word : phrase)
                    for (std::string& w : words(word))
                        phraseWords.push_back(std::move(w));
                if (!phraseWords.empty())
                    said.push_back(joined(phraseWords));
            }
            std::sort(said.begin(), said.end());
            said.erase(std::unique(said.begin(), said.end()), said.end());
            if (said.empty())
                continue;
            std::string base = "set_";
            for (char c : lowercase(name))
                base += (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') ? c : '_';
            std::string rule = base;
            for (int n = 2; !ruleNames.insert(rule).second; ++n)
                rule = base + "_" + std::to_string(n);
            m_setRules[name] = {rule, std::move(said)};
        }
    }

    // The vocabulary's speakable words, those the patterns and sets use most first, capped.
    void makeWildcardWords()
    {
        std::unordered_map<std::string, std::size_t> uses;
        for (const auto& pattern : m_source.patterns)
            for (const PatternItem& item : pattern)
                if (item.kind == PatternItem::Kind::Word)
                    for (const std::string& w : speakableWords(item.word))
                        ++uses[w];
        for (const auto& [name, rule] : m_setRules)
            for (const std::string& phrase : rule.second)
                for (const std::string& w : speakableWords(phrase))
                    ++uses[w];
        std::vector<std::string> vocabulary;
        std::set<std::string> seen;
        for (const std::string& token : m_source.vocabulary)
            for (std::string& w : words(token))
                if (seen.insert(w).second)
                    vocabulary.push_back(std::move(w));
        std::stable_sort(vocabulary.begin(), vocabulary.end(), [&](const std::string& a, const std::string& b) {
            const auto count = [&](const std::string& w) { const auto at = uses.find(w); return at == uses.end() ? 0 : at->second; };
            return count(a) > count(b);
        });
        if (vocabulary.size() > m_options.maxWildcardWords) {
            m_grammar.wildcardWordsLeftOut = vocabulary.size() - m_options.maxWildcardWords;
            vocabulary.resize(m_options.maxWildcardWords);
        }
        m_grammar.wildcardWords = std::move(vocabulary);
    }

    void skip(std::size_t pattern, const std::string& why)
    {
        ++m_grammar.patternsSkipped;
        m_grammar.notes.push_back("Pattern " + std::to_string(pattern + 1) + " is left out: " + why + ".");
    }

    void addPattern(std::size_t p)
    {
        std::vector<Key> steps;
        const bool canWild = !m_grammar.wildcardWords.empty();
        for (const PatternItem& item : m_source.patterns[p]) {
            switch (item.kind) {
            case PatternItem::Kind::Word:
                for (std::string& w : words(item.word))
                    steps.emplace_back(Step::Word, std::move(w));
                break;
            case PatternItem::Kind::SetOf: {
                const auto set = m_setRules.find(item.set);
                if (set == m_setRules.end())
                    return skip(p, "its set " + inQuotes(item.set) + " is not defined or has nothing to say");
                steps.emplace_back(Step::Set, set->second.first);
                m_usedSets.insert(item.set);
                break;
            }
            case PatternItem::Kind::OneOrMore:
                if (!canWild)
                    return skip(p, "it has a wildcard, and there is no vocabulary to stand for it");
                steps.emplace_back(Step::Any, "");
                break;
            case PatternItem::Kind::ZeroOrMore:
                if (canWild)
                    steps.emplace_back(Step::MaybeAny, "");
                break;
            }
        }
        if (std::all_of(steps.begin(), steps.end(), [](const Key& k) { return k.first == Step::MaybeAny; }))
            return skip(p, "it has no word that must be said");
        addSteps(m_trees.utterance, steps, 1);
        ++m_grammar.patternsUsed;
    }

    static bool isWildcard(const Key& step) { return step.first == Step::Any || step.first == Step::MaybeAny; }

    // `steps` into `forest`, split at the first step that is not the last and is a set or a
    // wildcard (from `wildFrom` on: a pattern's leading wildcard is its first step); the rest
    // goes to the tails. A wildcard that ends them is written once for all: "(what is | tell me
    // about) <any>" rather than a copy of the word loop after each.
    void addSteps(Forest& forest, std::span<Key> steps, std::size_t wildFrom)
    {
        std::size_t split = 0;
        while (split + 1 < steps.size() && !(steps[split].first == Step::Set || (split >= wildFrom && isWildcard(steps[split]))))
            ++split;
        if (split + 1 < steps.size()) {
            const Key& at = steps[split];
            if (at.first == Step::Set) {
                insert(forest.thenSet[at.second], steps.first(split));
                return addSteps(m_trees.setTails[at.second], steps.subspan(split + 1), 0);
            }
            m_usesInnerWildcard = true;
            insert(at.first == Step::Any ? forest.thenFew : forest.thenMaybeFew, steps.first(split));
            return addSteps(m_trees.tails, steps.subspan(split + 1), 0);
        }
        if (isWildcard(steps.back())) {
            m_usesWildcard = true;
            return insert(steps.back().first == Step::Any ? forest.thenAny : forest.thenMaybeAny, steps.first(steps.size() - 1));
        }
        insert(forest.plain, steps);
    }

    void insert(Node& root, std::span<Key> steps)
    {
        Node* node = &root;
        for (Key& step : steps) {
            m_usesWildcard = m_usesWildcard || isWildcard(step);
            if (step.first == Step::Word)
                m_words.insert(step.second);
            auto& child = node->children[std::move(step)];
            if (!child)
                child = std::make_unique<Node>();
            node = child.get();
        }
        node->end = true;
    }

    // The alternatives of `forest`, each followed by what its tree leads to.
    static void writeForest(const Forest& forest, std::string& out)
    {
        bool first = true;
        const auto alternative = [&] {
            out += first ? "\n    " : "\n  | ";
            first = false;
        };
        for (const auto& [key, child] : forest.plain.children) {
            alternative();
            out += stepText(key);
            if (!child->children.empty()) {
                out += ' ';
                writeRest(*child, out);
            }
        }
        for (const auto& [prefixes, then] : {std::pair{&forest.thenAny, "<any>"}, std::pair{&forest.thenMaybeAny, "[<any>]"},
                                             std::pair{&forest.thenFew, "<few> <tails>"}, std::pair{&forest.thenMaybeFew, "[<few>] <tails>"}}) {
            if (prefixes->children.empty() && !prefixes->end)
                continue;
            alternative();
            if (!prefixes->children.empty()) {
                writeRest(*prefixes, out);
                out += ' ';
            }
            out += then;
        }
        for (const auto& [rule, prefixes] : forest.thenSet) {
            alternative();
            if (!prefixes.children.empty()) {
                writeRest(prefixes, out);
                out += ' ';
            }
            out += "<" + rule + "> <then_" + rule + ">";
        }
        out += ";\n";
    }

    ListeningGrammar write()
    {
        std::string& out = m_grammar.jsgf;
        out = "#JSGF V1.0;\ngrammar " + m_options.grammarName + ";\n\npublic <utterance> =";
        writeForest(m_trees.utterance, out);
        if (m_usesInnerWildcard) {
            out += "\n<tails> =";
            writeForest(m_trees.tails, out);
        }
        for (const auto& [rule, tails] : m_trees.setTails) {
            out += "\n<then_" + rule + "> =";
            writeForest(tails, out);
        }
        if (m_usesWildcard) {
            out += "\n<any> = <word> [<any>];\n<word> = " + joinedAlternatives(m_grammar.wildcardWords) + ";\n";
            m_words.insert(m_grammar.wildcardWords.begin(), m_grammar.wildcardWords.end());
        }
        if (m_usesInnerWildcard) {
            const std::size_t few = std::min(m_grammar.wildcardWords.size(), m_options.maxInnerWildcardWords);
            m_grammar.innerWildcardWords.assign(m_grammar.wildcardWords.begin(), m_grammar.wildcardWords.begin() + std::ptrdiff_t(few));
            out += "\n<few> = <fewword> [<few>];\n<fewword> = " + joinedAlternatives(m_grammar.innerWildcardWords) + ";\n";
            m_words.insert(m_grammar.innerWildcardWords.begin(), m_grammar.innerWildcardWords.end());
        }
        if (!m_usesWildcard)
            m_grammar.wildcardWords.clear();
        for (const std::string& set : m_usedSets) {
            const auto& [rule, phrases] = m_setRules.at(set);
            out += "<" + rule + "> = " + joinedAlternatives(phrases) + ";\n";
            for (const std::string& phrase : phrases)
                for (const std::string& w : speakableWords(phrase))
                    m_words.insert(w);
            m_trees.setPhrases[rule] = phrases;
        }
        m_grammar.words.assign(m_words.begin(), m_words.end());
        m_trees.anyWords = m_grammar.wildcardWords;
        m_trees.fewWords = m_grammar.innerWildcardWords;
        m_trees.wildcardWordWeight = m_options.wildcardWordWeight;
        m_grammar.graph = listening::wordGraphOf(m_trees);
        return std::move(m_grammar);
    }

    static std::string joinedAlternatives(const std::vector<std::string>& items)
    {
        std::string text;
        for (std::size_t i = 0; i < items.size(); ++i)
            text += (i == 0 ? "" : i % 12 == 0 ? "\n    | " : " | ") + items[i];
        return text;
    }

    const GrammarSource& m_source;
    const ListeningOptions& m_options;
    ListeningGrammar m_grammar;
    std::map<std::string, std::pair<std::string, std::vector<std::string>>> m_setRules; ///< set → rule, phrases
    std::set<std::string> m_usedSets, m_words, m_noted;
    listening::Trees m_trees;
    bool m_usesWildcard = false, m_usesInnerWildcard = false;
};

} // namespace

std::vector<std::string> speakableWords(std::string_view token, std::string* dropped)
{
    std::vector<std::string> out;
    std::string word, digits;
    const auto flush = [&] {
        if (!digits.empty())
            for (std::string& w : spelledDigits(digits))
                out.push_back(std::move(w));
        if (!word.empty() && word.back() == '\'')
            word.pop_back(); // an apostrophe stays only between letters
        if (!word.empty())
            out.push_back(std::move(word));
        word.clear();
        digits.clear();
    };
    for (std::size_t at = 0; at < token.size();) {
        const auto [c, length] = decode(token.substr(at));
        const std::string_view original = token.substr(at, length);
        at += length;
        const bool apostrophe = c == U'\'' || c == U'\u2019';
        if (c < 0x80 && std::isalpha(int(c))) {
            if (!digits.empty())
                flush();
            word += char(std::tolower(int(c)));
        } else if (c >= U'0' && c <= U'9') {
            if (!word.empty())
                flush();
            digits += char(c);
        } else if (apostrophe && !word.empty()) {
            word += '\'';
        } else if (const std::string_view base = latinBase(c); !base.empty()) {
            if (!digits.empty())
                flush();
            word += base;
        } else {
            flush();
            if (dropped && !(c == U' ' || c == U'\t'))
                *dropped += original;
        }
    }
    flush();
    return out;
}

Result<ListeningGrammar> makeListeningGrammar(const GrammarSource& source, const ListeningOptions& options)
{
    return Builder(source, options).build();
}

} // namespace thespis::core::dialogue
