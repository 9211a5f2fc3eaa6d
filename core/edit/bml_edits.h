#pragma once
// A BML block put on a character's timeline (issue 33) as one undo step, planned as the Stage's
// realizer plays it (speech/bml_plan.h), from the playhead:
//  - each speech as a speech line with its visemes (edit::insertSpeech);
//  - gestures and pointing as their gesticon entries' actions, stretched from their start to
//    their end with ready … relax as fades, on the "Gestures" body layer; a pointing one keeps
//    its target and hand (ActionSpec::pointing), so that the Stage aims its arm;
//  - head nods, shakes and tilts as keyframed clips ("head NOD") on the additive "Head" body layer;
//  - faceLexemes as clips of their FAPs ("faceLexeme RAISE_BROWS") on the additive "Face lexemes"
//    face layer;
//  - gaze as actions of the "Gaze" gaze layer, until their relax point when the block gives one,
//    else until the block ends.
// The block's composition does not apply: the timeline places it at the playhead.

#include <map>
#include <optional>
#include <string>

#include "edit/scenario_edit.h"
#include "scenario/scenario_runtime.h"
#include "speech/bml.h"
#include "speech/bml_plan.h"
#include "speech/espeak_voice.h"
#include "speech/viseme_set.h"
#include "util/tick.h"

namespace thespis::core::edit {

/// What insertBml() adds, for a caller to tell the user.
struct BmlInsertion {
    Edit edit;
    int speeches = 0, visemeActions = 0, gestures = 0, headGestures = 0, faceLexemes = 0, gazes = 0;
    double seconds = 0; ///< from the playhead to the block's last end
};

/// How the block's speeches and gestures are made.
struct BmlInsertOptions {
    speech::VoiceSettings voice;          ///< the speeches were said with it (kept on their lines)
    speech::VisemeSet visemes = speech::mpeg4Visemes();
    /// The gesture lexemes' table; nullopt: the character's own (Character::bmlLexicon).
    std::optional<speech::BmlLexicon> lexicon;
};

/// `spoken` holds each speech's utterance by behaviour id (SpeakJob's bmlSpeech); `runtime` is
/// the scenario's, for its gestures' lengths and the character's skeleton. Errors: no such
/// character; what planBml() refuses (naming the behaviour's line and column); a head gesture
/// the skeleton cannot make; a locked layer; a block with nothing that shows.
Result<BmlInsertion> insertBml(const scenario::Scenario& scenario, const scenario::ScenarioRuntime& runtime,
                               int character, const speech::BmlBlock& block,
                               const std::map<std::string, speech::Utterance>& spoken,
                               const BmlInsertOptions& options, Tick at);

} // namespace thespis::core::edit
