// The BML realizer (runtime/bml_performance.h) on the demo: Creon says a BML block in which a
// beat gesture's stroke falls on a word, a nod follows the stroke, his brows rise over the speech
// and he looks at Antigone — each at the time its sync references give from espeak-ng's timing,
// as seen in the poses the Stage gives; his pointing finger on its target; blocks composed;
// errors named with line and column.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "motion/pointing.h"
#include "runtime/bml_performance.h"
#include "runtime/clock.h"
#include "runtime/sound.h"
#include "runtime/stage.h"
#include "scenario/scenario_io.h"
#include "scene/fap.h"
#include "test_support.h"

namespace thespis::test {
namespace {

namespace speech = core::speech;
namespace runtime = core::runtime;
using core::secondsToTicks;

struct Demo {
    std::shared_ptr<runtime::Stage> stage;
    std::shared_ptr<runtime::SoundService> sound;
    std::string creon;
};

Demo demo()
{
    auto scenario = core::scenario::loadScenario(resources("demo.thespis"));
    EXPECT_TRUE(scenario) << core::describe(scenario.error());
    auto built = core::scenario::buildRuntime(*scenario, resources());
    EXPECT_TRUE(built) << core::describe(built.error());
    Demo d;
    d.stage = std::make_shared<runtime::Stage>(std::move(built).value());
    d.sound = std::make_shared<runtime::SoundService>(resources(), std::make_shared<runtime::ManualClock>());
    d.creon = scenario->characters[0].name;
    return d;
}

double eventTime(const runtime::BmlPerformance& p, const std::string& name)
{
    for (const runtime::BmlEvent& e : p.events)
        if (e.name == name)
            return e.time;
    ADD_FAILURE() << "no event " << name;
    return -1;
}

runtime::CharacterPose poseAt(runtime::Stage& stage, double seconds)
{
    runtime::PoseSet poses = stage.makePoseSet();
    stage.evaluate(secondsToTicks(seconds), poses);
    return poses.characters[0];
}

constexpr const char* kBlock = R"(<bml xmlns="http://www.bml-initiative.org/bml/bml-1.0" id="bml1" characterId="Creon">
  <speech id="s1"><text>Hear me, <sync id="t1"/>Antigone, daughter of Oedipus.</text></speech>
  <gesture id="g1" lexeme="BEAT" stroke="s1:t1"/>
  <head id="h1" lexeme="NOD" start="g1:stroke + 0.3" repetition="2"/>
  <faceLexeme id="f1" lexeme="RAISE_BROWS" start="s1:start" end="s1:end"/>
  <gaze id="z1" target="Antigone" influence="HEAD" start="s1:start"/>
</bml>)";

} // namespace

