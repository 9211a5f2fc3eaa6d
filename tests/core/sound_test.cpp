// The voice and sound service (core/runtime/sound.h) on real speech recordings
// (../shared/data/speech/pocketsphinx/cards, 16 kHz WAV): sounds start at the clock's time, mix
// sample-exact, stop, and come back from the WAV written headless; bad files are refused.

#include <gtest/gtest.h>

#include <cmath>

#include "runtime/sound.h"
#include "test_support.h"

namespace thespis::test {
namespace {

using core::secondsToTicks;
using namespace core::runtime;

const std::string kSpeech = sharedData("speech/pocketsphinx/cards/001.wav").string();

TEST(Sound, ReadsARealRecording)
{
    auto clip = loadSound(kSpeech);
    ASSERT_TRUE(clip) << core::describe(clip.error());
    EXPECT_EQ((*clip)->rate, 16000);
    EXPECT_GT((*clip)->duration(), 0.5);
    float peak = 0;
    for (const float s : (*clip)->samples)
        peak = std::max(peak, std::abs(s));
    EXPECT_GT(peak, 0.05f); // speech, not silence
}

TEST(Sound, PlaysFromTheClocksTimeAndStops)
{
    auto clock = std::make_shared<ManualClock>(secondsToTicks(1.0));
    SoundService sound(sharedData(), clock, 16000); // the recording's own rate: samples exactly
    ASSERT_TRUE(sound.play("speech/pocketsphinx/cards/001.wav", 0.5, "Creon"));
    auto clip = loadSound(kSpeech);
    ASSERT_TRUE(clip);
    std::vector<float> out(16000);
    sound.mix(secondsToTicks(0.5), out); // 0.5 s of silence, then the speech at half volume
    for (std::size_t i = 0; i < 8000; ++i)
        ASSERT_EQ(out[i], 0.0f) << i;
    for (std::size_t i = 8000; i < 16000; ++i)
        ASSERT_NEAR(out[i], 0.5f * (*clip)->samples[i - 8000], 1e-6f) << i;
    EXPECT_TRUE(sound.isPlaying("speech/pocketsphinx/cards/001.wav"));
    clock->setTime(secondsToTicks(1.25));
    EXPECT_TRUE(sound.stop("speech/pocketsphinx/cards/001.wav"));
    EXPECT_FALSE(sound.isPlaying("speech/pocketsphinx/cards/001.wav"));
    sound.mix(secondsToTicks(1.25), out);
    for (const float s : out)
        ASSERT_EQ(s, 0.0f);
}

TEST(Sound, TheWavWrittenHeadlessHoldsTheMix)
{
    auto clock = std::make_shared<ManualClock>(secondsToTicks(0.2));
    SoundService sound(sharedData(), clock); // 48 kHz: resampled from 16 kHz
    ASSERT_TRUE(sound.play("speech/pocketsphinx/cards/002.wav"));
    const auto path = artifact("sound_mix.wav");
    ASSERT_TRUE(sound.writeWav(path, 0, secondsToTicks(1.5)));
    auto back = loadSound(path);
    ASSERT_TRUE(back) << core::describe(back.error());
    EXPECT_EQ((*back)->rate, 48000);
    ASSERT_EQ((*back)->samples.size(), 72000u);
    std::vector<float> expected(72000);
    sound.mix(0, expected);
    for (std::size_t i = 0; i < expected.size(); ++i)
        ASSERT_NEAR((*back)->samples[i], expected[i], 1.0f / 32000) << i;
    // Resampling keeps the sound's length: it starts at 0.2 s.
    EXPECT_EQ(expected[9599], 0.0f);
}

TEST(Sound, BadFilesAreRefusedWithTheirName)
{
    auto missing = loadSound("/nonexistent/speech.wav");
    ASSERT_FALSE(missing);
    EXPECT_EQ(missing.error().code, core::ErrorCode::FileNotFound);
    auto notSound = loadSound(sharedData("mocap/cmu/02_01.bvh"));
    ASSERT_FALSE(notSound);
    EXPECT_EQ(notSound.error().code, core::ErrorCode::NotOurFormat);
    EXPECT_NE(notSound.error().message.find("02_01.bvh"), std::string::npos);
    SoundService sound(sharedData(), std::make_shared<ManualClock>());
    EXPECT_FALSE(sound.play("speech/nothing.wav"));
    EXPECT_TRUE(sound.activations().empty()); // nothing half-started
}

} // namespace
} // namespace thespis::test
