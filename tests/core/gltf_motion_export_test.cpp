// bake-motion to glTF 2.0 (scene/gltf_motion_export.h through MotionBakeJob) on real characters
// from ../shared/data: CesiumMan, whose rig the import turns to face +Z, walking a CMU clip on its
// own rig; RobotExpressive, whose IK feet the import hangs from the knees, on the H-Anim LOA1
// skeleton (the motion retargeted onto its rig), with its Head's morph targets driven by face
// layers through the model's face mapping table.
// The .glb read back by the character import gives the baked frames within 1e-4 rad.

#include <gtest/gtest.h>

#include <tiny_gltf.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "anim/quat.h"
#include "runtime/motion_bake_job.h"
#include "scenario/scenario_character.h"
#include "scenario/scenario_runtime.h"
#include "scene/gltf_character.h"
#include "test_support.h"

using namespace thespis::core;
using namespace thespis::core::scenario;
using thespis::core::runtime::MotionBakeJob;
namespace fs = std::filesystem;

namespace {

constexpr double kFps = 30;

fs::path freshFolder(const std::string& name)
{
    const fs::path folder = fs::temp_directory_path() / ("thespis_gltf_motion_" + name);
    fs::remove_all(folder);
    fs::create_directories(folder);
    return folder;
}

Scenario walking(const std::string& model, const std::string& skeleton, const std::string& clipFile)
{
    Scenario s;
    s.name = "glTF motion";
    s.duration = secondsToTicks(2.0);
    Character c;
    c.name = "Walker";
    c.model = model;
    c.skeleton = skeleton;
    ClipAsset clip;
    clip.name = "walk";
    clip.file = clipFile;
    c.clips.push_back(clip);
    Layer layer;
    layer.name = "body";
    ActionSpec action;
    action.name = "walk";
    action.clip = "walk";
    layer.actions.push_back(action);
    c.layers.push_back(layer);
    s.characters.push_back(c);
    return s;
}

::testing::AssertionResult bake(const Scenario& scenario, const fs::path& out, bool animationOnly = false)
{
    MotionBakeJob job;
    job.scenario = scenario;
    job.assets = Assets(out.parent_path());
    job.character = scenario.characters[0].name;
    job.output = out;
    job.fps = kFps;
    job.animationOnly = animationOnly;
    JobContext context;
    if (auto baked = job.run(context); !baked)
        return ::testing::AssertionFailure() << baked.error().message << " " << baked.error().detail;
    return ::testing::AssertionSuccess();
}

/// What the studio poses the model with: the schedule retargeted onto the model's rig.
struct Expected {
    anim::Skeleton skeleton;
    std::vector<float> frames;
};
Expected expectedFrames(const Scenario& scenario, const Assets& assets)
{
    auto runtime = buildRuntime(scenario, assets);
    EXPECT_TRUE(runtime) << runtime.error().message;
    const CharacterRuntime& body = runtime->characters[0];
    auto model = loadCharacterBody(scenario, 0, assets);
    EXPECT_TRUE(model) << model.error().message;
    const anim::FrameRetarget retarget = retargetOntoBody(body.skeleton, *model);
    const std::size_t from = body.skeleton.frameLayout()->floatCount(), to = model->skeleton.frameLayout()->floatCount();
    Expected expected{model->skeleton, {}};
    std::vector<float> source(from), target(to);
    for (int i = 0; i <= int(ticksToSeconds(runtime->duration) * kFps + 1e-6); ++i) {
        body.body->evaluate(double(i) / kFps, source);
        retarget.apply(source, target);
        expected.frames.insert(expected.frames.end(), target.begin(), target.end());
    }
    return expected;
}

/// Reads the .glb back as a character and checks its clip against the baked frames.
void expectSameMotion(const fs::path& glb, const Expected& expected, const std::string& clipName)
{
    scene::GltfCharacterOptions options;
    options.clipFrameRate = kFps;
    options.loadTextures = false;
    auto read = scene::loadGltfCharacter(glb, options);
    ASSERT_TRUE(read) << read.error().message;
    const anim::Skeleton& skeleton = read->skeleton;
    ASSERT_EQ(skeleton.jointCount(), expected.skeleton.jointCount());
    for (int j = 0; j < skeleton.jointCount(); ++j) {
        EXPECT_EQ(skeleton.joint(j).name, expected.skeleton.joint(j).name);
        const anim::Vec3d d = skeleton.joint(j).offset - expected.skeleton.joint(j).offset;
        EXPECT_NEAR(std::sqrt(anim::dot(d, d)), 0.0, 1e-5) << skeleton.joint(j).name;
    }
    const anim::KeyframeClip* clip = nullptr;
    for (const auto& c : read->clips)
        if (c->name() == clipName)
            clip = c.get();
    ASSERT_NE(clip, nullptr) << "no animation " << clipName;
    // Joint by joint: local and world rotations, world positions. (The layouts may differ in
    // which joints translate: a joint that does not move in this motion reads back as fixed.)
    const std::size_t floats = skeleton.frameLayout()->floatCount(), expectedFloats = expected.skeleton.frameLayout()->floatCount();
    const std::size_t frames = expected.frames.size() / expectedFloats;
    ASSERT_EQ(clip->data().size(), frames * floats);
    const auto joints = std::size_t(skeleton.jointCount());
    std::vector<anim::Vec3d> positions(joints), expectedPositions(joints);
    std::vector<anim::Quatd> rotations(joints), expectedRotations(joints);
    double worstAngle = 0, worstMove = 0;
    for (std::size_t f = 0; f < frames; ++f) {
        const std::span<const float> a(clip->data().data() + f * floats, floats);
        const std::span<const float> b(expected.frames.data() + f * expectedFloats, expectedFloats);
        skeleton.worldTransforms(a, positions, rotations);
        expected.skeleton.worldTransforms(b, expectedPositions, expectedRotations);
        for (std::size_t j = 0; j < joints; ++j) {
            const anim::Quatd la{a[4 * j], a[4 * j + 1], a[4 * j + 2], a[4 * j + 3]};
            const anim::Quatd lb{b[4 * j], b[4 * j + 1], b[4 * j + 2], b[4 * j + 3]};
            worstAngle = std::max({worstAngle, anim::angleBetween(anim::normalize(la), anim::normalize(lb)),
                                   anim::angleBetween(rotations[j], expectedRotations[j])});
            const anim::Vec3d d = positions[j] - expectedPositions[j];
            worstMove = std::max(worstMove, std::sqrt(anim::dot(d, d)));
        }
    }
    EXPECT_LT(worstAngle, 1e-4) << "radians, worst joint of any frame";
    EXPECT_LT(worstMove, 1e-4) << "metres";
    // The motion really moves: the last frame is not the first.
    EXPECT_NE(std::vector<float>(clip->data().begin(), clip->data().begin() + long(floats)),
              std::vector<float>(clip->data().end() - long(floats), clip->data().end()));
}

tinygltf::Model readModel(const fs::path& glb)
{
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader([](tinygltf::Image*, int, std::string*, std::string*, int, int, const unsigned char*, int,
                             void*) { return true; },
                          nullptr);
    tinygltf::Model model;
    std::string error, warning;
    EXPECT_TRUE(loader.LoadBinaryFromFile(&model, &error, &warning, glb.string())) << error;
    return model;
}

std::vector<float> floats(const tinygltf::Model& model, int accessorIndex)
{
    const tinygltf::Accessor& accessor = model.accessors[std::size_t(accessorIndex)];
    const tinygltf::BufferView& view = model.bufferViews[std::size_t(accessor.bufferView)];
    const std::size_t components = accessor.type == TINYGLTF_TYPE_VEC4 ? 4 : accessor.type == TINYGLTF_TYPE_VEC3 ? 3 : 1;
    std::vector<float> values(accessor.count * components);
    std::memcpy(values.data(), model.buffers[std::size_t(view.buffer)].data.data() + view.byteOffset + accessor.byteOffset,
                values.size() * sizeof(float));
    return values;
}

/// node name + path → the channel's values.
std::map<std::string, std::vector<float>> channels(const tinygltf::Model& model)
{
    std::map<std::string, std::vector<float>> out;
    for (const tinygltf::AnimationChannel& channel : model.animations.at(0).channels)
        out[model.nodes[std::size_t(channel.target_node)].name + "/" + channel.target_path] =
            floats(model, model.animations[0].samplers[std::size_t(channel.sampler)].output);
    return out;
}

} // namespace

