// espeak-ng speech (core/speech/espeak_voice.h): the audio and its phoneme timing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "speech/espeak_voice.h"
#include "speech/phonemes.h"

namespace speech = thespis::core::speech;

namespace {

speech::Utterance spoken(std::string_view text, speech::VoiceSettings settings = {})
{
    auto utterance = speech::speak(text, settings);
    EXPECT_TRUE(utterance.ok()) << (utterance.ok() ? "" : utterance.error().message);
    return utterance.ok() ? std::move(utterance).value() : speech::Utterance{};
}

// Root mean square of the samples in [from, to) seconds.
double loudness(const speech::Utterance& u, double from, double to)
{
    const std::size_t a = std::size_t(std::max(0.0, from) * u.rate), b = std::min(u.samples.size(), std::size_t(to * u.rate));
    double sum = 0;
    for (std::size_t i = a; i < b; ++i)
        sum += double(u.samples[i]) * u.samples[i];
    return b > a ? std::sqrt(sum / double(b - a)) : 0.0;
}

} // namespace

TEST(SpeechVoice, PhonemesTileTheAudioAndEndWithIt)
{
    const speech::Utterance u = spoken("Pop the bubble, Antigone.");
    ASSERT_GT(u.samples.size(), 22050u / 2);
    EXPECT_EQ(u.rate, 22050);
    const auto& phonemes = u.timing.phonemes;
    ASSERT_GT(phonemes.size(), 10u);
    EXPECT_EQ(phonemes.front().start, 0.0);
    for (std::size_t i = 1; i < phonemes.size(); ++i) {
        EXPECT_DOUBLE_EQ(phonemes[i].start, phonemes[i - 1].end) << i;
        EXPECT_LE(phonemes[i].start, phonemes[i].end) << i;
        EXPECT_TRUE(speech::isPhoneme(phonemes[i].phoneme)) << phonemes[i].phoneme;
    }
    EXPECT_NEAR(phonemes.back().end, u.duration(), 0.020);
}

TEST(SpeechVoice, WordsAreTheTextsWordsInOrder)
{
    const std::string text = "Are you really sure about that?";
    const speech::Utterance u = spoken(text);
    std::vector<std::string> words;
    for (const auto& w : u.timing.words)
        words.push_back(w.text);
    EXPECT_EQ(words, (std::vector<std::string>{"Are", "you", "really", "sure", "about", "that"}));
    for (std::size_t i = 0; i < u.timing.words.size(); ++i) {
        const auto& w = u.timing.words[i];
        EXPECT_EQ(text.substr(w.textBegin, w.textEnd - w.textBegin), w.text);
        EXPECT_LT(w.start, w.end);
        if (i > 0) {
            EXPECT_GE(w.start, u.timing.words[i - 1].end - 1e-9);
        }
    }
    // "really": R IY L IY (or IH) — the phonemes of a word are its own.
    std::vector<std::string> really;
    for (const auto& p : u.timing.phonemes)
        if (p.word == 2)
            really.push_back(p.phoneme);
    ASSERT_FALSE(really.empty());
    EXPECT_EQ(really.front(), "R");
}

TEST(SpeechVoice, PausesAreQuietAndWordsAreNot)
{
    const speech::Utterance u = spoken("Hello. Goodbye.");
    double pauseLoudness = 0, speechLoudness = 0;
    for (const auto& p : u.timing.phonemes) {
        if (p.end - p.start < 0.03)
            continue;
        const double l = loudness(u, p.start + 0.01, p.end - 0.01);
        if (speech::isPause(p.phoneme))
            pauseLoudness = std::max(pauseLoudness, l);
        else if (p.phoneme == "OW" || p.phoneme == "AY")
            speechLoudness = std::max(speechLoudness, l);
    }
    EXPECT_GT(speechLoudness, 0.02);
    EXPECT_LT(pauseLoudness, speechLoudness / 10);
}

TEST(SpeechVoice, MarksComeWhereTheyAreInTheText)
{
    const std::string text = "Are you really sure about that?";
    const std::size_t at = text.find("really");
    auto u = speech::speak(text, {}, {{at, "g1"}, {text.size(), "end"}});
    ASSERT_TRUE(u.ok()) << u.error().message;
    ASSERT_EQ(u->marks.size(), 2u);
    EXPECT_EQ(u->marks[0].name, "g1");
    EXPECT_NEAR(u->marks[0].time, u->timing.words[2].start, 0.03);
    EXPECT_EQ(u->marks[1].name, "end");
}

