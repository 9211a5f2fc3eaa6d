// libFuzzer target for the viseme set reader (core/speech/viseme_set.h).
//
// Any bytes: parseVisemeSet must return a set or an error with a message, never crash, hang or
// throw. A set it accepts validates, writes and reads back equal, writes the same text again, and
// plans visemes for every phoneme (a cue per phoneme and viseme, inside the utterance).

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "speech/phonemes.h"
#include "speech/speech_plan.h"
#include "speech/viseme_set.h"

namespace speech = thespis::core::speech;

namespace {

[[noreturn]] void failure(const char* what, const std::string& detail)
{
    std::fprintf(stderr, "fuzz_viseme_set: %s\n%s\n", what, detail.c_str());
    std::abort();
}

// Every ARPAbet phoneme once, a tenth of a second each, a pause between.
const speech::SpeechTiming& everyPhoneme()
{
    static const speech::SpeechTiming timing = [] {
        speech::SpeechTiming t;
        double at = 0;
        for (std::string_view p : speech::arpabetPhonemes()) {
            t.phonemes.push_back({std::string(p), at, at + 0.1, -1});
            t.phonemes.push_back({"SIL", at + 0.1, at + 0.15, -1});
            at += 0.15;
        }
        t.duration = at;
        return t;
    }();
    return timing;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    auto first = speech::parseVisemeSet(text);
    if (!first) {
        if (first.error().message.empty() || first.error().code == thespis::core::ErrorCode::Internal)
            failure("an error without a message, or an internal one", first.error().message);
        return 0;
    }
    if (auto valid = first->validate(); !valid)
        failure("a set the reader accepts does not validate", valid.error().message);
    const std::string written = speech::serializeVisemeSet(*first);
    auto second = speech::parseVisemeSet(written);
    if (!second)
        failure("the writer's output does not read back", second.error().message + "\n" + written);
    if (!(*second == *first))
        failure("the set changed in a write/read round trip", written);
    if (speech::serializeVisemeSet(*second) != written)
        failure("writing is not stable", written);
    for (const speech::VisemeCue& cue : speech::visemeCues(everyPhoneme(), *first))
        if (!(cue.start >= 0 && cue.duration > 0 && cue.start + cue.duration <= everyPhoneme().duration + 1e-9
              && cue.weight.validate().ok()))
            failure("a viseme cue outside the utterance or with a bad curve", written);
    return 0;
}
