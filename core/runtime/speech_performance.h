#pragma once
// Speech played live on the Stage (paper §5.2 and §4.5's voiceService): the visemes of an
// utterance as one live Override action on the character's face — a schedule holding, per viseme
// cue, an action of that viseme weighted by its dominance curve over the Speech mask, exactly as
// edit::insertSpeech puts them on the timeline's Override "Speech" layer — and the gestures of
// its tagged text, planned as BML's are (runtime/bml_performance.h shares the gesture playing). The studio's Preview, scripts and conversation
// all speak through here.

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "anim/blending_schedule.h"
#include "runtime/stage.h"
#include "scenario/scenario.h"
#include "speech/bml_plan.h"
#include "speech/speech_plan.h"
#include "speech/tagged_bml.h"
#include "util/error.h"
#include "util/tick.h"

namespace thespis::core::runtime {

/// The face of `cues` on the MPEG-4 face layout: one action per cue, from its start (seconds from
/// the utterance's start), over the Speech face mask; where cues overlap each counts by its
/// dominance. Played as an Override action, it covers the face by how much the visemes do. Errors: a cue that is not one
/// of MPEG-4's 14 visemes or that lasts no time.
Result<std::shared_ptr<anim::BlendingSchedule>> speechFace(const std::vector<speech::VisemeCue>& cues);

/// The timing a speech line keeps (seconds from its start); its words are found in order in
/// `spoken` (the line's text without tags), so that gestures can be timed by them.
speech::SpeechTiming timingOf(const scenario::SpeechLine& line, std::string_view spoken);

/// What performSpeech() started.
struct SpeechPerformance {
    std::string action;          ///< the live face action's name ("speech NAME")
    int visemes = 0;             ///< viseme cues in it
    int gestures = 0;            ///< face and body gestures played ("NAME:ID")
    std::vector<std::string> unknownGestures; ///< tags naming a gesture the character cannot play
};

/// Plays the viseme cues (MPEG-4's, speech::visemeCues) live on `character`'s face from `at` as
/// the action "speech `name`" (replacing one of that name still playing), and the gestures of its
/// tagged text as the BML planner times them (speech/tagged_bml.h: each over its words with its
/// fades), named "`name`:ID", on the track whose gesticon has them; a tag naming a gesture the
/// character lacks is reported, not played. Errors: no such character; nothing to say; a cue
/// speechFace() refuses.
Result<SpeechPerformance> performSpeech(Stage& stage, const std::string& character, const std::string& name,
                                        const std::vector<speech::VisemeCue>& cues,
                                        const speech::TaggedBml& gestures, Tick at);

/// `character`'s gestures on `stage` as the BML planner sees them: its body actions (gestures
/// with their fades, stroke and hold), then its face actions. Each template the planner asks for
/// is kept in `asked`, to be played; the gesticon refers to `stage` and `asked`.
speech::BmlGesticon stageGesticon(const Stage& stage, const std::string& character,
                                  std::map<std::string, ActionTemplate>& asked);

/// A planned gesture's template (from stageGesticon()) with its clip fitted to the planned time
/// (stretched, or warped to keep its stroke) and the plan's fades as its weight.
Result<ActionTemplate> fittedGesture(ActionTemplate gesture, const speech::BmlPlanned& planned);

} // namespace thespis::core::runtime
