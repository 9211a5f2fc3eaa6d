#include "speech/bml.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <iterator>

#include "util/text.h"

// The sync constraints as a graph: a node for each constrained point (its reference's target is
// what it waits for) and one "timing" node per behaviour standing for all its other points and
// its speech's sync marks (it waits for every constrained point of its behaviour, since pins
// shift and stretch the rest). Nodes are resolved in dependency order; what is left over lies on
// or behind a cycle.

namespace thespis::core::speech {
namespace {

using Times = std::array<double, kBmlPointCount>;

constexpr int kTimingNode = kBmlPointCount; ///< a node's point index when it is the timing node
constexpr int kNodesPerBehavior = kBmlPointCount + 1;

// "g1 (line 4, column 5)", or "g1" for a block built in code.
std::string named(const BmlBehavior& b)
{
    if (b.line <= 0)
        return b.id;
    return b.id + " (line " + std::to_string(b.line) + ", column " + std::to_string(b.column) + ")";
}

// "<gesture> "g1"".
std::string described(const BmlBehavior& b)
{
    std::string out = "<";
    out += bmlKindName(b.kind);
    out += "> ";
    out += inQuotes(b.id);
    return out;
}

std::string secondsString(double seconds)
{
    char buffer[32];
    const auto written = std::to_chars(buffer, buffer + sizeof buffer, seconds, std::chars_format::general, 6);
    return std::string(buffer, written.ptr) + " s";
}

Error invalid(const BmlBehavior& b, const std::string& message)
{
    return makeError(ErrorCode::InvalidArgument, named(b) + ": " + message + ".");
}

// Where a constrained point's reference leads: a behaviour and one of its points or sync marks.
struct Target {
    int behavior = -1; ///< −1: seconds from the block's start
    int point = -1;    ///< a BmlPoint, or −1 for a sync mark
    int mark = -1;     ///< into the speech's syncMarks
};

// Natural offsets from 0 to `end` for the kinds whose own points are a start and an end.
Times startAndEnd(double end) { return {0, 0, 0, 0, end, end, end}; }

// `natural` (offsets by point, non-decreasing) mapped through the resolved points `at`: piecewise
// linear between them, shifted beyond them. For a speech's sync marks.
double mapThrough(const Times& natural, const Times& at, double offset)
{
    if (offset <= natural.front())
        return at.front() + (offset - natural.front());
    if (offset >= natural.back())
        return at.back() + (offset - natural.back());
    int i = 0;
    while (!(natural[i] <= offset && offset < natural[i + 1]))
        ++i;
    const double fraction = (offset - natural[i]) / (natural[i + 1] - natural[i]);
    return std::min(std::max(at[i] + fraction * (at[i + 1] - at[i]), at[i]), at[i + 1]);
}

class Resolver {
public:
    Resolver(const BmlBlock& block, const std::map<std::string, SpeechTiming>& speech, const BmlNaturalTiming& natural)
        : m_block(block), m_speech(speech), m_natural(natural), m_count(int(block.behaviors.size()))
    {
        m_markIndex.resize(m_count);
        for (int b = 0; b < m_count; ++b) {
            m_index.emplace(block.behaviors[b].id, b);
            const auto& marks = block.behaviors[b].syncMarks;
            for (std::size_t m = 0; m < marks.size(); ++m)
                m_markIndex[b].emplace(marks[m].first, int(m));
        }
    }

