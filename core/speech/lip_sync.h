#pragma once
// Lip sync from a recording (issue 32 §4): a voice recording and what it says → when each word
// and phoneme is spoken, by forced alignment with pocketsphinx's en-us model. Without a
// transcript, pocketsphinx recognises the words first and those are aligned.
//
// How: the recording (any rate; loadSound mixes it to mono) is resampled to 16 kHz. Words
// pass: a grammar that is the transcript word by word, with every pronunciation CMUdict has for
// each word — espeak-ng's for a word it lacks, with a warning — and optional pauses between
// words, with room for a filler ("uh", "um") inside a pause; on failure again with wide beams. Phonemes
// pass, per stretch of speech between pauses of 0.3 s or more: a grammar whose words are the
// phonemes of the pronunciations the words pass chose, with optional pauses between words; on
// failure again with wide beams, and failing that the stretch's words are split evenly into their
// phonemes (a warning says where). Then each boundary moves to the greatest change of the sound
// within 15 ms (boundary_refinement.h). A word's phonemes tile it; pauses are "SIL" (word −1),
// and fillers are phonemes of no word ("uh": AH, word −1).

#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "speech/speech_timing.h"
#include "util/error.h"
#include "util/job.h"

namespace thespis::core::speech {

struct LipSyncResult {
    SpeechTiming timing;               ///< words index `transcript`
    std::string transcript;            ///< as given, or as recognised
    std::vector<std::string> warnings; ///< for people: words pronounced by espeak-ng, phonemes spread evenly
};

/// Aligns `samples` (mono, `rate` Hz) with `transcript`, or with what is recognised in them when
/// the transcript has no words. Reports the stages of LipSyncJob on `context` and stops when it
/// is stopped (ErrorCode::Cancelled). Errors: no sound, the model missing, nothing recognised,
/// the transcript not alignable with the sound (it is not what is said).
Result<LipSyncResult> lipSync(std::span<const float> samples, int rate, std::string_view transcript, JobContext& context);

/// A recording's lip sync: LipSyncResult for `audio` (WAV, FLAC, OGG; any rate, mono or stereo).
class LipSyncJob final : public Job {
public:
    static constexpr const char* RecognisingStage = "Recognising words";
    static constexpr const char* WordsStage = "Aligning words";
    static constexpr const char* PhonemesStage = "Aligning phonemes";

    std::filesystem::path audio;
    std::string transcript;  ///< what the recording says; empty: recognised
    LipSyncResult result;    ///< the output

    std::string title() const override;
    /// Rule: an audio file is named.
    Result<void> validate() const override;
    /// Errors name the audio file.
    Result<void> run(JobContext& context) override;
};

} // namespace thespis::core::speech
