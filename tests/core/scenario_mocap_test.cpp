// Real motion capture in scenarios, as a person would look at it: every body clip of
// ../shared/data/mocap played (through a scenario, as the studio and the CLI play it) on the
// built-in humanoid and on the glTF sample characters, the skinned body measured in the scene —
// the soles of its feet on the ground, the body its own height, where it should start. Also the
// glTF characters' own animations on their own rigs, loops that walk on, actions that continue
// where the previous one stopped, and a character's place and heading.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include "anim/hanim.h"
#include "anim/root_motion.h"
#include "render/scenario_scene.h"
#include "scenario/scenario_runtime.h"
#include "test_support.h"

namespace thespis::core::scenario {
namespace {

using test::sharedData;

struct ClipCase {
    const char* file;
    /// The share of frames with a foot within 4 cm of the floor (frames sampled at 10 Hz): most for
    /// walks and stances, less for the stylised walks (131_01/02 step lightly, on their toes) and
    /// the clips that leave the ground (jumps, a cartwheel, a hop, a pirouette).
    double grounded;
};

const ClipCase kClips[] = {
    {"mocap/cmu/01_01.bvh", 0.5},        {"mocap/cmu/02_01.bvh", 0.8},  {"mocap/cmu/05_06.bvh", 0.5},
    {"mocap/cmu/77_02.bvh", 0.8},        {"mocap/cmu/111_28.bvh", 0.8}, {"mocap/cmu/113_21.bvh", 0.8},
    {"mocap/cmu/131_01.bvh", 0.6},       {"mocap/cmu/131_02.bvh", 0.6}, {"mocap/cmu/131_03.bvh", 0.5},
    {"mocap/cmu/140_06.bvh", 0.8},       {"mocap/cmu/140_07.bvh", 0.8}, {"mocap/cmu/141_16.bvh", 0.8},
    {"mocap/cmu/141_20.bvh", 0.8},       {"mocap/threejs/pirouette.bvh", 0.5},
    {"mocap/makehuman/walk1.bvh", 0.8},  {"mocap/other/Boxing_Toes.bvh", 0.8},
};

struct Body {
    const char* name;
    const char* model;    ///< empty: the built-in humanoid
    const char* skeleton;
};

const Body kBodies[] = {
    {"humanoid", "", "hanim-loa1"},
    {"robot", "characters/RobotExpressive/RobotExpressive.glb", "model"},
    {"cesium", "characters/CesiumMan/CesiumMan.glb", "model"},
    {"figure", "characters/RiggedFigure/RiggedFigure.gltf", "model"},
};

Scenario oneClip(const Body& body, const std::string& file, const std::string& animation = {})
{
    Scenario s;
    s.name = "mocap";
    Character c;
    c.name = body.name;
    c.model = body.model;
    c.skeleton = body.skeleton;
    ClipAsset clip;
    clip.name = "motion";
    clip.file = file;
    clip.animation = animation;
    c.clips.push_back(clip);
    Layer layer;
    layer.name = "body";
    ActionSpec action;
    action.name = "motion";
    action.clip = "motion";
    action.placement = Placement::Character;
    layer.actions.push_back(action);
    c.layers.push_back(layer);
    s.characters.push_back(c);
    return s;
}

bool isFootJoint(const std::string& joint)
{
    for (const char* foot : {"talocrural", "tarsometatarsal", "metatarsophalangeal", "tarsal_interphalangeal"})
        if (joint.find(foot) != std::string::npos)
            return true;
    return false;
}

struct Seen {
    double lowestSole = 1e9, highestSole = -1e9; ///< per frame the lowest foot vertex, over the clip
    double groundedShare = 0;                    ///< frames whose lowest foot vertex is within 4 cm of the floor
    double restHeight = 0, firstHeight = 0;      ///< the body's height at rest and in the first frame
    double startDistance = 0;                    ///< from the character's place to its hips in the first frame
};

// Poses the scene every 1/10 s (1/2 s under sanitizers) and measures the skinned body.
Seen watch(render::ScenarioScene& scene)
{
    Seen seen;
    const render::CharacterNode& node = scene.scene().character(0);
    const scene::Character& character = node.character();
    std::vector<std::size_t> feet;
    for (std::size_t s = 0; s < character.mesh.segments.size(); ++s)
        if (isFootJoint(character.mesh.segments[s].joint))
            feet.push_back(s);
    EXPECT_FALSE(feet.empty()) << "no foot segments";
    const auto height = [&] {
        const render::Bounds b = node.bounds();
        return b.max.y - b.min.y;
    };
    const auto lowestFoot = [&] {
        double lowest = 1e9;
        for (std::size_t s : feet) {
            const scene::Segment& segment = character.mesh.segments[s];
            for (std::uint32_t v = segment.firstVertex; v < segment.firstVertex + segment.vertexCount; ++v)
                lowest = std::min(lowest, double(node.posedPositions()[v].y));
        }
        return lowest;
    };
    scene.playAt(core::secondsToTicks(-1.0)); // before the action: the rest pose where the character stands
    seen.restHeight = height();
    const double floor = lowestFoot(); // a model's soles may rest a little below y = 0
#ifdef THESPIS_SANITIZED
    const double step = 0.5;
#else
    const double step = 0.1;
#endif
    int frames = 0, grounded = 0;
    for (double t = 0; t <= core::ticksToSeconds(scene.duration()); t += step) {
        scene.playAt(core::secondsToTicks(t));
        const double lowest = lowestFoot() - floor;
        if (t == 0) {
            seen.firstHeight = height();
            const scenario::CharacterRuntime& runtime = scene.runtime().characters.at(0);
            std::vector<float> frame = runtime.skeleton.restFrame();
            runtime.evaluateBody(0.0, frame);
            const std::vector<anim::Vec3d> joints = runtime.skeleton.worldPositions(frame);
            const anim::Vec3d hips = joints[std::size_t(std::max(0, runtime.skeleton.find("humanoid_root")))];
            seen.startDistance = std::hypot(hips.x, hips.z);
        }
        seen.lowestSole = std::min(seen.lowestSole, lowest);
        seen.highestSole = std::max(seen.highestSole, lowest);
        grounded += std::abs(lowest) < 0.04 * seen.restHeight / 1.8;
        ++frames;
    }
    seen.groundedShare = double(grounded) / frames;
    return seen;
}

TEST(ScenarioMocap, EveryClipStandsOnTheGroundOnEveryBody)
{
    for (const Body& body : kBodies)
        for (const ClipCase& clip : kClips) {
            SCOPED_TRACE(std::string(clip.file) + " on " + body.name);
            auto scene = render::ScenarioScene::create(oneClip(body, clip.file), sharedData());
            ASSERT_TRUE(scene.ok()) << describe(scene.error());
            const Seen seen = watch(**scene);
            std::printf("%-30s on %-9s sole %+.3f … %+.3f m  grounded %.2f  height %.2f of %.2f m  start %.2f m\n",
                        clip.file, body.name, seen.lowestSole, seen.highestSole, seen.groundedShare, seen.firstHeight,
                        seen.restHeight, seen.startDistance);
            // Centimetres, larger on a giant (the robot is 4.5 m tall: a human's on a 1.8 m body).
            const double cm = std::max(seen.restHeight, 1.8) / 180.0;
            // The soles never sink into the floor by more than a toe turning does (2.5 cm), and stand
            // on it: in every frame of a stance, most of a walk, often in a jump.
            EXPECT_GT(seen.lowestSole, -2.5 * cm);
            EXPECT_GE(seen.groundedShare, clip.grounded);
            // The body is its own size (a crouched stance is lower, a jump higher at most by a little).
            EXPECT_LT(seen.firstHeight, seen.restHeight * 1.1);
            EXPECT_GT(seen.firstHeight, seen.restHeight * 0.8);
            // It starts where the character stands.
            EXPECT_LT(seen.startDistance, 30 * cm);
        }
}

// The glTF samples' own animations, on their own rig and on the built-in humanoid.
TEST(ScenarioMocap, GltfAnimationsStandOnTheGround)
{
    const struct {
        const char* model;
        const char* animation;
        double grounded;
    } cases[] = {
        {"characters/RobotExpressive/RobotExpressive.glb", "Walking", 0.8},
        {"characters/RobotExpressive/RobotExpressive.glb", "Idle", 0.8},
        {"characters/RobotExpressive/RobotExpressive.glb", "Wave", 0.8},
        {"characters/RobotExpressive/RobotExpressive.glb", "Jump", 0.3},
        {"characters/RiggedFigure/RiggedFigure.gltf", "", 0.8},
        {"characters/CesiumMan/CesiumMan.glb", "", 0.3}, // a cartoon walk: both feet up as they pass
    };
    for (const auto& c : cases)
        for (const Body& body : {kBodies[0], Body{"own", c.model, "model"}}) {
            SCOPED_TRACE(std::string(c.model) + " " + c.animation + " on " + body.name);
            auto scene = render::ScenarioScene::create(oneClip(body, c.model, c.animation), sharedData());
            ASSERT_TRUE(scene.ok()) << describe(scene.error());
            const Seen seen = watch(**scene);
            const double cm = std::max(seen.restHeight, 1.8) / 180.0;
            EXPECT_GT(seen.lowestSole, -2.5 * cm);
            EXPECT_GE(seen.groundedShare, c.grounded);
            EXPECT_LT(seen.startDistance, 30 * cm);
        }
}

Scenario twoActions(const char* first, double secondStart, const char* second, Placement placement)
{
    Scenario s = oneClip(kBodies[0], first);
    Character& c = s.characters[0];
    c.clips.push_back(c.clips[0]);
    c.clips[1].name = "second";
    c.clips[1].file = second;
    ActionSpec next = c.layers[0].actions[0];
    next.name = "second";
    next.clip = "second";
    next.start = secondsToTicks(secondStart);
    next.placement = placement;
    next.weight = anim::Curve::cubicFade(0.3, 0.3);
    c.layers[0].actions[0].weight = anim::Curve::cubicFade(0.0, 0.3);
    c.layers[0].actions.push_back(next);
    return s;
}

struct RootPose {
    anim::Vec3 position;
    double heading = 0;
};

RootPose rootOf(const anim::BlendablePtr& source, double t)
{
    std::vector<float> frame(source->layout()->floatCount());
    source->evaluate(t, frame);
    const anim::RootElements root = anim::rootElements(*source->layout());
    return {{frame[root.translation], frame[root.translation + 1], frame[root.translation + 2]},
            anim::heading(anim::rotationAt(std::span<const float>(frame), root.rotation))};
}

// "Continue": the next action starts where the previous one leaves the body at its start, facing
// the same way; "character": where the character stands, facing its way.
TEST(ScenarioMocap, ActionsStartWhereTheyArePlaced)
{
    for (const Placement placement : {Placement::Continue, Placement::Character, Placement::World}) {
        auto runtime = buildRuntime(twoActions("mocap/cmu/02_01.bvh", 2.0, "mocap/cmu/141_16.bvh", placement), sharedData());
        ASSERT_TRUE(runtime.ok()) << describe(runtime.error());
        const CharacterRuntime& c = runtime->characters[0];
        const anim::BlendingSchedule& layer = *c.layers[0];
        const anim::BlendingAction* walk = layer.action(c.actionIds[0][0]);
        const anim::BlendingAction* wave = layer.action(c.actionIds[0][1]);
        ASSERT_TRUE(walk && wave);
        const RootPose start = rootOf(wave->source, wave->source->domain().start);
        const RootPose first = rootOf(walk->source, walk->source->domain().start);
        EXPECT_NEAR(std::hypot(first.position.x, first.position.z), 0.0, 1e-4); // the walk starts at the character
        EXPECT_NEAR(first.heading, 0.0, 1e-4);
        if (placement == Placement::Continue) {
            const RootPose there = rootOf(walk->source, 2.0);
            EXPECT_GT(std::hypot(there.position.x, there.position.z), 1.0); // two seconds of walking
            EXPECT_NEAR(start.position.x, there.position.x, 1e-3);
            EXPECT_NEAR(start.position.z, there.position.z, 1e-3);
            EXPECT_NEAR(start.heading, there.heading, 1e-3);
        } else if (placement == Placement::Character) {
            EXPECT_NEAR(std::hypot(start.position.x, start.position.z), 0.0, 1e-4);
            EXPECT_NEAR(start.heading, 0.0, 1e-4);
        } else {
            EXPECT_GT(std::hypot(start.position.x, start.position.z), 0.5); // as recorded, elsewhere
        }
    }
}

// A looped walk with root motion goes on: no jump back at the seams, three times one cycle's way.
TEST(ScenarioMocap, LoopWithRootMotionWalksOn)
{
    Scenario s = oneClip(kBodies[0], "mocap/cmu/02_01.bvh");
    ModifierSpec loop;
    loop.kind = ModifierKind::Loop;
    loop.count = 3;
    loop.rootMotion = true;
    s.characters[0].layers[0].actions[0].modifiers.push_back(loop);
    auto runtime = buildRuntime(s, sharedData());
    ASSERT_TRUE(runtime.ok()) << describe(runtime.error());
    const CharacterRuntime& c = runtime->characters[0];
    const anim::BlendablePtr& source = c.layers[0]->action(c.actionIds[0][0])->source;
    const anim::TimeDomain domain = source->domain();
    const double cycle = domain.duration() / 3.0;
    double largestStep = 0, path = 0, firstCycle = 0;
    RootPose last = rootOf(source, domain.start);
    int steps = 0;
    for (double t = domain.start + 1.0 / 120; t <= domain.end; t += 1.0 / 120) {
        const RootPose now = rootOf(source, t);
        const double step = std::hypot(now.position.x - last.position.x, now.position.z - last.position.z);
        largestStep = std::max(largestStep, step);
        path += step;
        if (t < domain.start + cycle)
            firstCycle = path;
        ++steps;
        last = now;
    }
    EXPECT_LT(largestStep, 4 * path / steps) << "a jump at a seam";
    EXPECT_GT(firstCycle, 1.0);
    // The way walked: three times one cycle's (the walk's own turn makes it curve, not jump).
    EXPECT_NEAR(path, 3 * firstCycle, 0.03 * path);

    // Without root motion the loop jumps back to where the walk started, every cycle.
    s.characters[0].layers[0].actions[0].modifiers[0].rootMotion = false;
    auto plain = buildRuntime(s, sharedData());
    ASSERT_TRUE(plain.ok());
    const anim::BlendablePtr& back = plain->characters[0].layers[0]->action(plain->characters[0].actionIds[0][0])->source;
    const RootPose before = rootOf(back, domain.start + cycle - 1.0 / 120), after = rootOf(back, domain.start + cycle + 1.0 / 120);
    EXPECT_GT(std::hypot(after.position.x - before.position.x, after.position.z - before.position.z), 1.0);
}

// A character's place and heading move its whole motion.
TEST(ScenarioMocap, TheCharacterStandsWhereItIsPut)
{
    Scenario s = oneClip(kBodies[0], "mocap/cmu/113_21.bvh");
    s.characters[0].position = {2.0f, 0.0f, -1.0f};
    s.characters[0].heading = 90.0;
    auto runtime = buildRuntime(s, sharedData());
    ASSERT_TRUE(runtime.ok()) << describe(runtime.error());
    const CharacterRuntime& c = runtime->characters[0];
    std::vector<float> frame = c.skeleton.restFrame();
    c.evaluateBody(0.0, frame);
    const std::vector<anim::Vec3d> joints = c.skeleton.worldPositions(frame);
    const anim::Vec3d hips = joints[std::size_t(c.skeleton.find("humanoid_root"))];
    EXPECT_NEAR(hips.x, 2.0, 0.05);
    EXPECT_NEAR(hips.z, -1.0, 0.05);
    // Facing +X: its left hip is towards −Z.
    EXPECT_LT(joints[std::size_t(c.skeleton.find("l_hip"))].z, joints[std::size_t(c.skeleton.find("r_hip"))].z - 0.1);
}

// What a file brings is told only when it matters: a joint without an H-Anim name whose motion
// reaches nothing of the character (MakeHuman's jaw and eyes on a humanoid), not CMU's hip
// joints (the legs below carry their turn) nor a model's own joints played on its own rig.
TEST(ScenarioMocap, WarnsOfJointsThatMoveNothingOnly)
{
    const auto warningsOf = [](const Scenario& s) {
        auto built = buildRuntime(s, sharedData());
        EXPECT_TRUE(built.ok()) << built.error().message;
        return built.ok() ? built->characters.at(0).warnings : std::vector<std::string>{};
    };
    EXPECT_EQ(warningsOf(oneClip(kBodies[0], "mocap/cmu/02_01.bvh")), std::vector<std::string>{});
    EXPECT_EQ(warningsOf(oneClip(kBodies[1], "characters/RobotExpressive/RobotExpressive.glb", "Walking")),
              std::vector<std::string>{});
    const auto makeHuman = warningsOf(oneClip(kBodies[0], "mocap/makehuman/walk1.bvh"));
    ASSERT_EQ(makeHuman.size(), 1u);
    EXPECT_NE(makeHuman[0].find("clip \"motion\": 18 joints of the file have no H-Anim name and move nothing"),
              std::string::npos) << makeHuman[0];
    EXPECT_NE(makeHuman[0].find("Jaw"), std::string::npos);
    const auto robotOnHumanoid = warningsOf(oneClip(kBodies[0], "characters/RobotExpressive/RobotExpressive.glb", "Walking"));
    ASSERT_EQ(robotOnHumanoid.size(), 1u);
    EXPECT_NE(robotOnHumanoid[0].find("PoleTarget.L, PoleTarget.R"), std::string::npos) << robotOnHumanoid[0];
}

// Bad files are refused with the reader's words, naming the file; nothing plays half.
TEST(ScenarioMocap, BadClipFilesSayWhatAndWhere)
{
    Scenario missing = oneClip(kBodies[0], "characters/RobotExpressive/RobotExpressive.glb", "Moonwalk");
    auto refused = buildRuntime(missing, sharedData());
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().message.find("RobotExpressive.glb has no animation named \"Moonwalk\" (it has Dance, Death"),
              std::string::npos)
        << refused.error().message;

    Scenario face = oneClip(kBodies[0], "mocap/makehuman/face-poseunits.bvh");
    refused = buildRuntime(face, sharedData());
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().message.find("it moves no joint of the character's skeleton"), std::string::npos)
        << refused.error().message;

    Scenario notBvh = oneClip(kBodies[0], "vision/calibration/left_intrinsics.yml");
    refused = buildRuntime(notBvh, sharedData());
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().message.find("file \"vision/calibration/left_intrinsics.yml\": left_intrinsics.yml"),
              std::string::npos)
        << refused.error().message;
}

} // namespace
} // namespace thespis::core::scenario
