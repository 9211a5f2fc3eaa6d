#include "speech/speech_timing.h"

#include <algorithm>

namespace thespis::core::speech {

void SpeechTiming::fitWordsToPhonemes()
{
    for (WordTiming& word : words)
        word.start = -1;
    for (const PhonemeTiming& phoneme : phonemes) {
        if (phoneme.word < 0 || phoneme.word >= int(words.size()))
            continue;
        WordTiming& word = words[std::size_t(phoneme.word)];
        if (word.start < 0)
            word.start = phoneme.start;
        word.end = phoneme.end;
    }
    double previousEnd = 0;
    for (WordTiming& word : words) {
        if (word.start < 0)
            word.start = word.end = previousEnd;
        previousEnd = word.end;
    }
}

void SpeechTiming::shift(double seconds)
{
    for (WordTiming& word : words) {
        word.start += seconds;
        word.end += seconds;
    }
    for (PhonemeTiming& phoneme : phonemes) {
        phoneme.start += seconds;
        phoneme.end += seconds;
    }
    duration += seconds;
}

void SpeechTiming::append(const SpeechTiming& next, double offset, std::size_t textOffset)
{
    const int firstWord = int(words.size());
    for (WordTiming word : next.words) {
        word.start += offset;
        word.end += offset;
        word.textBegin += textOffset;
        word.textEnd += textOffset;
        words.push_back(std::move(word));
    }
    for (PhonemeTiming phoneme : next.phonemes) {
        phoneme.start += offset;
        phoneme.end += offset;
        if (phoneme.word >= 0)
            phoneme.word += firstWord;
        phonemes.push_back(std::move(phoneme));
    }
    duration = std::max(duration, offset + next.duration);
}

} // namespace thespis::core::speech
