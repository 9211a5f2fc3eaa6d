#include "dialogue/bot_grammar.h"

#include <algorithm>
#include <unordered_set>

#include "dialogue/normalise.h"
#include "util/text.h"

namespace thespis::core::dialogue {

namespace {

// The name in `<set>name</set>` or `<bot name="name"/>`; empty when `token` is neither.
std::string_view elementName(std::string_view token, std::string_view open, std::string_view close)
{
    if (!token.starts_with(open) || !token.ends_with(close) || token.size() < open.size() + close.size())
        return {};
    return token.substr(open.size(), token.size() - open.size() - close.size());
}

} // namespace

GrammarSource grammarSourceOf(const Bot& bot)
{
    GrammarSource source;
    std::unordered_set<std::string> known;
    const auto word = [&](std::vector<PatternItem>& items, std::string text) {
        if (known.insert(text).second)
            source.vocabulary.push_back(text);
        items.push_back({PatternItem::Kind::Word, std::move(text), {}});
    };
    for (const Category& category : bot.categories()) {
        if (category.pattern == kNotUnderstood)
            continue;
        std::vector<PatternItem> items;
        for (const std::string_view token : patternTokens(category.pattern)) {
            if (token == "*" || token == "_")
                items.push_back({PatternItem::Kind::OneOrMore, {}, {}});
            else if (token == "#" || token == "^")
                items.push_back({PatternItem::Kind::ZeroOrMore, {}, {}});
            else if (const auto set = elementName(token, "<set>", "</set>"); !set.empty()) {
                const std::string name = lowercase(set);
                items.push_back({PatternItem::Kind::SetOf, {}, name});
                const auto found = bot.sets().find(name);
                if (found == bot.sets().end()) { // the bot skipped the category when it loaded
                    items.clear();
                    break;
                }
                if (!source.sets.contains(name))
                    for (const std::string& phrase : found->second.phrases)
                        source.sets[name].push_back(wordsOf(phrase));
            } else if (const auto property = elementName(token, "<bot name=\"", "\"/>"); !property.empty()) {
                for (std::string& w : wordsOf(bot.property(property)))
                    word(items, std::move(w));
            } else
                word(items, std::string(token.starts_with('$') ? token.substr(1) : token));
        }
        // A pattern of wildcards alone (the catch-all "*") stands for anything: as a free loop of
        // words it would let the recogniser hear words in any noise. What it answers is what the
        // grammar leaves out, heard as not understood.
        const bool says = std::any_of(items.begin(), items.end(),
                                      [](const PatternItem& item) { return item.kind == PatternItem::Kind::Word || item.kind == PatternItem::Kind::SetOf; });
        if (says)
            source.patterns.push_back(std::move(items));
    }
    return source;
}

Result<speech::GrammarRecogniser> listenFor(const Bot& bot, const ListeningOptions& listening,
                                            const speech::RecogniserOptions& recognising)
{
    auto grammar = makeListeningGrammar(grammarSourceOf(bot), listening);
    if (!grammar)
        return grammar.error();
    return speech::GrammarRecogniser::open(grammar->graph, recognising);
}

} // namespace thespis::core::dialogue
