// Pointing on the timeline (format 11, scenario.h's PointingSpec): the golden file, the upgrade
// from version 10, the reader and the runtime naming what is wrong, and a BML <pointing> put on
// the demo's timeline (edit::insertBml, the studio's Insert and `thespis-cli speak --bml`) that,
// played back from the saved scenario, points Creon's finger at its target as the live realizer
// does — and does not without its pointing.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "edit/bml_edits.h"
#include "motion/pointing.h"
#include "runtime/bml_performance.h"
#include "runtime/stage.h"
#include "scenario/scenario_io.h"
#include "scenario/scenario_runtime.h"
#include "scenario_formats.h"
#include "test_support.h"
#include "util/file_io.h"

namespace thespis::test {
namespace {

using namespace core::scenario;
using core::secondsToTicks;
using json = nlohmann::json;
namespace runtime = core::runtime;

std::string runtimeProblem(const Scenario& scenario)
{
    auto built = buildRuntime(scenario, resources());
    EXPECT_FALSE(built);
    return built ? std::string() : built.error().message;
}

Scenario demo()
{
    auto loaded = loadScenario(resources("demo.thespis"));
    EXPECT_TRUE(loaded) << core::describe(loaded.error());
    return loaded ? std::move(loaded).value() : Scenario{};
}

// A point in front of Creon at his chest's height, which his "point" entry, as drawn, does not
// point at.
constexpr const char* kTarget = "0.2 1.2 2.5";
const core::anim::Vec3d kTargetPoint{0.2, 1.2, 2.5};
constexpr double kAt = 1.0; // seconds: where the block goes on the timeline

// Degrees between where Creon's right arm points and the target, in the pose `stage` gives at `t`.
double aimError(runtime::Stage& stage, double t)
{
    runtime::PoseSet poses = stage.makePoseSet();
    stage.evaluate(secondsToTicks(t), poses);
    const runtime::CharacterPose& pose = poses.characters[0];
    const auto skeleton = stage.skeleton("Creon").value();
    const auto arm = core::motion::pointingArms(skeleton, core::motion::PointingHand::Right).value().front();
    const auto& r = pose.placement.rotation;
    const auto& p = pose.placement.translation;
    const core::anim::Vec3d inBody = core::anim::rotate(core::anim::conjugate(core::anim::Quatd{r.x, r.y, r.z, r.w}),
                                                        kTargetPoint - core::anim::Vec3d{p.x, p.y, p.z});
    return core::motion::pointingError(skeleton, arm, pose.body, inBody);
}

} // namespace

TEST(ScenarioPointing, TheGoldenFileHasAGesturePointingAtTheOtherCharactersHand)
{
    const Scenario s = goldenScenario(11);
    const ActionSpec& wave = s.characters[0].layers[1].actions[0];
    ASSERT_TRUE(wave.pointing);
    EXPECT_EQ(wave.pointing->target, "Inline:r_radiocarpal");
    EXPECT_EQ(wave.pointing->hand, "LEFT_HAND");
    EXPECT_EQ(wave.clip, "wave");
    // Version 10 reads as before: nothing in it points.
    for (const Character& c : goldenScenario(10).characters)
        for (const Layer& l : c.layers)
            for (const ActionSpec& a : l.actions)
                EXPECT_FALSE(a.pointing);
}

TEST(ScenarioPointing, TheReaderNamesTheFieldThatIsWrong)
{
    const json doc = json::parse(core::readTextFile(testData("formats/v11/scenario.thespis")).value());
    json noTarget = doc;
    noTarget["characters"][0]["layers"][1]["actions"][0]["pointing"].erase("target");
    EXPECT_NE(refusedScenario(noTarget).find("characters[0].layers[1].actions[0].pointing.target: this field is required"),
              std::string::npos)
        << refusedScenario(noTarget);
    json unknown = doc;
    unknown["characters"][0]["layers"][1]["actions"][0]["pointing"]["finger"] = 2;
    EXPECT_NE(refusedScenario(unknown).find("pointing.finger: unknown member of a pointing"), std::string::npos)
        << refusedScenario(unknown);
    json notAnObject = doc;
    notAnObject["characters"][0]["layers"][1]["actions"][0]["pointing"] = "Inline";
    EXPECT_NE(refusedScenario(notAnObject).find("actions[0].pointing"), std::string::npos) << refusedScenario(notAnObject);
}

TEST(ScenarioPointing, TheRuntimeNamesAPointingThatCannotPlay)
{
    Scenario s = demo();
    ActionSpec& wave = s.characters[0].layers[0].actions[1];
    ASSERT_EQ(wave.name, "creon_wave");
    wave.pointing = PointingSpec{"Antigone", "RIGHT_HAND"};
    ASSERT_TRUE(buildRuntime(s, resources())) << "Antigone and the right hand are fine";
    Scenario nobody = s;
    nobody.characters[0].layers[0].actions[1].pointing->target = "Ismene";
    EXPECT_NE(runtimeProblem(nobody).find("action \"creon_wave\", pointing.target: the scenario has no character named "
                                          "\"Ismene\""),
              std::string::npos)
        << runtimeProblem(nobody);
    Scenario hand = s;
    hand.characters[0].layers[0].actions[1].pointing->hand = "THIRD_HAND";
    EXPECT_NE(runtimeProblem(hand).find("pointing.hand: mode \"THIRD_HAND\""), std::string::npos) << runtimeProblem(hand);
    Scenario onFace = s;
    onFace.characters[0].layers[1].actions[0].pointing = PointingSpec{};
    EXPECT_NE(runtimeProblem(onFace).find("pointing: only an action of a body layer points"), std::string::npos)
        << runtimeProblem(onFace);
}

TEST(ScenarioPointing, AnInsertedPointingAimsTheFingerWhenPlayedBackAsTheLiveRealizerDoes)
{
    const Scenario document = demo();
    auto built = buildRuntime(document, resources());
    ASSERT_TRUE(built) << core::describe(built.error());
    auto block = core::speech::parseBml(std::string("<bml id=\"b\"><pointing id=\"p\" target=\"") + kTarget + "\"/></bml>");
    ASSERT_TRUE(block) << block.error().message;
    auto inserted = core::edit::insertBml(document, *built, 0, *block, {}, {}, secondsToTicks(kAt));
    ASSERT_TRUE(inserted) << inserted.error().message;
    EXPECT_EQ(inserted->gestures, 1);
    Scenario after = document;
    ASSERT_TRUE(inserted->edit.apply(after));
    const ActionSpec& point = after.characters[0].layers.back().actions.back();
    EXPECT_EQ(point.clip, "point") << "the demo's own POINT entry";
    ASSERT_TRUE(point.pointing);
    EXPECT_EQ(*point.pointing, (PointingSpec{kTarget, "RIGHT_HAND"}));

    // Saved and read back, as the studio and the CLI leave it.
    auto read = parseScenario(serializeScenario(after));
    ASSERT_TRUE(read) << core::describe(read.error());
    auto played = buildRuntime(*read, resources());
    ASSERT_TRUE(played) << core::describe(played.error());
    ASSERT_EQ(played->characters[0].pointing.size(), 1u);
    runtime::Stage authored(*played);

    // The same block played live.
    auto liveStage = std::make_shared<runtime::Stage>(*built);
    runtime::BmlRealizer realizer(liveStage, nullptr);
    auto performed = realizer.perform("Creon", *block, {}, secondsToTicks(kAt));
    ASSERT_TRUE(performed) << performed.error().message;
    double ready = -1, relax = -1;
    for (const runtime::BmlEvent& e : performed->events) {
        ready = e.name == "p:ready" ? e.time : ready;
        relax = e.name == "p:relax" ? e.time : relax;
    }
    ASSERT_LT(ready, relax);
    for (const double t : {ready, 0.5 * (ready + relax), relax}) {
        SCOPED_TRACE("at " + std::to_string(t) + " s");
        EXPECT_LT(aimError(authored, t), 1.0);
        EXPECT_NEAR(aimError(authored, t), aimError(*liveStage, t), 0.05);
    }

    // Without its pointing the entry points elsewhere: the aim is what the format adds.
    Scenario unaimed = *read;
    unaimed.characters[0].layers.back().actions.back().pointing.reset();
    auto plain = buildRuntime(unaimed, resources());
    ASSERT_TRUE(plain) << core::describe(plain.error());
    EXPECT_TRUE(plain->characters[0].pointing.empty());
    runtime::Stage gestureOnly(*plain);
    EXPECT_GT(aimError(gestureOnly, 0.5 * (ready + relax)), 10.0);
    // Before the action and after it, the aim changes nothing.
    runtime::PoseSet a = authored.makePoseSet(), b = gestureOnly.makePoseSet();
    for (const double t : {kAt - 0.1, performed->end + 0.2}) {
        authored.evaluate(secondsToTicks(t), a);
        gestureOnly.evaluate(secondsToTicks(t), b);
        EXPECT_EQ(a.characters[0].body, b.characters[0].body) << "at " << t << " s";
    }
}

TEST(ScenarioPointing, AMutedLayerDoesNotPoint)
{
    Scenario s = demo();
    ActionSpec& wave = s.characters[0].layers[0].actions[1];
    wave.pointing = PointingSpec{kTarget, "RIGHT_HAND"};
    auto built = buildRuntime(s, resources());
    ASSERT_TRUE(built);
    EXPECT_EQ(built->characters[0].pointing.size(), 1u);
    s.characters[0].layers[0].mute = true;
    auto muted = buildRuntime(s, resources());
    ASSERT_TRUE(muted);
    EXPECT_TRUE(muted->characters[0].pointing.empty());
}

} // namespace thespis::test
