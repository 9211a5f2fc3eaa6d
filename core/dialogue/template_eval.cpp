#include "dialogue/template_eval.h"

#include <algorithm>
#include <charconv>
#include <ctime>

#include "dialogue/aiml_functions.h"
#include "dialogue/normalise.h"
#include "util/text.h"

namespace thespis::core::dialogue {
namespace {

void appendText(std::string& out, std::string_view text)
{
    for (char c : text)
        appendEscaped(out, c, false);
}

std::string joinWords(const std::vector<std::string_view>& words, std::uint32_t begin, std::uint32_t end)
{
    std::string out;
    for (std::uint32_t i = begin; i < end; ++i)
        out.append(i > begin ? " " : "").append(words[i]);
    return out;
}

// "2" → 2; "2,1" → 2 (first) and 1 (second); anything else → 1.
std::pair<int, int> indexPair(std::string_view text)
{
    const auto number = [](std::string_view part) {
        part = trimmed(part);
        int value = 1;
        const auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), value);
        return error == std::errc() && end == part.data() + part.size() && value >= 1 ? value : 1;
    };
    const std::size_t comma = text.find(',');
    if (comma == std::string_view::npos)
        return {number(text), 1};
    return {number(text.substr(0, comma)), number(text.substr(comma + 1))};
}

// The n-th newest entry (1 = newest) of a history, or "".
template <class T>
const T* newest(const std::vector<T>& history, int n)
{
    return n >= 1 && std::size_t(n) <= history.size() ? &history[history.size() - std::size_t(n)] : nullptr;
}

std::string firstWord(std::string_view text)
{
    const std::string tidy = collapseSpaces(text); // splitWords' views point into it
    const std::vector<std::string_view> words = splitWords(tidy);
    return words.empty() ? "NIL" : std::string(words.front());
}

std::string restWords(std::string_view text)
{
    const std::string tidy = collapseSpaces(text);
    const std::size_t space = tidy.find(' ');
    return space == std::string::npos ? "NIL" : tidy.substr(space + 1);
}

std::string exploded(std::string_view text)
{
    std::string out;
    for (char c : matchForm(text, false))
        if (c != ' ')
            out.append(out.empty() ? "" : " ").append(1, c);
    return out;
}

// `element` (its children ignored) written as XML around `inner`, markup text already.
std::string elementAround(TemplateNode element, const std::string& inner)
{
    element.children = {TemplateNode{TemplateOp::Text, "\x01", {}, {}}};
    std::string xml;
    appendXml(xml, {element});
    const std::size_t hole = xml.find('\x01');
    return xml.substr(0, hole) + inner + xml.substr(hole + 1);
}

} // namespace

TemplateEvaluator::TemplateEvaluator(Conversation& conversation)
    : m_conversation(conversation), m_bot(*conversation.m_bot), m_state(conversation.m_state),
      m_matchVisitsLeft(conversation.m_limits.matchVisits)
{
}

std::string TemplateEvaluator::answer(std::string_view sentence, MatchedCategory& matched, std::string& problem)
{
    try {
        return matchAndEvaluate(sentence, &matched);
    } catch (const Cut& cut) {
        problem = cut.why;
        return {};
    }
}

