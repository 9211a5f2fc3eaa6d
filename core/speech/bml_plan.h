#pragma once
// One planner for a <bml> block (issue 33), whoever plays it, and for tagged text made BML
// (speech/tagged_bml.h): it checks that the character can play each behaviour — a gesticon entry
// for each gesture lexeme, a known faceLexeme and head lexeme, a gaze target, influence and
// offset that read — and times them all (resolveBml) from the speeches' TTS timing and each
// kind's own timing. A gesture's clip is fitted to its time, its stroke where the block puts it
// (speech::fitGesture); a gesture never starts before its block. The Stage's realizer
// (runtime/bml_performance.h) plays the plan live; edit::insertBml puts it on the timeline.

#include <array>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "anim/curve.h"
#include "motion/gaze.h"
#include "motion/gaze_target.h"
#include "motion/head_gesture.h"
#include "motion/pointing.h"
#include "speech/bml.h"
#include "speech/bml_lexicon.h"
#include "speech/speech_plan.h"
#include "util/error.h"

namespace thespis::core::speech {

/// What planning needs of a gesticon entry: its motion's length and fades, in seconds, how it
/// meets a time longer or shorter than its motion, and whether it moves the face (or the body).
struct BmlGestureEntry {
    double seconds = 0, fadeIn = 0, fadeOut = 0;
    GestureShape shape;
    bool face = false;
};

/// The character's gesticon as the planner sees it: its entries' names, and each one's timing
/// (nullopt for an entry that cannot play a gesture, e.g. an open-ended one).
struct BmlGesticon {
    std::vector<std::string> names;
    std::function<std::optional<BmlGestureEntry>(const std::string& name)> entry;
};

/// A faceLexeme lasts this long when nothing constrains it; a gaze shift takes this long.
inline constexpr double kBmlFaceLexemeSeconds = 1.0, kBmlGazeShiftSeconds = 0.4;

/// One behaviour of the block, ready to play.
struct BmlPlanned {
    std::size_t behavior = 0;                 ///< index in the block's behaviours
    BmlTimes times;                           ///< seconds from the block's start
    double length() const { return times.at[kBmlPointCount - 1] - times.at[0]; }
    /// Gesture, FaceLexeme: ready … relax as fades.
    anim::Curve weight = anim::Curve::constant(1);
    std::string gesture;                      ///< Gesture, Pointing: the gesticon entry
    BmlGestureEntry entry;                    ///< its timing
    GestureFit fit;                           ///< how its clip fills start … end
    motion::HeadGestureOptions head;          ///< Head (duration: its length)
    std::vector<std::pair<int, double>> faps; ///< FaceLexeme: FAP number → value, amount applied
    motion::GazeTarget target;                ///< Gaze, Pointing
    motion::PointingHand hand = motion::PointingHand::Right; ///< Pointing: BML's mode
    motion::GazeSettings gaze;                ///< Gaze: the defaults given with its influence and offset
    /// Gaze: lets go at its relax point when the block constrains it, else at its end when the
    /// block constrains that; otherwise it holds.
    bool gazeLetsGo = false;
    double gazeLetGo = 0;                     ///< seconds from the block's start
};

struct BmlPlan {
    std::vector<BmlPlanned> behaviors;        ///< in document order
    double end = 0;                           ///< seconds from the block's start to its last end
};

/// Plans `block` for a character with `gesticon`, the speeches timed by `speech` (by behaviour
/// id; every speech of the block must have one), gaze with `gazeDefaults` for what BML does not
/// say. Errors name the behaviour with its line and column: a gesture lexeme no entry plays, an
/// unknown faceLexeme or head lexeme, a gaze target, influence or offset that does not read, a
/// speech without timing, and whatever resolveBml() refuses.
Result<BmlPlan> planBml(const BmlBlock& block, const std::map<std::string, SpeechTiming>& speech,
                        const BmlGesticon& gesticon, const BmlLexicon& lexicon,
                        const motion::GazeSettings& gazeDefaults = {});

/// "line L, column C: gesture "g1": what" — how every BML problem of a behaviour reads.
Error bmlBehaviorError(ErrorCode code, const BmlBehavior& behavior, const std::string& what);

} // namespace thespis::core::speech
