#include "speech/word_graph.h"

#include <algorithm>

namespace thespis::core::speech {

WordGraphWalker::WordGraphWalker(const WordGraph& graph) : m_graph(graph)
{
    const std::size_t states = std::size_t(std::max(graph.states, 0));
    m_first.assign(states + 1, 0);
    for (const WordGraph::Arc& arc : graph.arcs)
        if (arc.from >= 0 && arc.from < graph.states && arc.to >= 0 && arc.to < graph.states)
            ++m_first[std::size_t(arc.from) + 1];
    for (std::size_t s = 0; s < states; ++s)
        m_first[s + 1] += m_first[s];
    m_out.resize(m_first.back());
    std::vector<std::size_t> next(m_first.begin(), m_first.end() - 1);
    for (const WordGraph::Arc& arc : graph.arcs)
        if (arc.from >= 0 && arc.from < graph.states && arc.to >= 0 && arc.to < graph.states)
            m_out[next[std::size_t(arc.from)]++] = &arc;
    for (std::size_t w = 0; w < graph.words.size(); ++w)
        m_ids.emplace(graph.words[w], int(w));
    m_in.assign(states, 0);
}

void WordGraphWalker::closeOverEmptyArcs(std::vector<int>& states) const
{
    for (std::size_t i = 0; i < states.size(); ++i)
        for (std::size_t a = m_first[std::size_t(states[i])]; a < m_first[std::size_t(states[i]) + 1]; ++a)
            if (m_out[a]->word == WordGraph::kEmpty && !m_in[std::size_t(m_out[a]->to)]) {
                m_in[std::size_t(m_out[a]->to)] = 1;
                states.push_back(m_out[a]->to);
            }
}

bool WordGraphWalker::accepts(std::span<const std::string> sentence) const
{
    const int states = m_graph.states;
    if (m_graph.start < 0 || m_graph.start >= states || m_graph.end < 0 || m_graph.end >= states)
        return false;
    std::fill(m_in.begin(), m_in.end(), 0);
    std::vector<int> current{m_graph.start};
    m_in[std::size_t(m_graph.start)] = 1;
    closeOverEmptyArcs(current);
    for (const std::string& word : sentence) {
        const auto id = m_ids.find(word);
        if (id == m_ids.end())
            return false;
        std::fill(m_in.begin(), m_in.end(), 0);
        std::vector<int> next;
        for (const int state : current)
            for (std::size_t a = m_first[std::size_t(state)]; a < m_first[std::size_t(state) + 1]; ++a)
                if (m_out[a]->word == id->second && !m_in[std::size_t(m_out[a]->to)]) {
                    m_in[std::size_t(m_out[a]->to)] = 1;
                    next.push_back(m_out[a]->to);
                }
        closeOverEmptyArcs(next);
        if (next.empty())
            return false;
        current = std::move(next);
    }
    return std::find(current.begin(), current.end(), m_graph.end) != current.end();
}

Result<void> checkWordGraph(const WordGraph& graph)
{
    const auto inRange = [&](int state) { return state >= 0 && state < graph.states; };
    const auto bad = std::find_if(graph.arcs.begin(), graph.arcs.end(), [&](const WordGraph::Arc& arc) {
        return !inRange(arc.from) || !inRange(arc.to) || arc.word < WordGraph::kEmpty || arc.word >= int(graph.words.size())
               || !(arc.weight > 0 && arc.weight <= 1);
    });
    if (bad != graph.arcs.end())
        return makeError(ErrorCode::InvalidArgument, "A word graph's arc " + std::to_string(bad - graph.arcs.begin() + 1)
                                                         + " leads from or to no state, says no word of the graph or has a weight outside (0, 1].");
    if (!inRange(graph.start) || !inRange(graph.end))
        return makeError(ErrorCode::InvalidArgument, "A word graph's start or end is not one of its states.");
    return {};
}

bool WordGraph::accepts(std::span<const std::string> sentence) const
{
    return WordGraphWalker(*this).accepts(sentence);
}

std::size_t WordGraph::wordArcs() const
{
    return std::size_t(std::count_if(arcs.begin(), arcs.end(), [](const Arc& arc) { return arc.word != kEmpty; }));
}

} // namespace thespis::core::speech