TEST(BmlRealizer, BehavioursPlayAtTheirSyncPointsOnTheSpeechsWords)
{
    Demo d = demo();
    auto block = speech::parseBml(kBlock);
    ASSERT_TRUE(block) << block.error().message;
    runtime::BmlRealizer realizer(d.stage, d.sound);
    runtime::BmlOptions options;
    options.voice = {.voice = "en-gb", .wordsPerMinute = 140};
    options.gaze.saccades = false;
    const double at = 1.0;
    auto performed = realizer.perform(d.creon, *block, options, secondsToTicks(at));
    ASSERT_TRUE(performed) << performed.error().message;

    // "Antigone" is the third word: the beat's stroke is on it, and the speech's audio starts at 1 s.
    auto said = speech::speak("Hear me, Antigone, daughter of Oedipus.", options.voice);
    ASSERT_TRUE(said);
    const double word = at + said->timing.words.at(2).start;
    // (espeak-ng's timing of the same words may move by a few samples from one call to the next.)
    EXPECT_NEAR(eventTime(*performed, "s1:t1"), word, 0.002);
    EXPECT_NEAR(eventTime(*performed, "g1:stroke"), eventTime(*performed, "s1:t1"), 1e-9);
    EXPECT_NEAR(eventTime(*performed, "h1:start"), eventTime(*performed, "g1:stroke") + 0.3, 1e-9);
    EXPECT_NEAR(eventTime(*performed, "bml1:end"), at + said->duration(), 0.01);
    ASSERT_EQ(d.sound->activations().size(), 1u);
    EXPECT_EQ(d.sound->activations()[0].start, secondsToTicks(at));

    // What a viewer sees. The beat plays around its stroke; the nod after it; brows up while he speaks.
    EXPECT_TRUE(*d.stage->isPlaying(d.creon, runtime::Track::Body, "bml1:g1", secondsToTicks(word)));
    EXPECT_TRUE(*d.stage->isPlaying(d.creon, runtime::Track::Body, "bml1:h1", secondsToTicks(word + 0.4)));
    EXPECT_FALSE(*d.stage->isPlaying(d.creon, runtime::Track::Body, "bml1:h1", secondsToTicks(word + 0.25)));
    const auto brows = [&](double t) { return poseAt(*d.stage, t).face[std::size_t(core::scene::fapChannel(33))]; };
    EXPECT_TRUE(*d.stage->isPlaying(d.creon, runtime::Track::Face, "bml1:f1", secondsToTicks(at + said->duration() / 2)));
    EXPECT_GT(brows(at + said->duration() / 2), 250.0f);
    EXPECT_NEAR(brows(at + said->duration() + 0.1), 0.0f, 1.0f);
    auto gaze = d.stage->gazeState(d.creon);
    ASSERT_TRUE(gaze && *gaze) << "looking at Antigone";

    // Appended, the next block waits for this one; replacing stops it.
    auto next = speech::parseBml(R"(<bml id="bml2" composition="append"><head id="h" lexeme="SHAKE"/></bml>)");
    ASSERT_TRUE(next);
    auto appended = realizer.perform(d.creon, *next, options, secondsToTicks(at));
    ASSERT_TRUE(appended);
    EXPECT_NEAR(appended->start, performed->end, 1e-9);
    auto replacing = speech::parseBml(R"(<bml id="bml3" composition="replace"><head id="h" lexeme="TILT"/></bml>)");
    ASSERT_TRUE(replacing);
    ASSERT_TRUE(realizer.perform(d.creon, *replacing, options, secondsToTicks(word)));
    EXPECT_FALSE(*d.stage->isPlaying(d.creon, runtime::Track::Body, "bml1:g1", secondsToTicks(word + 0.5)));
    // Its feedback ends where it was cut off: nothing it would have done later is reported.
    const std::vector<runtime::BmlEvent> cut = realizer.events(d.creon, "bml1");
    ASSERT_FALSE(cut.empty());
    EXPECT_EQ(cut.back().name, "bml1:end");
    EXPECT_DOUBLE_EQ(cut.back().time, word);
    EXPECT_LT(cut.size(), performed->events.size());
    EXPECT_TRUE(std::all_of(cut.begin(), cut.end(), [&](const runtime::BmlEvent& e) { return e.time <= word; }));
}

// A script's own loop takes each event once, as the clock reaches it, in time order.
TEST(BmlRealizer, EventsAreTakenOnceAsTheClockReachesThem)
{
    Demo d = demo();
    auto block = speech::parseBml(kBlock);
    ASSERT_TRUE(block) << block.error().message;
    runtime::BmlRealizer realizer(d.stage, d.sound);
    runtime::BmlOptions options;
    options.gaze.saccades = false;
    auto performed = realizer.perform(d.creon, *block, options, secondsToTicks(1.0));
    ASSERT_TRUE(performed) << performed.error().message;
    EXPECT_TRUE(realizer.takeEvents(0.5).empty()) << "nothing before the block starts";
    const double stroke = eventTime(*performed, "g1:stroke");
    std::vector<std::string> taken;
    for (double now : {1.0, stroke, stroke, performed->end + 1}) {
        double last = -1;
        for (const auto& [character, e] : realizer.takeEvents(now)) {
            EXPECT_EQ(character, d.creon);
            EXPECT_LE(e.time, now);
            EXPECT_GE(e.time, last);
            last = e.time;
            taken.push_back(e.name);
        }
        if (now == 1.0) {
            EXPECT_NE(std::find(taken.begin(), taken.end(), "bml1:start"), taken.end());
        }
    }
    std::vector<std::string> all;
    for (const runtime::BmlEvent& e : performed->events)
        all.push_back(e.name);
    EXPECT_EQ(taken, all) << "each once, in order";
}

// The point where the arm's line meets the target, in the body frame the pose is in.
core::anim::Vec3d inBodyFrame(const core::anim::Placement& placement, const core::anim::Vec3d& p)
{
    const core::anim::Quatd r{placement.rotation.x, placement.rotation.y, placement.rotation.z, placement.rotation.w};
    const core::anim::Vec3d t{placement.translation.x, placement.translation.y, placement.translation.z};
    return core::anim::rotate(core::anim::conjugate(r), p - t);
}

