// Speech recognition against a grammar (core/speech/grammar_recogniser.h) on pocketsphinx's
// own recordings and on espeak-ng's speech, with rejection of what the grammar does not cover.
#include <gtest/gtest.h>

#include <fstream>
#include <iostream>
#include <sstream>

#include "dialogue/listening_grammar.h"
#include "runtime/sound.h"
#include "speech/espeak_voice.h"
#include "speech/grammar_recogniser.h"
#include "speech/resample.h"
#include "listening_source.h"
#include "test_support.h"
#include "util/file_io.h"
#include "util/text.h"

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

// What a small bot answers: greetings, questions with wildcards and a set, a number, and a name
// CMUdict does not have ("zorblax").
thespis::core::dialogue::GrammarSource botSource()
{
    using Item = thespis::core::dialogue::PatternItem;
    const auto said = [](std::string_view text) {
        std::vector<Item> items;
        std::istringstream in{std::string(text)};
        for (std::string token; in >> token;) {
            if (token == "*")
                items.push_back({Item::Kind::OneOrMore, "", ""});
            else if (token == "<colour>")
                items.push_back({Item::Kind::SetOf, "", "colour"});
            else
                items.push_back({Item::Kind::Word, token, ""});
        }
        return items;
    };
    thespis::core::dialogue::GrammarSource source;
    for (const char* pattern : {"hello", "good morning", "how are you", "what is your name", "who made you",
                                "what can you do", "tell me a story", "where do you live", "do you like <colour>",
                                "my favourite colour is <colour>", "what is *", "tell me about *", "i like *",
                                "can you dance", "goodbye", "thank you very much", "what time is it",
                                "are you a robot", "I am 42 years old", "call zorblax now"})
        source.patterns.push_back(said(pattern));
    source.sets["colour"] = {{"red"}, {"green"}, {"blue"}, {"light", "blue"}};
    source.vocabulary = {"music", "football", "the", "weather", "paris", "chocolate", "dogs", "history"};
    return source;
}