TEST(GltfMotionExport, CesiumManWalksACmuClipOnItsOwnTurnedRig)
{
    const Scenario s = walking(thespis::test::sharedData("characters/CesiumMan/CesiumMan.glb").string(), "model",
                               thespis::test::sharedData("mocap/cmu/02_01.bvh").string());
    const fs::path out = freshFolder("cesium") / "walk.glb";
    ASSERT_TRUE(bake(s, out));
    expectSameMotion(out, expectedFrames(s, Assets(out.parent_path())), "Walker");
    // The model travels whole: its mesh, skin and texture are in the one file.
    const tinygltf::Model model = readModel(out);
    EXPECT_EQ(model.meshes.size(), 1u);
    EXPECT_EQ(model.skins.size(), 1u);
    ASSERT_EQ(model.images.size(), 1u);
    EXPECT_GE(model.images[0].bufferView, 0);
    EXPECT_EQ(model.buffers.size(), 1u);
    EXPECT_EQ(model.animations.size(), 1u);
}

TEST(GltfMotionExport, RobotExpressiveTakesAnHAnimSkeletonsMotionRetargeted)
{
    const Scenario s = walking(thespis::test::sharedData("characters/RobotExpressive/RobotExpressive.glb").string(),
                               "hanim-loa1", thespis::test::sharedData("mocap/cmu/02_01.bvh").string());
    const fs::path folder = freshFolder("robot");
    ASSERT_TRUE(bake(s, folder / "walk.glb"));
    const Expected expected = expectedFrames(s, Assets(folder));
    expectSameMotion(folder / "walk.glb", expected, "Walker");

    // Animation only: the nodes and the same channels, nothing else.
    ASSERT_TRUE(bake(s, folder / "walk_only.glb", true));
    const tinygltf::Model whole = readModel(folder / "walk.glb"), only = readModel(folder / "walk_only.glb");
    EXPECT_TRUE(only.meshes.empty() && only.skins.empty() && only.images.empty() && only.materials.empty());
    ASSERT_EQ(only.nodes.size(), whole.nodes.size());
    EXPECT_EQ(channels(only), channels(whole));
    EXPECT_LT(fs::file_size(folder / "walk_only.glb"), fs::file_size(folder / "walk.glb") / 2);
}

