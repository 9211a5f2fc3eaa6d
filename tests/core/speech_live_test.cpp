// Speech played live (core/runtime/speech_performance.h, voice_service.h): the studio's Preview
// shows the face Insert puts on the timeline, and the paper's script line
// voiceService.activateAction(Creon, "…", 1.0) says a speech line of the scenario — its audio in
// the mix from that moment and its lips on the Stage — on the demo through the stage the studio,
// the command line and scripts share.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "edit/speech_edits.h"
#include "runtime/clock.h"
#include "runtime/sound.h"
#include "runtime/speech_performance.h"
#include "runtime/stage.h"
#include "runtime/voice_service.h"
#include "scenario/scenario_io.h"
#include "scene/fap.h"
#include "speech/espeak_voice.h"
#include "speech/speak_job.h"
#include "test_support.h"

namespace thespis::test {
namespace {

namespace speech = core::speech;
using core::scenario::Scenario;
using core::secondsToTicks;

Scenario demo()
{
    auto scenario = core::scenario::loadScenario(resources("demo.thespis"));
    EXPECT_TRUE(scenario) << core::describe(scenario.error());
    return scenario ? std::move(scenario).value() : Scenario{};
}

std::shared_ptr<core::runtime::Stage> stageOf(const Scenario& scenario)
{
    auto runtime = core::scenario::buildRuntime(scenario, resources());
    EXPECT_TRUE(runtime) << core::describe(runtime.error());
    return runtime ? std::make_shared<core::runtime::Stage>(std::move(runtime).value()) : nullptr;
}

std::vector<float> faceAt(core::runtime::Stage& stage, int character, double seconds)
{
    core::runtime::PoseSet poses = stage.makePoseSet();
    stage.evaluate(secondsToTicks(seconds), poses);
    return poses.characters[std::size_t(character)].face;
}

float visemeOf(const std::vector<float>& face, int viseme) { return face[std::size_t(core::scene::visemeChannel(viseme))]; }

// The demo with `job`'s visemes inserted for Creon at `at` seconds, as the studio's Insert does.
Scenario insertedInDemo(const speech::SpeakJob& job, double at)
{
    Scenario inserted = demo();
    auto insertion = core::edit::insertSpeech(
        inserted, 0, core::edit::speechLine(job.text, job.voice, job.utterance.timing, "", secondsToTicks(at)),
        job.visemeCues);
    EXPECT_TRUE(insertion) << (insertion ? "" : insertion.error().message);
    if (insertion)
        EXPECT_TRUE(insertion->edit.apply(inserted).ok());
    return inserted;
}

} // namespace

TEST(SpeechLive, PreviewShowsTheFaceInsertPutsOnTheTimeline)
{
    speech::SpeakJob job;
    job.text = "Pop the bubble, Bob. Maybe mum may come by the mill.";
    core::JobContext context;
    ASSERT_TRUE(job.run(context).ok());
    const double at = 1.0;

    auto authored = stageOf(insertedInDemo(job, at));

    auto live = stageOf(demo());
    const std::string creon = demo().characters[0].name;
    auto performed = core::runtime::performSpeech(*live, creon, "line", job.visemeCues, {}, secondsToTicks(at));
    ASSERT_TRUE(performed) << performed.error().message;
    EXPECT_EQ(performed->visemes, int(job.visemeCues.size()));

    float largest = 0, worst = 0;
    double worstAt = 0;
    for (double t = at; t < at + job.utterance.duration(); t += 0.01) {
        const auto a = faceAt(*authored, 0, t), l = faceAt(*live, 0, t);
        for (int v = 1; v <= core::scene::kVisemeCount; ++v) {
            if (std::abs(visemeOf(l, v) - visemeOf(a, v)) > worst) {
                worst = std::abs(visemeOf(l, v) - visemeOf(a, v));
                worstAt = t;
            }
            largest = std::max(largest, visemeOf(l, v));
        }
    }
    EXPECT_LT(worst, 1e-4f) << "at " << worstAt << " s";
    EXPECT_GT(largest, 0.6f); // the comparison saw a face that speaks
}

TEST(VoiceService, SaysALineOfTheScenarioWithItsAudioAndItsLips)
{
    Scenario scenario = demo();
    core::scenario::SpeechLine line;
    line.name = "bring_me_the_boy";
    line.start.reset(); // said by the script, not on the timeline
    line.text = "Bring me the boy.";
    line.voice = "en-gb";
    line.rate = 150;
    scenario.characters[0].speech.push_back(line);
    const std::string creon = scenario.characters[0].name;
    auto stage = stageOf(scenario);
    ASSERT_TRUE(stage);
    auto clock = std::make_shared<core::runtime::ManualClock>(secondsToTicks(2.0));
    auto sound = std::make_shared<core::runtime::SoundService>(resources(), clock);
    core::runtime::VoiceService voice(stage, sound);

    // Nothing plays before the script speaks: the line is not on the timeline.
    EXPECT_TRUE(sound->playSpeech(scenario).empty());
    EXPECT_EQ(sound->activationCount(), 0u);

    auto said = voice.activateAction(creon, line.name, 1.0);
    ASSERT_TRUE(said) << said.error().message;
    const auto activations = sound->activations();
    ASSERT_EQ(activations.size(), 1u);
    EXPECT_EQ(activations[0].owner, creon);
    EXPECT_EQ(activations[0].start, secondsToTicks(2.0));
    EXPECT_TRUE(voice.isPlaying(creon, line.name));

    // The same words in the same voice: where its "b" is, the mix sounds and the lips are shut.
    auto spoken = speech::speak("Bring me the boy.", {.voice = "en-gb", .wordsPerMinute = 150});
    ASSERT_TRUE(spoken);
    EXPECT_NEAR(core::ticksToSeconds(activations[0].end - activations[0].start), spoken->duration(), 0.01);
    int closures = 0;
    for (const speech::PhonemeTiming& p : spoken->timing.phonemes) {
        if (p.phoneme != "B" && p.phoneme != "M")
            continue;
        const auto face = faceAt(*stage, 0, 2.0 + (p.start + p.end) / 2);
        EXPECT_GT(visemeOf(face, 1), 0.6f) << p.phoneme << " at " << p.start;
        ++closures;
    }
    EXPECT_EQ(closures, 3);
    std::vector<float> mix(4800);
    sound->mix(secondsToTicks(2.0 + spoken->timing.words.at(1).start), mix);
    const float loudest = std::abs(*std::max_element(mix.begin(), mix.end(), [](float a, float b) { return std::abs(a) < std::abs(b); }));
    EXPECT_GT(loudest, 0.05f);

    // Stopped, the lips let go.
    clock->setTime(secondsToTicks(2.3));
    EXPECT_TRUE(voice.stop(creon, line.name));
    EXPECT_FALSE(voice.isPlaying(creon, line.name));
    EXPECT_LT(visemeOf(faceAt(*stage, 0, 2.6), 1), 0.01f);
}

TEST(VoiceService, ANameThatIsNoLineIsASoundFileNamedInTheError)
{
    auto stage = stageOf(demo());
    ASSERT_TRUE(stage);
    auto sound = std::make_shared<core::runtime::SoundService>(resources(), std::make_shared<core::runtime::ManualClock>());
    core::runtime::VoiceService voice(stage, sound);
    auto missing = voice.activateAction(demo().characters[0].name, "no_such_line.wav");
    ASSERT_FALSE(missing);
    EXPECT_NE(missing.error().message.find("no_such_line.wav"), std::string::npos) << missing.error().message;
    auto nobody = voice.activateAction("Ismene", "hello");
    ASSERT_FALSE(nobody);
    EXPECT_NE(nobody.error().message.find("Ismene"), std::string::npos);
}

// The paper §5.2: "the TTS timing information is used to plan the length of the gesture motions.
// A blending fade-in and fade-out is applied". On the demo, Creon's tagged body gestures (nested:
// a nod inside a greeting) fade in before their words and out after them, within a frame, played
// live and inserted alike; and the greeting moves his arm while its words are said.
TEST(SpeechGestures, ATaggedBodyGestureSpansItsWordsWithItsFades)
{
    speech::SpeakJob job;
    job.text = "Welcome home. <begin_gesture id=\"g1\" anim=\"greet\"/>My <begin_gesture id=\"g2\" anim=\"agree\"/>dear"
               "<end_gesture id=\"g2\"/> friend and guest<end_gesture id=\"g1\"/>, to Thebes.";
    job.voice = {.voice = "en-gb", .wordsPerMinute = 140};
    core::JobContext context;
    ASSERT_TRUE(job.run(context).ok());
    ASSERT_EQ(job.gestureCues.size(), 2u);
    const Scenario scenario = demo();
    const auto& creon = scenario.characters[0];
    const double frame = 1.0 / 60, at = 2.0;

    // When each gesture must play: its words, widened by its gesticon entry's fades.
    struct Expected {
        std::string name; // live: "LINE:ID"; on the timeline: "ID GESTURE"
        double start, end;
    };
    std::vector<Expected> expected;
    for (const speech::GestureCue& cue : job.gestureCues) {
        const auto* gesture = creon.findGesture(cue.animation);
        ASSERT_TRUE(gesture) << cue.animation;
        expected.push_back({"welcome:" + cue.id, at + cue.start - core::ticksToSeconds(gesture->fadeIn),
                            at + cue.end + core::ticksToSeconds(gesture->fadeOut)});
        EXPECT_GT(cue.start, core::ticksToSeconds(gesture->fadeIn)) << "the test wants a gesture after the first words";
    }
    EXPECT_LT(expected[0].start, expected[1].start);
    EXPECT_GT(expected[0].end, expected[1].end);

    // Live.
    auto live = stageOf(scenario);
    ASSERT_TRUE(performSpeech(*live, creon.name, "welcome", job.visemeCues, job.gestureBml, secondsToTicks(at)));
    for (const Expected& e : expected) {
        SCOPED_TRACE("live " + e.name);
        EXPECT_NEAR(*live->actionEnd(creon.name, core::runtime::Track::Body, e.name), e.end, frame);
        EXPECT_FALSE(*live->isPlaying(creon.name, core::runtime::Track::Body, e.name, secondsToTicks(e.start - frame)));
        EXPECT_TRUE(*live->isPlaying(creon.name, core::runtime::Track::Body, e.name, secondsToTicks(e.start + frame)));
    }
    // Its arm moves while the words are said: the greeting is no still pose.
    auto still = stageOf(scenario);
    core::runtime::PoseSet waving = live->makePoseSet(), standing = still->makePoseSet();
    const double middle = (job.gestureCues[0].start + job.gestureCues[0].end) / 2 + at;
    live->evaluate(secondsToTicks(middle), waving);
    still->evaluate(secondsToTicks(middle), standing);
    float moved = 0;
    for (std::size_t i = 0; i < waving.characters[0].body.size(); ++i)
        moved = std::max(moved, std::abs(waving.characters[0].body[i] - standing.characters[0].body[i]));
    EXPECT_GT(moved, 0.1f);

    // Inserted at the same time: the timeline's actions play over the same spans.
    Scenario inserted = scenario;
    auto runtime = core::scenario::buildRuntime(scenario, resources());
    ASSERT_TRUE(runtime) << core::describe(runtime.error());
    auto insertion = core::edit::insertSpeech(
        inserted, 0, core::edit::speechLine(job.text, job.voice, job.utterance.timing, "", secondsToTicks(at)),
        job.visemeCues, job.gestureBml, &*runtime);
    ASSERT_TRUE(insertion) << insertion.error().message;
    EXPECT_EQ(insertion->bodyGestures, 2);
    ASSERT_TRUE(insertion->edit.apply(inserted).ok());
    auto authored = stageOf(inserted);
    for (std::size_t g = 0; g < expected.size(); ++g) {
        const std::string name = job.gestureCues[g].id + " " + job.gestureCues[g].animation;
        SCOPED_TRACE("inserted " + name);
        EXPECT_NEAR(*authored->actionEnd(creon.name, core::runtime::Track::Body, name), expected[g].end, frame);
        EXPECT_FALSE(*authored->isPlaying(creon.name, core::runtime::Track::Body, name,
                                          secondsToTicks(expected[g].start - frame)));
        EXPECT_TRUE(*authored->isPlaying(creon.name, core::runtime::Track::Body, name,
                                         secondsToTicks(expected[g].start + frame)));
    }
}

} // namespace thespis::test

