#include "speech/bml_lexicon.h"

#include <algorithm>

#include "util/text.h"

namespace thespis::core::speech {

BmlLexicon BmlLexicon::defaults()
{
    return {{{"BEAT", "agree"}, {"NOD", "agree"}, {"AGREE", "agree"}, {"WAVE", "greet"}, {"GREET", "greet"},
             {"POINT", "point"}}};
}

BmlLexicon BmlLexicon::of(const std::optional<std::map<std::string, std::string>>& rows)
{
    if (!rows)
        return defaults();
    BmlLexicon lexicon;
    for (const auto& [lexeme, entry] : *rows)
        lexicon.set(lexeme, entry);
    return lexicon;
}

void BmlLexicon::set(const std::string& lexeme, std::string entry)
{
    gestures[uppercase(lexeme)] = std::move(entry);
}

std::string BmlLexicon::entryFor(const std::string& lexeme, const std::vector<std::string>& gesticon) const
{
    const std::string wanted = uppercase(lexeme);
    if (const auto row = gestures.find(wanted); row != gestures.end())
        if (std::find(gesticon.begin(), gesticon.end(), row->second) != gesticon.end())
            return row->second;
    for (const std::string& g : gesticon)
        if (uppercase(g) == wanted)
            return g;
    return {};
}

} // namespace thespis::core::speech
