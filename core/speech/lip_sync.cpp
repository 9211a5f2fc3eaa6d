#include "speech/lip_sync.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <optional>
#include <set>

#include "runtime/sound.h"
#include "speech/boundary_refinement.h"
#include "speech/espeak_voice.h"
#include "speech/phonemes.h"
#include "speech/resample.h"
#include "speech/sphinx_decoder.h"
#include "util/text.h"

namespace thespis::core::speech {
namespace {

// espeak-ng's voice for the words CMUdict lacks: the accent the en-us model knows.
const std::string kEspeakVoice = "en-us";
// A frame's features come from a 25.6 ms window starting at its 10 ms step: the boundary
// between frames n − 1 and n lies half a window minus half a step after n·10 ms.
constexpr double kBoundaryOffset = (kSphinxWindow - kSphinxFrame) / 2;
// Pauses at least this long split the phonemes pass into stretches.
constexpr int kStretchPauseFrames = 30;
// Between words may come a pause: the model's noise phone, which takes silence, breath and
// clicks. Its silence phone would be the natural choice, but as a grammar word it sometimes
// leaves no path to the grammar's end in this version ("my [SIL] mother made me a warm woollen
// jumper for the winter"), as do the pauses pocketsphinx adds by itself.
const std::string kPauseWord = "pause";
const std::string kPause = kPauseWord + "+";
// Fillers a transcript leaves out ("uh", "um"), only between pauses: elsewhere they take the
// schwas of the words around them.
const std::map<std::string, std::vector<std::string>> kFillers = {{"uh", {"AH"}}, {"um", {"AH", "M"}}};
const std::string kPauseOrFiller = kPause + " | " + kPause + " (uh | um) " + kPause;

struct TranscriptWord {
    std::string text;        // as written
    std::size_t begin = 0, end = 0;
    std::string key;         // as CMUdict spells words: ASCII lower case, ’ as '
    std::vector<std::vector<std::string>> pronunciations;
};

// A word or filler as the words pass placed it.
struct Placed {
    int word = -1;                   // index into the transcript's words; −1: a filler
    std::vector<std::string> phones; // the pronunciation chosen
    int firstFrame = 0, lastFrame = 0;
};

// One phoneme's frames [first, end).
struct PlacedPhone {
    std::string phoneme;
    int word = -1;
    int firstFrame = 0, endFrame = 0;
};

// The length in bytes of the UTF-8 sequence starting with `lead` (1 for a stray byte).
std::size_t sequenceLength(unsigned char lead)
{
    return lead >= 0xF0 ? 4 : lead >= 0xE0 ? 3 : lead >= 0xC0 ? 2 : 1;
}

// Letters and digits make words, ASCII or not; Latin-1's signs (U+0080–U+00BF) and general
// punctuation (U+2000–U+206F: dashes, quotes, ellipsis) do not.
bool isWordCharacter(std::string_view character)
{
    const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(character[i]); };
    if (character.size() == 1)
        return std::isalnum(byte(0));
    if (character.size() == 2 && byte(0) == 0xC2)
        return false;
    return !(character.size() == 3 && byte(0) == 0xE2 && (byte(1) == 0x80 || byte(1) == 0x81));
}

bool isApostrophe(std::string_view character)
{
    return character == "'" || character == "\u2019";
}

std::vector<TranscriptWord> transcriptWords(std::string_view text)
{
    std::vector<TranscriptWord> words;
    std::size_t at = 0, start = std::string_view::npos;
    auto characterAt = [&](std::size_t i) {
        return text.substr(i, std::min(sequenceLength(static_cast<unsigned char>(text[i])), text.size() - i));
    };
    auto close = [&](std::size_t end) {
        if (start == std::string_view::npos)
            return;
        TranscriptWord word;
        word.begin = start;
        word.end = end;
        word.text = std::string(text.substr(start, end - start));
        for (std::size_t i = 0; i < word.text.size();) {
            const std::string_view c = characterAt(start + i);
            word.key += isApostrophe(c) ? "'" : lowercase(c);
            i += c.size();
        }
        words.push_back(std::move(word));
        start = std::string_view::npos;
    };
    while (at < text.size()) {
        const std::string_view c = characterAt(at);
        if (isWordCharacter(c)) {
            if (start == std::string_view::npos)
                start = at;
        } else if (!(isApostrophe(c) && start != std::string_view::npos && at + c.size() < text.size()
                     && isWordCharacter(characterAt(at + c.size())))) {
            close(at); // an apostrophe stays only between letters ("don't", not 'quoted')
        }
        at += c.size();
    }
    close(text.size());
    return words;
}

// Each word's pronunciations: CMUdict's, or espeak-ng's (with a warning); none when neither
// has one (a warning too: the word is left out of the alignment).
Result<void> pronounce(std::vector<TranscriptWord>& words, const SphinxModel& model, std::vector<std::string>& warnings)
{
    std::set<std::string, std::less<>> keys;
    for (const TranscriptWord& word : words)
        keys.insert(word.key);
    auto dictionary = readPronunciations(model.dictionary, keys);
    if (!dictionary)
        return dictionary.error();
    std::set<std::string> warned;
    for (TranscriptWord& word : words) {
        if (const auto found = dictionary->find(word.key); found != dictionary->end()) {
            word.pronunciations = found->second;
            continue;
        }
        auto phones = phonemesOf(word.text, kEspeakVoice);
        if (phones && !phones->empty())
            word.pronunciations.push_back(*phones);
        if (!warned.insert(word.key).second)
            continue;
        if (word.pronunciations.empty())
            warnings.push_back(inQuotes(word.text) + " is in no pronunciation dictionary, and espeak-ng cannot say it: "
                               "it is left out.");
        else
            warnings.push_back(inQuotes(word.text) + " is not in pocketsphinx's dictionary: espeak-ng's pronunciation "
                               + joined(word.pronunciations.front()) + " is used.");
    }
    return {};
}

// A phoneme as a word of the phonemes pass: "ph_aa".
std::string phoneWord(const std::string& phone)
{
    return "ph_" + lowercase(phone);
}

// The transcript's words are named by their index ("w12", its second pronunciation "w12(2)"),
// so that any spelling makes a grammar token.
std::string wordName(std::size_t word, std::size_t pronunciation = 0)
{
    std::string name = "w";
    name += std::to_string(word);
    if (pronunciation > 0) {
        name += '(';
        name += std::to_string(pronunciation + 1);
        name += ')';
    }
    return name;
}

// Registers the words, the fillers, the pause, and the phonemes as words for the phonemes pass.
Result<void> addWords(SphinxDecoder& decoder, const std::vector<TranscriptWord>& words)
{
    for (std::size_t i = 0; i < words.size(); ++i)
        for (std::size_t p = 0; p < words[i].pronunciations.size(); ++p) {
            if (auto added = decoder.addWord(wordName(i, p), joined(words[i].pronunciations[p])); !added)
                return added.error();
        }
    for (const auto& [filler, phones] : kFillers)
        if (auto added = decoder.addWord(filler, joined(phones)); !added)
            return added.error();
    for (std::string_view phone : arpabetPhonemes())
        if (auto added = decoder.addWord(phoneWord(std::string(phone)), std::string(phone)); !added)
            return added.error();
    return decoder.addWord(kPauseWord, "+NSN+");
}

// wordName's inverse: "w12(3)" → word 12, pronunciation 2; nothing for other words.
std::optional<std::pair<int, int>> parseWordName(std::string_view name)
{
    if (name.size() < 2 || name[0] != 'w' || !std::isdigit(static_cast<unsigned char>(name[1])))
        return std::nullopt;
    const std::size_t paren = name.find('(');
    const int word = std::stoi(std::string(name.substr(1, paren - 1)));
    const int alternative = paren == std::string_view::npos ? 0 : std::stoi(std::string(name.substr(paren + 1))) - 1;
    return std::pair{word, alternative};
}

// The words pass: where each pronounced word and each filler is, or nothing when the grammar
// cannot be followed to its end.
Result<std::optional<std::vector<Placed>>> alignWords(SphinxDecoder& decoder, const std::vector<TranscriptWord>& words,
                                                      std::span<const std::int16_t> pcm, bool wideBeams)
{
    std::string grammar = "#JSGF V1.0;\ngrammar words;\n<gap> = " + kPauseOrFiller + ";\npublic <utterance> = [<gap>]";
    std::vector<int> expected;
    for (std::size_t i = 0; i < words.size(); ++i)
        if (!words[i].pronunciations.empty()) {
            grammar += ' ' + wordName(i) + " [<gap>]";
            expected.push_back(int(i));
        }
    grammar += ";\n";
    auto segments = decoder.decodeGrammar(grammar, pcm, wideBeams);
    if (!segments)
        return segments.error();
    std::vector<Placed> placed;
    std::vector<int> found;
    for (const SphinxSegment& segment : *segments) {
        Placed item{-1, {}, segment.firstFrame, segment.lastFrame};
        if (const auto filler = kFillers.find(segment.word); filler != kFillers.end()) {
            item.phones = filler->second;
        } else if (const auto word = parseWordName(segment.word)) {
            item.word = word->first;
            item.phones = words[std::size_t(word->first)].pronunciations.at(std::size_t(word->second));
            found.push_back(word->first);
        } else {
            continue; // a pause or noise
        }
        placed.push_back(std::move(item));
    }
    if (found != expected)
        return std::optional<std::vector<Placed>>{};
    return std::optional{std::move(placed)};
}

// The phonemes pass over one stretch of placed words, whose audio `pcm` starts at frame
// `frameBegin`: the phonemes' frames, or nothing when the grammar cannot be followed to its end.
Result<std::optional<std::vector<PlacedPhone>>> alignPhonemes(SphinxDecoder& decoder, std::span<const Placed> stretch,
                                                              std::span<const std::int16_t> pcm, int frameBegin,
                                                              bool wideBeams)
{
    std::string grammar = "#JSGF V1.0;\ngrammar phonemes;\n<gap> = " + kPause + ";\npublic <utterance> = [<gap>]";
    std::vector<PlacedPhone> phones;
    for (const Placed& item : stretch) {
        for (const std::string& phone : item.phones) {
            grammar += ' ';
            grammar += phoneWord(phone);
            phones.push_back({phone, item.word, 0, 0});
        }
        grammar += " [<gap>]";
    }
    grammar += ";\n";
    auto segments = decoder.decodeGrammar(grammar, pcm, wideBeams);
    if (!segments)
        return segments.error();
    std::size_t next = 0;
    for (const SphinxSegment& segment : *segments) {
        if (segment.word == kPauseWord)
            continue;
        if (next == phones.size() || segment.word != phoneWord(phones[next].phoneme))
            return std::optional<std::vector<PlacedPhone>>{};
        phones[next].firstFrame = frameBegin + segment.firstFrame;
        phones[next].endFrame = frameBegin + segment.lastFrame + 1;
        ++next;
    }
    if (next != phones.size())
        return std::optional<std::vector<PlacedPhone>>{};
    return std::optional{std::move(phones)};
}

// A stretch's words split evenly into their phonemes: when the phonemes pass failed there.
std::vector<PlacedPhone> spreadEvenly(std::span<const Placed> stretch)
{
    std::vector<PlacedPhone> phones;
    for (const Placed& item : stretch) {
        const int frames = item.lastFrame + 1 - item.firstFrame, count = int(item.phones.size());
        for (int k = 0; k < count; ++k)
            phones.push_back({item.phones[std::size_t(k)], item.word, item.firstFrame + frames * k / count,
                              item.firstFrame + frames * (k + 1) / count});
    }
    return phones;
}

// The placed phonemes in seconds, with the pauses between them as "SIL": from 0 to `duration`.
std::vector<PhonemeTiming> timedPhonemes(const std::vector<PlacedPhone>& phones, double duration)
{
    const auto time = [&](int frame) { return std::clamp(frame * kSphinxFrame + kBoundaryOffset, 0.0, duration); };
    std::vector<PhonemeTiming> timed;
    double at = 0;
    for (const PlacedPhone& phone : phones) {
        const double start = std::max(at, time(phone.firstFrame)), end = std::max(start, time(phone.endFrame));
        if (start > at)
            timed.push_back({"SIL", at, start, -1});
        timed.push_back({phone.phoneme, start, end, phone.word});
        at = end;
    }
    if (at < duration)
        timed.push_back({"SIL", at, duration, -1});
    return timed;
}

Result<std::string> recognisedText(const SphinxModel& model, std::span<const std::int16_t> pcm)
{
    auto decoder = SphinxDecoder::open(model, SphinxDecoder::Mode::Recognise);
    if (!decoder)
        return decoder.error();
    auto segments = decoder->recognise(pcm);
    if (!segments)
        return segments.error();
    std::string text;
    for (const SphinxSegment& segment : *segments) {
        if (segment.word.starts_with('<') || segment.word.starts_with('['))
            continue; // a pause or noise
        text += (text.empty() ? "" : " ") + segment.word.substr(0, segment.word.find('('));
    }
    if (text.empty())
        return makeError(ErrorCode::InvalidArgument, "No words were recognised in the recording.");
    return text;
}

std::string stretchText(const std::vector<TranscriptWord>& words, std::span<const Placed> stretch)
{
    std::string text;
    for (const Placed& item : stretch)
        if (item.word >= 0)
            text += (text.empty() ? "" : " ") + words[std::size_t(item.word)].text;
    return text;
}

} // namespace