namespace thespis::test {

// Overlapping tags (neither inside the other): a greeting over "My dear friend" and a nod over
// "friend and guest". Both play on the Stage while "friend" is said, each over its own words, and
// each shows: the pose in the overlap is neither the greeting's alone nor the nod's alone.
TEST(SpeechGestures, OverlappingGesturesBothPlayWhereTheirWordsMeet)
{
    const auto spoken = [](const std::string& text) {
        speech::SpeakJob job;
        job.text = text;
        job.voice = {.voice = "en-gb", .wordsPerMinute = 140};
        core::JobContext context;
        EXPECT_TRUE(job.run(context).ok());
        return job;
    };
    const speech::SpeakJob both = spoken(
        "Welcome home. <begin_gesture id=\"g1\" anim=\"greet\"/>My dear <begin_gesture id=\"g2\" anim=\"agree\"/>friend"
        "<end_gesture id=\"g1\"/> and guest<end_gesture id=\"g2\"/>, to Thebes.");
    const speech::SpeakJob greetOnly = spoken(
        "Welcome home. <begin_gesture id=\"g1\" anim=\"greet\"/>My dear friend<end_gesture id=\"g1\"/> and guest, to Thebes.");
    const speech::SpeakJob nodOnly = spoken(
        "Welcome home. My dear <begin_gesture id=\"g2\" anim=\"agree\"/>friend and guest<end_gesture id=\"g2\"/>, to Thebes.");
    ASSERT_EQ(both.gestureCues.size(), 2u);
    const speech::GestureCue &greet = both.gestureCues[0], &nod = both.gestureCues[1];
    ASSERT_LT(greet.start, nod.start);
    ASSERT_LT(nod.start, greet.end);
    ASSERT_LT(greet.end, nod.end);
    const Scenario scenario = demo();
    const std::string creon = scenario.characters[0].name;
    const double at = 1.0, friendWord = at + (nod.start + greet.end) / 2;

    const auto poseWith = [&](const speech::SpeakJob& job, std::shared_ptr<core::runtime::Stage>& stage) {
        stage = stageOf(scenario);
        EXPECT_TRUE(core::runtime::performSpeech(*stage, creon, "line", job.visemeCues, job.gestureBml, secondsToTicks(at)));
        core::runtime::PoseSet poses = stage->makePoseSet();
        stage->evaluate(secondsToTicks(friendWord), poses);
        return poses.characters[0].body;
    };
    std::shared_ptr<core::runtime::Stage> live, greeting, nodding;
    const std::vector<float> together = poseWith(both, live), greeted = poseWith(greetOnly, greeting),
                             nodded = poseWith(nodOnly, nodding);
    EXPECT_TRUE(*live->isPlaying(creon, core::runtime::Track::Body, "line:g1", secondsToTicks(friendWord)));
    EXPECT_TRUE(*live->isPlaying(creon, core::runtime::Track::Body, "line:g2", secondsToTicks(friendWord)));
    EXPECT_LT(*live->actionEnd(creon, core::runtime::Track::Body, "line:g1"),
              *live->actionEnd(creon, core::runtime::Track::Body, "line:g2"));
    const auto largestDifference = [](const std::vector<float>& a, const std::vector<float>& b) {
        float largest = 0;
        for (std::size_t i = 0; i < a.size(); ++i)
            largest = std::max(largest, std::abs(a[i] - b[i]));
        return largest;
    };
    EXPECT_GT(largestDifference(together, greeted), 0.01f) << "the nod shows over the greeting";
    EXPECT_GT(largestDifference(together, nodded), 0.01f) << "the greeting shows under the nod";
}

} // namespace thespis::test

