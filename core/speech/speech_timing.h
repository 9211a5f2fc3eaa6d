#pragma once
// When each word and phoneme of an utterance is spoken: what the text-to-speech engine reports
// (speech/espeak_voice.h) or forced alignment finds in a recording (speech/lip_sync.h). Phonemes
// are ARPAbet (CMUdict's 39, upper case, no stress digits) plus "SIL" for a pause; they tile the
// utterance from its start to its end with no gap. Times are seconds from the utterance's start.

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "util/error.h"

namespace thespis::core::speech {

struct WordTiming {
    std::string text;             ///< as written in the text spoken ("Really")
    double start = 0, end = 0;    ///< seconds
    std::size_t textBegin = 0;    ///< the word's bytes in the text spoken: [textBegin, textEnd)
    std::size_t textEnd = 0;
    bool stressed = false;        ///< espeak-ng gave it a primary stress (a content word)
    bool operator==(const WordTiming&) const = default;
};

struct PhonemeTiming {
    std::string phoneme;          ///< ARPAbet ("P", "AA") or "SIL"
    double start = 0, end = 0;    ///< seconds
    int word = -1;                ///< index into SpeechTiming::words; −1 in a pause or a filler ("uh")
    bool operator==(const PhonemeTiming&) const = default;
};

struct SpeechTiming {
    std::vector<WordTiming> words;
    std::vector<PhonemeTiming> phonemes;
    double duration = 0;          ///< seconds: the audio's length
    bool operator==(const SpeechTiming&) const = default;

    /// Sets each word's times from its phonemes: from its first to its last; a word with none is
    /// empty, where the one before ends.
    void fitWordsToPhonemes();
    /// The same timing `seconds` later (words and phonemes; the duration grows by it).
    void shift(double seconds);
    /// Appends `next`, which starts `offset` seconds after this one's start; its word indices
    /// and text offsets (by `textOffset` bytes) follow this one's.
    void append(const SpeechTiming& next, double offset, std::size_t textOffset);
};

/// True for "SIL".
inline bool isPause(const std::string& phoneme) { return phoneme == "SIL"; }

} // namespace thespis::core::speech