/// A copy of RobotExpressive whose Head's three targets (Angry, Surprised, Sad) are renamed.
void writeRenamedRobot(const fs::path& file, const std::vector<std::string>& targetNames, int& head)
{
    tinygltf::Model robot = readModel(thespis::test::sharedData("characters/RobotExpressive/RobotExpressive.glb"));
    head = -1;
    for (std::size_t m = 0; m < robot.meshes.size(); ++m)
        if (robot.meshes[m].name == "Head")
            head = int(m);
    ASSERT_GE(head, 0);
    tinygltf::Value::Array names;
    for (const std::string& name : targetNames)
        names.emplace_back(name);
    tinygltf::Value::Object extras{{"targetNames", tinygltf::Value(names)}};
    robot.meshes[std::size_t(head)].extras = tinygltf::Value(extras);
    std::ostringstream bytes;
    ASSERT_TRUE(tinygltf::TinyGLTF().WriteGltfSceneToStream(&robot, bytes, false, true));
    std::ofstream(file, std::ios::binary) << bytes.str();
}

/// The walk with a face layer playing `scalars` keyed at 2 fps.
Scenario walkingWithFace(const std::string& model, std::vector<std::string> scalars, std::vector<float> frames)
{
    Scenario s = walking(model, "model", thespis::test::sharedData("mocap/cmu/02_01.bvh").string());
    ClipAsset face;
    face.name = "face";
    face.frameRate = 2;
    face.scalars = std::move(scalars);
    face.frames = std::move(frames);
    s.characters[0].clips.push_back(face);
    Layer faceLayer;
    faceLayer.name = "face";
    faceLayer.kind = LayerKind::Face;
    ActionSpec action;
    action.name = "face";
    action.clip = "face";
    faceLayer.actions.push_back(action);
    s.characters[0].layers.push_back(faceLayer);
    return s;
}

