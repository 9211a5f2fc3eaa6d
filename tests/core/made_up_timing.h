#pragma once
// A made-up speech timing for tests and fuzz targets of what follows speech timing (tagged-text
// gestures, BML sync points): one word per run of non-spaces, each `seconds` long, back to back.

#include <algorithm>
#include <string>

#include "speech/speech_timing.h"

namespace thespis::test {

inline core::speech::SpeechTiming madeUpTiming(const std::string& text, double seconds)
{
    core::speech::SpeechTiming timing;
    for (std::size_t i = 0; i < text.size();) {
        if (text[i] == ' ') {
            ++i;
            continue;
        }
        const std::size_t end = std::min(text.find(' ', i), text.size());
        const double start = seconds * double(timing.words.size());
        timing.words.push_back({text.substr(i, end - i), start, start + seconds, i, end});
        i = end;
    }
    timing.duration = seconds * double(timing.words.size());
    return timing;
}

} // namespace thespis::test
