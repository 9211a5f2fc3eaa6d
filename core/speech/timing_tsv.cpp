#include "speech/timing_tsv.h"

#include <cstdio>

#include "speech/viseme_set.h"
#include "util/file_io.h"

namespace thespis::core::speech {

std::string timingTsv(const SpeechTiming& timing)
{
    std::string text = "start\tend\tword\tphoneme\tviseme\n";
    for (const PhonemeTiming& phoneme : timing.phonemes) {
        char times[64];
        std::snprintf(times, sizeof times, "%.3f\t%.3f\t", phoneme.start, phoneme.end);
        text += times;
        if (phoneme.word >= 0 && std::size_t(phoneme.word) < timing.words.size())
            text += timing.words[std::size_t(phoneme.word)].text;
        text += "\t" + phoneme.phoneme + "\t" + std::to_string(mpeg4Viseme(phoneme.phoneme)) + "\n";
    }
    return text;
}

Result<void> writeTimingTsv(const std::filesystem::path& path, const SpeechTiming& timing)
{
    return writeFileAtomically(path, timingTsv(timing));
}

} // namespace thespis::core::speech