    Result<std::vector<BmlTimes>> run()
    {
        m_targets.assign(m_count * kNodesPerBehavior, Target{});
        m_naturalAt.resize(m_count);
        m_markNatural.resize(m_count);
        m_at.resize(m_count);
        m_markAt.resize(m_count);
        for (int b = 0; b < m_count; ++b)
            if (auto error = findTargets(b))
                return *error;
        for (int b = 0; b < m_count; ++b)
            if (auto error = findNaturalTiming(b))
                return *error;
        std::vector<int> order;
        if (auto error = orderNodes(order))
            return *error;
        for (int node : order)
            if (auto error = resolve(node))
                return *error;
        std::vector<BmlTimes> out;
        for (int b = 0; b < m_count; ++b)
            out.push_back({m_block.behaviors[b].id, m_at[b], m_markAt[b]});
        return out;
    }

private:
    const BmlBehavior& behavior(int b) const { return m_block.behaviors[b]; }
    static int node(int b, int point) { return b * kNodesPerBehavior + point; }
    bool constrained(int b, int point) const { return behavior(b).sync.contains(BmlPoint(point)); }

    // The node a reference's value comes from once resolved.
    int nodeOf(const Target& t) const
    {
        return t.point >= 0 && constrained(t.behavior, t.point) ? node(t.behavior, t.point)
                                                                : node(t.behavior, kTimingNode);
    }

    std::optional<Error> findTargets(int b)
    {
        for (const auto& [point, ref] : behavior(b).sync) {
            if (ref.behavior.empty())
                continue;
            Target& target = m_targets[node(b, int(point))];
            const auto found = m_index.find(ref.behavior);
            std::string missing;
            if (found == m_index.end()) {
                missing = "the block has no behaviour " + inQuotes(ref.behavior);
            } else {
                target.behavior = found->second;
                const BmlBehavior& other = behavior(target.behavior);
                const auto& marks = m_markIndex[target.behavior];
                const auto mark = marks.find(ref.point);
                if (const auto standard = bmlPointNamed(ref.point))
                    target.point = int(*standard);
                else if (mark != marks.end())
                    target.mark = mark->second;
                else
                    missing = described(other) + " has no sync point " + inQuotes(ref.point);
            }
            if (!missing.empty())
                return invalid(behavior(b), std::string(bmlPointName(point)) + " refers to "
                                                + inQuotes(ref.behavior + ":" + ref.point)
                                                + ", which does not exist: " + missing);
        }
        return std::nullopt;
    }

    std::optional<Error> findNaturalTiming(int b)
    {
        const BmlBehavior& self = behavior(b);
        Times& n = m_naturalAt[b];
        if (self.kind == BmlBehaviorKind::Speech) {
            const auto timing = m_speech.find(self.id);
            if (timing == m_speech.end())
                return invalid(self, "no word timing was given for this speech");
            const std::vector<WordTiming>& words = timing->second.words;
            const double lastWordEnd = words.empty() ? 0 : words.back().end;
            n = startAndEnd(std::max(timing->second.duration, lastWordEnd));
            for (const auto& mark : self.syncMarks) {
                const auto next = std::partition_point(words.begin(), words.end(),
                                                       [&](const WordTiming& w) { return w.textBegin < mark.second; });
                if (next != words.begin() && std::prev(next)->textEnd == mark.second)
                    m_markNatural[b].push_back(std::prev(next)->end); // right after its word: the word's end
                else
                    m_markNatural[b].push_back(next == words.end() ? lastWordEnd : next->start);
            }
            m_markAt[b].resize(self.syncMarks.size());
        } else if (self.kind == BmlBehaviorKind::Wait) {
            n = startAndEnd(self.duration);
        } else if (m_natural) {
            n = m_natural(self);
        } else {
            n = {};
        }
        const bool finite = std::all_of(n.begin(), n.end(), [](double t) { return std::isfinite(t); })
                            && std::all_of(m_markNatural[b].begin(), m_markNatural[b].end(),
                                           [](double t) { return std::isfinite(t); });
        if (!finite || !std::is_sorted(n.begin(), n.end()))
            return invalid(self, "its natural timing is not finite and in order");
        return std::nullopt;
    }

