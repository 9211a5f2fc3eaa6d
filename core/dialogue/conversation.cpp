#include "dialogue/conversation.h"

#include "dialogue/normalise.h"
#include "dialogue/template_eval.h"
#include "util/json_document.h"

namespace thespis::core::dialogue {
namespace {

constexpr std::string_view kFormat = "thespis-conversation";
constexpr int kVersion = 1;
constexpr json_document::Kind kKind{"conversation", kFormat, 1, kVersion};
const std::string kLearnedFile = "learned";

// The answer's words without its markup (gesture tags, BML), as <that> matches them.
std::string withoutMarkup(std::string_view text)
{
    std::string out;
    bool inTag = false;
    for (char c : text) {
        if (c == '<' || c == '>') {
            inTag = c == '<';
            out += ' ';
        } else if (!inTag) {
            out += c;
        }
    }
    return out;
}

// Trimmed only when twice as long, so that most answers move no strings.
template <class T>
void keepNewest(std::vector<T>& history)
{
    if (history.size() >= 2 * kHistoryLength)
        history.erase(history.begin(), history.end() - std::ptrdiff_t(kHistoryLength));
}

} // namespace

Conversation::Conversation(std::shared_ptr<const Bot> bot, std::string id) : m_bot(std::move(bot))
{
    m_state.id = std::move(id);
    m_state.predicates = m_bot->predicateDefaults();
    m_learnedGraph.freeze();
}

bool Conversation::learn(const std::string& aiml)
{
    CategoryStore store;
    std::vector<LoadProblem> problems;
    readAiml("<aiml>" + aiml + "</aiml>", kLearnedFile, store, problems);
    if (store.categories.empty())
        return false;
    // Learned categories are added after the earlier ones, so a relearned pattern replaces.
    for (std::size_t i = 0; i < store.categories.size(); ++i) {
        Category category = std::move(store.categories[i]);
        category.templateIndex = std::uint32_t(m_learned.templates.size());
        m_learned.templates.push_back(std::move(store.templates[i]));
        m_learned.categories.push_back(std::move(category));
    }
    m_state.learned.push_back(aiml);
    Graphmaster graph;
    std::string problem;
    for (std::size_t i = 0; i < m_learned.categories.size(); ++i)
        graph.add(m_learned.categories[i], std::uint32_t(i), m_bot->patternContext(), problem);
    graph.freeze();
    m_learnedGraph = std::move(graph);
    return true;
}

Answer Conversation::respond(std::string_view input)
{
    Answer answer;
    const std::string_view splitters = m_bot->sentenceSplitters();
    TemplateEvaluator evaluator(*this);
    for (const std::string& sentence : splitSentences(m_bot->substitutions("normal").apply(input), splitters)) {
        m_state.inputs.push_back(sentence);
        keepNewest(m_state.inputs);
        MatchedCategory matched;
        std::string text = evaluator.answer(sentence, matched, answer.problem);
        if (!answer.problem.empty())
            break;
        if (!matched.pattern.empty())
            answer.matched.push_back(std::move(matched));
        text = collapseSpaces(text);
        if (!text.empty())
            answer.text.append(answer.text.empty() ? "" : " ").append(text);
    }
    // Requests, like responses, join the history after the answer: <request index="1"/> is the
    // visitor's previous input (alice's badanswer.aiml relies on it), while <input/> is the
    // sentence being answered.
    m_state.requests.emplace_back(input);
    keepNewest(m_state.requests);
    m_state.responses.push_back(answer.text);
    keepNewest(m_state.responses);
    m_state.thats.push_back(splitSentences(withoutMarkup(answer.text), splitters));
    keepNewest(m_state.thats);
    return answer;
}

std::string Conversation::saveJson() const
{
    using json = nlohmann::json;
    json document = {{"format", kFormat},
                     {"version", kVersion},
                     {"id", m_state.id},
                     {"predicates", m_state.predicates},
                     {"inputs", m_state.inputs},
                     {"thats", m_state.thats},
                     {"requests", m_state.requests},
                     {"responses", m_state.responses},
                     {"learned", m_state.learned},
                     {"randomState", m_state.randomState}};
    return document.dump(2, ' ', false, json::error_handler_t::replace);
}

Result<Conversation> Conversation::restore(std::shared_ptr<const Bot> bot, std::string_view text)
{
    auto parsed = json_document::parseVersioned(text, kKind);
    if (!parsed)
        return parsed.error();
    const nlohmann::json& document = parsed->document;
    Conversation conversation(std::move(bot));
    ConversationState& state = conversation.m_state;
    // Each field must have its type; a missing one keeps the new conversation's value.
    const auto field = [&](const char* name, auto& into) -> std::optional<Error> {
        const auto it = document.find(name);
        if (it == document.end())
            return std::nullopt;
        try {
            into = it->get<std::decay_t<decltype(into)>>();
        } catch (const nlohmann::json::exception&) {
            return makeError(ErrorCode::CorruptData, std::string(name) + ": " + json_document::describeValue(*it)
                                                         + " is not of the type a conversation keeps there.");
        }
        return std::nullopt;
    };
    std::vector<std::string> learned;
    for (auto error : {field("id", state.id), field("predicates", state.predicates), field("inputs", state.inputs),
                       field("thats", state.thats), field("requests", state.requests), field("responses", state.responses),
                       field("learned", learned), field("randomState", state.randomState)})
        if (error)
            return *error;
    for (std::size_t i = 0; i < learned.size(); ++i)
        if (!conversation.learn(learned[i]))
            return makeError(ErrorCode::CorruptData, "learned[" + std::to_string(i) + "]: it holds no category.");
    return conversation;
}

} // namespace thespis::core::dialogue
