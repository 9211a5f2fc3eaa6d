#include "dialogue/aiml_reader.h"

#include <expat.h>

#include <algorithm>
#include <array>
#include <limits>
#include <memory>
#include <optional>

#include "util/text.h"

namespace thespis::core::dialogue {
namespace {

// A hostile file could nest elements without end; evaluation and destruction recurse on depth.
constexpr std::size_t kMaxDepth = 200;

constexpr std::array kOps = {
    TemplateOp::Star,      TemplateOp::ThatStar,    TemplateOp::TopicStar, TemplateOp::Srai,
    TemplateOp::Sr,        TemplateOp::Sraix,       TemplateOp::Random,    TemplateOp::Li,
    TemplateOp::Condition, TemplateOp::Loop,        TemplateOp::Set,       TemplateOp::Get,
    TemplateOp::Bot,       TemplateOp::Think,       TemplateOp::Person,    TemplateOp::Person2,
    TemplateOp::Gender,    TemplateOp::Uppercase,   TemplateOp::Lowercase, TemplateOp::Formal,
    TemplateOp::Sentence,  TemplateOp::Explode,     TemplateOp::Normalize, TemplateOp::Denormalize,
    TemplateOp::Date,      TemplateOp::Interval,    TemplateOp::Map,       TemplateOp::First,
    TemplateOp::Rest,      TemplateOp::Input,       TemplateOp::That,      TemplateOp::Request,
    TemplateOp::Response,  TemplateOp::Learn,       TemplateOp::Learnf,    TemplateOp::Eval,
    TemplateOp::Id,        TemplateOp::Size,        TemplateOp::Vocabulary, TemplateOp::Program,
};

// AIML 2.0 lets these attributes be written as child elements holding template content.
constexpr std::array<std::string_view, 11> kAttributeElements = {
    "name", "var", "value", "index", "format", "jformat", "locale", "timezone", "from", "to", "style"};

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

// Appends text with each run of white space as one space (templates are indented freely).
void appendCollapsed(std::string& out, std::string_view text)
{
    for (char c : text) {
        if (isSpace(c)) {
            if (out.empty() || out.back() != ' ')
                out += ' ';
        } else {
            out += c;
        }
    }
}

// Appends the words of pattern text as tokens, in upper case (patterns match in upper case).
void appendPatternWords(std::vector<std::string>& tokens, std::string_view text)
{
    std::string word;
    for (char c : text) {
        if (!isSpace(c)) {
            word += c >= 'a' && c <= 'z' ? char(c - 'a' + 'A') : c;
        } else if (!word.empty()) {
            tokens.push_back(std::move(word));
            word.clear();
        }
    }
    if (!word.empty())
        tokens.push_back(std::move(word));
}

std::string joined(const std::vector<std::string>& tokens)
{
    std::string out;
    for (const std::string& token : tokens)
        out += (out.empty() ? "" : " ") + token;
    return out;
}

enum class Part { None, Pattern, That, Topic, Template };

class AimlReader {
public:
    AimlReader(XML_Parser parser, const std::string& file, CategoryStore& store, std::vector<LoadProblem>& problems)
        : m_parser(parser), m_file(file), m_store(store), m_problems(problems)
    {
    }

    static void XMLCALL onStart(void* self, const XML_Char* name, const XML_Char** attributes)
    {
        static_cast<AimlReader*>(self)->start(name, attributes);
    }
    static void XMLCALL onEnd(void* self, const XML_Char* name) { static_cast<AimlReader*>(self)->end(name); }
    static void XMLCALL onCharacters(void* self, const XML_Char* text, int length)
    {
        static_cast<AimlReader*>(self)->characters(std::string_view(text, std::size_t(length)));
    }

private:
    // What an open element collects into.
    struct Frame {
        enum Kind { Outside, TopicBlock, Category, PatternPart, PatternSet, PatternOther, TemplateContent } kind;
        std::vector<TemplateNode>* target = nullptr; // TemplateContent: where children go
        bool raw = false;                            // inside <learn> or <bml>: elements kept as written
        std::string previousTopic;                   // TopicBlock: the topic to restore
    };

    int line() const { return int(XML_GetCurrentLineNumber(m_parser)); }

    void problem(std::string message, int atLine = 0)
    {
        m_problems.push_back(LoadProblem{m_file, atLine ? atLine : line(),
                                         atLine ? 0 : int(XML_GetCurrentColumnNumber(m_parser)) + 1,
                                         std::move(message)});
    }

    static std::string_view attribute(const XML_Char** attributes, std::string_view key)
    {
        for (const XML_Char** a = attributes; *a; a += 2)
            if (key == a[0])
                return a[1];
        return {};
    }