    // Kahn's algorithm over the nodes that take part: constrained points and timing nodes.
    std::optional<Error> orderNodes(std::vector<int>& order)
    {
        const int nodes = m_count * kNodesPerBehavior;
        std::vector<int> waitingFor(nodes, 0);
        std::vector<std::vector<int>> dependents(nodes);
        for (int b = 0; b < m_count; ++b) {
            for (const auto& [point, ref] : behavior(b).sync) {
                const int self = node(b, int(point));
                dependents[self].push_back(node(b, kTimingNode));
                ++waitingFor[node(b, kTimingNode)];
                if (const Target& t = m_targets[self]; t.behavior >= 0) {
                    dependents[nodeOf(t)].push_back(self);
                    ++waitingFor[self];
                }
            }
        }
        for (int b = 0; b < m_count; ++b)
            for (int p = 0; p <= kTimingNode; ++p)
                if ((p == kTimingNode || constrained(b, p)) && waitingFor[node(b, p)] == 0)
                    order.push_back(node(b, p));
        for (std::size_t next = 0; next < order.size(); ++next)
            for (int dependent : dependents[order[next]])
                if (--waitingFor[dependent] == 0)
                    order.push_back(dependent);
        if (order.size() == std::size_t(m_count) + countConstrained())
            return std::nullopt;
        return cycleError(waitingFor);
    }

    std::size_t countConstrained() const
    {
        std::size_t count = 0;
        for (const BmlBehavior& b : m_block.behaviors)
            count += b.sync.size();
        return count;
    }

    // Every node left waiting waits for another left waiting: following them from the first
    // constrained one must come round to a node seen before, and from it round again.
    Error cycleError(const std::vector<int>& waitingFor) const
    {
        int first = 0;
        while (!(waitingFor[first] > 0 && first % kNodesPerBehavior != kTimingNode))
            ++first;
        std::vector<int> path{first};
        std::vector<bool> seen(waitingFor.size(), false);
        while (!seen[path.back()]) {
            seen[path.back()] = true;
            path.push_back(stuckDependency(path.back(), waitingFor));
        }
        std::vector<int> cycle(std::find(path.begin(), path.end(), path.back()), path.end() - 1);
        // Name it from its constrained point that comes first in the document.
        std::erase_if(cycle, [](int n) { return n % kNodesPerBehavior == kTimingNode; });
        std::rotate(cycle.begin(), std::min_element(cycle.begin(), cycle.end()), cycle.end());
        std::vector<std::string> steps;
        for (int n : cycle) {
            const BmlBehavior& b = behavior(n / kNodesPerBehavior);
            const std::string self = b.id + ":" + std::string(bmlPointName(BmlPoint(n % kNodesPerBehavior)));
            if (steps.empty() || steps.back() != self)
                steps.push_back(self);
            const BmlSyncRef& ref = b.sync.at(BmlPoint(n % kNodesPerBehavior));
            steps.push_back(ref.behavior + ":" + ref.point);
        }
        if (steps.back() != steps.front())
            steps.push_back(steps.front());
        std::string chain;
        for (const std::string& step : steps)
            chain += (chain.empty() ? "" : " → ") + step;
        return invalid(behavior(cycle.front() / kNodesPerBehavior), "its sync references form a cycle: " + chain);
    }

    // A node left waiting that `n`, left waiting itself, waits for.
    int stuckDependency(int n, const std::vector<int>& waitingFor) const
    {
        const int b = n / kNodesPerBehavior, point = n % kNodesPerBehavior;
        if (point != kTimingNode)
            return nodeOf(m_targets[n]);
        const auto& sync = behavior(b).sync;
        const auto pin = std::find_if(sync.begin(), sync.end(),
                                      [&](const auto& p) { return waitingFor[node(b, int(p.first))] > 0; });
        assert(pin != sync.end());
        return node(b, int(pin->first));
    }

