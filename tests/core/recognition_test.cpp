// Speech recognition against a grammar (core/speech/grammar_recogniser.h) on pocketsphinx's
// own recordings and on espeak-ng's speech, with rejection of what the grammar does not cover.
#include <gtest/gtest.h>

#include <fstream>
#include <iostream>
#include <sstream>

#include "runtime/sound.h"
#include "speech/espeak_voice.h"
#include "speech/grammar_recogniser.h"
#include "speech/resample.h"
#include "test_support.h"
#include "util/file_io.h"

namespace speech = thespis::core::speech;
using thespis::core::ErrorCode;
using thespis::test::sharedData;

namespace {

std::filesystem::path pocketsphinxData(const std::string& relative)
{
    return sharedData("speech/pocketsphinx/" + relative);
}

std::string textOf(const std::filesystem::path& path)
{
    auto text = thespis::core::readTextFile(path);
    EXPECT_TRUE(text) << path;
    return text ? *text : std::string{};
}

std::vector<std::int16_t> goforwardSamples()
{
    const std::string bytes = textOf(pocketsphinxData("goforward.raw"));
    std::vector<std::int16_t> samples(bytes.size() / 2);
    for (std::size_t i = 0; i < samples.size(); ++i) // little-endian (SOURCES.md §8)
        samples[i] = std::int16_t(std::uint16_t(static_cast<unsigned char>(bytes[2 * i]))
                                  | std::uint16_t(static_cast<unsigned char>(bytes[2 * i + 1])) << 8);
    return samples;
}

std::vector<std::int16_t> wavSamples(const std::filesystem::path& path)
{
    auto clip = thespis::core::runtime::loadSound(path);
    EXPECT_TRUE(clip) << path;
    if (!clip)
        return {};
    EXPECT_EQ((*clip)->rate, speech::kSphinxRate);
    std::vector<std::int16_t> samples((*clip)->samples.size());
    for (std::size_t i = 0; i < samples.size(); ++i) // the recording's own 16-bit values, exactly
        samples[i] = std::int16_t(std::lround((*clip)->samples[i] * 32768.0f));
    return samples;
}

// "<s> ten of clubs  </s> (001)" for each recording: 001 → "ten of clubs".
std::map<std::string, std::string> cardsTranscripts()
{
    std::map<std::string, std::string> transcripts;
    std::istringstream in(textOf(pocketsphinxData("cards/cards.transcription")));
    for (std::string line; std::getline(in, line);) {
        const std::size_t open = line.rfind('('), close = line.rfind(')');
        const std::string words = line.substr(3, line.find("</s>") - 3);
        std::istringstream split(words);
        std::string text;
        for (std::string word; split >> word;)
            text += (text.empty() ? "" : " ") + word;
        transcripts[line.substr(open + 1, close - open - 1)] = text;
    }
    return transcripts;
}

speech::GrammarRecogniser openRecogniser(const std::string& jsgf, const speech::RecogniserOptions& options = {})
{
    auto recogniser = speech::GrammarRecogniser::open(jsgf, options);
    if (!recogniser) {
        ADD_FAILURE() << describe(recogniser.error());
        std::abort();
    }
    return std::move(*recogniser);
}

std::vector<std::int16_t> spoken(const std::string& text, const speech::VoiceSettings& voice)
{
    auto utterance = speech::speak(text, voice);
    EXPECT_TRUE(utterance) << describe(utterance.error());
    if (!utterance)
        return {};
    return speech::dithered16(speech::resampled(utterance->samples, utterance->rate, speech::kSphinxRate));
}

} // namespace

TEST(GrammarRecogniser, RecognisesGoforwardExactly)
{
    speech::GrammarRecogniser recogniser = openRecogniser(textOf(pocketsphinxData("goforward.gram")));
    auto heard = recogniser.recognise(goforwardSamples());
    ASSERT_TRUE(heard) << describe(heard.error());
    std::string expected = textOf(pocketsphinxData("goforward.txt"));
    while (!expected.empty() && std::isspace(static_cast<unsigned char>(expected.back())))
        expected.pop_back();
    EXPECT_EQ(heard->text, expected);
    EXPECT_TRUE(heard->understood()) << heard->confidence;
    std::cout << "goforward: confidence " << heard->confidence << " over " << heard->frames << " frames\n";
    ASSERT_EQ(heard->words.size(), 4u);
    EXPECT_LT(heard->words[0].start, heard->words[1].start);
    EXPECT_LE(heard->words[3].end, 2.79 + 0.01);
}

TEST(GrammarRecogniser, RecognisesEveryCardsRecordingExactly)
{
    speech::GrammarRecogniser recogniser = openRecogniser(textOf(pocketsphinxData("cards/cards.gram")));
    for (const auto& [id, transcript] : cardsTranscripts()) {
        auto heard = recogniser.recognise(wavSamples(pocketsphinxData("cards/" + id + ".wav")));
        ASSERT_TRUE(heard) << describe(heard.error());
        EXPECT_EQ(heard->text, transcript) << id;
        EXPECT_TRUE(heard->understood()) << id << ": " << heard->confidence;
        std::cout << "cards " << id << ": " << heard->text << ", confidence " << heard->confidence << "\n";
    }
}

TEST(GrammarRecogniser, RejectsCardsHeardWithGoforwardsGrammar)
{
    speech::GrammarRecogniser recogniser = openRecogniser(textOf(pocketsphinxData("goforward.gram")));
    for (const auto& [id, transcript] : cardsTranscripts()) {
        auto heard = recogniser.recognise(wavSamples(pocketsphinxData("cards/" + id + ".wav")));
        ASSERT_TRUE(heard) << describe(heard.error());
        EXPECT_FALSE(heard->understood()) << id << ": " << heard->text << " " << heard->confidence;
        std::cout << "cards " << id << " as goforward: " << heard->text << ", confidence " << heard->confidence << "\n";
    }
}
