#include "dialogue/graphmaster.h"

#include <algorithm>
#include <tuple>

#include "dialogue/normalise.h"
#include "util/text.h"

namespace thespis::core::dialogue {
namespace {


// Step priorities, in AIML 2.0's order; the words a step took break ties (fewest first, except
// sets, which try their longest phrase first).
enum Rank : std::uint16_t { PriorityWord, Hash, Underscore, Word, Set, Caret, Star };

std::uint16_t orderKey(Rank rank, std::uint32_t words)
{
    const std::uint16_t taken = std::uint16_t(std::min<std::uint32_t>(words, 63));
    return std::uint16_t(rank * 64 + (rank == Set ? 63 - taken : taken));
}

std::uint64_t buildKey(std::uint32_t parent, std::uint32_t kind, std::uint32_t key)
{
    return (std::uint64_t(parent) << 32) | (std::uint64_t(kind) << 30) | key;
}

bool isNumber(std::string_view word)
{
    return !word.empty() && std::all_of(word.begin(), word.end(), [](char c) { return c >= '0' && c <= '9'; });
}

} // namespace

std::vector<std::string_view> patternTokens(std::string_view pattern)
{
    std::vector<std::string_view> tokens;
    std::size_t at = 0;
    while (at < pattern.size()) {
        if (pattern[at] == ' ') {
            ++at;
            continue;
        }
        // An element token ("<bot name=\"x\"/>") holds a space: it ends at the first space after '>'.
        const std::size_t from = pattern[at] == '<' ? std::min(pattern.find('>', at), pattern.size()) : at;
        const std::size_t end = std::min(pattern.find(' ', from), pattern.size());
        tokens.push_back(pattern.substr(at, end - at));
        at = end;
    }
    return tokens;
}

std::uint32_t Graphmaster::wordId(std::string_view word)
{
    const auto [it, added] = m_words.try_emplace(std::string(word), std::uint32_t(m_words.size()));
    return it->second;
}

std::uint32_t Graphmaster::child(std::uint32_t parent, EdgeKind kind, std::uint32_t key)
{
    const auto [it, added] = m_building.try_emplace(buildKey(parent, std::uint32_t(kind), key), std::uint32_t(m_nodes.size()));
    if (added)
        m_nodes.emplace_back();
    return it->second;
}

std::uint32_t Graphmaster::wildcardChild(std::uint32_t parent, char wildcard)
{
    auto slot = [&]() -> std::uint32_t& {
        Node& node = m_nodes[parent];
        return wildcard == '#' ? node.hash : wildcard == '_' ? node.underscore : wildcard == '^' ? node.caret : node.star;
    };
    if (slot() == kNone) {
        const auto index = std::uint32_t(m_nodes.size());
        m_nodes.emplace_back(); // may move the nodes: slot() is looked up again below
        slot() = index;
    }
    return slot();
}

bool Graphmaster::addTokens(std::uint32_t& node, std::string_view tokens, const PatternContext& context, std::string& problem)
{
    for (std::string_view token : patternTokens(tokens)) {
        if (token.size() == 1 && std::string_view("*_#^").find(token[0]) != std::string_view::npos) {
            node = wildcardChild(node, token[0]);
        } else if (token.starts_with("<set>")) {
            const std::string name = lowercase(token.substr(5, token.size() - std::min<std::size_t>(token.size(), 11)));
            const auto set = context.sets ? context.sets->find(name) : decltype(context.sets->end()){};
            const bool known = context.sets && set != context.sets->end();
            if (!known && name != "number") {
                problem = "the pattern uses the set " + inQuotes(name) + ", which the bot does not have";
                return false;
            }
            const auto [it, added] = m_setKeys.try_emplace(name, std::uint32_t(m_sets.size()));
            if (added)
                m_sets.push_back(known ? &set->second : nullptr);
            node = child(node, EdgeKind::Set, it->second);
        } else if (token.starts_with("<bot")) {
            const std::size_t open = token.find('"'), close = token.rfind('"');
            const std::string name(open < close ? token.substr(open + 1, close - open - 1) : std::string_view());
            const auto property = context.properties ? context.properties->find(name) : decltype(context.properties->end()){};
            if (!context.properties || property == context.properties->end()) {
                problem = "the pattern uses the bot property " + inQuotes(name) + ", which the bot does not have";
                return false;
            }
            const std::string words = matchForm(property->second); // splitWords' views point into it
            for (std::string_view word : splitWords(words))
                node = child(node, EdgeKind::Word, wordId(word));
        } else {
            const bool priority = token.size() > 1 && token[0] == '$';
            const std::string words = matchForm(priority ? token.substr(1) : token);
            bool first = true;
            for (std::string_view word : splitWords(words)) {
                node = child(node, priority && first ? EdgeKind::PriorityWord : EdgeKind::Word, wordId(word));
                first = false;
            }
        }
    }
    return true;
}

bool Graphmaster::add(const Category& category, std::uint32_t index, const PatternContext& context, std::string& problem)
{
    std::uint32_t node = 0;
    if (!addTokens(node, category.pattern, context, problem))
        return false;
    node = child(node, EdgeKind::Word, wordId(kThatMarker));
    if (!addTokens(node, category.that, context, problem))
        return false;
    node = child(node, EdgeKind::Word, wordId(kTopicMarker));
    if (!addTokens(node, category.topic, context, problem))
        return false;
    m_nodes[node].category = index;
    return true;
}

void Graphmaster::freeze()
{
    std::vector<std::tuple<std::uint32_t, std::uint32_t, std::uint32_t, std::uint32_t>> edges; // parent, kind, key, child
    edges.reserve(m_building.size());
    for (const auto& [key, childIndex] : m_building)
        edges.emplace_back(std::uint32_t(key >> 32), std::uint32_t(key >> 30) & 3, std::uint32_t(key) & 0x3FFFFFFF, childIndex);
    std::sort(edges.begin(), edges.end());
    m_edges.clear();
    m_edges.reserve(edges.size());
    for (const auto& [parent, kind, key, childIndex] : edges) {
        Node& node = m_nodes[parent];
        const auto at = std::uint32_t(m_edges.size());
        auto [begin, end] = kind == std::uint32_t(EdgeKind::Word)           ? std::tie(node.wordBegin, node.wordEnd)
                             : kind == std::uint32_t(EdgeKind::PriorityWord) ? std::tie(node.priorityBegin, node.priorityEnd)
                                                                            : std::tie(node.setBegin, node.setEnd);
        if (begin == end)
            begin = at;
        end = at + 1;
        m_edges.push_back(Edge{key, childIndex});
    }
    m_building = {};
}

// One depth-first search, trying each node's ways on in priority order.
struct Graphmaster::Search {
    const Graphmaster& graph;
    const MatchInput& input;
    std::vector<std::uint32_t> ids;        // each word's id, kNone when no pattern has it
    std::vector<std::uint32_t> segmentEnd; // for each position, where its part ends (the next marker)
    std::uint32_t thatAt = 0, topicAt = 0; // marker positions
    std::vector<Capture> captures;
    std::vector<std::uint16_t> order;
    std::string phrase; // a set's candidate phrase
    std::uint32_t& visits; // what is left of the caller's budget
    std::uint32_t found = kNone;