Result<LipSyncResult> lipSync(std::span<const float> samples, int rate, std::string_view transcript, JobContext& context)
{
    if (rate <= 0 || samples.empty())
        return makeError(ErrorCode::InvalidArgument, "The recording has no sound.");
    const double duration = double(samples.size()) / rate;
    const std::vector<std::int16_t> pcm = dithered16(resampled(samples, rate, kSphinxRate));
    const SphinxModel model = SphinxModel::installed();
    const auto cancelled = [] { return cancelledError("The lip sync"); };

    LipSyncResult result;
    result.transcript = transcript;
    if (transcriptWords(transcript).empty()) {
        context.beginStage(LipSyncJob::RecognisingStage);
        auto recognised = recognisedText(model, pcm);
        if (!recognised)
            return recognised.error();
        result.transcript = std::move(*recognised);
    }
    if (context.stopRequested())
        return cancelled();

    context.beginStage(LipSyncJob::WordsStage, 1);
    std::vector<TranscriptWord> words = transcriptWords(result.transcript);
    if (auto pronounced = pronounce(words, model, result.warnings); !pronounced)
        return pronounced.error();
    auto decoder = SphinxDecoder::open(model, SphinxDecoder::Mode::Align);
    if (!decoder)
        return decoder.error();
    if (auto added = addWords(*decoder, words); !added)
        return added.error();
    std::optional<std::vector<Placed>> placed;
    for (const bool wide : {false, true}) {
        auto aligned = alignWords(*decoder, words, pcm, wide);
        if (!aligned)
            return aligned.error();
        if ((placed = std::move(*aligned)) || context.stopRequested())
            break;
    }
    if (context.stopRequested())
        return cancelled();
    if (!placed)
        return makeError(ErrorCode::InvalidArgument,
                         "The transcript could not be aligned with the recording; check that it is what is said.");
    context.setDone(1);

    // Stretches of speech between long pauses: placed items [first, end).
    std::vector<std::size_t> cuts = {0};
    for (std::size_t i = 1; i < placed->size(); ++i)
        if ((*placed)[i].firstFrame - (*placed)[i - 1].lastFrame > kStretchPauseFrames)
            cuts.push_back(i);
    cuts.push_back(placed->size());
    context.beginStage(LipSyncJob::PhonemesStage, cuts.size() - 1);
    const int frames = int(pcm.size() / (kSphinxRate * kSphinxFrame));
    std::vector<PlacedPhone> phones;
    for (std::size_t s = 0; s + 1 < cuts.size(); ++s) {
        const std::span<const Placed> stretch(placed->data() + cuts[s], cuts[s + 1] - cuts[s]);
        // From the middle of the pause before to the middle of the pause after.
        const int frameBegin = s == 0 ? 0 : ((*placed)[cuts[s] - 1].lastFrame + stretch.front().firstFrame) / 2;
        const int frameEnd = s + 2 == cuts.size() ? frames
                                                  : (stretch.back().lastFrame + (*placed)[cuts[s + 1]].firstFrame) / 2;
        const auto first = std::size_t(frameBegin * kSphinxRate * kSphinxFrame);
        const auto audio = std::span(pcm).subspan(first, std::min(pcm.size(), std::size_t(frameEnd * kSphinxRate * kSphinxFrame)) - first);
        std::optional<std::vector<PlacedPhone>> aligned;
        for (const bool wide : {false, true}) {
            auto attempt = alignPhonemes(*decoder, stretch, audio, frameBegin, wide);
            if (!attempt)
                return attempt.error();
            if ((aligned = std::move(*attempt)) || context.stopRequested())
                break;
        }
        if (context.stopRequested())
            return cancelled();
        if (!aligned) {
            aligned = spreadEvenly(stretch);
            result.warnings.push_back("The phonemes of " + inQuotes(stretchText(words, stretch))
                                      + " could not be aligned: they are spread evenly over their words.");
        }
        phones.insert(phones.end(), aligned->begin(), aligned->end());
        context.setDone(s + 1);
    }
    result.timing.duration = duration;
    result.timing.phonemes = timedPhonemes(phones, duration);
    refineBoundaries(result.timing.phonemes, pcm);
    for (const TranscriptWord& word : words)
        result.timing.words.push_back({word.text, 0, 0, word.begin, word.end});
    result.timing.fitWordsToPhonemes();
    return result;
}

std::string LipSyncJob::title() const
{
    return "The lip sync of " + audio.filename().string();
}

Result<void> LipSyncJob::validate() const
{
    if (audio.empty())
        return makeError(ErrorCode::InvalidArgument, "audio: no recording is named.");
    return {};
}

Result<void> LipSyncJob::run(JobContext& context)
{
    auto sound = runtime::loadSound(audio);
    if (!sound)
        return sound.error();
    auto synced = lipSync((*sound)->samples, (*sound)->rate, transcript, context);
    if (!synced) {
        Error error = synced.error();
        if (error.code != ErrorCode::Cancelled && error.code != ErrorCode::FileNotFound)
            error.message = audio.string() + ": " + lowerFirst(error.message);
        return error;
    }
    result = std::move(*synced);
    return {};
}

} // namespace thespis::core::speech