// A JSGF grammar's text or a word graph.
template <typename Grammar>
speech::GrammarRecogniser openRecogniser(const Grammar& grammar, const speech::RecogniserOptions& options = {})
{
    auto recogniser = speech::GrammarRecogniser::open(grammar, options);
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

TEST(GrammarRecogniser, StreamedBlocksAreHeardAsTheWholeIs)
{
    speech::GrammarRecogniser recogniser = openRecogniser(textOf(pocketsphinxData("goforward.gram")));
    const std::vector<std::int16_t> samples = goforwardSamples();
    ASSERT_TRUE(recogniser.start());
    for (std::size_t at = 0; at < samples.size(); at += 1600) // 0.1 s blocks, as a microphone gives them
        ASSERT_TRUE(recogniser.feed(std::span(samples).subspan(at, std::min<std::size_t>(1600, samples.size() - at))));
    auto heard = recogniser.finish();
    ASSERT_TRUE(heard) << describe(heard.error());
    EXPECT_EQ(heard->text, "go forward ten meters");
    EXPECT_TRUE(heard->understood()) << heard->confidence;
    std::cout << "goforward streamed: confidence " << heard->confidence << "\n";
    auto early = recogniser.feed(samples);
    ASSERT_FALSE(early);
    EXPECT_EQ(early.error().code, ErrorCode::InvalidArgument);
}

TEST(GrammarRecogniser, EspeakSpeechOfADialoguesGrammarIsRecognised)
{
    const auto source = botSource();
    auto grammar = thespis::core::dialogue::makeListeningGrammar(source);
    ASSERT_TRUE(grammar) << describe(grammar.error());
    speech::GrammarRecogniser recogniser = openRecogniser(grammar->graph);
    // Two voices other than one accent: American and British English, at their own rates.
    const std::vector<speech::VoiceSettings> voices = {{"en-us", 160}, {"gmw/en", 150}};
    const std::vector<std::string> wildcardWords = {"music", "the weather", "paris", "chocolate"};
    int sentences = 0, exact = 0;
    double confidences = 0;
    for (const auto& voice : voices)
        for (std::size_t p = 0; p < source.patterns.size(); ++p) {
            const std::string expected =
                thespis::core::joined(thespis::test::literalForm(source, source.patterns[p], wildcardWords[p % wildcardWords.size()]));
            auto heard = recogniser.recognise(spoken(expected, voice));
            ASSERT_TRUE(heard) << describe(heard.error());
            ++sentences;
            // The words, not the verdict: synthetic voices score below the threshold that suits
            // people (see RecogniserOptions::rejectBelow).
            const bool right = heard->text == expected;
            exact += right;
            confidences += right ? heard->confidence : 0;
            if (!right)
                std::cout << voice.voice << ": \"" << expected << "\" heard as \"" << heard->text << "\", confidence "
                          << heard->confidence << "\n";
        }
    std::cout << exact << " of " << sentences << " espeak-ng sentences recognised exactly, mean confidence "
              << confidences / std::max(1, exact) << "\n";
    EXPECT_GE(double(exact) / sentences, 0.9);
}

TEST(GrammarRecogniser, AWordMissingFromCmudictIsPronouncedByEspeakAndHeard)
{
    auto grammar = thespis::core::dialogue::makeListeningGrammar(botSource());
    ASSERT_TRUE(grammar) << describe(grammar.error());
    speech::GrammarRecogniser recogniser = openRecogniser(grammar->graph);
    ASSERT_EQ(recogniser.espeakPronounced().size(), 1u);
    EXPECT_EQ(recogniser.espeakPronounced()[0].substr(0, 9), "zorblax: ");
    std::cout << "espeak-ng's pronunciation: " << recogniser.espeakPronounced()[0] << "\n";
    for (const speech::VoiceSettings& voice : {speech::VoiceSettings{"en-us", 160}, speech::VoiceSettings{"gmw/en", 150}}) {
        auto heard = recogniser.recognise(spoken("call zorblax now", voice));
        ASSERT_TRUE(heard) << describe(heard.error());
        EXPECT_EQ(heard->text, "call zorblax now") << voice.voice;
        std::cout << voice.voice << ": \"call zorblax now\", confidence " << heard->confidence << "\n";
    }
}

TEST(GrammarRecogniser, RejectsSentencesTheDialogueCannotAnswer)
{
    auto grammar = thespis::core::dialogue::makeListeningGrammar(botSource());
    ASSERT_TRUE(grammar) << describe(grammar.error());
    speech::GrammarRecogniser recogniser = openRecogniser(grammar->graph);
    int rejected = 0, sentences = 0;
    for (const char* unrelated : {"the quick brown fox jumps over the lazy dog",
                                  "please submit your expense reports before friday",
                                  "seventeen submarines surfaced near the harbour"})
        for (const speech::VoiceSettings& voice : {speech::VoiceSettings{"en-us", 160}, speech::VoiceSettings{"gmw/en", 150}}) {
            auto heard = recogniser.recognise(spoken(unrelated, voice));
            ASSERT_TRUE(heard) << describe(heard.error());
            ++sentences;
            rejected += !heard->understood();
            std::cout << voice.voice << ": \"" << unrelated << "\" heard as \"" << heard->text << "\", confidence "
                      << heard->confidence << (heard->understood() ? " (understood!)" : " (not understood)") << "\n";
        }
    EXPECT_EQ(rejected, sentences);
}

TEST(GrammarRecogniser, ErrorsNameWhatIsWrong)
{
    speech::RecogniserOptions noModel;
    noModel.model.acousticModel = "/nonexistent/en-us";
    auto missing = speech::GrammarRecogniser::open(textOf(pocketsphinxData("goforward.gram")), noModel);
    ASSERT_FALSE(missing);
    EXPECT_EQ(missing.error().code, ErrorCode::FileNotFound);
    EXPECT_NE(missing.error().message.find("pocketsphinx-en-us"), std::string::npos) << missing.error().message;

    auto broken = speech::GrammarRecogniser::open("#JSGF V1.0;\ngrammar g;\npublic <a> = (hello;\n");
    ASSERT_FALSE(broken);
    EXPECT_EQ(broken.error().code, ErrorCode::CorruptData);
    EXPECT_NE(broken.error().message.find("line 3, column 20"), std::string::npos) << broken.error().message;

    auto importing = speech::GrammarRecogniser::open(textOf(pocketsphinxData("grammars/test.gram")));
    ASSERT_FALSE(importing);
    EXPECT_EQ(importing.error().code, ErrorCode::InvalidArgument);

    auto noPublic = speech::GrammarRecogniser::open("#JSGF V1.0;\ngrammar g;\n<a> = hello;\n");
    ASSERT_FALSE(noPublic);
    EXPECT_NE(noPublic.error().message.find("no public rule"), std::string::npos) << noPublic.error().message;

    speech::WordGraph graph{.states = 2, .start = 0, .end = 1, .words = {"hello"}, .arcs = {{0, 1, 0}}};
    ASSERT_TRUE(speech::GrammarRecogniser::open(graph));
    graph.arcs.push_back({1, 2, 0});
    auto offTheGraph = speech::GrammarRecogniser::open(graph);
    ASSERT_FALSE(offTheGraph);
    EXPECT_EQ(offTheGraph.error().code, ErrorCode::InvalidArgument);
    EXPECT_NE(offTheGraph.error().message.find("arc 2"), std::string::npos) << offTheGraph.error().message;
    graph.arcs.back() = {1, 0, 1};
    EXPECT_FALSE(speech::GrammarRecogniser::open(graph)) << "a word the graph does not have";
}
