#pragma once
// A finite-state grammar as a graph of words: what pocketsphinx's grammar search walks. A
// recogniser can be given one directly instead of JSGF text: pocketsphinx compiles JSGF by
// copying a rule's arcs at every reference, so a grammar of ten thousand patterns whose
// wildcards are word loops becomes millions of arcs and takes minutes to open, while the same
// language as a graph that shares its common beginnings and endings is small.
//
// States are numbered from 0; arcs say a word or nothing (an empty arc, taken without sound).

#include <cstdint>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

#include "util/error.h"

namespace thespis::core::speech {

struct WordGraph {
    static constexpr int kEmpty = -1; ///< an arc that says nothing
    struct Arc {
        int from = 0, to = 0;
        int word = kEmpty;   ///< index into words, or kEmpty
        float weight = 1;    ///< probability of taking it (1: no penalty)
    };
    int states = 0;
    int start = 0, end = 0;
    std::vector<std::string> words; ///< the words arcs say; each once
    std::vector<Arc> arcs;

    /// Whether `sentence` is a path from start to end (WordGraphWalker for many sentences).
    bool accepts(std::span<const std::string> sentence) const;
    /// Arcs that say a word.
    std::size_t wordArcs() const;
};

/// Error (InvalidArgument, naming the arc): an arc from or to no state, saying no word of the
/// graph or with a weight outside (0, 1]; the start or end not a state.
Result<void> checkWordGraph(const WordGraph& graph);

/// Checks sentences against one graph, which it indexes once; the graph must outlive it.
class WordGraphWalker {
public:
    explicit WordGraphWalker(const WordGraph& graph);
    bool accepts(std::span<const std::string> sentence) const;

private:
    void closeOverEmptyArcs(std::vector<int>& states) const;

    const WordGraph& m_graph;
    std::vector<std::size_t> m_first;         ///< state → its first arc in m_out (one past the last: next state's)
    std::vector<const WordGraph::Arc*> m_out; ///< arcs by the state they leave
    std::unordered_map<std::string, int> m_ids;
    mutable std::vector<char> m_in;           ///< scratch: states reached
};

} // namespace thespis::core::speech
