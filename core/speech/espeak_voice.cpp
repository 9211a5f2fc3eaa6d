#include "speech/espeak_voice.h"

#include <espeak-ng/speak_lib.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <mutex>

#include "speech/phonemes.h"
#include "util/job.h"
#include "util/text.h"

namespace thespis::core::speech {
namespace {

std::mutex& espeakMutex()
{
    static std::mutex mutex;
    return mutex;
}

// What one espeak_Synth call delivers through the callback (espeak-ng calls it on the calling
// thread in synchronous mode).
struct Collector {
    std::vector<float> samples;
    struct Event {
        espeak_EVENT_TYPE type;
        int sample;
        int textPosition; // 1-based character position in the text given to espeak-ng
        int length;
        std::string name;
    };
    std::vector<Event> events;
    const std::stop_token* stop = nullptr;
};

int collect(short* wav, int count, espeak_EVENT* events)
{
    auto* collector = static_cast<Collector*>(events->user_data);
    if (wav && count > 0)
        for (int i = 0; i < count; ++i)
            collector->samples.push_back(float(wav[i]) / 32768.0f);
    for (espeak_EVENT* e = events; e->type != espeakEVENT_LIST_TERMINATED; ++e) {
        Collector::Event event{e->type, e->sample, e->text_position, e->length, {}};
        if (e->type == espeakEVENT_PHONEME)
            event.name.assign(e->id.string, strnlen(e->id.string, sizeof e->id.string));
        else if (e->type == espeakEVENT_MARK && e->id.name)
            event.name = e->id.name;
        collector->events.push_back(std::move(event));
    }
    return collector->stop && collector->stop->stop_requested() ? 1 : 0;
}

// Initialises espeak-ng once; the error stays (a missing data folder does not appear later).
Result<void> ensureInitialised()
{
    static const int rate = espeak_Initialize(AUDIO_OUTPUT_SYNCHRONOUS, 0, nullptr,
                                              espeakINITIALIZE_PHONEME_EVENTS | espeakINITIALIZE_DONT_EXIT);
    if (rate <= 0)
        return makeError(ErrorCode::FileNotFound,
                         "espeak-ng could not start: its voice data is missing (install the espeak-ng-data package).");
    static const bool callbackSet = (espeak_SetSynthCallback(collect), true);
    (void)callbackSet;
    return {};
}

std::string voiceNames(const std::vector<VoiceInfo>& voices)
{
    std::string names;
    for (const VoiceInfo& v : voices) {
        if (v.language.rfind("en", 0) != 0)
            continue;
        names += names.empty() ? "" : ", ";
        names += v.language;
    }
    return names;
}

std::vector<VoiceInfo> listVoicesLocked()
{
    std::vector<VoiceInfo> out;
    for (const espeak_VOICE** v = espeak_ListVoices(nullptr); v && *v; ++v) {
        VoiceInfo info;
        info.name = (*v)->name ? (*v)->name : "";
        info.identifier = (*v)->identifier ? (*v)->identifier : "";
        // languages: a priority byte, then the language name, repeated; the first is the main one.
        if ((*v)->languages && (*v)->languages[0])
            info.language = (*v)->languages + 1;
        info.gender = (*v)->gender;
        out.push_back(std::move(info));
    }
    return out;
}

// A voice's languages: a priority byte, a name, a zero byte, … up to an empty name.
std::vector<std::string> languagesOf(const espeak_VOICE& voice)
{
    std::vector<std::string> out;
    for (const char* at = voice.languages; at && at[0] && at[1]; at += 1 + std::strlen(at + 1) + 1)
        out.emplace_back(at + 1);
    return out;
}

// espeak-ng quietly falls back to a default for names it does not know, and finds voices by file
// (identifier) more reliably than by language: the voice asked for is looked up among those
// installed — by name, identifier or any of its languages ("en", "en-gb") — and selected by its
// identifier. A "+variant" suffix ("en-us+f3") picks a variant of it.
// The voice selectVoice() last selected (under espeakMutex).
std::string& selectedVoice()
{
    static std::string voice;
    return voice;
}

Result<void> selectVoice(const std::string& voice)
{
    selectedVoice().clear();
    const std::size_t plus = voice.find('+');
    const std::string base = lowercase(voice.substr(0, plus));
    const std::string variant = plus == std::string::npos ? std::string{} : voice.substr(plus);
    for (const espeak_VOICE** v = espeak_ListVoices(nullptr); v && *v; ++v) {
        const std::vector<std::string> languages = languagesOf(**v);
        const bool match = ((*v)->name && lowercase((*v)->name) == base)
                           || ((*v)->identifier && lowercase((*v)->identifier) == base)
                           || std::find(languages.begin(), languages.end(), base) != languages.end();
        if (match && (*v)->identifier && espeak_SetVoiceByName(((*v)->identifier + variant).c_str()) == EE_OK) {
            selectedVoice() = voice;
            return {};
        }
    }
    return makeError(ErrorCode::NotFound, "There is no espeak-ng voice " + inQuotes(voice)
                                              + "; English voices installed: " + voiceNames(listVoicesLocked()) + ".");
}

// The text as SSML for espeak-ng: markup characters escaped, marks put in; `origin[i]` is the
// byte of `text` that byte i of the result came from.
std::string toSsml(std::string_view text, const std::vector<std::pair<std::size_t, std::string>>& marks,
                   std::vector<std::size_t>& origin)
{
    std::string out;
    origin.clear();
    auto emit = [&](std::string_view piece, std::size_t from) {
        out += piece;
        origin.insert(origin.end(), piece.size(), from);
    };
    std::size_t nextMark = 0;
    for (std::size_t i = 0; i <= text.size(); ++i) {
        for (; nextMark < marks.size() && marks[nextMark].first == i; ++nextMark)
            emit("<mark name=\"" + marks[nextMark].second + "\"/>", i);
        if (i == text.size())
            break;
        switch (text[i]) {
        case '<': emit("&lt;", i); break;
        case '>': emit("&gt;", i); break;
        case '&': emit("&amp;", i); break;
        default: emit(text.substr(i, 1), i);
        }
    }
    return out;
}

// espeak-ng counts text positions in characters, not bytes: the byte offset of character
// `position` (1-based) of UTF-8 `text`.
std::size_t byteOfCharacter(std::string_view text, int position)
{
    int characters = 0;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if ((static_cast<unsigned char>(text[i]) & 0xC0) == 0x80)
            continue;
        if (++characters == position)
            return i;
    }
    return text.size();
}

bool isStop(const std::string& phoneme)
{
    return phoneme == "P" || phoneme == "B" || phoneme == "T" || phoneme == "D" || phoneme == "K" || phoneme == "G"
           || phoneme == "CH" || phoneme == "JH";
}

// espeak-ng reports a stop at its burst and counts the silent closure before it (up to ~50 ms of
// zeros) to the phoneme before; but the lips shut for a p, b or m from the closure on, and that is
// where a recording's aligner puts the stop too. The closure's silence moves to the stop.
void includeClosures(const std::vector<float>& samples, double rate, std::vector<PhonemeTiming>& phonemes)
{
    constexpr double kLongestClosure = 0.08, kShortestMove = 0.005;
    constexpr float kSilence = 1e-3f;
    for (std::size_t i = 1; i < phonemes.size(); ++i) {
        PhonemeTiming& stop = phonemes[i];
        PhonemeTiming& before = phonemes[i - 1];
        if (!isStop(stop.phoneme))
            continue;
        const auto burst = std::size_t(std::lround(stop.start * rate));
        // Never more than half of the phoneme before, so that it keeps its own middle.
        const double earliest = std::max(stop.start - kLongestClosure, (before.start + before.end) / 2);
        const auto limit = std::size_t(std::max(0.0, std::ceil(earliest * rate)));
        std::size_t at = std::min(burst, samples.size());
        while (at > limit && std::abs(samples[at - 1]) < kSilence)
            --at;
        const double closure = double(at) / rate;
        if (stop.start - closure >= kShortestMove)
            before.end = stop.start = closure;
    }
}

} // namespace

