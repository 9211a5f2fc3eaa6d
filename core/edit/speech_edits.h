#pragma once
// Speech put into a scenario (paper §5.2), as one undo step: the line is kept on its character
// (its text, voice, audio and timing; format 9), and the visemes of its utterance become
// actions on the character's "Speech" face layer — each playing a viseme clip (one face channel
// held at 1) stretched over its cue, weighted by the cue's dominance curve, over the Speech face
// mask (mouth and tongue) — and the gestures of its tagged text play their gesticon entries over
// the time of their words, timed by the BML planner as BML's gestures are: face gestures on the
// same face layer, body gestures on a "Gestures" body layer.

#include <string>
#include <vector>

#include "edit/scenario_edit.h"
#include "speech/espeak_voice.h"
#include "scenario/scenario_runtime.h"
#include "speech/speech_plan.h"
#include "speech/tagged_bml.h"
#include "util/tick.h"

namespace thespis::core::edit {

/// What insertSpeech() adds, for a caller to tell the user.
struct SpeechInsertion {
    Edit edit;
    int visemeActions = 0;
    int faceGestures = 0, bodyGestures = 0;
};

/// A speech line of tagged `text` spoken by `voice` with `timing`, its audio in `audio` (relative
/// to the scenario), from `start`; named "line".
scenario::SpeechLine speechLine(const std::string& text, const speech::VoiceSettings& voice,
                                const speech::SpeechTiming& timing, std::string audio, Tick start);

/// Adds `line` to `character` (its name made unique among the character's lines) with the MPEG-4
/// viseme cues of its utterance from line.start, and its tagged gestures as the BML planner times
/// them (speech/tagged_bml.h: each over its words with its fades) on the character's gesticon as
/// `runtime` has built it. Creates what is missing: the viseme clips ("viseme p_b_m"), the
/// "Speech" face mask, the layers. Errors: no such character; gestures without `runtime`; a
/// gesture not in its gesticon (naming the tag's line and column and the gestures it has); a
/// locked layer.
Result<SpeechInsertion> insertSpeech(const scenario::Scenario& scenario, int character, scenario::SpeechLine line,
                                     const std::vector<speech::VisemeCue>& visemes,
                                     const speech::TaggedBml& gestures = {},
                                     const scenario::ScenarioRuntime* runtime = nullptr);

} // namespace thespis::core::edit
