#pragma once
// Tagged text's gestures as BML, so that one planner (speech/bml_plan.h) times both (issue 33):
// the text becomes a block's speech, and each tag a <gesture> naming its gesticon entry whose
// ready point is its first word's start, its relax point its last word's end and its stroke the
// start of its first stressed word (its first word when none is) — sync marks in the speech's
// text. The planner adds the entry's fades around the words and keeps its stroke on the stress.

#include <map>
#include <string>

#include "speech/bml.h"
#include "speech/speech_timing.h"
#include "speech/tagged_text.h"

namespace thespis::core::speech {

struct TaggedBml {
    BmlBlock block;                              ///< its speech first, then a gesture per tag
    std::map<std::string, SpeechTiming> speech;  ///< the speech's timing, by its id
    bool empty() const { return block.behaviors.size() <= 1; } ///< no gesture
};

/// `text`'s gestures over `timing` (the timing of `text.text`). A gesture spanning no word lasts
/// from the end of the word before it to the start of the next.
TaggedBml taggedBml(const TaggedText& text, const SpeechTiming& timing);

} // namespace thespis::core::speech
