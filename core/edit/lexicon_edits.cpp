#include "edit/lexicon_edits.h"

#include "speech/bml_lexicon.h"
#include "util/text.h"

namespace thespis::core::edit {

using scenario::Character;
using scenario::Scenario;
using Rows = std::map<std::string, std::string>;

namespace {

Error invalid(std::string message) { return makeError(ErrorCode::InvalidArgument, std::move(message)); }

const Character* characterOf(const Scenario& scenario, int character)
{
    return character >= 0 && std::size_t(character) < scenario.characters.size()
               ? &scenario.characters[std::size_t(character)]
               : nullptr;
}

} // namespace

Rows bmlLexiconRows(const Character& character)
{
    if (character.bmlLexicon)
        return *character.bmlLexicon;
    Rows rows;
    for (const auto& [lexeme, entry] : speech::BmlLexicon::defaults().gestures)
        if (character.findGesture(entry))
            rows[lexeme] = entry;
    return rows;
}

Result<Edit> setBmlLexicon(const Scenario& scenario, int character, std::optional<Rows> rows)
{
    const Character* who = characterOf(scenario, character);
    if (!who)
        return invalid("There is no character " + std::to_string(character) + ".");
    if (rows) {
        Rows upper;
        for (const auto& [lexeme, entry] : *rows) {
            if (lexeme.empty())
                return invalid("A BML lexeme needs a name.");
            const std::string key = uppercase(lexeme);
            if (!upper.emplace(key, entry).second)
                return invalid("The lexeme " + key + " is in the table twice.");
            const bool kept = who->bmlLexicon && who->bmlLexicon->contains(key) && who->bmlLexicon->at(key) == entry;
            if (!who->findGesture(entry) && !kept)
                return invalid(who->name + " has no gesture named " + inQuotes(entry) + " to play " + key + ".");
        }
        rows = std::move(upper);
    }
    return Edit(BmlLexiconChange{character, who->bmlLexicon, std::move(rows)});
}

Result<Edit> setBmlLexeme(const Scenario& scenario, int character, const std::string& lexeme,
                          std::optional<std::string> entry)
{
    const Character* who = characterOf(scenario, character);
    if (!who)
        return invalid("There is no character " + std::to_string(character) + ".");
    Rows rows = bmlLexiconRows(*who);
    if (entry)
        rows[uppercase(lexeme)] = std::move(*entry);
    else if (rows.erase(uppercase(lexeme)) == 0)
        return invalid("The BML lexicon of " + who->name + " has no row " + uppercase(lexeme) + ".");
    return setBmlLexicon(scenario, character, std::move(rows));
}

Result<Edit> renameBmlLexeme(const Scenario& scenario, int character, const std::string& from, const std::string& to)
{
    const Character* who = characterOf(scenario, character);
    if (!who)
        return invalid("There is no character " + std::to_string(character) + ".");
    Rows rows = bmlLexiconRows(*who);
    const auto row = rows.find(uppercase(from));
    if (row == rows.end())
        return invalid("The BML lexicon of " + who->name + " has no row " + uppercase(from) + ".");
    if (uppercase(to) == row->first)
        return Edit(BmlLexiconChange{character, who->bmlLexicon, who->bmlLexicon}); // changes nothing
    if (to.empty())
        return invalid("A BML lexeme needs a name.");
    if (rows.contains(uppercase(to)))
        return invalid("The lexeme " + uppercase(to) + " already has a row.");
    std::string entry = row->second;
    rows.erase(row);
    rows[uppercase(to)] = std::move(entry);
    return setBmlLexicon(scenario, character, std::move(rows));
}

} // namespace thespis::core::edit
