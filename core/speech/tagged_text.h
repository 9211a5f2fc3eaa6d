#pragma once
// The paper's tagged text (§5.2): what a character says, with the gestures that go with its
// words —
//   Are you <begin_gesture id="g1" anim="raise_eyebrows"/>really sure about that?<end_gesture id="g1"/>
// A gesture spans the words between its begin and end tags; gestures nest and may overlap.
// `&lt;` `&gt;` `&amp;` `&quot;` `&apos;` stand for their characters; a "<" not followed by a
// letter or "/" is text ("1 < 2"). Errors give the line and column (in characters, from 1).

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "util/error.h"

namespace thespis::core::speech {

struct TaggedGesture {
    std::string id;            ///< unique among the text's gestures
    std::string animation;     ///< the `anim` attribute: a gesticon entry's name
    std::size_t begin = 0;     ///< byte offsets of its span in TaggedText::text: [begin, end)
    std::size_t end = 0;
    int line = 0, column = 0;  ///< where its begin tag is, for messages
    bool operator==(const TaggedGesture&) const = default;
};

struct TaggedText {
    std::string text;                    ///< what is spoken: the tags taken out
    std::vector<TaggedGesture> gestures; ///< in the order their begin tags come
    bool operator==(const TaggedText&) const = default;
};

/// Reads tagged text. CorruptData with "line L, column C: …" for an unknown or malformed tag, a
/// begin without id or anim, an id used twice, an end without its begin, a begin never ended.
Result<TaggedText> parseTaggedText(std::string_view input);

/// The text with its tags written back (attributes in double quotes, markup characters escaped).
std::string taggedTextString(const TaggedText& tagged);

} // namespace thespis::core::speech