TEST(BmlRealizer, PointingAimsTheArmAtItsTargetThroughTheStroke)
{
    // A point in front of Creon at his chest's height, which his "point" entry (the lexicon's
    // POINT), as drawn, does not point at.
    const core::anim::Vec3d target{0.2, 1.2, 2.5};
    const auto perform = [&](const char* behaviour, std::string& creon) {
        Demo d = demo();
        creon = d.creon;
        const std::string xml = std::string("<bml id=\"b\">") + behaviour + "</bml>";
        auto block = speech::parseBml(xml);
        EXPECT_TRUE(block) << block.error().message;
        runtime::BmlRealizer realizer(d.stage, d.sound);
        auto performed = realizer.perform(d.creon, *block, {}, secondsToTicks(1.0));
        EXPECT_TRUE(performed) << performed.error().message;
        return std::make_pair(d, performed ? *performed : runtime::BmlPerformance{});
    };
    std::string creon;
    auto [pointing, performance] = perform("<pointing id=\"p\" target=\"0.2 1.2 2.5\" mode=\"RIGHT_HAND\"/>", creon);
    auto [gestureOnly, unused] = perform("<gesture id=\"p\" lexeme=\"POINT\"/>", creon);
    auto skeleton = pointing.stage->skeleton(creon);
    ASSERT_TRUE(skeleton);
    auto arms = core::motion::pointingArms(*skeleton, core::motion::PointingHand::Right);
    ASSERT_TRUE(arms) << arms.error().message;
    ASSERT_EQ(arms->size(), 1u);
    EXPECT_EQ(skeleton->joint(arms->front().tip).name, "r_radiocarpal") << "a rig without fingers aims its wrist";
    const auto error = [&](runtime::Stage& stage, double t) {
        const runtime::CharacterPose pose = poseAt(stage, t);
        return core::motion::pointingError(*skeleton, arms->front(), pose.body, inBodyFrame(pose.placement, target));
    };
    // From its ready point to its relax point the fingertip is on the line from the shoulder to
    // the target; the same entry played as a gesture points elsewhere.
    const double ready = eventTime(performance, "p:ready"), relax = eventTime(performance, "p:relax");
    ASSERT_LT(ready, relax);
    for (const double t : {ready, 0.5 * (ready + relax), relax})
        EXPECT_LT(error(*pointing.stage, t), 1.0) << "at " << t << " s";
    EXPECT_GT(error(*gestureOnly.stage, 0.5 * (ready + relax)), 10.0) << "the entry alone must not point there";
    // The aim comes and goes with the gesture: none before it starts or after it ends.
    const double end = eventTime(performance, "p:end");
    EXPECT_EQ(poseAt(*pointing.stage, end + 0.1).body, poseAt(*gestureOnly.stage, end + 0.1).body);
    EXPECT_EQ(poseAt(*pointing.stage, 0.9).body, poseAt(*gestureOnly.stage, 0.9).body);
}

TEST(BmlRealizer, WhatCannotPlayIsNamedWithItsLineAndColumn)
{
    Demo d = demo();
    runtime::BmlRealizer realizer(d.stage, d.sound);
    const runtime::BmlOptions options;
    const auto fails = [&](const char* xml) {
        auto block = speech::parseBml(xml);
        EXPECT_TRUE(block) << block.error().message;
        auto performed = realizer.perform(d.creon, *block, options, 0);
        EXPECT_FALSE(performed);
        return performed ? std::string() : performed.error().message;
    };
    EXPECT_NE(fails("<bml id=\"b\">\n  <gesture id=\"g\" lexeme=\"JUGGLE\"/></bml>").find("line 2, column 3"),
              std::string::npos);
    EXPECT_NE(fails("<bml id=\"b\"><faceLexeme id=\"f\" lexeme=\"WIGGLE_EARS\"/></bml>").find("WIGGLE_EARS"),
              std::string::npos);
    EXPECT_NE(fails("<bml id=\"b\"><gaze id=\"z\" target=\"Ismene\"/></bml>").find("Ismene"), std::string::npos);
    EXPECT_NE(fails("<bml id=\"b\"><pointing id=\"p\" target=\"Antigone:l_tail\"/></bml>").find("l_tail"), std::string::npos);
    EXPECT_NE(fails("<bml id=\"b\"><pointing id=\"p\" target=\"camera\" mode=\"THIRD_HAND\"/></bml>").find("THIRD_HAND"),
              std::string::npos);
    const std::string cycle =
        fails("<bml id=\"b\"><head id=\"a\" lexeme=\"NOD\" start=\"c:end\"/><head id=\"c\" lexeme=\"NOD\" start=\"a:end\"/></bml>");
    EXPECT_NE(cycle.find("→"), std::string::npos) << cycle;
}

} // namespace thespis::test