    Capture::Part partAt(std::uint32_t at) const
    {
        return at > topicAt ? Capture::Topic : at > thatAt ? Capture::That : Capture::Pattern;
    }

    const Edge* findEdge(std::uint32_t begin, std::uint32_t end, std::uint32_t key) const
    {
        const Edge* first = graph.m_edges.data() + begin;
        const Edge* last = graph.m_edges.data() + end;
        const Edge* edge = std::lower_bound(first, last, Edge{key, 0});
        return edge != last && edge->key == key ? edge : nullptr;
    }

    bool step(std::uint32_t childNode, std::uint32_t at, std::uint32_t taken, Rank rank, bool capture)
    {
        order.push_back(orderKey(rank, taken));
        if (capture)
            captures.push_back(Capture{partAt(at), at, at + taken});
        if (walk(childNode, at + taken))
            return true;
        order.pop_back();
        if (capture)
            captures.pop_back();
        return false;
    }

    bool wildcard(std::uint32_t childNode, std::uint32_t at, std::uint32_t least, std::uint32_t most, Rank rank)
    {
        for (std::uint32_t taken = least; childNode != kNone && taken <= most; ++taken)
            if (step(childNode, at, taken, rank, true))
                return true;
        return false;
    }

    bool inSet(std::uint32_t setKey, std::uint32_t at, std::uint32_t words)
    {
        const PhraseSet* set = graph.m_sets[setKey];
        if (!set)
            return words == 1 && isNumber(input.words[at]);
        phrase.clear();
        for (std::uint32_t i = at; i < at + words; ++i)
            phrase.append(i > at ? " " : "").append(input.words[i]);
        return set->matchKeys.contains(phrase);
    }

