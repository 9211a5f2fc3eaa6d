#pragma once
// From speech timing to what the face does (paper §5.2): every phoneme shows its viseme, as a
// blending action on the face track whose weight is the coarticulation dominance curve (eq. 3)
// over the phoneme widened by the viseme's spread, so that neighbouring visemes overlap and blend
// (Cohen and Massaro's model: where several are active, each counts by its dominance); and how a
// gesture's clip fills the time the BML planner gives it. One plan serves the studio's preview
// and Insert, the command line and scripts.

#include <string>
#include <vector>

#include "anim/curve.h"
#include "speech/speech_timing.h"
#include "speech/tagged_text.h"
#include "speech/viseme_set.h"

namespace thespis::core::speech {

struct VisemeCue {
    int viseme = 0;           ///< the set's id
    int mpeg4 = 0;            ///< the MPEG-4 viseme the face shows it as (Viseme::mpeg4; 0: at rest)
    std::string name;         ///< the viseme's name ("p_b_m")
    std::string phoneme;      ///< the ARPAbet phoneme it shows
    int phonemeIndex = 0;     ///< into SpeechTiming::phonemes
    double start = 0;         ///< seconds: the phoneme widened by the spread (never below 0)
    double duration = 0;
    double centre = 0;        ///< where it peaks: the middle of its phoneme (or of its part of it)
    anim::Curve weight;       ///< dominance(α) × the viseme's weight, over [start, start + duration]
};

struct GestureCue {
    std::string id, animation;
    double start = 0, end = 0; ///< seconds: from its first word's start to its last word's end
    int line = 0, column = 0;  ///< of its tag
};

/// The visemes of `timing` in `set`: one cue per phoneme (two or more when the set shows a
/// phoneme as a sequence, "ey" → 4, 6, each taking an equal part), none in pauses, all within
/// the utterance. Sorted by start.
std::vector<VisemeCue> visemeCues(const SpeechTiming& timing, const VisemeSet& set = mpeg4Visemes());

/// The words each gesture of `text` spans, in time (the timing of `text.text`, whose words' text
/// offsets are into it), as a person reads them; the planner times the gesture itself
/// (speech/tagged_bml.h). A gesture spanning no word (tags side by side, or around punctuation)
/// lasts from the end of the word before it to the start of the next.
std::vector<GestureCue> gestureCues(const TaggedText& text, const SpeechTiming& timing);

/// How a gesture entry meets words longer or shorter than its motion (scenario.h's Gesture): its
/// stroke, seconds into its clip (−1: none marked), and whether it holds rather than stretches.
struct GestureShape {
    bool hold = false;
    double stroke = -1;
};

/// Where a gesture plays, as the planner (speech/bml_plan.h) times it: seconds from its block's
/// start, fades included; `stroke` is when its stroke shows (−1: where its clip puts it).
struct GestureSpan {
    double start = 0, end = 0, stroke = -1;
};

struct GestureFit {
    double start = 0;     ///< seconds from the block's start
    double duration = 0;  ///< seconds, fades included
    double stretch = 1;   ///< the clip's time scale (2: twice as long)
    /// Local seconds → the clip's seconds, when the gesture is not simply stretched (a stroke to
    /// put on its time, a hold): a monotone curve through its keys. Empty: `stretch`.
    std::vector<anim::CurveKey> warp;
};

/// How a clip of `clipSeconds` fills `span` (paper §5.2: "the TTS timing information is used to
/// plan the length of the gesture motions"): stretched or shrunk to it; with `shape`, a marked
/// stroke falls on the span's stroke, each side of it time-scaled to fit, and a holding entry
/// plays at its own speed and holds its stroke (or middle) pose for as long as the span lasts,
/// scaled only where it leaves too little time.
GestureFit fitGesture(const GestureSpan& span, double clipSeconds, const GestureShape& shape = {});

} // namespace thespis::core::speech
