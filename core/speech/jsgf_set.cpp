#include <algorithm>
#include <map>
#include <set>
#include <unordered_map>

#include "speech/jsgf.h"
#include "util/file_io.h"

namespace thespis::core::speech {
namespace {

// More grammars than one import chain of a real grammar pulls in: a cap on hostile chains.
constexpr std::size_t kMaxGrammars = 64;
// Rules nested deeper than this while matching (a chain of thousands of rules, each naming the
// next) match nothing: the stack stays bounded on hostile grammars.
constexpr int kMaxRuleDepth = 1000;

Error importError(const JsgfGrammar& grammar, const JsgfImport& imported, const std::string& what)
{
    return makeError(ErrorCode::CorruptData, "JSGF grammar " + grammar.name + ", line " + std::to_string(imported.line)
                                                 + ", column " + std::to_string(imported.column) + ": " + what + ".");
}

void collectTokens(const JsgfExpansion& expansion, std::set<std::string>& tokens)
{
    if (expansion.kind == JsgfExpansion::Kind::Token)
        tokens.insert(expansion.text);
    for (const JsgfExpansion& child : expansion.children)
        collectTokens(child, tokens);
}

Result<void> checkResolved(const JsgfSet& set, const JsgfGrammar& grammar, const JsgfExpansion& expansion)
{
    if (expansion.kind == JsgfExpansion::Kind::RuleRef && !set.resolve(grammar, expansion.text))
        return makeError(ErrorCode::CorruptData, "JSGF grammar " + grammar.name + ", line " + std::to_string(expansion.line)
                                                     + ", column " + std::to_string(expansion.column) + ": <"
                                                     + expansion.text + "> is no public rule of the grammars imported.");
    for (const JsgfExpansion& child : expansion.children)
        if (auto checked = checkResolved(set, grammar, child); !checked)
            return checked;
    return {};
}

// Which word positions a part of a grammar can reach from a given one: sets of end positions
// (0 … words.size()) per node and start. A rule's sets are memoised per start; a rule met again
// while it is being matched (recursion that consumes nothing yet) answers what it has so far,
// and the match is repeated until no answer grows.
class Matcher {
public:
    Matcher(const JsgfSet& set, std::span<const std::string> words) : m_set(set), m_words(words) {}

    bool matchesWhole(const JsgfRule& rule)
    {
        while (true) {
            m_done.clear();
            m_recursed = false;
            const Positions ends = matchRule(rule, 0);
            if (ends[m_words.size()])
                return true;
            if (!m_recursed || !m_grew)
                return false;
            m_grew = false;
        }
    }

private:
    using Positions = std::vector<char>;
    using Key = std::pair<const JsgfRule*, std::size_t>;

    Positions none() const { return Positions(m_words.size() + 1, 0); }

    Positions matchRule(const JsgfRule& rule, std::size_t start)
    {
        const Key key{&rule, start};
        Positions& known = m_memo.try_emplace(key, none()).first->second; // map references stay valid
        const auto [state, first] = m_done.try_emplace(key, false);
        if (!first) {
            m_recursed = m_recursed || !state->second;
            return known;
        }
        Positions found = none();
        if (m_depth < kMaxRuleDepth) {
            ++m_depth;
            match(m_set.grammarOf(rule), rule.expansion, start, found);
            --m_depth;
        }
        if (found != known) {
            m_grew = true;
            known = found;
        }
        m_done[key] = true;
        return found;
    }

    // Adds to `ends` the positions `expansion` reaches from each of `starts`.
    void matchFrom(const JsgfGrammar& grammar, const JsgfExpansion& expansion, const Positions& starts, Positions& ends)
    {
        for (std::size_t p = 0; p < starts.size(); ++p)
            if (starts[p])
                match(grammar, expansion, p, ends);
    }

    // Adds to `reached` everything reached from it by repeating `expansion`.
    void closure(const JsgfGrammar& grammar, const JsgfExpansion& expansion, Positions& reached)
    {
        std::vector<std::size_t> todo;
        for (std::size_t p = 0; p < reached.size(); ++p)
            if (reached[p])
                todo.push_back(p);
        Positions next = none();
        while (!todo.empty()) {
            const std::size_t p = todo.back();
            todo.pop_back();
            std::fill(next.begin(), next.end(), 0);
            match(grammar, expansion, p, next);
            for (std::size_t q = 0; q < next.size(); ++q)
                if (next[q] && !reached[q]) {
                    reached[q] = 1;
                    todo.push_back(q);
                }
        }
    }