    void start(std::string_view name, const XML_Char** attributes)
    {
        if (m_stack.size() >= kMaxDepth) {
            problem("elements nest deeper than " + std::to_string(kMaxDepth) + " levels; the rest of the file is skipped");
            XML_StopParser(m_parser, XML_FALSE);
            return;
        }
        const Frame::Kind parent = m_stack.empty() ? Frame::Outside : m_stack.back().kind;
        switch (parent) {
        case Frame::Outside:
        case Frame::TopicBlock:
            if (name == "category")
                return beginCategory();
            if (name == "topic") {
                m_stack.push_back(Frame{Frame::TopicBlock, nullptr, false, m_topic});
                std::vector<std::string> tokens;
                appendPatternWords(tokens, attribute(attributes, "name"));
                m_topic = joined(tokens);
                if (m_topic.empty())
                    m_topic = "*";
                return;
            }
            m_stack.push_back(Frame{Frame::Outside});
            return;
        case Frame::Category:
            if (name == "pattern" || name == "that" || name == "topic") {
                m_part = name == "pattern" ? Part::Pattern : name == "that" ? Part::That : Part::Topic;
                m_patternText.clear();
                m_patternTokens.clear();
                m_stack.push_back(Frame{Frame::PatternPart});
                return;
            }
            if (name == "template") {
                m_part = Part::Template;
                m_hasTemplate = true;
                m_stack.push_back(Frame{Frame::TemplateContent, &m_template});
                return;
            }
            problem("<" + std::string(name) + "> is not a part of a category; it is ignored");
            m_stack.push_back(Frame{Frame::PatternOther});
            return;
        case Frame::PatternPart:
        case Frame::PatternSet:
        case Frame::PatternOther:
            flushPatternText();
            if (name == "set") {
                m_stack.push_back(Frame{Frame::PatternSet});
            } else if (name == "bot") {
                m_patternTokens.push_back("<bot name=\"" + std::string(attribute(attributes, "name")) + "\"/>");
                m_stack.push_back(Frame{Frame::PatternOther});
            } else {
                problem("<" + std::string(name) + "> cannot be matched in a pattern; its text is kept");
                m_stack.push_back(Frame{Frame::PatternOther});
            }
            return;
        case Frame::TemplateContent:
            return beginTemplateElement(name, attributes);
        }
    }

    void beginCategory()
    {
        m_stack.push_back(Frame{Frame::Category});
        m_categoryLine = line();
        m_pattern.reset();
        m_that.clear();
        m_categoryTopic.clear();
        m_template.clear();
        m_hasTemplate = false;
    }

    void beginTemplateElement(std::string_view name, const XML_Char** attributes)
    {
        Frame& parent = m_stack.back();
        std::vector<TemplateNode>& target = *parent.target;
        TemplateNode* owner = m_nodeStack.empty() ? nullptr : m_nodeStack.back();
        const bool ownerTakesAttributes = owner && owner->op != TemplateOp::Markup && owner->op != TemplateOp::Text;
        if (!parent.raw && ownerTakesAttributes
            && std::find(kAttributeElements.begin(), kAttributeElements.end(), name) != kAttributeElements.end()) {
            owner->attributes.push_back(TemplateAttribute{std::string(name), {}});
            m_stack.push_back(Frame{Frame::TemplateContent, &owner->attributes.back().value});
            m_nodeStack.push_back(nullptr);
            return;
        }
        TemplateNode node;
        node.op = TemplateOp::Markup;
        node.text = std::string(name);
        if (!parent.raw || name == "eval") {
            const auto op = std::find_if(kOps.begin(), kOps.end(), [&](TemplateOp o) { return templateOpName(o) == name; });
            if (op != kOps.end())
                node.op = *op;
        }
        for (const XML_Char** a = attributes; *a; a += 2) {
            TemplateNode value;
            value.text = a[1];
            node.attributes.push_back(TemplateAttribute{a[0], {std::move(value)}});
        }
        if (node.op != TemplateOp::Markup)
            node.text.clear();
        const bool raw = (parent.raw && node.op != TemplateOp::Eval) || node.op == TemplateOp::Learn
                         || node.op == TemplateOp::Learnf || name == "bml";
        target.push_back(std::move(node));
        m_stack.push_back(Frame{Frame::TemplateContent, &target.back().children, raw});
        m_nodeStack.push_back(&target.back());
    }

