#pragma once
// A template parsed once at load into a small tree that evaluation walks (no XML per answer).
// Attributes may be written as child elements in AIML 2.0 (<get><name>x</name></get>), so an
// attribute's value is itself template content, a single text node when it was an attribute.

#include <string>
#include <string_view>
#include <vector>

namespace thespis::core::dialogue {

enum class TemplateOp : unsigned char {
    Text,      ///< literal characters (`text`)
    Markup,    ///< an element we pass through as XML (`text` is its name): speech markup, html, oob
    Star, ThatStar, TopicStar,
    Srai, Sr, Sraix,
    Random, Li, Condition, Loop,
    Set, Get, Bot, Think,
    Person, Person2, Gender,
    Uppercase, Lowercase, Formal, Sentence, Explode, Normalize, Denormalize,
    Date, Interval, Map, First, Rest,
    Input, That, Request, Response,
    Learn, Learnf, Eval,
    Id, Size, Vocabulary, Program,
};

struct TemplateNode;

struct TemplateAttribute {
    std::string name;
    std::vector<TemplateNode> value;
};

struct TemplateNode {
    TemplateOp op = TemplateOp::Text;
    std::string text;
    std::vector<TemplateAttribute> attributes;
    std::vector<TemplateNode> children;

    const TemplateAttribute* attribute(std::string_view key) const
    {
        for (const TemplateAttribute& a : attributes)
            if (a.name == key)
                return &a;
        return nullptr;
    }
};

using Template = std::vector<TemplateNode>;

/// The template element name an op is read from and written back as ("" for Text and Markup).
std::string_view templateOpName(TemplateOp op);

/// Appends `nodes` as AIML/XML text; <eval> content is left as written (learn evaluates it first).
void appendXml(std::string& out, const std::vector<TemplateNode>& nodes);

} // namespace thespis::core::dialogue