namespace thespis::test {

// A face gesture of the gesticon (its clip moves no joint, only the face: Creon's stern look)
// tagged in a line plays live on the face track over its words, as a body gesture plays on the
// body: the runtime builds it on the face, with no warning that scripts cannot play it.
TEST(SpeechGestures, ATaggedFaceGesturePlaysLiveOnTheFaceTrack)
{
    Scenario scenario = demo();
    auto& creon = scenario.characters[0];
    creon.gestures.push_back({.name = "frown", .clip = "stern", .fadeIn = secondsToTicks(0.15),
                              .fadeOut = secondsToTicks(0.15), .dependentJointFilter = true});
    auto runtime = core::scenario::buildRuntime(scenario, resources());
    ASSERT_TRUE(runtime) << core::describe(runtime.error());
    const auto* built = runtime->findCharacter(creon.name);
    ASSERT_TRUE(built);
    for (const std::string& warning : built->warnings)
        EXPECT_EQ(warning.find("frown"), std::string::npos) << warning;
    ASSERT_TRUE(built->gestures.contains("frown"));
    EXPECT_TRUE(built->gestures.at("frown").face);

    speech::SpeakJob job;
    job.text = R"(You <begin_gesture id="g1" anim="frown"/>dare defy the law<end_gesture id="g1"/> of Thebes?)";
    core::JobContext context;
    ASSERT_TRUE(job.run(context).ok());
    ASSERT_EQ(job.gestureCues.size(), 1u);
    const speech::GestureCue& cue = job.gestureCues[0];
    const double at = 1.0, middle = at + (cue.start + cue.end) / 2;
    auto stage = std::make_shared<core::runtime::Stage>(std::move(runtime).value());
    auto performed = core::runtime::performSpeech(*stage, creon.name, "line", job.visemeCues, job.gestureBml,
                                                  secondsToTicks(at));
    ASSERT_TRUE(performed) << performed.error().message;
    EXPECT_EQ(performed->gestures, 1);
    EXPECT_TRUE(performed->unknownGestures.empty());
    EXPECT_TRUE(*stage->isPlaying(creon.name, core::runtime::Track::Face, "line:g1", secondsToTicks(middle)));
    EXPECT_FALSE(*stage->isPlaying(creon.name, core::runtime::Track::Body, "line:g1", secondsToTicks(middle)));

    const int stern = core::scene::expressionChannel(3);
    EXPECT_GT(faceAt(*stage, 0, middle)[std::size_t(stern)], 0.5f) << "the stern look shows on 'dare defy the law'";
    EXPECT_LT(faceAt(*stage, 0, at + cue.start - 0.2)[std::size_t(stern)], 0.05f) << "not before";
    EXPECT_LT(faceAt(*stage, 0, at + cue.end + 0.4)[std::size_t(stern)], 0.05f) << "nor after";
}

} // namespace thespis::test