    void end(std::string_view name)
    {
        if (m_stack.empty())
            return;
        const Frame frame = std::move(m_stack.back());
        m_stack.pop_back();
        switch (frame.kind) {
        case Frame::Outside:
        case Frame::PatternOther:
            return;
        case Frame::TopicBlock:
            m_topic = frame.previousTopic;
            return;
        case Frame::PatternSet:
            m_patternTokens.push_back("<set>" + lowercase(trimmed(m_patternText)) + "</set>");
            m_patternText.clear();
            return;
        case Frame::PatternPart: {
            flushPatternText();
            std::string tidy = joined(m_patternTokens);
            if (m_part == Part::Pattern)
                m_pattern = std::move(tidy);
            else if (m_part == Part::That)
                m_that = std::move(tidy);
            else
                m_categoryTopic = std::move(tidy);
            m_part = Part::None;
            return;
        }
        case Frame::TemplateContent:
            if (!m_stack.empty() && m_stack.back().kind == Frame::Category)
                m_part = Part::None;
            else
                m_nodeStack.pop_back();
            return;
        case Frame::Category:
            return endCategory(name);
        }
    }

    void endCategory(std::string_view)
    {
        if (!m_pattern || m_pattern->empty()) {
            problem("this category has no pattern; it is skipped", m_categoryLine);
            return;
        }
        if (!m_hasTemplate) {
            problem("the category " + inQuotes(*m_pattern) + " has no template; it is skipped", m_categoryLine);
            return;
        }
        Category category;
        category.pattern = std::move(*m_pattern);
        category.that = m_that.empty() ? "*" : std::move(m_that);
        category.topic = !m_categoryTopic.empty() ? std::move(m_categoryTopic) : m_topic;
        category.source = SourcePlace{m_file, m_categoryLine};
        category.templateIndex = std::uint32_t(m_store.templates.size());
        m_store.templates.push_back(std::move(m_template));
        m_store.categories.push_back(std::move(category));
    }

    void flushPatternText()
    {
        appendPatternWords(m_patternTokens, m_patternText);
        m_patternText.clear();
    }

    void characters(std::string_view text)
    {
        if (m_stack.empty())
            return;
        const Frame& frame = m_stack.back();
        switch (frame.kind) {
        case Frame::PatternPart:
        case Frame::PatternSet:
        case Frame::PatternOther:
            m_patternText += text;
            return;
        case Frame::TemplateContent: {
            std::vector<TemplateNode>& target = *frame.target;
            if (target.empty() || target.back().op != TemplateOp::Text)
                target.push_back(TemplateNode{});
            if (frame.raw)
                target.back().text += text;
            else
                appendCollapsed(target.back().text, text);
            return;
        }
        default:
            return;
        }
    }

    XML_Parser m_parser;
    const std::string& m_file;
    CategoryStore& m_store;
    std::vector<LoadProblem>& m_problems;

    std::vector<Frame> m_stack;
    std::vector<TemplateNode*> m_nodeStack; // the template element each TemplateContent frame fills
    std::string m_topic = "*";
    Part m_part = Part::None;
    std::string m_patternText;                // pattern text (or a <set>'s name) not yet made tokens
    std::vector<std::string> m_patternTokens; // the pattern part read so far
    int m_categoryLine = 0;
    std::optional<std::string> m_pattern;
    std::string m_that, m_categoryTopic;
    Template m_template;
    bool m_hasTemplate = false;
};

} // namespace

void readAiml(std::string_view xml, const std::string& file, CategoryStore& store, std::vector<LoadProblem>& problems)
{
    const std::unique_ptr<std::remove_pointer_t<XML_Parser>, decltype(&XML_ParserFree)> parser(
        XML_ParserCreate(nullptr), &XML_ParserFree);
    AimlReader reader(parser.get(), file, store, problems);
    XML_SetUserData(parser.get(), &reader);
    XML_SetElementHandler(parser.get(), &AimlReader::onStart, &AimlReader::onEnd);
    XML_SetCharacterDataHandler(parser.get(), &AimlReader::onCharacters);
    if (xml.size() > std::size_t(std::numeric_limits<int>::max())) {
        problems.push_back(LoadProblem{file, 0, 0, "the file is too large to read"});
        return;
    }
    if (XML_Parse(parser.get(), xml.data(), int(xml.size()), XML_TRUE) != XML_STATUS_OK
        && XML_GetErrorCode(parser.get()) != XML_ERROR_ABORTED)
        problems.push_back(LoadProblem{file, int(XML_GetCurrentLineNumber(parser.get())),
                                       int(XML_GetCurrentColumnNumber(parser.get())) + 1,
                                       std::string("the XML is malformed: ") + XML_ErrorString(XML_GetErrorCode(parser.get()))
                                           + "; categories after this point are not loaded"});
}

} // namespace thespis::core::dialogue

namespace thespis::core::dialogue {

std::string describe(const LoadProblem& problem)
{
    // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) about ":" + std::to_string(…).
    std::string text = problem.file;
    for (const int place : {problem.line, problem.column > 0 && problem.line > 0 ? problem.column : 0})
        if (place > 0)
            text.append(":").append(std::to_string(place));
    return text.append(": ").append(problem.message);
}

} // namespace thespis::core::dialogue