    bool walk(std::uint32_t nodeIndex, std::uint32_t at)
    {
        if (visits == 0)
            return false;
        --visits;
        const Node& node = graph.m_nodes[nodeIndex];
        const auto size = std::uint32_t(ids.size());
        if (at == size && node.category != kNone) {
            found = node.category;
            return true;
        }
        const std::uint32_t end = at < size ? segmentEnd[at] : size;
        const std::uint32_t available = end - at; // words before the next marker
        const std::uint32_t id = at < size ? ids[at] : kNone;
        if (available > 0 && node.priorityBegin != node.priorityEnd)
            if (const Edge* edge = findEdge(node.priorityBegin, node.priorityEnd, id); edge && step(edge->child, at, 1, PriorityWord, false))
                return true;
        if (wildcard(node.hash, at, 0, available, Hash) || wildcard(node.underscore, at, 1, available, Underscore))
            return true;
        if (at < size && node.wordBegin != node.wordEnd)
            if (const Edge* edge = findEdge(node.wordBegin, node.wordEnd, id); edge && step(edge->child, at, 1, Word, false))
                return true;
        for (std::uint32_t e = node.setBegin; e < node.setEnd && available > 0; ++e) {
            const PhraseSet* set = graph.m_sets[graph.m_edges[e].key];
            const auto longest = std::min<std::uint32_t>(available, set ? std::uint32_t(set->longestWords) : 1);
            for (std::uint32_t words = longest; words >= 1; --words)
                if (inSet(graph.m_edges[e].key, at, words) && step(graph.m_edges[e].child, at, words, Set, true))
                    return true;
        }
        return wildcard(node.caret, at, 0, available, Caret) || wildcard(node.star, at, 1, available, Star);
    }
};

std::optional<GraphMatch> Graphmaster::match(const MatchInput& input, std::uint32_t& visits) const
{
    Search search{*this, input, {}, {}, 0, 0, {}, {}, {}, visits, kNone};
    const auto size = std::uint32_t(input.words.size());
    search.ids.reserve(size);
    for (std::string_view word : input.words) {
        const auto it = m_words.find(word);
        search.ids.push_back(it == m_words.end() ? kNone : it->second);
    }
    search.segmentEnd.resize(size);
    std::uint32_t end = size;
    for (std::uint32_t at = size; at-- > 0;) {
        if (input.words[at] == kThatMarker || input.words[at] == kTopicMarker) {
            (input.words[at] == kThatMarker ? search.thatAt : search.topicAt) = at;
            end = at;
        }
        search.segmentEnd[at] = end;
    }
    if (!search.walk(0, 0))
        return std::nullopt;
    return GraphMatch{search.found, std::move(search.captures), std::move(search.order)};
}

} // namespace thespis::core::dialogue