namespace thespis::test {

// Spoken with Microsoft's SAPI visemes (or Oculus'), the built-in face shows each as its MPEG-4
// viseme: live and inserted on the timeline alike, the lips shut on every p, b and m and open on
// every "aa"; the timeline's clips are named after the MPEG-4 viseme they show.
TEST(SpeechLive, AnyVisemeSetSpeaksOnTheFace)
{
    for (const speech::VisemeSet* set : {&speech::sapiVisemes(), &speech::oculusVisemes()}) {
        SCOPED_TRACE(set->name);
        speech::SpeakJob job;
        job.text = "Pop the bubble, Bob. Father may come by the mill.";
        job.visemes = *set;
        core::JobContext context;
        ASSERT_TRUE(job.run(context).ok());
        const double at = 1.0;
        const std::string creon = demo().characters[0].name;
        auto live = stageOf(demo());
        auto performed = core::runtime::performSpeech(*live, creon, "line", job.visemeCues, {}, secondsToTicks(at));
        ASSERT_TRUE(performed) << performed.error().message;

        const Scenario inserted = insertedInDemo(job, at);
        EXPECT_TRUE(inserted.characters[0].findClip("viseme p_b_m"));
        auto authored = stageOf(inserted);

        int shut = 0, open = 0;
        for (const auto& p : job.utterance.timing.phonemes) {
            const double middle = at + (p.start + p.end) / 2;
            for (auto* stage : {live.get(), authored.get()}) {
                const auto face = faceAt(*stage, 0, middle);
                if (p.phoneme == "P" || p.phoneme == "B" || p.phoneme == "M") {
                    EXPECT_GT(visemeOf(face, 1), 0.6f) << p.phoneme << " at " << p.start;
                    ++shut;
                } else if (p.phoneme == "AA") {
                    EXPECT_GT(visemeOf(face, 10), 0.5f) << p.phoneme << " at " << p.start;
                    EXPECT_LT(visemeOf(face, 1), 0.3f) << p.phoneme << " at " << p.start;
                    ++open;
                }
            }
        }
        EXPECT_GE(shut, 2 * 7);
        EXPECT_GE(open, 2 * 1);
    }
}

} // namespace thespis::test