TEST(SpeechVoice, MarkupCharactersAreSpokenAsText)
{
    const speech::Utterance u = spoken("1 < 2 & 3 > 2");
    EXPECT_GE(u.timing.words.size(), 5u);
}

TEST(SpeechVoice, RateChangesTheLength)
{
    const std::string text = "The quick brown fox jumps over the lazy dog.";
    speech::VoiceSettings slow, fast;
    slow.wordsPerMinute = 120;
    fast.wordsPerMinute = 300;
    EXPECT_GT(spoken(text, slow).duration(), 1.8 * spoken(text, fast).duration());
}

TEST(SpeechVoice, BadSettingsAndVoicesAreNamed)
{
    speech::VoiceSettings settings;
    settings.wordsPerMinute = 600;
    auto tooFast = speech::speak("Hello", settings);
    ASSERT_FALSE(tooFast.ok());
    EXPECT_NE(tooFast.error().message.find("rate"), std::string::npos);
    settings = {};
    settings.voice = "vulcan";
    auto unknown = speech::speak("Hello", settings);
    ASSERT_FALSE(unknown.ok());
    EXPECT_NE(unknown.error().message.find("vulcan"), std::string::npos);
    EXPECT_NE(unknown.error().message.find("en-us"), std::string::npos);
}

TEST(SpeechVoice, VoicesAreListed)
{
    auto voices = speech::listVoices();
    ASSERT_TRUE(voices.ok());
    EXPECT_GT(voices->size(), 50u);
    EXPECT_TRUE(std::any_of(voices->begin(), voices->end(), [](const auto& v) { return v.language == "en-us"; }));
}

TEST(SpeechVoice, CancelStopsSpeaking)
{
    std::stop_source stop;
    stop.request_stop();
    auto u = speech::speak("This will not be heard.", {}, {}, stop.get_token());
    ASSERT_FALSE(u.ok());
    EXPECT_EQ(u.error().code, thespis::core::ErrorCode::Cancelled);
}

TEST(SpeechVoice, PhonemesOfAWord)
{
    auto p = speech::phonemesOf("thespis");
    ASSERT_TRUE(p.ok());
    ASSERT_GE(p->size(), 5u);
    EXPECT_EQ(p->front(), "TH");
    auto hello = speech::phonemesOf("hello");
    ASSERT_TRUE(hello.ok());
    EXPECT_EQ(hello->front(), "HH");
    EXPECT_EQ(hello->back(), "OW");
}

TEST(SpeechPhonemes, EspeakMnemonicsMapToArpabet)
{
    EXPECT_EQ(speech::arpabetFromEspeak("tS"), std::vector<std::string>{"CH"});
    EXPECT_EQ(speech::arpabetFromEspeak("@L"), (std::vector<std::string>{"AH", "L"}));
    EXPECT_EQ(speech::arpabetFromEspeak("_:"), std::vector<std::string>{"SIL"});
    EXPECT_TRUE(speech::arpabetFromEspeak(";").empty());
    EXPECT_EQ(speech::normalizedPhoneme("ah0"), "AH");
    EXPECT_EQ(speech::arpabetPhonemes().size(), 39u);
}

// espeak-ng reports a stop at its burst; the silent closure before the burst belongs to the stop
// (the lips are shut for a p from there), not to the vowel before it.
TEST(SpeechVoice, AStopBeginsWithItsClosure)
{
    const speech::Utterance u = spoken("Keep a cap, Pete, pick a top pot.");
    int stops = 0;
    const auto& phonemes = u.timing.phonemes;
    for (std::size_t i = 1; i < phonemes.size(); ++i) {
        const auto& p = phonemes[i];
        const std::string& before = phonemes[i - 1].phoneme;
        const bool afterVowel = before == "IY" || before == "AE" || before == "AH" || before == "IH" || before == "AA";
        if ((p.phoneme != "P" && p.phoneme != "T" && p.phoneme != "K") || !afterVowel)
            continue;
        EXPECT_LT(loudness(u, p.start, p.start + 0.015), 0.005) << p.phoneme << " at " << p.start << " starts quiet";
        EXPECT_GT(loudness(u, p.start - 0.015, p.start), 0.005) << "the " << before << " before it sounds to its end";
        ++stops;
    }
    EXPECT_GE(stops, 5);
}
