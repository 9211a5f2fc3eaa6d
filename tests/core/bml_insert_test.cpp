// A BML block put on the demo's timeline (edit::insertBml, what the studio's Insert and `thespis-cli
// speak --bml` do): its behaviours land on their layers at the times the live realizer plays them,
// in one undo step, and played back from the saved scenario Creon looks Antigone in the eyes while
// he speaks and lets go after; a muted gaze layer does nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "edit/bml_edits.h"
#include "edit/document_edits.h"
#include "motion/gaze.h"
#include "runtime/bml_performance.h"
#include "runtime/stage.h"
#include "scenario/scenario_io.h"
#include "scene/fap.h"
#include "test_support.h"

namespace thespis::test {
namespace {

namespace speech = core::speech;
namespace runtime = core::runtime;
namespace scenario = core::scenario;
using core::anim::Quatd;
using core::anim::Vec3d;
using core::secondsToTicks;

constexpr double kDegree = std::numbers::pi / 180;
constexpr double kAt = 1.0; // seconds: where the block goes on the timeline

constexpr const char* kBlock = R"(<bml id="bml1" characterId="Creon">
  <speech id="s1"><text>Hear me, <sync id="t1"/>Antigone, daughter of Oedipus.</text></speech>
  <gesture id="g1" lexeme="BEAT" stroke="s1:t1"/>
  <head id="h1" lexeme="NOD" start="g1:stroke + 0.3" repetition="2"/>
  <faceLexeme id="f1" lexeme="RAISE_BROWS" start="s1:start" end="s1:end"/>
  <gaze id="z1" target="Antigone" influence="HEAD" start="s1:start" end="s1:end"/>
</bml>)";

struct Demo {
    scenario::Scenario document;
    scenario::ScenarioRuntime runtime;
};

Demo demo()
{
    Demo d;
    auto loaded = scenario::loadScenario(resources("demo.thespis"));
    EXPECT_TRUE(loaded) << core::describe(loaded.error());
    d.document = std::move(loaded).value();
    auto built = scenario::buildRuntime(d.document, resources());
    EXPECT_TRUE(built) << core::describe(built.error());
    d.runtime = std::move(built).value();
    return d;
}

const scenario::Layer* layerNamed(const scenario::Character& character, const std::string& name)
{
    for (const scenario::Layer& layer : character.layers)
        if (layer.name == name)
            return &layer;
    return nullptr;
}

double length(const Vec3d& v) { return std::sqrt(core::anim::dot(v, v)); }
double angleBetween(const Vec3d& a, const Vec3d& b)
{
    return std::acos(std::clamp(core::anim::dot(a, b) / (length(a) * length(b)), -1.0, 1.0)) / kDegree;
}

// Where a character's eyes are and look, in the scene: its head turned by the eyeball FAPs.
struct Look {
    Vec3d eyes, direction;
};
Look lookOf(const runtime::CharacterPose& pose, const core::anim::Skeleton& skeleton)
{
    const auto rig = core::motion::GazeRig::create(skeleton).value();
    std::vector<Vec3d> positions(std::size_t(skeleton.jointCount()));
    std::vector<Quatd> orientations(positions.size());
    skeleton.worldTransforms(pose.body, positions, orientations);
    const Quatd placement{pose.placement.rotation.x, pose.placement.rotation.y, pose.placement.rotation.z,
                          pose.placement.rotation.w};
    const Vec3d shift{pose.placement.translation.x, pose.placement.translation.y, pose.placement.translation.z};
    const auto head = std::size_t(skeleton.find("skullbase"));
    const Quatd orientation = placement * orientations[head];
    const auto fap = [&](int n) { return double(pose.face[std::size_t(core::scene::fapChannel(n))]) * 1e-5; };
    const double yaw = fap(23), pitch = fap(25);
    const Quatd eye = Quatd{0, std::sin(yaw / 2), 0, std::cos(yaw / 2)} * Quatd{std::sin(pitch / 2), 0, 0, std::cos(pitch / 2)};
    return {core::anim::rotate(placement, positions[head] + core::anim::rotate(orientations[head], rig.eyes)) + shift,
            core::anim::rotate(orientation * eye, Vec3d{0, 0, 1})};
}

// The share of frames from `from` to `to` seconds in which Creon looks within 5° of Antigone's eyes (Eyes
// Alive's saccades take his eyes a few degrees off now and then);
// `angles` gets the angle of each frame (degrees), for messages.
double shareLookingAtHer(const scenario::ScenarioRuntime& built, double from, double to, std::string* angles = nullptr)
{
    runtime::Stage stage(built);
    runtime::PoseSet poses = stage.makePoseSet();
    int on = 0, frames = 0;
    for (double t = 0; t <= to; t += 1.0 / 30) {
        stage.evaluate(secondsToTicks(t), poses);
        if (t < from)
            continue;
        const Look creon = lookOf(poses.characters[0], built.characters[0].skeleton);
        const Look antigone = lookOf(poses.characters[1], built.characters[1].skeleton);
        ++frames;
        const double angle = angleBetween(creon.direction, antigone.eyes - creon.eyes);
        on += angle < 5.0;
        if (angles)
            *angles += std::to_string(int(std::lround(angle))) + " ";
    }
    return double(on) / std::max(frames, 1);
}

} // namespace