namespace {

// The face bake of "Walker" in `folder` into face.glb.
MotionBakeJob walkerBake(const Scenario& s, const fs::path& folder)
{
    MotionBakeJob job;
    job.scenario = s;
    job.assets = Assets(folder);
    job.character = "Walker";
    job.output = folder / "face.glb";
    job.fps = kFps;
    return job;
}

} // namespace

TEST(GltfMotionExport, FaceLayersDriveMorphTargetsNamedAfterTheirFaps)
{
    // RobotExpressive's Head has the targets Angry, Surprised and Sad; a copy names two of them
    // after FAPs, as an artist would name a face rig's targets for Thespis.
    const fs::path folder = freshFolder("face");
    int head = -1;
    writeRenamedRobot(folder / "robot_faps.glb", {"fap19", "Surprised", "FAP21"}, head);
    const Scenario s = walkingWithFace("robot_faps.glb", {"fap19", "fap21"},
                                       {0.0f, 0.0f, 1.0f, 0.25f, 0.5f, 1.0f, 0.0f, 0.0f, 0.0f, 0.0f});

    MotionBakeJob job = walkerBake(s, folder);
    JobContext context;
    auto baked = job.run(context);
    ASSERT_TRUE(baked) << baked.error().message;
    // Surprised is the model's own surprise (its name is recognised): driven, though at 0 here.
    EXPECT_EQ(job.morphTargets,
              (std::vector<std::string>{"mesh Head: fap19", "mesh Head: Surprised", "mesh Head: FAP21"}));

    const tinygltf::Model out = readModel(folder / "face.glb");
    auto runtime = buildRuntime(s, Assets(folder));
    ASSERT_TRUE(runtime);
    const anim::FrameLayout& faceLayout = *runtime->characters[0].face->layout();
    std::vector<float> frame(faceLayout.floatCount());
    int weightChannels = 0;
    for (const tinygltf::AnimationChannel& channel : out.animations.at(0).channels) {
        if (channel.target_path != "weights")
            continue;
        ++weightChannels;
        EXPECT_EQ(out.nodes[std::size_t(channel.target_node)].mesh, head);
        const std::vector<float> weights = floats(out, out.animations[0].samplers[std::size_t(channel.sampler)].output);
        ASSERT_EQ(weights.size(), 61u * 3u);
        for (std::size_t f = 0; f < 61; ++f) {
            runtime->characters[0].face->evaluate(double(f) / kFps, frame);
            EXPECT_FLOAT_EQ(weights[3 * f], frame[faceLayout.scalarOffset() + 18]);     // fap19
            EXPECT_FLOAT_EQ(weights[3 * f + 1], 0.0f);                                  // Surprised: no surprise plays
            EXPECT_FLOAT_EQ(weights[3 * f + 2], frame[faceLayout.scalarOffset() + 20]); // fap21
        }
        EXPECT_FLOAT_EQ(weights[3 * 15], 1.0f); // 0.5 s: the clip's second key
    }
    EXPECT_EQ(weightChannels, 1);
}

