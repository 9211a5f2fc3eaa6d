#pragma once
// One visitor's conversation with a bot: the state AIML templates read and change (predicates,
// the topic, input and answer history, categories learned with <learn>), answering inputs, and
// saving that state to JSON and restoring it. The bot is shared and never changed.

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "dialogue/aiml.h"
#include "dialogue/aiml_reader.h"
#include "dialogue/bot.h"
#include "dialogue/graphmaster.h"
#include "util/error.h"

namespace thespis::core::dialogue {

/// What a conversation remembers; all of it is saved. Histories are newest last and keep at
/// least the last kHistoryLength entries.
struct ConversationState {
    std::string id = "visitor";                    ///< <id/>
    std::map<std::string, std::string> predicates; ///< <set name>/<get name>; "topic" among them
    std::vector<std::string> inputs;               ///< input sentences after substitution
    std::vector<std::vector<std::string>> thats;   ///< each answer's sentences, markup removed
    std::vector<std::string> requests;             ///< whole inputs as typed
    std::vector<std::string> responses;            ///< whole answers
    std::vector<std::string> learned;              ///< AIML of each <learn>ed category, in order
    std::uint64_t randomState = 0x9E3779B97F4A7C15ull; ///< <random>'s generator, so a restore continues it
};

inline constexpr std::size_t kHistoryLength = 64;

/// Limits that turn a looping script into an answer with a problem instead of a hang.
struct ConversationLimits {
    int sraiDepth = 100;        ///< <srai> within <srai> ...
    int sraiCalls = 2000;       ///< <srai> evaluations for one input
    int loopIterations = 100;   ///< one <condition>'s <loop/> repeats
    int nodeVisits = 1000000;   ///< template elements evaluated for one input
    std::uint32_t matchVisits = 2000000; ///< graphmaster nodes visited for one input (every srai included)
};

class Conversation {
public:
    explicit Conversation(std::shared_ptr<const Bot> bot, std::string id = "visitor");

    /// Answers one input (it may hold several sentences; each is answered in turn).
    Answer respond(std::string_view input);

    const ConversationState& state() const { return m_state; }
    const Bot& bot() const { return *m_bot; }
    const std::shared_ptr<const Bot>& sharedBot() const { return m_bot; }
    /// Categories learned in this conversation (<learn>/<learnf>), with their file given as "learned".
    const std::vector<Category>& learnedCategories() const { return m_learned.categories; }
    void setLimits(const ConversationLimits& limits) { m_limits = limits; }
    const ConversationLimits& limits() const { return m_limits; }

    /// The state as a versioned JSON document ("thespis-conversation").
    std::string saveJson() const;
    /// A conversation with `bot` continuing from a saved state. NotOurFormat, NewerVersion, or
    /// CorruptData naming the field.
    static Result<Conversation> restore(std::shared_ptr<const Bot> bot, std::string_view json);

private:
    friend class TemplateEvaluator;
    /// Parses `aiml` (one or more categories) into the learned categories; false if none was read.
    bool learn(const std::string& aiml);

    std::shared_ptr<const Bot> m_bot;
    ConversationState m_state;
    ConversationLimits m_limits;
    CategoryStore m_learned;
    Graphmaster m_learnedGraph;
};

} // namespace thespis::core::dialogue