const Template* TemplateEvaluator::matchSentence(std::string_view sentence, Frame& frame, MatchedCategory* matched)
{
    const std::vector<std::string>* lastAnswer = newest(m_state.thats, 1);
    const std::string that = lastAnswer && !lastAnswer->empty() ? lastAnswer->back() : std::string();
    const auto topic = m_state.predicates.find("topic");
    const std::string topicText = topic != m_state.predicates.end() ? topic->second : std::string();

    // The same words twice: in upper case to match, and as written for the stars.
    std::string upper[3] = {matchForm(sentence), matchForm(that), matchForm(topicText)};
    std::string shown[3] = {matchForm(sentence, false), matchForm(that, false), matchForm(topicText, false)};
    for (int part = 1; part < 3; ++part)
        if (upper[part].empty())
            upper[part] = shown[part] = "UNKNOWN";
    MatchInput input;
    std::vector<std::string_view> shownWords;
    for (int part = 0; part < 3; ++part) {
        if (part > 0) {
            input.words.push_back(part == 1 ? kThatMarker : kTopicMarker);
            shownWords.push_back(input.words.back());
        }
        for (std::string_view word : splitWords(upper[part]))
            input.words.push_back(word);
        for (std::string_view word : splitWords(shown[part]))
            shownWords.push_back(word);
    }
    if (shownWords.size() != input.words.size())
        shownWords = input.words; // case folding changed a word's bytes: show it in upper case

    std::optional<GraphMatch> match = m_bot.graph().match(input, m_matchVisitsLeft);
    bool learned = false;
    if (!m_conversation.m_learnedGraph.empty())
        if (std::optional<GraphMatch> own = m_conversation.m_learnedGraph.match(input, m_matchVisitsLeft);
            own && (!match || own->order <= match->order)) {
            match = std::move(own);
            learned = true;
        }
    if (m_matchVisitsLeft == 0)
        throw Cut{"The answer was cut: matching its sentences visited more than "
                  + std::to_string(m_conversation.m_limits.matchVisits) + " pattern nodes."};
    if (!match)
        return nullptr;
    const Category& category = learned ? m_conversation.m_learned.categories[match->category] : m_bot.categories()[match->category];
    for (const Capture& capture : match->captures) {
        auto& stars = capture.part == Capture::Pattern ? frame.stars : capture.part == Capture::That ? frame.thatStars : frame.topicStars;
        stars.push_back(joinWords(shownWords, capture.begin, capture.end));
    }
    if (matched)
        *matched = MatchedCategory{upper[0], category.pattern, category.that, category.topic, category.source, learned};
    return learned ? &m_conversation.m_learned.templates[category.templateIndex] : &m_bot.templateOf(category);
}

std::string TemplateEvaluator::matchAndEvaluate(std::string_view sentence, MatchedCategory* matched)
{
    Frame frame;
    const Template* answerTemplate = matchSentence(sentence, frame, matched);
    return answerTemplate ? evaluate(*answerTemplate, frame) : std::string();
}

std::string TemplateEvaluator::srai(const std::string& text)
{
    if (++m_sraiCalls > m_conversation.m_limits.sraiCalls)
        throw Cut{"The answer was cut: its categories called <srai> more than " + std::to_string(m_conversation.m_limits.sraiCalls)
                  + " times (last with " + inQuotes(matchForm(text)) + ")."};
    if (m_depth >= m_conversation.m_limits.sraiDepth)
        throw Cut{"The answer was cut: <srai> went " + std::to_string(m_depth) + " levels deep, a loop in the script (at "
                  + inQuotes(matchForm(text)) + ")."};
    ++m_depth;
    std::string result;
    // A srai's text may hold several sentences; each is answered, as an input would be.
    for (const std::string& sentence : splitSentences(text, m_bot.sentenceSplitters()))
        result.append(result.empty() ? "" : " ").append(matchAndEvaluate(sentence, nullptr));
    --m_depth;
    return result;
}

std::string TemplateEvaluator::evaluate(const std::vector<TemplateNode>& nodes, Frame& frame)
{
    std::string out;
    for (const TemplateNode& node : nodes)
        evaluateNode(node, frame, out);
    return out;
}

std::string TemplateEvaluator::attribute(const TemplateNode& node, std::string_view name, Frame& frame)
{
    const TemplateAttribute* found = node.attribute(name);
    return found ? std::string(trimmed(evaluate(found->value, frame))) : std::string();
}

std::string TemplateEvaluator::predicate(const TemplateNode& node, Frame& frame)
{
    const std::string var = attribute(node, "var", frame);
    const std::map<std::string, std::string>& scope = var.empty() ? m_state.predicates : frame.vars;
    const auto it = scope.find(var.empty() ? attribute(node, "name", frame) : var);
    if (it != scope.end())
        return it->second;
    const auto fallback = m_bot.properties().find("default-get");
    return fallback != m_bot.properties().end() ? fallback->second : "unknown";
}

void TemplateEvaluator::setPredicate(const TemplateNode& node, Frame& frame, const std::string& value)
{
    const std::string var = attribute(node, "var", frame);
    if (!var.empty())
        frame.vars[var] = value;
    else if (const std::string name = attribute(node, "name", frame); !name.empty())
        m_state.predicates[name] = value;
}

