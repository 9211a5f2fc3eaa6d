#pragma once
// The graphmaster: every category's pattern, that and topic as one path of a word trie, matched
// in AIML 2.0's priority order at each node ($word > # > _ > word > <set> > ^ > *), wildcards
// taking the fewest words first. Built from categories, then frozen into flat arrays: nodes, and
// their edges sorted by key in one contiguous vector.

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "dialogue/aiml.h"
#include "dialogue/bot_files.h"

namespace thespis::core::dialogue {

/// What a pattern's <set> and <bot> refer to while categories are added.
struct PatternContext {
    const std::map<std::string, PhraseSet>* sets = nullptr;         ///< by lower-case name
    const std::map<std::string, std::string>* properties = nullptr; ///< the bot's properties
};

/// A word range of the matched input a wildcard or a set took.
struct Capture {
    enum Part : unsigned char { Pattern, That, Topic } part;
    std::uint32_t begin, end; ///< into MatchInput::words
};

struct GraphMatch {
    std::uint32_t category = 0; ///< the index given to Graphmaster::add
    std::vector<Capture> captures;
    /// Each step's priority (kind, then words taken): of two graphs' matches, the smaller one is
    /// the match a single graph holding both would have found.
    std::vector<std::uint16_t> order;
};

/// The words one sentence is matched with: the input, then "<THAT>", the bot's last sentence,
/// then "<TOPIC>", the topic; all in match form (normalise.h).
struct MatchInput {
    std::vector<std::string_view> words;
};
inline constexpr std::string_view kThatMarker = "<THAT>";
inline constexpr std::string_view kTopicMarker = "<TOPIC>";

class Graphmaster {
public:
    /// Adds a category's path; a later category with the same path replaces the earlier one (so
    /// update files loaded last win). False with `problem` set when a <set> or <bot> is unknown.
    bool add(const Category& category, std::uint32_t index, const PatternContext& context, std::string& problem);
    /// Turns what was added into the flat arrays matching reads; add() may not follow.
    void freeze();

    /// The best match, or nullopt. Each node visited takes one from `visits`; at 0 the search
    /// gives up (patterns such as "* * * *" against a long input would otherwise take ages).
    std::optional<GraphMatch> match(const MatchInput& input, std::uint32_t& visits) const;
    std::size_t nodeCount() const { return m_nodes.size(); }
    /// Distinct words the patterns hold, the two part markers included.
    std::size_t wordCount() const { return m_words.size(); }
    bool empty() const { return m_nodes.size() <= 1 && m_nodes[0].category == kNone; }

    static constexpr std::uint32_t kNone = 0xFFFFFFFF;

private:
    enum class EdgeKind : std::uint32_t { Word = 0, PriorityWord = 1, Set = 2 };
    struct Node {
        std::uint32_t wordBegin = 0, wordEnd = 0;         // m_edges range: exact words
        std::uint32_t priorityBegin = 0, priorityEnd = 0; // m_edges range: $words
        std::uint32_t setBegin = 0, setEnd = 0;           // m_edges range: sets (key = set index)
        std::uint32_t hash = kNone, underscore = kNone, caret = kNone, star = kNone;
        std::uint32_t category = kNone;
    };
    struct Edge {
        std::uint32_t key;
        std::uint32_t child;
        bool operator<(const Edge& other) const { return key < other.key; }
    };
    struct Search;

    std::uint32_t wordId(std::string_view word);
    std::uint32_t child(std::uint32_t parent, EdgeKind kind, std::uint32_t key);
    std::uint32_t wildcardChild(std::uint32_t parent, char wildcard);
    bool addTokens(std::uint32_t& node, std::string_view tokens, const PatternContext& context, std::string& problem);

    std::vector<Node> m_nodes = std::vector<Node>(1);
    std::vector<Edge> m_edges;
    // Looked up by string_view, so matching a word allocates nothing.
    struct WordHash {
        using is_transparent = void;
        std::size_t operator()(std::string_view word) const { return std::hash<std::string_view>{}(word); }
    };
    std::unordered_map<std::string, std::uint32_t, WordHash, std::equal_to<>> m_words; // match-form word → id
    std::vector<const PhraseSet*> m_sets;                    // by set key; nullptr is the built-in number set
    std::map<std::string, std::uint32_t, std::less<>> m_setKeys;
    // Only while building: (parent, kind, key) → child.
    std::unordered_map<std::uint64_t, std::uint32_t> m_building;
};

} // namespace thespis::core::dialogue
