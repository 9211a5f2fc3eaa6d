#pragma once
// Text to speech with espeak-ng (paper §5.1: "the output text is first converted into a speech
// signal by the text-to-speech engine … every phoneme corresponds to a different lip position").
// espeak-ng 1.51 reports phoneme events only when initialised through its legacy API with
// espeakINITIALIZE_PHONEME_EVENTS; each event's `sample` is the exact first sample of the
// phoneme, so the timing here is exact to the sample. Its output is 22 050 Hz mono.
//
// espeak-ng keeps one global state: every call here takes one process-wide lock, and is safe
// from any thread. A missing data folder is an error here, never an exit of the process.

#include <cstdint>
#include <functional>
#include <stop_token>
#include <string>
#include <string_view>
#include <vector>

#include "speech/speech_timing.h"
#include "util/error.h"

namespace thespis::core::speech {

inline constexpr int kEspeakRate = 22050;
inline constexpr int kMinWordsPerMinute = 80, kMaxWordsPerMinute = 450; ///< espeak-ng's own limits

struct VoiceSettings {
    std::string voice = "en-us";  ///< an installed voice's name or identifier (listVoices())
    int wordsPerMinute = 175;     ///< 80 … 450: beyond espeak-ng's maximum its timing breaks
    int pitch = 50;               ///< 0 … 100, 50 normal
    int volume = 100;             ///< 0 … 200, 100 normal
    bool operator==(const VoiceSettings&) const = default;

    /// What is out of range, naming the setting; nothing when all are fine.
    Result<void> validate() const;
};

struct VoiceInfo {
    std::string name;        ///< "English_(America)"
    std::string identifier;  ///< "gmw/en-US": also accepted as a voice
    std::string language;    ///< "en-us"
    int gender = 0;          ///< 0 unknown, 1 male, 2 female
};

/// The voices espeak-ng has installed. Error: its data folder is missing.
Result<std::vector<VoiceInfo>> listVoices();

/// A mark in SSML text (`<mark name="g1"/>`): where speech had got to there.
struct SpokenMark {
    std::string name;
    double time = 0; ///< seconds
};

/// Speech made from text: its samples (22 050 Hz mono, −1 … 1) and when each word and phoneme is.
struct Utterance {
    int rate = kEspeakRate;
    std::vector<float> samples;
    SpeechTiming timing;
    std::vector<SpokenMark> marks;
    double duration() const { return double(samples.size()) / rate; }
};

/// Speaks `text` (UTF-8, plain: it is escaped for espeak-ng's SSML reader, so "<" is read as
/// a character; marks are put in at the given byte offsets as `<mark name=…/>`). Words'
/// textBegin / textEnd are offsets into `text`. Stops with ErrorCode::Cancelled when `stop` is
/// requested. Errors: bad settings, an unknown voice (naming the installed ones), no data.
Result<Utterance> speak(std::string_view text, const VoiceSettings& settings,
                        const std::vector<std::pair<std::size_t, std::string>>& marks = {},
                        std::stop_token stop = {});

/// The ARPAbet phonemes espeak-ng would say for `word` with `voice` (for words a recogniser's
/// dictionary lacks); empty when it says none. Error: unknown voice.
Result<std::vector<std::string>> phonemesOf(std::string_view word, const std::string& voice = "en-us");

} // namespace thespis::core::speech
