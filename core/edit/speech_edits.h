#pragma once
// Speech put into a scenario (paper §5.2), as one undo step: the visemes of an utterance become
// actions on the character's "Speech" face layer — each playing a viseme clip (one face channel
// held at 1) stretched over its cue, weighted by the cue's dominance curve, over the Speech face
// mask (mouth and tongue) — and the gestures of its tagged text play their gesticon entries over
// the time of their words: face gestures on the same face layer, stretched to their words when
// they are keyframed, body gestures on a "Gestures" body layer from their first word.

#include <string>
#include <vector>

#include "edit/scenario_edit.h"
#include "speech/speech_plan.h"
#include "util/tick.h"

namespace thespis::core::edit {

/// What insertSpeech() adds, for a caller to tell the user.
struct SpeechInsertion {
    Edit edit;
    int visemeActions = 0;
    int faceGestures = 0, bodyGestures = 0;
};

/// Inserts the MPEG-4 viseme cues and the gesture cues of an utterance spoken by `character`
/// from `at`. Creates what is missing: the viseme clips ("viseme p_b_m"), the "Speech" face mask,
/// the layers. Errors: no such character; a gesture's animation not in its gesticon (naming the
/// tag's line and column and the gestures it has); a locked layer.
Result<SpeechInsertion> insertSpeech(const scenario::Scenario& scenario, int character, Tick at,
                                     const std::vector<speech::VisemeCue>& visemes,
                                     const std::vector<speech::GestureCue>& gestures);

} // namespace thespis::core::edit
