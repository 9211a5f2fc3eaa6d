#pragma once
// The gesticon of a character's runtime: every gesture built as the actions that play it live
// (with and without the dependent-joint filter), for the Stage's library, and its BML lexicon.

#include <functional>
#include <optional>
#include <string>

#include "anim/blending_schedule.h"
#include "scenario/scenario.h"
#include "scenario/scenario_runtime.h"

namespace thespis::core::scenario {

/// Builds an action of the character on a layer of `kind` as the runtime builds an authored one
/// (problems are the builder's to report); `widened` is the mask the action plays over when the
/// scenario has none of its name yet.
using BuildGestureAction = std::function<std::optional<anim::BlendingAction>(
    const ActionSpec&, LayerKind kind, const NamedMask* widened, const std::string& where)>;

/// Fills runtime.gestures from the character's gesticon. A gesture whose clip moves no joint of
/// the skeleton but has face values (runtime.faceClips) is a face gesture: built on the face
/// layout, without the dependent-joint filter (a body's). The filtered action is built only when
/// `basesReadable` (the filter needs the scenario's posture bases); a gesture with its filter on
/// is then left out, with a warning.
void buildGestures(const Scenario& scenario, const Character& character, const BuildGestureAction& build,
                   bool basesReadable, CharacterRuntime& runtime);

/// Sets runtime.bmlLexicon from the character's (or the defaults). A row of the character's own
/// naming no gesture of it is a warning, not an error: it only
/// matters once BML names its lexeme, and the planner then says that nothing plays it; the rest of
/// the scenario plays (and removing a gesture must not stop it).
void buildBmlLexicon(const Character& character, CharacterRuntime& runtime);

} // namespace thespis::core::scenario
