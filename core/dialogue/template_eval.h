#pragma once
// Matching one sentence and evaluating the answering category's template against a
// conversation's state (internal to core/dialogue; Conversation::respond drives it).

#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "dialogue/conversation.h"
#include "dialogue/template_tree.h"

namespace thespis::core::dialogue {

class TemplateEvaluator {
public:
    explicit TemplateEvaluator(Conversation& conversation);

    /// The answer to one input sentence (after substitution), as markup text. When a limit cuts
    /// the evaluation, returns "" and says why in `problem`.
    std::string answer(std::string_view sentence, MatchedCategory& matched, std::string& problem);

private:
    // The stars and local variables of one category's evaluation.
    struct Frame {
        std::vector<std::string> stars, thatStars, topicStars;
        std::map<std::string, std::string> vars;
        bool loopRequested = false;
    };
    struct Cut {
        std::string why;
    };

    std::string matchAndEvaluate(std::string_view sentence, MatchedCategory* matched);
    std::string evaluate(const std::vector<TemplateNode>& nodes, Frame& frame);
    void evaluateNode(const TemplateNode& node, Frame& frame, std::string& out);
    std::string attribute(const TemplateNode& node, std::string_view name, Frame& frame);
    std::string predicate(const TemplateNode& node, Frame& frame);
    void setPredicate(const TemplateNode& node, Frame& frame, const std::string& value);
    bool conditionHolds(const TemplateNode& test, const TemplateNode& condition, Frame& frame);
    void condition(const TemplateNode& node, Frame& frame, std::string& out);
    std::string history(const TemplateNode& node, Frame& frame);
    std::string learnText(const std::vector<TemplateNode>& nodes, Frame& frame);
    std::string srai(const std::string& text);
    const Template* matchSentence(std::string_view sentence, Frame& frame, MatchedCategory* matched);

    Conversation& m_conversation;
    const Bot& m_bot;
    ConversationState& m_state;
    int m_depth = 0, m_sraiCalls = 0, m_visits = 0;
    std::uint32_t m_matchVisitsLeft;
};

} // namespace thespis::core::dialogue
