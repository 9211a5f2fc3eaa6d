// libFuzzer target for the tagged-text reader (core/speech/tagged_text.h).
//
// Any bytes: parseTaggedText must return tagged text or an error with "line L, column C: …",
// never crash, hang or throw. Text it accepts has every gesture span inside the text and in
// order, writes back to tagged text that reads equal, and its speech plan (gestureCues over a
// made-up word timing) keeps every gesture inside the utterance.

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "speech/speech_plan.h"
#include "speech/tagged_text.h"
#include "../core/made_up_timing.h"

namespace speech = thespis::core::speech;

namespace {

[[noreturn]] void failure(const char* what, const std::string& detail)
{
    std::fprintf(stderr, "fuzz_tagged_text: %s\n%s\n", what, detail.c_str());
    std::abort();
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string_view input(reinterpret_cast<const char*>(data), size);
    auto first = speech::parseTaggedText(input);
    if (!first) {
        if (first.error().message.rfind("line ", 0) != 0 || first.error().message.find(", column ") == std::string::npos)
            failure("an error without its line and column", first.error().message);
        return 0;
    }
    for (const speech::TaggedGesture& g : first->gestures)
        if (g.begin > g.end || g.end > first->text.size() || g.id.empty() || g.animation.empty() || g.line < 1
            || g.column < 1)
            failure("a gesture outside the text or without id, anim or place", std::string(input));
    const std::string written = speech::taggedTextString(*first);
    auto second = speech::parseTaggedText(written);
    if (!second)
        failure("the writer's output does not read back", second.error().message + "\n" + written);
    // Line and column name where a tag was written, which writing changes; the rest must not.
    speech::TaggedText a = *first, b = *second;
    for (auto* t : {&a, &b})
        for (speech::TaggedGesture& g : t->gestures)
            g.line = g.column = 0;
    if (!(a == b))
        failure("the tagged text changed in a write/read round trip", written);

    const speech::SpeechTiming timing = thespis::test::madeUpTiming(first->text, 0.1);
    for (const speech::GestureCue& cue : speech::gestureCues(*first, timing))
        if (!(cue.start >= 0 && cue.start <= cue.end && cue.end <= timing.duration + 1e-9))
            failure("a gesture cue outside the utterance", std::string(input));
    return 0;
}