TEST(GltfMotionExport, FaceLayersBecomeTheModelsOwnTargetWeightsThroughItsMappingTable)
{
    // The Head's targets renamed as ARKit and expression names: open_jaw reaches jawOpen through
    // the ARKit table (weight 1 at 1536 MNS units, none below 0), anger plays Angry.
    const fs::path folder = freshFolder("face_mapping");
    int head = -1;
    writeRenamedRobot(folder / "robot_arkit.glb", {"Angry", "jawOpen", "Sad"}, head);
    const Scenario s = walkingWithFace("robot_arkit.glb", {"fap3", "expression3"},
                                       {0.0f, 0.0f, 768.0f, 1.0f, 1536.0f, 0.5f, -400.0f, 0.0f, 0.0f, 0.0f});
    MotionBakeJob job = walkerBake(s, folder);
    JobContext context;
    auto baked = job.run(context);
    ASSERT_TRUE(baked) << baked.error().message;
    EXPECT_EQ(job.morphTargets,
              (std::vector<std::string>{"mesh Head: Angry", "mesh Head: jawOpen", "mesh Head: Sad"}));

    const tinygltf::Model out = readModel(folder / "face.glb");
    auto runtime = buildRuntime(s, Assets(folder));
    ASSERT_TRUE(runtime);
    const anim::FrameLayout& faceLayout = *runtime->characters[0].face->layout();
    std::vector<float> frame(faceLayout.floatCount());
    const std::size_t openJaw = faceLayout.scalarOffset() + 2, anger = faceLayout.scalarOffset() + 68 + 14 + 2;
    ASSERT_EQ(faceLayout.scalarNames()[openJaw - faceLayout.scalarOffset()], "fap3");
    ASSERT_EQ(faceLayout.scalarNames()[anger - faceLayout.scalarOffset()], "expression3");
    const std::map<std::string, std::vector<float>> all = channels(out);
    ASSERT_TRUE(all.contains("Head/weights"));
    const std::vector<float>& weights = all.at("Head/weights");
    ASSERT_EQ(weights.size(), 61u * 3u);
    for (std::size_t f = 0; f < 61; ++f) {
        runtime->characters[0].face->evaluate(double(f) / kFps, frame);
        EXPECT_FLOAT_EQ(weights[3 * f], frame[anger]) << f;
        EXPECT_FLOAT_EQ(weights[3 * f + 1], float(1.0 / 1536) * std::max(frame[openJaw], 0.0f)) << f;
        EXPECT_FLOAT_EQ(weights[3 * f + 2], 0.0f) << f;
    }
    EXPECT_FLOAT_EQ(weights[3 * 15 + 1], 0.5f); // 0.5 s: open_jaw 768
    EXPECT_FLOAT_EQ(weights[3 * 30 + 1], 1.0f); // 1 s: open_jaw 1536
    EXPECT_FLOAT_EQ(weights[3 * 45 + 1], 0.0f); // 1.5 s: a closed jaw (−400) does not push jawOpen below 0
}

TEST(GltfMotionExport, RefusesWhatItCannotWrite)
{
    Scenario s = walking("", "hanim-loa1", thespis::test::sharedData("mocap/cmu/02_01.bvh").string());
    MotionBakeJob job;
    job.scenario = s;
    job.character = "Walker";
    job.output = freshFolder("refuse") / "w.glb";
    EXPECT_TRUE(job.validate()); // the built-in humanoid is written whole (gltf_character_export.h)
    job.character = "Nobody";
    auto valid = job.validate();
    ASSERT_FALSE(valid);
    EXPECT_NE(valid.error().message.find("Walker"), std::string::npos) << valid.error().message;
    job.character = "Walker";
    job.output = freshFolder("refuse") / "w.fbx";
    EXPECT_NE(job.validate().error().message.find(".bvh or .glb"), std::string::npos);
}
