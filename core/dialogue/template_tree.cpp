#include "dialogue/template_tree.h"

#include <algorithm>

#include "util/text.h"

namespace thespis::core::dialogue {

std::string_view templateOpName(TemplateOp op)
{
    switch (op) {
    case TemplateOp::Text: return "";
    case TemplateOp::Markup: return "";
    case TemplateOp::Star: return "star";
    case TemplateOp::ThatStar: return "thatstar";
    case TemplateOp::TopicStar: return "topicstar";
    case TemplateOp::Srai: return "srai";
    case TemplateOp::Sr: return "sr";
    case TemplateOp::Sraix: return "sraix";
    case TemplateOp::Random: return "random";
    case TemplateOp::Li: return "li";
    case TemplateOp::Condition: return "condition";
    case TemplateOp::Loop: return "loop";
    case TemplateOp::Set: return "set";
    case TemplateOp::Get: return "get";
    case TemplateOp::Bot: return "bot";
    case TemplateOp::Think: return "think";
    case TemplateOp::Person: return "person";
    case TemplateOp::Person2: return "person2";
    case TemplateOp::Gender: return "gender";
    case TemplateOp::Uppercase: return "uppercase";
    case TemplateOp::Lowercase: return "lowercase";
    case TemplateOp::Formal: return "formal";
    case TemplateOp::Sentence: return "sentence";
    case TemplateOp::Explode: return "explode";
    case TemplateOp::Normalize: return "normalize";
    case TemplateOp::Denormalize: return "denormalize";
    case TemplateOp::Date: return "date";
    case TemplateOp::Interval: return "interval";
    case TemplateOp::Map: return "map";
    case TemplateOp::First: return "first";
    case TemplateOp::Rest: return "rest";
    case TemplateOp::Input: return "input";
    case TemplateOp::That: return "that";
    case TemplateOp::Request: return "request";
    case TemplateOp::Response: return "response";
    case TemplateOp::Learn: return "learn";
    case TemplateOp::Learnf: return "learnf";
    case TemplateOp::Eval: return "eval";
    case TemplateOp::Id: return "id";
    case TemplateOp::Size: return "size";
    case TemplateOp::Vocabulary: return "vocabulary";
    case TemplateOp::Program: return "program";
    }
    return "";
}

namespace {
// An attribute given as name="text" rather than as a child element with markup inside.
bool isLiteral(const TemplateAttribute& attribute)
{
    return attribute.value.empty() || (attribute.value.size() == 1 && attribute.value[0].op == TemplateOp::Text);
}
} // namespace

void appendXml(std::string& out, const std::vector<TemplateNode>& nodes)
{
    for (const TemplateNode& node : nodes) {
        if (node.op == TemplateOp::Text) {
            for (char c : node.text)
                appendEscaped(out, c, false);
            continue;
        }
        const std::string_view name = node.op == TemplateOp::Markup ? std::string_view(node.text) : templateOpName(node.op);
        out += '<';
        out += name;
        for (const TemplateAttribute& attribute : node.attributes) {
            // An attribute read from a child element is written back as one, to keep its content.
            if (!isLiteral(attribute))
                continue;
            out += ' ';
            out += attribute.name;
            out += "=\"";
            for (char c : attribute.value.empty() ? std::string() : attribute.value[0].text)
                appendEscaped(out, c, true);
            out += '"';
        }
        const bool hasElementAttributes =
            std::any_of(node.attributes.begin(), node.attributes.end(), [](const auto& a) { return !isLiteral(a); });
        if (node.children.empty() && !hasElementAttributes) {
            out += "/>";
            continue;
        }
        out += '>';
        for (const TemplateAttribute& attribute : node.attributes) {
            if (isLiteral(attribute))
                continue;
            out += '<' + attribute.name + '>';
            appendXml(out, attribute.value);
            out += "</" + attribute.name + '>';
        }
        appendXml(out, node.children);
        out += "</";
        out += name;
        out += '>';
    }
}

} // namespace thespis::core::dialogue