bool TemplateEvaluator::conditionHolds(const TemplateNode& test, const TemplateNode& condition, Frame& frame)
{
    const TemplateNode& named = test.attribute("name") || test.attribute("var") ? test : condition;
    const std::string actual = predicate(named, frame);
    const std::string expected = attribute(test, "value", frame);
    if (expected == "*") {
        const std::string var = attribute(named, "var", frame);
        return var.empty() ? m_state.predicates.contains(attribute(named, "name", frame)) : frame.vars.contains(var);
    }
    return matchForm(actual) == matchForm(expected);
}

void TemplateEvaluator::condition(const TemplateNode& node, Frame& frame, std::string& out)
{
    if (node.attribute("value")) { // <condition name="x" value="y">…</condition>
        if (conditionHolds(node, node, frame))
            out += evaluate(node.children, frame);
        return;
    }
    for (int iteration = 0;; ++iteration) {
        if (iteration >= m_conversation.m_limits.loopIterations)
            throw Cut{"The answer was cut: a <condition> looped " + std::to_string(iteration) + " times."};
        const auto chosen = std::find_if(node.children.begin(), node.children.end(), [&](const TemplateNode& li) {
            return li.op == TemplateOp::Li && (!li.attribute("value") || conditionHolds(li, node, frame));
        });
        if (chosen == node.children.end())
            return;
        frame.loopRequested = false;
        out += evaluate(chosen->children, frame);
        if (!frame.loopRequested)
            return;
    }
}

std::string TemplateEvaluator::history(const TemplateNode& node, Frame& frame)
{
    const auto [n, m] = indexPair(attribute(node, "index", frame));
    std::string out;
    switch (node.op) {
    case TemplateOp::Input:
        if (const std::string* input = newest(m_state.inputs, n))
            appendText(out, *input);
        break;
    case TemplateOp::Request:
        if (const std::string* request = newest(m_state.requests, n))
            appendText(out, *request);
        break;
    case TemplateOp::Response:
        if (const std::string* response = newest(m_state.responses, n))
            out = *response;
        break;
    default: // That: the m-th sentence from the end of the n-th last answer
        if (const std::vector<std::string>* answer = newest(m_state.thats, n))
            if (const std::string* sentence = newest(*answer, m))
                appendText(out, *sentence);
    }
    return out;
}

// The XML of a <learn>'s category with its <eval> parts evaluated (the rest is kept as written).
std::string TemplateEvaluator::learnText(const std::vector<TemplateNode>& nodes, Frame& frame)
{
    std::string xml;
    for (const TemplateNode& node : nodes) {
        if (node.op == TemplateOp::Eval) {
            xml += evaluate(node.children, frame);
            continue;
        }
        if (node.op == TemplateOp::Text || node.children.empty()) {
            appendXml(xml, {node});
            continue;
        }
        TemplateNode element = node;
        element.children.clear();
        xml += elementAround(std::move(element), learnText(node.children, frame));
    }
    return xml;
}