Result<void> VoiceSettings::validate() const
{
    if (voice.empty())
        return makeError(ErrorCode::InvalidArgument, "voice: name a voice (e.g. \"en-us\").");
    if (wordsPerMinute < kMinWordsPerMinute || wordsPerMinute > kMaxWordsPerMinute)
        return makeError(ErrorCode::InvalidArgument, "rate: " + std::to_string(wordsPerMinute)
                                                         + " words a minute is outside espeak-ng's 80 … 450.");
    if (pitch < 0 || pitch > 100)
        return makeError(ErrorCode::InvalidArgument, "pitch: " + std::to_string(pitch) + " is outside 0 … 100.");
    if (volume < 0 || volume > 200)
        return makeError(ErrorCode::InvalidArgument, "volume: " + std::to_string(volume) + " is outside 0 … 200.");
    return {};
}

namespace {

// espeak-ng's transcription of `text` (its voice selected, its lock held): one token of phoneme
// mnemonics per word it says, stress marks included ("DI2; 'oUld m'an s'at 0nD@ b'EntS" — "on the"
// said as one word, as its word events have it).
std::vector<std::string> transcribedWords(const std::string& text, int phonemeMode)
{
    std::vector<std::string> words;
    const void* cursor = text.c_str();
    while (cursor) {
        const char* clause = espeak_TextToPhonemes(&cursor, espeakCHARS_UTF8, phonemeMode);
        if (!clause)
            break;
        std::string_view rest(clause);
        while (!rest.empty()) {
            const std::size_t space = rest.find(' ');
            if (space != 0)
                words.emplace_back(rest.substr(0, space));
            rest = space == std::string_view::npos ? std::string_view{} : rest.substr(space + 1);
        }
    }
    return words;
}

// The word events carry no stress; the transcription of the whole text does (`transcribed`): when
// it has as many words as the events, a word with a primary stress mark (') is stressed.
void markStressedWords(const std::vector<std::string>& transcribed, std::vector<WordTiming>& words)
{
    if (transcribed.size() != words.size())
        return;
    for (std::size_t w = 0; w < words.size(); ++w)
        words[w].stressed = transcribed[w].find('\'') != std::string::npos;
}

} // namespace