    std::optional<Error> resolve(int n)
    {
        const int b = n / kNodesPerBehavior, point = n % kNodesPerBehavior;
        if (point == kTimingNode)
            return placeBehavior(b);
        const BmlSyncRef& ref = behavior(b).sync.at(BmlPoint(point));
        const Target& t = m_targets[n];
        double at = ref.offset;
        if (t.behavior >= 0)
            at += t.mark >= 0 ? m_markAt[t.behavior][t.mark] : m_at[t.behavior][t.point];
        m_at[b][point] = at;
        return std::nullopt;
    }

    // Its points from its pins (already in m_at) and its natural timing: shifted before the first
    // pin and after the last, stretched between consecutive pins.
    std::optional<Error> placeBehavior(int b)
    {
        const BmlBehavior& self = behavior(b);
        const Times& n = m_naturalAt[b];
        Times& at = m_at[b];
        std::vector<int> pins;
        for (const auto& [point, ref] : self.sync)
            pins.push_back(int(point));
        for (std::size_t i = 1; i < pins.size(); ++i)
            if (at[pins[i]] < at[pins[i - 1]])
                return invalid(self, pinText(b, pins[i]) + " would come before " + pinText(b, pins[i - 1]));
        if (pins.empty()) {
            for (int p = 0; p < kBmlPointCount; ++p)
                at[p] = n[p] - n[0];
        }
        for (std::size_t i = 0; i < pins.size(); ++i) {
            const int pin = pins[i];
            if (i == 0)
                for (int p = 0; p < pin; ++p)
                    at[p] = at[pin] + (n[p] - n[pin]);
            if (i + 1 == pins.size()) {
                for (int p = pin + 1; p < kBmlPointCount; ++p)
                    at[p] = at[pin] + (n[p] - n[pin]);
                break;
            }
            const int next = pins[i + 1];
            for (int p = pin + 1; p < next; ++p) {
                const double fraction = n[next] > n[pin] ? (n[p] - n[pin]) / (n[next] - n[pin])
                                                         : double(p - pin) / double(next - pin);
                // Clamped: rounding must not carry a point past the pins around it.
                at[p] = std::min(std::max(at[pin] + fraction * (at[next] - at[pin]), at[pin]), at[next]);
            }
        }
        for (std::size_t m = 0; m < m_markAt[b].size(); ++m)
            m_markAt[b][m] = mapThrough(n, at, m_markNatural[b][m]);
        const auto finite = [](double t) { return std::isfinite(t); };
        if (!std::all_of(at.begin(), at.end(), finite) || !std::all_of(m_markAt[b].begin(), m_markAt[b].end(), finite))
            return invalid(self, "its times are out of range: the offsets are too large");
        return std::nullopt;
    }

    // "its stroke ("s1:t1", at 1.2 s)".
    std::string pinText(int b, int point) const
    {
        return "its " + std::string(bmlPointName(BmlPoint(point))) + " ("
               + inQuotes(bmlSyncRefString(behavior(b).sync.at(BmlPoint(point)))) + ", at "
               + secondsString(m_at[b][point]) + ")";
    }

    const BmlBlock& m_block;
    const std::map<std::string, SpeechTiming>& m_speech;
    const BmlNaturalTiming& m_natural;
    const int m_count;
    std::map<std::string_view, int> m_index;         ///< behaviour id → index
    std::vector<std::map<std::string_view, int>> m_markIndex; ///< by behaviour: sync mark id → index
    std::vector<Target> m_targets;                   ///< by node, for constrained points
    std::vector<Times> m_naturalAt;                 ///< by behaviour
    std::vector<std::vector<double>> m_markNatural;  ///< a speech's sync marks, natural offsets
    std::vector<Times> m_at;                         ///< by behaviour: resolved seconds
    std::vector<std::vector<double>> m_markAt;       ///< a speech's sync marks, resolved seconds
};

} // namespace

Result<std::vector<BmlTimes>> resolveBml(const BmlBlock& block, const std::map<std::string, SpeechTiming>& speech,
                                         const BmlNaturalTiming& natural)
{
    return Resolver(block, speech, natural).run();
}

} // namespace thespis::core::speech