TEST(BmlInsert, EachBehaviourLandsOnItsLayerWhenTheRealizerPlaysIt)
{
    Demo d = demo();
    ASSERT_EQ(d.document.characters[0].name, "Creon");
    auto block = speech::parseBml(kBlock);
    ASSERT_TRUE(block) << block.error().message;
    const speech::VoiceSettings voice{.voice = "en-gb", .wordsPerMinute = 140};
    auto said = speech::speak(block->behaviors[0].text, voice);
    ASSERT_TRUE(said) << said.error().message;
    const std::map<std::string, speech::Utterance> spoken{{"s1", *said}};

    core::edit::BmlInsertOptions options;
    options.voice = voice;
    auto inserted = core::edit::insertBml(d.document, d.runtime, 0, *block, spoken, options, secondsToTicks(kAt));
    ASSERT_TRUE(inserted) << inserted.error().message;
    EXPECT_EQ(inserted->speeches, 1);
    EXPECT_EQ(inserted->gestures, 1);
    EXPECT_EQ(inserted->headGestures, 1);
    EXPECT_EQ(inserted->faceLexemes, 1);
    EXPECT_EQ(inserted->gazes, 1);
    EXPECT_GT(inserted->visemeActions, 20);
    scenario::Scenario after = d.document;
    ASSERT_TRUE(inserted->edit.apply(after));

    // The live realizer, given the same speech, says when each behaviour starts and ends.
    auto stage = std::make_shared<runtime::Stage>(d.runtime);
    runtime::BmlRealizer realizer(stage, nullptr);
    runtime::BmlOptions live;
    live.voice = voice;
    live.spoken = std::make_shared<const std::map<std::string, speech::Utterance>>(spoken);
    auto performed = realizer.perform("Creon", *block, live, secondsToTicks(kAt));
    ASSERT_TRUE(performed) << performed.error().message;
    const auto when = [&](const std::string& event) {
        for (const runtime::BmlEvent& e : performed->events)
            if (e.name == event)
                return e.time;
        ADD_FAILURE() << event;
        return -1.0;
    };

    auto rebuilt = scenario::buildRuntime(after, resources());
    ASSERT_TRUE(rebuilt) << core::describe(rebuilt.error());
    const scenario::Character& creon = after.characters[0];
    const auto spanOf = [&](const std::string& layer, int action) {
        const scenario::Layer* found = layerNamed(creon, layer);
        EXPECT_TRUE(found) << layer;
        const int l = int(found - creon.layers.data());
        return core::edit::actionSpan(after, *rebuilt, {0, l, action}).value();
    };
    const double tick = core::ticksToSeconds(1) * 2;
    struct Expected {
        const char* layer;
        int action;
        const char* behaviour;
    };
    const int gestureIndex = int(layerNamed(creon, "Gestures")->actions.size()) - 1;
    for (const Expected& e : {Expected{"Gestures", gestureIndex, "g1"}, Expected{"Head", 0, "h1"},
                              Expected{"Face lexemes", 0, "f1"}}) {
        SCOPED_TRACE(e.behaviour);
        const core::edit::ActionSpan span = spanOf(e.layer, e.action);
        EXPECT_NEAR(core::ticksToSeconds(span.start), when(std::string(e.behaviour) + ":start"), tick);
        EXPECT_NEAR(core::ticksToSeconds(span.end), when(std::string(e.behaviour) + ":end"), 0.04);
    }
    // The gaze holds from the speech's start to its end (its relax: a gaze lets go there).
    const core::edit::ActionSpan gaze = spanOf("Gaze", 0);
    EXPECT_NEAR(core::ticksToSeconds(gaze.start), when("s1:start"), tick);
    EXPECT_NEAR(core::ticksToSeconds(gaze.end), when("s1:end"), tick);
    EXPECT_EQ(layerNamed(creon, "Gaze")->kind, scenario::LayerKind::Gaze);
    EXPECT_EQ(layerNamed(creon, "Head")->mode, core::anim::BlendMode::Additive);
    ASSERT_EQ(creon.speech.size(), d.document.characters[0].speech.size() + 1);
    EXPECT_EQ(creon.speech.back().text, "Hear me, Antigone, daughter of Oedipus.");
    EXPECT_EQ(creon.speech.back().start, secondsToTicks(kAt));

    // One undo step gives the demo back.
    scenario::Scenario undone = after;
    ASSERT_TRUE(inserted->edit.inverse().apply(undone));
    EXPECT_EQ(undone, d.document);

    // Saved and read back it is the same; an unconstrained gaze holds until the block ends.
    const auto path = artifact("bml_insert") / "demo_bml.thespis";
    std::filesystem::create_directories(path.parent_path());
    ASSERT_TRUE(scenario::saveScenario(path, after));
    auto read = scenario::loadScenario(path);
    ASSERT_TRUE(read) << core::describe(read.error());
    EXPECT_EQ(read->characters[0].layers, creon.layers);
}