    // Adds to `ends` the positions `expansion` reaches from `start` (written into, never
    // cleared: alternatives add up without copies).
    void match(const JsgfGrammar& grammar, const JsgfExpansion& expansion, std::size_t start, Positions& ends)
    {
        using Kind = JsgfExpansion::Kind;
        switch (expansion.kind) {
        case Kind::Token:
            if (start < m_words.size() && m_words[start] == expansion.text)
                ends[start + 1] = 1;
            break;
        case Kind::Null: ends[start] = 1; break;
        case Kind::Void: break;
        case Kind::RuleRef:
            if (const JsgfRule* rule = resolved(grammar, expansion)) {
                const Positions reached = matchRule(*rule, start);
                for (std::size_t q = 0; q < reached.size(); ++q)
                    ends[q] |= reached[q];
            }
            break;
        case Kind::Sequence: {
            const JsgfExpansion& first = expansion.children.front();
            if (first.kind == Kind::Token && (start >= m_words.size() || m_words[start] != first.text))
                return; // most alternatives of a large grammar end here: no sets made
            Positions frontier = none(), next = none();
            frontier[start] = 1;
            for (const JsgfExpansion& child : expansion.children) {
                std::fill(next.begin(), next.end(), 0);
                matchFrom(grammar, child, frontier, next);
                std::swap(frontier, next);
                if (std::none_of(frontier.begin(), frontier.end(), [](char c) { return c != 0; }))
                    return;
            }
            for (std::size_t q = 0; q < frontier.size(); ++q)
                ends[q] |= frontier[q];
            break;
        }
        case Kind::Alternatives:
            for (const JsgfExpansion& child : expansion.children)
                match(grammar, child, start, ends);
            break;
        case Kind::Optional:
            match(grammar, expansion.children.front(), start, ends);
            ends[start] = 1;
            break;
        case Kind::ZeroOrMore:
        case Kind::OneOrMore: {
            Positions reached = none();
            if (expansion.kind == Kind::ZeroOrMore)
                reached[start] = 1;
            else
                match(grammar, expansion.children.front(), start, reached);
            closure(grammar, expansion.children.front(), reached);
            for (std::size_t q = 0; q < reached.size(); ++q)
                ends[q] |= reached[q];
            break;
        }
        }
    }

    const JsgfRule* resolved(const JsgfGrammar& grammar, const JsgfExpansion& reference)
    {
        const auto [at, added] = m_references.try_emplace(&reference, nullptr);
        if (added)
            at->second = m_set.resolve(grammar, reference.text);
        return at->second;
    }