void TemplateEvaluator::evaluateNode(const TemplateNode& node, Frame& frame, std::string& out)
{
    if (++m_visits > m_conversation.m_limits.nodeVisits)
        throw Cut{"The answer was cut: its templates evaluated more than " + std::to_string(m_conversation.m_limits.nodeVisits)
                  + " elements."};
    const auto content = [&] { return evaluate(node.children, frame); };
    // <person/>, <gender/>, <sr/> … with no content work on the first star.
    const auto contentOrStar = [&] {
        if (!node.children.empty())
            return content();
        std::string star;
        appendText(star, frame.stars.empty() ? std::string_view() : std::string_view(frame.stars.front()));
        return star;
    };
    const auto star = [&](const std::vector<std::string>& stars) {
        const std::size_t index = std::size_t(indexPair(attribute(node, "index", frame)).first);
        if (index <= stars.size())
            appendText(out, stars[index - 1]);
    };
    switch (node.op) {
    case TemplateOp::Text: appendText(out, node.text); return;
    case TemplateOp::Markup: {
        // Markup's attributes are always literal (only AIML elements take attribute elements).
        TemplateNode shell{TemplateOp::Markup, node.text, node.attributes, {}};
        if (node.children.empty()) {
            appendXml(out, {shell});
            return;
        }
        out += elementAround(std::move(shell), content());
        return;
    }
    case TemplateOp::Star: return star(frame.stars);
    case TemplateOp::ThatStar: return star(frame.thatStars);
    case TemplateOp::TopicStar: return star(frame.topicStars);
    case TemplateOp::Srai: out += srai(content()); return;
    case TemplateOp::Sr: out += srai(contentOrStar()); return;
    case TemplateOp::Sraix: out += attribute(node, "default", frame); return; // no remote bots
    case TemplateOp::Random: {
        std::vector<const TemplateNode*> items;
        for (const TemplateNode& child : node.children)
            if (child.op == TemplateOp::Li)
                items.push_back(&child);
        if (items.empty())
            return;
        // xorshift64*: small, and its one number of state is saved with the conversation.
        std::uint64_t& x = m_state.randomState;
        x ^= x >> 12, x ^= x << 25, x ^= x >> 27;
        out += evaluate(items[(x * 0x2545F4914F6CDD1Dull >> 33) % items.size()]->children, frame);
        return;
    }
    case TemplateOp::Li: out += content(); return;
    case TemplateOp::Condition: return condition(node, frame, out);
    case TemplateOp::Loop: frame.loopRequested = true; return;
    case TemplateOp::Set: {
        const std::string value(trimmed(content()));
        setPredicate(node, frame, value);
        out += value;
        return;
    }
    case TemplateOp::Get: out += predicate(node, frame); return;
    case TemplateOp::Bot: appendText(out, m_bot.property(attribute(node, "name", frame))); return;
    case TemplateOp::Think: content(); return;
    case TemplateOp::Person: out += m_bot.substitutions("person").apply(contentOrStar()); return;
    case TemplateOp::Person2: out += m_bot.substitutions("person2").apply(contentOrStar()); return;
    case TemplateOp::Gender: out += m_bot.substitutions("gender").apply(contentOrStar()); return;
    case TemplateOp::Uppercase: out += uppercase(content()); return;
    case TemplateOp::Lowercase: out += lowercase(content()); return;
    case TemplateOp::Formal: out += formal(content()); return;
    case TemplateOp::Sentence: out += sentenceCase(content()); return;
    case TemplateOp::Explode: out += exploded(content()); return;
    case TemplateOp::Normalize: out += m_bot.substitutions("normal").apply(content()); return;
    case TemplateOp::Denormalize: out += m_bot.substitutions("denormal").apply(content()); return;
    case TemplateOp::Date: {
        const std::string format = attribute(node, "format", frame);
        appendText(out, formatDate(format.empty() ? strftimeFromJava(attribute(node, "jformat", frame)) : format, std::time(nullptr)));
        return;
    }
    case TemplateOp::Interval: {
        std::string format = attribute(node, "format", frame);
        if (format.empty())
            format = strftimeFromJava(attribute(node, "jformat", frame));
        const auto units = dateInterval(attribute(node, "from", frame), attribute(node, "to", frame), format, attribute(node, "style", frame));
        out += units ? std::to_string(*units) : "unknown";
        return;
    }
    case TemplateOp::Map: {
        const std::string name = lowercase(attribute(node, "name", frame));
        const std::string key = matchForm(content());
        const auto map = m_bot.maps().find(name);
        if (map != m_bot.maps().end())
            if (const auto value = map->second.find(key); value != map->second.end())
                return appendText(out, value->second);
        if (const auto value = builtInMap(name, key))
            return appendText(out, *value);
        appendText(out, m_bot.property("default-map"));
        return;
    }
    case TemplateOp::First: out += firstWord(content()); return;
    case TemplateOp::Rest: out += restWords(content()); return;
    case TemplateOp::Input:
    case TemplateOp::That:
    case TemplateOp::Request:
    case TemplateOp::Response: out += history(node, frame); return;
    case TemplateOp::Learn:
    case TemplateOp::Learnf: m_conversation.learn(learnText(node.children, frame)); return;
    case TemplateOp::Eval: out += content(); return;
    case TemplateOp::Id: appendText(out, m_state.id); return;
    case TemplateOp::Size: out += std::to_string(m_bot.categories().size() + m_conversation.m_learned.categories.size()); return;
    case TemplateOp::Vocabulary: out += std::to_string(m_bot.vocabularySize()); return;
    case TemplateOp::Program: out += "Thespis AIML interpreter " THESPIS_VERSION; return;
    }
}

} // namespace thespis::core::dialogue
