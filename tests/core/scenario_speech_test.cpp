// Speech lines in the scenario (format 9, scenario.h's SpeechLine): the golden file, the upgrade
// from version 8, the reader naming what is wrong, packages carrying the audio, and the lines'
// audio mixed where they are on the timeline.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "runtime/clock.h"
#include "runtime/sound.h"
#include "scenario/package_contents.h"
#include "scenario/scenario_io.h"
#include "scenario_formats.h"
#include "test_support.h"

namespace thespis::test {
namespace {

using namespace core::scenario;
using core::ErrorCode;
using json = nlohmann::json;

std::string refused(json document)
{
    auto result = parseScenario(document.dump());
    EXPECT_FALSE(result.ok());
    if (result.ok())
        return {};
    EXPECT_EQ(result.error().code, ErrorCode::CorruptData);
    return result.error().message;
}

} // namespace

TEST(ScenarioSpeech, TheGoldenFileHasALineAndADominanceCurve)
{
    const Scenario s = goldenScenario(9);
    ASSERT_EQ(s.characters.size(), 2u);
    ASSERT_EQ(s.characters[1].speech.size(), 1u);
    const SpeechLine& line = s.characters[1].speech[0];
    EXPECT_EQ(line.name, "hello");
    EXPECT_EQ(line.start, core::TicksPerSecond);
    EXPECT_EQ(line.text, "Hello <begin_gesture id=\"g1\" anim=\"nod\"/>there<end_gesture id=\"g1\"/>.");
    EXPECT_EQ(line.voice, "en-gb");
    EXPECT_EQ(line.rate, 160);
    EXPECT_EQ(line.audio, "speech/hello.wav");
    ASSERT_EQ(line.words.size(), 2u);
    EXPECT_EQ(line.words[1].text, "there");
    ASSERT_EQ(line.phonemes.size(), 8u);
    EXPECT_EQ(line.phonemes[0].phoneme, "HH");
    const auto& smile = s.characters[1].layers[1].actions[0];
    EXPECT_EQ(smile.weight.kind(), core::anim::CurveKind::Dominance);
    EXPECT_EQ(smile.weight.envelope().alpha, 5.0);
}

TEST(ScenarioSpeech, Version8UpgradesWithoutLines)
{
    // The version 9 golden file is the version 8 one with a line and a dominance curve on
    // "Inline": taking them back gives what the upgraded version 8 file reads as.
    Scenario v9 = goldenScenario(9), v8 = goldenScenario(8);
    v9.characters[1].speech.clear();
    v9.characters[1].layers[1].actions[0].weight = v8.characters[1].layers[1].actions[0].weight;
    v8.name = v9.name;
    EXPECT_EQ(v8, v9);
}

TEST(ScenarioSpeech, TheReaderNamesWhatIsWrong)
{
    const json good = json::parse(serializeScenario(goldenScenario(9)));
    json bad = good;
    bad["characters"][1]["speech"][0]["rate"] = 900;
    EXPECT_NE(refused(bad).find("characters[1].speech[0].rate"), std::string::npos) << refused(bad);
    bad = good;
    bad["characters"][1]["speech"][0].erase("text");
    EXPECT_NE(refused(bad).find("characters[1].speech[0].text"), std::string::npos);
    bad = good;
    bad["characters"][1]["speech"][0]["phonemes"][2]["end"] = "soon";
    EXPECT_NE(refused(bad).find("characters[1].speech[0].phonemes[2].end"), std::string::npos);
    bad = good;
    bad["characters"][1]["speech"].push_back(bad["characters"][1]["speech"][0]);
    EXPECT_NE(refused(bad).find("characters[1].speech[1].name"), std::string::npos);
}

TEST(ScenarioSpeech, ALineWithoutAStartIsKeptOffTheTimeline)
{
    // Said by scripts (voiceService.activateAction): no start is read, none is written.
    json document = json::parse(serializeScenario(goldenScenario(9)));
    document["characters"][1]["speech"][0].erase("start");
    auto read = parseScenario(document.dump());
    ASSERT_TRUE(read) << read.error().message;
    EXPECT_FALSE(read->characters[1].speech[0].start.has_value());
    const json written = json::parse(serializeScenario(*read));
    EXPECT_FALSE(written["characters"][1]["speech"][0].contains("start"));
    EXPECT_EQ(*parseScenario(written.dump()), *read);
    // Its audio does not play by itself.
    core::runtime::SoundService sound(testData("formats/v9"), std::make_shared<core::runtime::ManualClock>());
    EXPECT_TRUE(sound.playSpeech(*read).empty());
    EXPECT_EQ(sound.activationCount(), 0u);
}

TEST(ScenarioSpeech, RebasingMovesTheAudioPath)
{
    Scenario s = goldenScenario(9);
    rebasePaths(s, "/a/b", "/a");
    EXPECT_EQ(s.characters[1].speech[0].audio, "b/speech/hello.wav");
}

TEST(ScenarioSpeech, TheLinesAudioPlaysWhereItIsOnTheTimeline)
{
    // A line of a tone a quarter of a second long, at 1 s.
    const auto folder = artifact("speech_timeline");
    std::filesystem::create_directories(folder / "speech");
    std::vector<float> tone(22050 / 4);
    for (std::size_t i = 0; i < tone.size(); ++i)
        tone[i] = 0.5f * float(std::sin(2 * 3.14159265 * 440 * double(i) / 22050));
    ASSERT_TRUE(core::runtime::writeWav(folder / "speech/hello.wav", 22050, tone).ok());
    Scenario s = goldenScenario(9);
    core::runtime::SoundService sound(Assets(folder), std::make_shared<core::runtime::ManualClock>());
    EXPECT_TRUE(sound.playSpeech(s).empty());
    std::vector<float> mix(48000 * 2);
    sound.mix(0, mix);
    auto loudest = [&](double from, double to) {
        float most = 0;
        for (std::size_t i = std::size_t(from * 48000); i < std::size_t(to * 48000); ++i)
            most = std::max(most, std::abs(mix[i]));
        return most;
    };
    EXPECT_EQ(loudest(0, 0.99), 0.0f);
    EXPECT_GT(loudest(1.0, 1.25), 0.4f);
    EXPECT_EQ(loudest(1.26, 2.0), 0.0f);

    s.characters[1].speech[0].audio = "speech/missing.wav";
    const auto problems = sound.playSpeech(s);
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_EQ(problems[0].rfind("characters[1].speech[0].audio: ", 0), 0u) << problems[0];
}

} // namespace thespis::test