Result<std::vector<VoiceInfo>> listVoices()
{
    std::lock_guard lock(espeakMutex());
    if (auto ready = ensureInitialised(); !ready)
        return ready.error();
    return listVoicesLocked();
}

Result<Utterance> speak(std::string_view text, const VoiceSettings& settings,
                        const std::vector<std::pair<std::size_t, std::string>>& marks, std::stop_token stop)
{
    if (auto valid = settings.validate(); !valid)
        return valid.error();
    for (const auto& [offset, name] : marks)
        if (offset > text.size() || name.find_first_of("\"<>&") != std::string::npos)
            return makeError(ErrorCode::InvalidArgument, "The speech mark " + inQuotes(name) + " is not in the text.");
    std::vector<std::size_t> origin;
    const std::string ssml = toSsml(text, marks, origin);

    std::lock_guard lock(espeakMutex());
    if (auto ready = ensureInitialised(); !ready)
        return ready.error();
    if (auto selected = selectVoice(settings.voice); !selected)
        return selected.error();
    espeak_SetParameter(espeakRATE, settings.wordsPerMinute, 0);
    espeak_SetParameter(espeakPITCH, settings.pitch, 0);
    espeak_SetParameter(espeakVOLUME, settings.volume, 0);

    // Transcribed first: espeak-ng's state after a transcription moves the next synthesis by a few
    // samples, so each synthesis follows its own transcription and repeats the same.
    const std::vector<std::string> transcribed = transcribedWords(std::string(text), 0);
    Collector collector;
    collector.stop = &stop;
    const espeak_ERROR status = espeak_Synth(ssml.c_str(), ssml.size() + 1, 0, POS_CHARACTER, 0,
                                             espeakCHARS_UTF8 | espeakSSML, nullptr, &collector);
    espeak_Synchronize();
    if (stop.stop_requested())
        return cancelledError("Speaking");
    if (status != EE_OK)
        return makeError(ErrorCode::Internal, "espeak-ng could not speak the text.",
                         "espeak_Synth returned " + std::to_string(int(status)));

    Utterance utterance;
    utterance.samples = std::move(collector.samples);
    const double rate = utterance.rate;
    const double duration = utterance.duration();
    SpeechTiming& timing = utterance.timing;
    timing.duration = duration;
    auto sourceByte = [&](int position) {
        const std::size_t byte = byteOfCharacter(ssml, position);
        return byte < origin.size() ? origin[byte] : text.size();
    };
    for (const Collector::Event& e : collector.events) {
        const double time = std::clamp(e.sample / rate, 0.0, duration);
        switch (e.type) {
        case espeakEVENT_WORD: {
            if (e.length <= 0)
                break; // the clause's closing pause reports an empty word
            WordTiming word;
            word.textBegin = sourceByte(e.textPosition);
            word.textEnd = std::max(word.textBegin, sourceByte(e.textPosition + e.length - 1) + 1);
            word.textEnd = std::min(word.textEnd, text.size());
            word.text = std::string(text.substr(word.textBegin, word.textEnd - word.textBegin));
            word.start = word.end = time;
            timing.words.push_back(std::move(word));
            break;
        }
        case espeakEVENT_PHONEME:
            for (std::string& phoneme : arpabetFromEspeak(e.name)) {
                const bool pause = isPause(phoneme);
                timing.phonemes.push_back({std::move(phoneme), time, time, pause ? -1 : int(timing.words.size()) - 1});
            }
            break;
        case espeakEVENT_MARK:
            utterance.marks.push_back({e.name, time});
            break;
        default:
            break;
        }
    }
    // A phoneme lasts until the next one starts; one mnemonic made of two (AH L) shares its time.
    auto& phonemes = timing.phonemes;
    for (std::size_t i = 0; i < phonemes.size();) {
        std::size_t j = i + 1;
        while (j < phonemes.size() && phonemes[j].start == phonemes[i].start)
            ++j;
        const double end = j < phonemes.size() ? phonemes[j].start : duration;
        for (std::size_t k = i; k < j; ++k) {
            phonemes[k].start = phonemes[i].start + (end - phonemes[i].start) * double(k - i) / double(j - i);
            phonemes[k].end = phonemes[i].start + (end - phonemes[i].start) * double(k - i + 1) / double(j - i);
        }
        i = j;
    }
    if (!phonemes.empty() && phonemes.front().start > 0)
        phonemes.insert(phonemes.begin(), {"SIL", 0.0, phonemes.front().start, -1});
    includeClosures(utterance.samples, rate, phonemes);
    timing.fitWordsToPhonemes();
    markStressedWords(transcribed, timing.words);
    return utterance;
}

Result<std::vector<std::string>> phonemesOf(std::string_view word, const std::string& voice)
{
    std::lock_guard lock(espeakMutex());
    if (auto ready = ensureInitialised(); !ready)
        return ready.error();
    // Selecting a voice reads every voice file: a grammar's thousands of words are transcribed in
    // the voice already selected.
    if (selectedVoice() != voice)
        if (auto selected = selectVoice(voice); !selected)
            return selected.error();
    std::vector<std::string> out;
    // With a separator (a space, bits 8–15) espeak-ng spaces the phonemes rather than the words.
    for (std::string_view mnemonic : transcribedWords(std::string(word), int(' ') << 8)) {
        // Stress marks lead a syllable's first phoneme: take them off.
        while (!mnemonic.empty() && (mnemonic.front() == '\'' || mnemonic.front() == ','))
            mnemonic.remove_prefix(1);
        for (std::string& p : arpabetFromEspeak(mnemonic))
            if (!isPause(p))
                out.push_back(std::move(p));
    }
    return out;
}

} // namespace thespis::core::speech