    const JsgfSet& m_set;
    std::span<const std::string> m_words;
    std::map<Key, Positions> m_memo;
    std::map<Key, bool> m_done; ///< this round's rules: finished, or still being matched
    std::unordered_map<const JsgfExpansion*, const JsgfRule*> m_references;
    bool m_recursed = false, m_grew = false;
    int m_depth = 0;
};

} // namespace

const JsgfRule* JsgfSet::resolve(const JsgfGrammar& from, std::string_view reference) const
{
    const auto publicRuleOf = [&](std::string_view grammarName, std::string_view rule) -> const JsgfRule* {
        for (const JsgfGrammar& grammar : grammars)
            if (grammar.name == grammarName) {
                const JsgfRule* found = grammar.findRule(rule);
                return found && (found->isPublic || &grammar == &from) ? found : nullptr;
            }
        return nullptr;
    };
    const std::size_t dot = reference.rfind('.');
    if (dot != std::string_view::npos)
        return publicRuleOf(reference.substr(0, dot), reference.substr(dot + 1));
    if (const JsgfRule* local = from.findRule(reference))
        return local;
    for (const JsgfImport& imported : from.imports)
        if (imported.rule == reference || imported.rule == "*")
            if (const JsgfRule* found = publicRuleOf(imported.grammar, reference))
                return found;
    return nullptr;
}

const JsgfGrammar& JsgfSet::grammarOf(const JsgfRule& rule) const
{
    for (const JsgfGrammar& grammar : grammars)
        if (!grammar.rules.empty() && &rule >= grammar.rules.data() && &rule < grammar.rules.data() + grammar.rules.size())
            return grammar;
    assert(false && "the rule belongs to no grammar of the set");
    return grammars.front();
}

bool JsgfSet::accepts(std::span<const std::string> words, std::string_view rule) const
{
    if (grammars.empty())
        return false;
    const JsgfGrammar& main = grammars.front();
    std::vector<const JsgfRule*> starts;
    if (!rule.empty()) {
        if (const JsgfRule* named = main.findRule(rule))
            starts.push_back(named);
    } else {
        starts = main.publicRules();
    }
    return std::any_of(starts.begin(), starts.end(),
                       [&](const JsgfRule* start) { return Matcher(*this, words).matchesWhole(*start); });
}

std::vector<std::string> JsgfSet::tokens() const
{
    std::set<std::string> tokens;
    for (const JsgfGrammar& grammar : grammars)
        for (const JsgfRule& rule : grammar.rules)
            collectTokens(rule.expansion, tokens);
    return {tokens.begin(), tokens.end()};
}

Result<JsgfSet> resolveJsgf(JsgfGrammar grammar, const JsgfLoader& load)
{
    JsgfSet set;
    set.grammars.push_back(std::move(grammar));
    for (std::size_t g = 0; g < set.grammars.size(); ++g) {
        for (std::size_t i = 0; i < set.grammars[g].imports.size(); ++i) {
            const JsgfImport imported = set.grammars[g].imports[i];
            const auto loaded = std::find_if(set.grammars.begin(), set.grammars.end(),
                                             [&](const JsgfGrammar& known) { return known.name == imported.grammar; });
            if (loaded != set.grammars.end())
                continue;
            if (set.grammars.size() >= kMaxGrammars)
                return importError(set.grammars[g], imported,
                                   "more than " + std::to_string(kMaxGrammars) + " grammars are imported");
            auto text = load(imported.grammar);
            if (!text)
                return importError(set.grammars[g], imported,
                                   "the grammar " + imported.grammar + " cannot be read (" + text.error().message + ")");
            auto parsed = parseJsgf(*text);
            if (!parsed)
                return importError(set.grammars[g], imported,
                                   "the imported grammar " + imported.grammar + " is broken: " + parsed.error().message);
            if (parsed->name != imported.grammar)
                return importError(set.grammars[g], imported,
                                   "the file for grammar " + imported.grammar + " names itself " + parsed->name);
            set.grammars.push_back(std::move(*parsed));
        }
    }
    for (const JsgfGrammar& each : set.grammars) {
        for (const JsgfImport& imported : each.imports) {
            const auto owner = std::find_if(set.grammars.begin(), set.grammars.end(),
                                            [&](const JsgfGrammar& known) { return known.name == imported.grammar; });
            const bool found = imported.rule == "*" ? !owner->publicRules().empty()
                                                    : owner->findRule(imported.rule) && owner->findRule(imported.rule)->isPublic;
            if (!found)
                return importError(each, imported,
                                   "the grammar " + imported.grammar + " has no public rule " + imported.rule);
        }
        for (const JsgfRule& rule : each.rules)
            if (auto checked = checkResolved(set, each, rule.expansion); !checked)
                return checked.error();
    }
    return set;
}

Result<JsgfSet> readJsgfFile(const std::filesystem::path& path)
{
    const auto prefixed = [&](const std::filesystem::path& file, Error error) {
        error.message = file.string() + ": " + error.message;
        return error;
    };
    auto text = readTextFile(path);
    if (!text)
        return text.error();
    auto grammar = parseJsgf(*text);
    if (!grammar)
        return prefixed(path, grammar.error());
    const std::filesystem::path folder = path.parent_path();
    auto set = resolveJsgf(std::move(*grammar), [&](const std::string& name) -> Result<std::string> {
        // "com.example.polite" lives in com/example/polite.gram, as Java's packages do.
        std::string relative = name;
        std::replace(relative.begin(), relative.end(), '.', '/');
        return readTextFile(folder / (relative + ".gram"));
    });
    if (!set)
        return prefixed(path, set.error());
    return set;
}

} // namespace thespis::core::speech
