#include "dialogue/listening_tree.h"

#include <unordered_map>

#include "dialogue/normalise.h"

namespace thespis::core::dialogue::listening {
namespace {

using speech::WordGraph;

// What follows where a tree's pattern ends (listening_tree.h's Forest).
enum End : unsigned { kNone = 0, kFinal = 1, kThenAny = 2, kThenMaybeAny = 4, kThenFew = 8, kThenMaybeFew = 16, kThenSet = 32 };

// A tree node up to what follows it: two nodes with the same signature end alike, and are one
// state of the graph (the minimal automaton of the patterns, built bottom up).
struct Signature {
    unsigned ends = kNone;
    std::string thenSet; ///< kThenSet: the set's rule
    std::vector<std::pair<Key, int>> children; ///< step → the state it leads to
    auto operator<=>(const Signature&) const = default;
};

class GraphBuilder {
public:
    explicit GraphBuilder(const Trees& trees) : m_trees(trees) {}

    WordGraph build()
    {
        const std::vector<int> utterance = roots(m_trees.utterance), tails = roots(m_trees.tails);
        std::map<std::string, std::vector<int>> setTails;
        for (const auto& [rule, forest] : m_trees.setTails)
            setTails[rule] = roots(forest);
        m_graph.states = int(m_nodes.size());
        m_graph.start = m_graph.states++;
        m_graph.end = m_graph.states++;
        m_tails = m_graph.states++;
        for (const int root : utterance)
            arc(m_graph.start, root);
        for (const int root : tails)
            arc(m_tails, root);
        for (const auto& [rule, starts] : setTails) {
            const int entry = m_setTails[rule] = m_graph.states++;
            for (const int root : starts)
                arc(entry, root);
        }
        for (std::size_t state = 0; state < m_nodes.size(); ++state)
            expand(int(state));
        return std::move(m_graph);
    }

private:
    std::vector<int> roots(const Forest& forest)
    {
        std::vector<int> states;
        for (const auto& [tree, ends] : {std::pair{&forest.plain, kFinal}, std::pair{&forest.thenAny, kThenAny},
                                         std::pair{&forest.thenMaybeAny, kThenMaybeAny}, std::pair{&forest.thenFew, kThenFew},
                                         std::pair{&forest.thenMaybeFew, kThenMaybeFew}})
            if (tree->end || !tree->children.empty())
                states.push_back(intern(*tree, ends, {}));
        for (const auto& [rule, tree] : forest.thenSet)
            states.push_back(intern(tree, kThenSet, rule));
        return states;
    }

    int intern(const Node& node, End ends, const std::string& thenSet)
    {
        Signature signature{node.end ? unsigned(ends) : kNone, node.end ? thenSet : std::string(), {}};
        for (const auto& [key, child] : node.children)
            signature.children.emplace_back(key, intern(*child, ends, thenSet));
        const auto [at, added] = m_ids.try_emplace(signature, int(m_nodes.size()));
        if (added)
            m_nodes.push_back(std::move(signature));
        return at->second;
    }

    void arc(int from, int to, int word = WordGraph::kEmpty, float weight = 1) { m_graph.arcs.push_back({from, to, word, weight}); }

    int wordId(const std::string& word)
    {
        const auto [at, added] = m_wordIds.try_emplace(word, int(m_graph.words.size()));
        if (added)
            m_graph.words.push_back(word);
        return at->second;
    }

    // The entry of a loop of one or more of `words` that then goes on to `to`; one per target.
    int loopTo(const std::vector<std::string>& words, int to)
    {
        const auto [at, added] = m_loops.try_emplace({&words, to}, m_graph.states);
        if (!added)
            return at->second;
        const int entry = m_graph.states++, said = m_graph.states++;
        for (const std::string& word : words)
            arc(entry, said, wordId(word), m_trees.wildcardWordWeight);
        arc(said, entry);
        arc(said, to);
        return entry;
    }

    // The entry of a set's phrases, then `to`; one per set and target.
    int setTo(const std::string& rule, int to)
    {
        const auto [at, added] = m_sets.try_emplace({rule, to}, m_graph.states);
        if (!added)
            return at->second;
        const int entry = m_graph.states++;
        std::map<std::pair<int, std::string>, int> prefixes; // the phrases share their beginnings
        for (const std::string& phrase : m_trees.setPhrases.at(rule)) {
            const std::vector<std::string> words = wordsOf(phrase);
            int state = entry;
            for (std::size_t w = 0; w + 1 < words.size(); ++w) {
                const auto [next, isNew] = prefixes.try_emplace({state, words[w]}, m_graph.states);
                if (isNew) {
                    arc(state, m_graph.states, wordId(words[w]));
                    ++m_graph.states;
                }
                state = next->second;
            }
            if (!words.empty())
                arc(state, to, wordId(words.back()));
        }
        return entry;
    }

    void expand(int state)
    {
        const Signature& node = m_nodes[std::size_t(state)];
        if (node.ends & (kFinal | kThenMaybeAny))
            arc(state, m_graph.end);
        if (node.ends & (kThenAny | kThenMaybeAny))
            arc(state, loopTo(m_trees.anyWords, m_graph.end));
        if (node.ends & kThenMaybeFew)
            arc(state, m_tails);
        if (node.ends & (kThenFew | kThenMaybeFew))
            arc(state, loopTo(m_trees.fewWords, m_tails));
        if (node.ends & kThenSet)
            arc(state, setTo(node.thenSet, m_setTails.at(node.thenSet)));
        for (const auto& [key, to] : node.children) {
            switch (key.first) {
            case Step::Word: arc(state, to, wordId(key.second)); break;
            case Step::Set: arc(state, setTo(key.second, to)); break;
            case Step::MaybeAny: arc(state, to); [[fallthrough]];
            case Step::Any: arc(state, loopTo(m_trees.anyWords, to)); break;
            }
        }
    }

    const Trees& m_trees;
    WordGraph m_graph;
    std::vector<Signature> m_nodes; ///< state → its signature (the first states of the graph)
    int m_tails = 0;                ///< where the tails begin
    std::map<std::string, int> m_setTails; ///< set rule → where what follows it begins
    std::map<Signature, int> m_ids;
    std::unordered_map<std::string, int> m_wordIds;
    std::map<std::pair<const std::vector<std::string>*, int>, int> m_loops;
    std::map<std::pair<std::string, int>, int> m_sets;
};

} // namespace

speech::WordGraph wordGraphOf(const Trees& trees)
{
    return GraphBuilder(trees).build();
}

} // namespace thespis::core::dialogue::listening