TEST(BmlInsert, PlayedBackCreonLooksAntigoneInTheEyesWhileHeSpeaksAndLetsGoAfter)
{
    Demo d = demo();
    auto block = speech::parseBml(kBlock);
    ASSERT_TRUE(block);
    const speech::VoiceSettings voice{.voice = "en-gb", .wordsPerMinute = 140};
    auto said = speech::speak(block->behaviors[0].text, voice);
    ASSERT_TRUE(said);
    core::edit::BmlInsertOptions options;
    options.voice = voice;
    // Without the demo's script nobody looks at anybody: only the inserted gaze plays.
    auto inserted = core::edit::insertBml(d.document, d.runtime, 0, *block, {{"s1", *said}}, options, secondsToTicks(kAt));
    ASSERT_TRUE(inserted) << inserted.error().message;
    scenario::Scenario after = d.document;
    ASSERT_TRUE(inserted->edit.apply(after));
    auto built = scenario::buildRuntime(after, resources());
    ASSERT_TRUE(built) << core::describe(built.error());
    ASSERT_EQ(built->characters[0].gaze.size(), 1u);
    const double end = kAt + said->duration();

    const double before = shareLookingAtHer(*built, 0.2, kAt - 0.1);
    std::string angles;
    const double during = shareLookingAtHer(*built, kAt + 0.6, end, &angles);
    // Eyes Alive's listening mode looks away now and then; SmartBody's head takes its time.
    EXPECT_GT(during, 0.8) << "frames looking within 5° of her eyes while he speaks: " << angles;
    EXPECT_LT(before, 0.2);
    runtime::Stage stage(*built);
    runtime::PoseSet poses = stage.makePoseSet();
    for (double t = 0; t <= end + 1.5; t += 1.0 / 30)
        stage.evaluate(secondsToTicks(t), poses);
    EXPECT_FALSE(*stage.gazeState("Creon")) << "let go after the speech";

    // The gaze layer muted, he does not turn to her.
    scenario::Scenario muted = after;
    for (scenario::Layer& layer : muted.characters[0].layers)
        layer.mute = layer.mute || layer.kind == scenario::LayerKind::Gaze;
    auto silent = scenario::buildRuntime(muted, resources());
    ASSERT_TRUE(silent);
    EXPECT_TRUE(silent->characters[0].gaze.empty());
    EXPECT_LT(shareLookingAtHer(*silent, kAt + 0.6, end), 0.2);
}

TEST(BmlInsert, WhatCannotGoOnTheTimelineIsNamed)
{
    Demo d = demo();
    const core::edit::BmlInsertOptions options;
    const std::map<std::string, speech::Utterance> nothingSpoken;
    const auto refused = [&](const char* xml) {
        auto block = speech::parseBml(xml);
        EXPECT_TRUE(block) << block.error().message;
        auto inserted = core::edit::insertBml(d.document, d.runtime, 0, *block, nothingSpoken, options, 0);
        EXPECT_FALSE(inserted);
        return inserted ? std::string() : inserted.error().message;
    };
    EXPECT_NE(refused("<bml id=\"b\">\n <gesture id=\"g\" lexeme=\"JUGGLE\"/></bml>").find("line 2, column 2"),
              std::string::npos);
    EXPECT_NE(refused("<bml id=\"b\"><speech id=\"s\"><text>Hi.</text></speech></bml>").find("not been spoken"),
              std::string::npos);
    EXPECT_NE(refused("<bml id=\"b\"><gaze id=\"z\" target=\"1 2\"/></bml>").find("three numbers"), std::string::npos);
    EXPECT_NE(refused("<bml id=\"b\"><wait id=\"w\" duration=\"1\"/></bml>").find("nothing to insert"),
              std::string::npos);
    // A locked layer stays as it is.
    for (scenario::Layer& layer : d.document.characters[0].layers)
        layer.lock = true;
    auto block = speech::parseBml("<bml id=\"b\"><head id=\"h\" lexeme=\"NOD\"/></bml>");
    ASSERT_TRUE(block);
    scenario::Layer head;
    head.name = "Head";
    head.lock = true;
    d.document.characters[0].layers.push_back(head);
    auto inserted = core::edit::insertBml(d.document, d.runtime, 0, *block, nothingSpoken, options, 0);
    ASSERT_FALSE(inserted);
    EXPECT_NE(inserted.error().message.find("locked"), std::string::npos);
}

} // namespace thespis::test
