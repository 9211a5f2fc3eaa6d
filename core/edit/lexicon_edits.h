#pragma once
// Edits of a character's BML lexicon (Character::bmlLexicon, speech/bml_lexicon.h): the table of
// gesture lexemes (BEAT, POINT, …) and the gestures of its gesticon that play them. The studio's
// "BML lexemes" table makes one of these per change, so each is one undo step; scripts make the
// same (thespis.edit). None of them changes the document itself.

#include <map>
#include <optional>
#include <string>

#include "edit/scenario_edit.h"
#include "scenario/scenario.h"
#include "util/error.h"

namespace thespis::core::edit {

/// The rows the character's BML lexicon has: its own, or, when it keeps none, the defaults whose
/// gestures it has (the others could not play and change nothing).
std::map<std::string, std::string> bmlLexiconRows(const scenario::Character& character);

/// Sets the character's whole lexicon (nullopt: back to the defaults); lexemes are kept in upper
/// case. Refused: no such character, an empty lexeme, two lexemes the same in any case, a row
/// naming no gesture of the character (unless the character's table already has that very row:
/// a gesture removed since keeps its rows until the user changes them).
Result<Edit> setBmlLexicon(const scenario::Scenario& scenario, int character,
                           std::optional<std::map<std::string, std::string>> rows);
/// Sets the row of `lexeme` (any case) to `entry`, or removes it (nullopt), in the character's
/// rows (bmlLexiconRows: a character without its own table gets one). Refused as setBmlLexicon.
Result<Edit> setBmlLexeme(const scenario::Scenario& scenario, int character, const std::string& lexeme,
                          std::optional<std::string> entry);
/// Gives the row of `from` the lexeme `to` (any case). Refused: no row of `from`, `to` has one.
Result<Edit> renameBmlLexeme(const scenario::Scenario& scenario, int character, const std::string& from,
                             const std::string& to);

} // namespace thespis::core::edit
