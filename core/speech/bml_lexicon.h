#pragma once
// BML gesture lexemes (BEAT, POINT, WAVE …) → entries of a character's gesticon (issue 33): the
// table the planner (bml_plan.h) looks a <gesture lexeme> up in. Each character keeps its own in
// the scenario (Character::bmlLexicon, format 12); one that keeps none has the defaults, made
// for the shipped gesticons.

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace thespis::core::speech {

struct BmlLexicon {
    /// Rows by lexeme, in upper case.
    std::map<std::string, std::string> gestures;

    /// Rows for the shipped gesticons: BEAT, NOD and AGREE → "agree"; WAVE and GREET → "greet";
    /// POINT → "point".
    static BmlLexicon defaults();
    /// A character's table as the scenario keeps it (lexemes in any case): nullopt is defaults().
    static BmlLexicon of(const std::optional<std::map<std::string, std::string>>& rows);

    /// Sets the row of `lexeme` (in any case) to `entry`.
    void set(const std::string& lexeme, std::string entry);
    /// The entry of `gesticon` (its gestures' names) that plays `lexeme` (in any case): its row's
    /// entry when the gesticon has it, else the entry of the lexeme's own name (in any case);
    /// empty when none does. A row thus redirects even a lexeme that names an entry.
    std::string entryFor(const std::string& lexeme, const std::vector<std::string>& gesticon) const;
};

} // namespace thespis::core::speech
