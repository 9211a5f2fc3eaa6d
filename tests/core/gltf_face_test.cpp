// glTF characters' own faces (gltf_character.h, face_naming.h): morph targets kept as the face's
// targets, recognised with no table written (a small model made here with ARKit and Oculus names,
// eye bones and a second mesh sharing target names), RobotExpressive's expressions played through
// the face deformer and through skinning, checked against offsets computed here from tinygltf's
// own reading of the file, a table naming targets the model lacks, and files the reader cannot
// decode.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <unistd.h>

#include <tiny_gltf.h>

#include "render/character_node.h"
#include "scene/face_naming.h"
#include "scene/gltf_character.h"
#include "scene/gltf_writing.h"
#include "scene/skinning.h"
#include "test_support.h"

namespace thespis::core::scene {
namespace {

namespace fs = std::filesystem;
using anim::Vec3d;

const char* const kRobot = "characters/RobotExpressive/RobotExpressive.glb";

fs::path scratch(const std::string& name)
{
    const fs::path folder = fs::temp_directory_path() / ("thespis_gltf_face_" + std::to_string(::getpid()));
    fs::create_directories(folder);
    return folder / name;
}

const MorphTarget* findTarget(const Character& character, const std::string& name)
{
    for (const MorphTarget& target : character.face.targets)
        if (target.name == name)
            return &target;
    return nullptr;
}

std::vector<float> faceFrame(std::initializer_list<std::pair<int, float>> channels)
{
    std::vector<float> face(kFaceChannelCount, 0.0f);
    for (const auto& [channel, value] : channels)
        face[std::size_t(channel)] = value;
    return face;
}

/// The rest mesh deformed by `face`.
std::vector<Vec3> deformed(const Character& character, const std::vector<float>& face)
{
    FaceDeformer deformer(character);
    std::vector<Vec3> positions = character.mesh.positions, normals = character.mesh.normals;
    deformer.deform(face, positions, normals);
    return positions;
}

/// Every vertex is at rest but the target's, which moved by exactly `weight` × its offsets.
::testing::AssertionResult movedBy(const Character& character, const std::vector<Vec3>& positions,
                                   const std::vector<std::pair<const MorphTarget*, float>>& targets)
{
    std::vector<Vec3> expected = character.mesh.positions;
    for (const auto& [target, weight] : targets)
        for (std::size_t i = 0; i < target->vertices.size(); ++i)
            expected[target->vertices[i]] = expected[target->vertices[i]] + target->offsets[i] * weight;
    for (std::size_t v = 0; v < expected.size(); ++v)
        if (!(positions[v] == expected[v]))
            return ::testing::AssertionFailure() << "vertex " << v << " is at (" << positions[v].x << ", "
                                                 << positions[v].y << ", " << positions[v].z << "), not at ("
                                                 << expected[v].x << ", " << expected[v].y << ", " << expected[v].z << ")";
    return ::testing::AssertionSuccess();
}

// ---- a small model with ARKit and Oculus names -------------------------------------------------------

/// A head (joint "Head", eyes "LeftEye" / "RightEye") with a skinned face grid of 25 vertices
/// and teeth of 4, whose targets are named as ARKit and OVR LipSync name them; both meshes have
/// "jawOpen" and "viseme_aa". browInnerUp rests at weight 0.5.
struct ArkitModel {
    fs::path path;
    std::vector<std::string> faceTargets{"eyeBlinkLeft", "eyeLookInLeft", "jawOpen",    "mouthSmileLeft",
                                         "viseme_aa",    "viseme_PP",     "viseme_sil", "browInnerUp"};
    /// File offset of face target k at grid vertex v (zero on most vertices: targets are sparse).
    static Vec3 delta(std::size_t k, std::size_t v)
    {
        if (k == 6 || v % 4 != k % 4) // viseme_sil moves nothing
            return {};
        return {0.001f * float(k + 1), -0.002f * float(v % 5), 0.0005f};
    }
    static Vec3 facePosition(std::size_t v) { return {-0.1f + 0.05f * float(v % 5), 1.55f + 0.05f * float(v / 5), 0.1f}; }
};

int addFloats(tinygltf::Model& model, const std::vector<Vec3>& values, int target = TINYGLTF_TARGET_ARRAY_BUFFER)
{
    std::vector<float> flat;
    for (const Vec3& v : values)
        flat.insert(flat.end(), {v.x, v.y, v.z});
    return gltf::addAccessor(model, flat, TINYGLTF_TYPE_VEC3, 3, true, target);
}

ArkitModel writeArkitModel()
{
    ArkitModel made;
    made.path = scratch("arkit_head.glb");
    tinygltf::Model model;
    model.asset.version = "2.0";
    model.buffers.emplace_back();
    const auto node = [&](const std::string& name, std::vector<double> translation, std::vector<int> children) {
        tinygltf::Node n;
        n.name = name;
        n.translation = std::move(translation);
        n.children = std::move(children);
        model.nodes.push_back(n);
    };
    node("Armature", {0, 0, 0}, {1});
    node("Head", {0, 1.6, 0}, {2, 3});
    node("LeftEye", {0.03, 0.05, 0.08}, {});
    node("RightEye", {-0.03, 0.05, 0.08}, {});
    const Vec3d world[] = {{0, 1.6, 0}, {0.03, 1.65, 0.08}, {-0.03, 1.65, 0.08}};
    tinygltf::Skin skin;
    skin.joints = {1, 2, 3};
    std::vector<float> inverseBind;
    for (const Vec3d& w : world)
        inverseBind.insert(inverseBind.end(), {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, float(-w.x), float(-w.y), float(-w.z), 1});
    skin.inverseBindMatrices = gltf::addAccessor(model, inverseBind, TINYGLTF_TYPE_MAT4, 16, false);
    model.skins.push_back(skin);

    const auto mesh = [&](const std::string& name, const std::vector<Vec3>& positions,
                          const std::vector<std::uint16_t>& triangles, const std::vector<std::string>& names,
                          const std::vector<std::vector<Vec3>>& deltas, std::vector<double> weights) {
        tinygltf::Primitive primitive;
        primitive.attributes["POSITION"] = addFloats(model, positions);
        const std::vector<std::uint16_t> joints(positions.size() * 4, 0);
        primitive.attributes["JOINTS_0"] = gltf::addIntegerAccessor(model, joints.data(), joints.size() * 2,
                                                                    TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                                                                    TINYGLTF_TYPE_VEC4, positions.size(),
                                                                    TINYGLTF_TARGET_ARRAY_BUFFER);
        std::vector<float> skinWeights;
        for (std::size_t v = 0; v < positions.size(); ++v)
            skinWeights.insert(skinWeights.end(), {1, 0, 0, 0});
        primitive.attributes["WEIGHTS_0"] = gltf::addAccessor(model, skinWeights, TINYGLTF_TYPE_VEC4, 4, false,
                                                              TINYGLTF_TARGET_ARRAY_BUFFER);
        primitive.indices = gltf::addIntegerAccessor(model, triangles.data(), triangles.size() * 2,
                                                     TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_SCALAR,
                                                     triangles.size(), TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
        primitive.mode = TINYGLTF_MODE_TRIANGLES;
        for (const std::vector<Vec3>& delta : deltas)
            primitive.targets.push_back({{"POSITION", addFloats(model, delta)}});
        tinygltf::Mesh m;
        m.name = name;
        m.primitives.push_back(primitive);
        m.weights = std::move(weights);
        tinygltf::Value::Array list;
        for (const std::string& n : names)
            list.emplace_back(n);
        m.extras = tinygltf::Value(tinygltf::Value::Object{{"targetNames", tinygltf::Value(list)}});
        model.meshes.push_back(m);
        tinygltf::Node n;
        n.name = name;
        n.mesh = int(model.meshes.size() - 1);
        n.skin = 0;
        model.nodes.push_back(n);
    };
    std::vector<Vec3> grid;
    for (std::size_t v = 0; v < 25; ++v)
        grid.push_back(ArkitModel::facePosition(v));
    std::vector<std::uint16_t> triangles;
    for (std::uint16_t r = 0; r < 4; ++r)
        for (std::uint16_t c = 0; c < 4; ++c) {
            const std::uint16_t a = std::uint16_t(r * 5 + c);
            triangles.insert(triangles.end(), {a, std::uint16_t(a + 1), std::uint16_t(a + 6), a, std::uint16_t(a + 6),
                                               std::uint16_t(a + 5)});
        }
    std::vector<std::vector<Vec3>> deltas;
    for (std::size_t k = 0; k < made.faceTargets.size(); ++k) {
        deltas.emplace_back();
        for (std::size_t v = 0; v < grid.size(); ++v)
            deltas.back().push_back(ArkitModel::delta(k, v));
    }
    mesh("Face", grid, triangles, made.faceTargets, deltas, {0, 0, 0, 0, 0, 0, 0, 0.5});
    const std::vector<Vec3> teeth{{-0.02f, 1.56f, 0.09f}, {0.02f, 1.56f, 0.09f}, {0.02f, 1.58f, 0.09f}, {-0.02f, 1.58f, 0.09f}};
    mesh("Teeth", teeth, {0, 1, 2, 0, 2, 3}, {"jawOpen", "viseme_aa"},
         {std::vector<Vec3>(4, Vec3{0, -0.01f, 0}), std::vector<Vec3>(4, Vec3{0, -0.005f, 0.001f})}, {});
    tinygltf::Scene scene;
    scene.nodes = {0, 4, 5};
    model.scenes.push_back(scene);
    model.defaultScene = 0;
    const Result<void> written = gltf::writeGlb(model, made.path);
    EXPECT_TRUE(written) << (written ? "" : written.error().message);
    return made;
}

const MorphDrive* findDrive(const Character& character, const std::string& target, int channel)
{
    for (const MorphDrive& drive : character.face.drives)
        if (character.face.targets[std::size_t(drive.target)].name == target && drive.channel == channel)
            return &drive;
    return nullptr;
}

TEST(GltfFace, ArkitAndOculusNamesAreMappedWithNoTableWritten)
{
    const ArkitModel made = writeArkitModel();
    Result<Character> loaded = loadGltfCharacter(made.path);
    ASSERT_TRUE(loaded) << loaded.error().message;
    const Character& character = *loaded;
    for (const std::string& warning : character.warnings)
        EXPECT_EQ(warning.find("face mapping"), std::string::npos) << warning;

    // The targets, one per name: the teeth's jawOpen and viseme_aa joined the face's.
    EXPECT_EQ(morphTargetNames(character), (std::vector<std::string>{"eyeBlinkLeft", "eyeLookInLeft", "jawOpen",
                                                                     "mouthSmileLeft", "viseme_aa", "viseme_PP",
                                                                     "viseme_sil", "browInnerUp"}));
    const MorphTarget* jawOpen = findTarget(character, "jawOpen");
    ASSERT_NE(jawOpen, nullptr);
    EXPECT_EQ(jawOpen->vertices.size(), 6u + 4u); // grid vertices 2, 6, 10 … 22 and the 4 teeth
    ASSERT_NE(findTarget(character, "viseme_sil"), nullptr);
    EXPECT_TRUE(findTarget(character, "viseme_sil")->vertices.empty());

    const FaceMapping mapping = recogniseFaceMapping(character);
    EXPECT_NE(mapping.name.find("ARKit blendshapes"), std::string::npos) << mapping.name;
    EXPECT_NE(mapping.name.find("Oculus visemes"), std::string::npos) << mapping.name;
    EXPECT_NE(mapping.name.find("eye bones"), std::string::npos) << mapping.name;

    // FAPs drive the ARKit shapes, one-sided; visemes drive their Oculus targets only.
    const MorphDrive* open = findDrive(character, "jawOpen", fapChannel(3));
    ASSERT_NE(open, nullptr);
    EXPECT_FLOAT_EQ(open->coefficient, 1.0f / 1536);
    EXPECT_EQ(open->side, MorphDrive::Side::Positive);
    ASSERT_NE(findDrive(character, "eyeBlinkLeft", fapChannel(19)), nullptr);
    ASSERT_NE(findDrive(character, "eyeBlinkLeft", fapChannel(21)), nullptr);
    ASSERT_NE(findDrive(character, "viseme_aa", visemeChannel(10)), nullptr);
    ASSERT_NE(findDrive(character, "viseme_PP", visemeChannel(1)), nullptr);
    EXPECT_EQ(findDrive(character, "jawOpen", visemeChannel(10)), nullptr);
    // The eyes turn with their bones, so eyeLookInLeft is left alone.
    for (const MorphDrive& drive : character.face.drives)
        EXPECT_NE(character.face.targets[std::size_t(drive.target)].name, "eyeLookInLeft");
    // Joy has no target of its own: ARKit's smile plays it.
    const MorphDrive* joy = findDrive(character, "mouthSmileLeft", expressionChannel(1));
    ASSERT_NE(joy, nullptr);
    EXPECT_FLOAT_EQ(joy->coefficient, 0.8f);

    // Viseme A: (aa) at weight 1 moves exactly viseme_aa's vertices by its offsets, on both meshes.
    const MorphTarget* aa = findTarget(character, "viseme_aa");
    ASSERT_NE(aa, nullptr);
    EXPECT_TRUE(movedBy(character, deformed(character, faceFrame({{visemeChannel(10), 1.0f}})), {{aa, 1.0f}}));
    // A top lid lowered by the whole eye opening blinks fully; a raised one does not open it wider.
    const MorphTarget* blink = findTarget(character, "eyeBlinkLeft");
    ASSERT_NE(blink, nullptr);
    EXPECT_TRUE(movedBy(character, deformed(character, faceFrame({{fapChannel(19), 1024.0f}})), {{blink, 1.0f}}));
    EXPECT_TRUE(movedBy(character, deformed(character, faceFrame({{fapChannel(19), -300.0f}})), {}));
    // open_jaw of 768 (half of jawOpen's 1536) opens it halfway, teeth included.
    EXPECT_TRUE(movedBy(character, deformed(character, faceFrame({{fapChannel(3), 768.0f}})), {{jawOpen, 0.5f}}));

    // browInnerUp rests at its default weight 0.5: the rest shape has half its offset, and its
    // target keeps the whole offset.
    const MorphTarget* brow = findTarget(character, "browInnerUp");
    ASSERT_TRUE(brow && !brow->vertices.empty());
    const std::uint32_t v = brow->vertices.front();
    const Vec3 file = ArkitModel::delta(7, v); // the face grid comes first, in file order
    EXPECT_NEAR(brow->offsets.front().y, file.y, 1e-7);
    EXPECT_NEAR(character.mesh.positions[v].y, ArkitModel::facePosition(v).y + 0.5f * file.y, 1e-6);

    // FAP 23 (yaw_l_eyeball) of 10000 AU turns the left eye 0.1 rad to the face's left (about +Y).
    const int eye = character.skeleton.find("LeftEye");
    ASSERT_GE(eye, 0);
    FaceDeformer deformer(character);
    std::vector<float> body = character.skeleton.restFrame();
    deformer.turnJoints(faceFrame({{fapChannel(23), 10000.0f}}), body);
    const anim::Quat turned = anim::rotationAt(std::span<const float>(body), eye);
    EXPECT_NEAR(turned.y, std::sin(0.05), 1e-6);
    EXPECT_NEAR(turned.w, std::cos(0.05), 1e-6);
}

// ---- RobotExpressive ----------------------------------------------------------------------------------

using Mat4 = std::array<double, 16>; // column-major

Mat4 multiply(const Mat4& a, const Mat4& b)
{
    Mat4 c{};
    for (int col = 0; col < 4; ++col)
        for (int row = 0; row < 4; ++row)
            for (int k = 0; k < 4; ++k)
                c[std::size_t(col * 4 + row)] += a[std::size_t(k * 4 + row)] * b[std::size_t(col * 4 + k)];
    return c;
}

/// A node's world matrix from its TRS chain, as glTF defines it.
Mat4 worldOf(const tinygltf::Model& model, int node)
{
    Mat4 world{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    for (int n = node; n >= 0;) {
        const tinygltf::Node& nd = model.nodes[std::size_t(n)];
        const double x = nd.rotation.size() == 4 ? nd.rotation[0] : 0, y = nd.rotation.size() == 4 ? nd.rotation[1] : 0,
                     z = nd.rotation.size() == 4 ? nd.rotation[2] : 0, w = nd.rotation.size() == 4 ? nd.rotation[3] : 1;
        const double s[3] = {nd.scale.size() == 3 ? nd.scale[0] : 1, nd.scale.size() == 3 ? nd.scale[1] : 1,
                             nd.scale.size() == 3 ? nd.scale[2] : 1};
        const double r[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
                                {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
                                {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}};
        Mat4 local{};
        for (int col = 0; col < 3; ++col)
            for (int row = 0; row < 3; ++row)
                local[std::size_t(col * 4 + row)] = r[row][col] * s[col];
        for (int row = 0; row < 3; ++row)
            local[std::size_t(12 + row)] = nd.translation.size() == 3 ? nd.translation[std::size_t(row)] : 0;
        local[15] = 1;
        world = multiply(local, world);
        int parent = -1;
        for (std::size_t p = 0; p < model.nodes.size(); ++p)
            for (int child : model.nodes[p].children)
                if (child == n)
                    parent = int(p);
        n = parent;
    }
    return world;
}

Vec3d apply(const Mat4& m, Vec3d p, double w)
{
    return {m[0] * p.x + m[4] * p.y + m[8] * p.z + m[12] * w, m[1] * p.x + m[5] * p.y + m[9] * p.z + m[13] * w,
            m[2] * p.x + m[6] * p.y + m[10] * p.z + m[14] * w};
}

std::vector<Vec3d> vectors(const tinygltf::Model& model, int index)
{
    const tinygltf::Accessor& accessor = model.accessors[std::size_t(index)];
    const tinygltf::BufferView& view = model.bufferViews[std::size_t(accessor.bufferView)];
    const unsigned char* bytes = model.buffers[std::size_t(view.buffer)].data.data() + view.byteOffset + accessor.byteOffset;
    const std::size_t stride = view.byteStride ? view.byteStride : 12;
    std::vector<Vec3d> result;
    for (std::size_t i = 0; i < accessor.count; ++i) {
        float f[3];
        std::memcpy(f, bytes + i * stride, sizeof f);
        result.push_back({f[0], f[1], f[2]});
    }
    return result;
}

TEST(GltfFace, RobotExpressiveOffsetsAreTheFilesTargetsInRestSpace)
{
    GltfCharacterOptions options;
    options.loadTextures = false;
    options.standardRig = false; // the file's own frame, as tinygltf reads it below
    Result<Character> loaded = loadGltfCharacter(test::sharedData(kRobot), options);
    ASSERT_TRUE(loaded) << loaded.error().message;
    tinygltf::Model model;
    std::string error, warning;
    ASSERT_TRUE(tinygltf::TinyGLTF().LoadBinaryFromFile(&model, &error, &warning, test::sharedData(kRobot).string()));

    int headNode = -1;
    for (std::size_t n = 0; n < model.nodes.size(); ++n)
        if (model.nodes[n].mesh >= 0 && model.meshes[std::size_t(model.nodes[n].mesh)].name == "Head")
            headNode = int(n);
    ASSERT_GE(headNode, 0);
    const Mat4 world = worldOf(model, headNode);
    const tinygltf::Mesh& head = model.meshes[std::size_t(model.nodes[std::size_t(headNode)].mesh)];
    const char* names[] = {"Angry", "Surprised", "Sad"};
    double extent = 0;
    for (const Vec3& p : loaded->mesh.positions)
        extent = std::max({extent, double(std::abs(p.x)), double(std::abs(p.y)), double(std::abs(p.z))});
    for (std::size_t t = 0; t < 3; ++t) {
        const MorphTarget* target = findTarget(*loaded, names[t]);
        ASSERT_NE(target, nullptr) << names[t];
        std::size_t moved = 0;
        for (const tinygltf::Primitive& primitive : head.primitives) {
            const std::vector<Vec3d> rest = vectors(model, primitive.attributes.at("POSITION"));
            const std::vector<Vec3d> delta = vectors(model, primitive.targets[t].at("POSITION"));
            for (std::size_t v = 0; v < rest.size(); ++v) {
                if (delta[v].x == 0 && delta[v].y == 0 && delta[v].z == 0)
                    continue;
                ++moved;
                // The character's vertex at this rest place carries the target's offset, in world space.
                const Vec3d at = apply(world, rest[v], 1), offset = apply(world, delta[v], 0);
                bool found = false;
                for (std::size_t i = 0; i < target->vertices.size() && !found; ++i) {
                    const Vec3& p = loaded->mesh.positions[target->vertices[i]];
                    const Vec3d d{p.x - at.x, p.y - at.y, p.z - at.z};
                    if (std::sqrt(anim::dot(d, d)) > 1e-6 * extent)
                        continue;
                    const Vec3& o = target->offsets[i];
                    const Vec3d miss{o.x - offset.x, o.y - offset.y, o.z - offset.z};
                    found = std::sqrt(anim::dot(miss, miss)) <= 1e-6 * extent;
                }
                EXPECT_TRUE(found) << names[t] << " vertex " << v;
            }
        }
        EXPECT_EQ(target->vertices.size(), moved) << names[t];
        EXPECT_GT(moved, 100u) << names[t];
    }
}

TEST(GltfFace, RobotExpressivesExpressionsPlay)
{
    Result<Character> loaded = loadGltfCharacter(test::sharedData(kRobot), {.loadTextures = false});
    ASSERT_TRUE(loaded) << loaded.error().message;
    const Character& robot = *loaded;
    ASSERT_EQ(morphTargetNames(robot), (std::vector<std::string>{"Angry", "Surprised", "Sad"}));
    EXPECT_NE(findDrive(robot, "Angry", expressionChannel(3)), nullptr);     // anger
    EXPECT_NE(findDrive(robot, "Surprised", expressionChannel(6)), nullptr); // surprise
    EXPECT_NE(findDrive(robot, "Sad", expressionChannel(2)), nullptr);       // sadness
    ASSERT_TRUE(robot.validate()) << robot.validate().error().message;

    // Anger at 1 moves the Head's vertices by exactly the Angry target's offsets, nothing else.
    const MorphTarget* angry = findTarget(robot, "Angry");
    EXPECT_TRUE(movedBy(robot, deformed(robot, faceFrame({{expressionChannel(3), 1.0f}})), {{angry, 1.0f}}));
    // Sadness at 0.5 with surprise at 0.25: both, weighted (added in target order, as the deformer does).
    EXPECT_TRUE(movedBy(robot,
                        deformed(robot, faceFrame({{expressionChannel(2), 0.5f}, {expressionChannel(6), 0.25f}})),
                        {{findTarget(robot, "Surprised"), 0.25f}, {findTarget(robot, "Sad"), 0.5f}}));
    // No face: the rest mesh, bit for bit.
    EXPECT_TRUE(movedBy(robot, deformed(robot, {}), {}));
}

TEST(GltfFace, RobotExpressivesMorphedHeadIsSkinnedWhereItsOffsetThenItsJointPutIt)
{
    Result<Character> loaded = loadGltfCharacter(test::sharedData(kRobot), {.loadTextures = false});
    ASSERT_TRUE(loaded) << loaded.error().message;
    auto robot = std::make_shared<const Character>(std::move(*loaded));
    const anim::Skeleton& skeleton = robot->skeleton;
    const MorphTarget* angry = findTarget(*robot, "Angry");
    ASSERT_NE(angry, nullptr);

    // The pose: the head turned 0.6 rad about +Y and tilted, the whole body moved.
    std::vector<float> frame = skeleton.restFrame();
    const int skull = skeleton.find("skullbase");
    ASSERT_GE(skull, 0);
    const anim::Quatd turn = anim::Quatd::fromAxisAngle({0, 1, 0}, 0.6) * anim::Quatd::fromAxisAngle({1, 0, 0}, 0.3);
    anim::rotationAt(std::span<float>(frame), skull) = {float(turn.x), float(turn.y), float(turn.z), float(turn.w)};
    auto node = render::CharacterNode::create(robot);
    ASSERT_TRUE(node) << node.error().message;
    (*node)->setPose(frame, faceFrame({{expressionChannel(3), 1.0f}}));
    const std::vector<Vec3> posed((*node)->posedPositions().begin(), (*node)->posedPositions().end());

    // Each Angry vertex: its rest place plus the offset, then skinned by the joints that carry it.
    const std::size_t joints = std::size_t(skeleton.jointCount());
    std::vector<Vec3d> rest = skeleton.worldPositions(skeleton.restFrame()), positions(joints);
    std::vector<anim::Quatd> orientations(joints);
    std::vector<RigidTransform> transforms(joints);
    computeSkinningTransforms(skeleton, frame, rest, positions, orientations, transforms);
    const int influences = robot->skin.influences;
    ASSERT_GT(influences, 0);
    double largest = 0;
    for (std::size_t i = 0; i < angry->vertices.size(); ++i) {
        const std::uint32_t v = angry->vertices[i];
        const Vec3 morphed = robot->mesh.positions[v] + angry->offsets[i];
        Vec3d expected{};
        for (int k = 0; k < influences; ++k) {
            const float w = robot->skin.weights[v * std::size_t(influences) + std::size_t(k)];
            if (w == 0)
                continue;
            const RigidTransform& t = transforms[robot->skin.joints[v * std::size_t(influences) + std::size_t(k)]];
            const anim::Quatd q{t.rotation.x, t.rotation.y, t.rotation.z, t.rotation.w};
            const Vec3d moved = anim::rotate(q, Vec3d{morphed.x, morphed.y, morphed.z}) +
                                Vec3d{t.translation.x, t.translation.y, t.translation.z};
            expected = expected + moved * double(w);
        }
        const Vec3d miss{posed[v].x - expected.x, posed[v].y - expected.y, posed[v].z - expected.z};
        largest = std::max(largest, std::sqrt(anim::dot(miss, miss)));
    }
    EXPECT_LT(largest, 1e-5);
    // The face really moved the skinned head: without the offsets it would be elsewhere.
    (*node)->setPose(frame, {});
    double moved = 0;
    for (const std::uint32_t v : angry->vertices) {
        const Vec3 d = (*node)->posedPositions()[v] - posed[v];
        moved = std::max(moved, double(std::sqrt(anim::dot(d, d))));
    }
    EXPECT_GT(moved, 1e-3);
}

TEST(GltfFace, ATableNamingMissingTargetsWarnsWithTheirNames)
{
    FaceMapping mapping;
    mapping.name = "studio rig";
    mapping.drives = {{"Angry", expressionChannel(3), 1.0, MorphDrive::Side::Both},
                      {"Blink_L", fapChannel(19), 1.0 / 1024, MorphDrive::Side::Positive},
                      {"Smile", expressionChannel(1), 1.0, MorphDrive::Side::Both}};
    mapping.joints = {{"EyeBone_L", fapChannel(23), {0, 1, 0}, 1e-5}};
    GltfCharacterOptions options;
    options.loadTextures = false;
    options.faceMapping = mapping;
    Result<Character> robot = loadGltfCharacter(test::sharedData(kRobot), options);
    ASSERT_TRUE(robot) << robot.error().message;
    std::vector<std::string> warnings;
    for (const std::string& warning : robot->warnings)
        if (warning.find("face mapping") != std::string::npos)
            warnings.push_back(warning);
    ASSERT_EQ(warnings.size(), 3u);
    EXPECT_EQ(warnings[0],
              "The face mapping \"studio rig\" drives the morph target \"Blink_L\", which RobotExpressive does not have.");
    EXPECT_NE(warnings[1].find("\"Smile\""), std::string::npos) << warnings[1];
    EXPECT_NE(warnings[2].find("joint \"EyeBone_L\""), std::string::npos) << warnings[2];
    // What the table could apply, it did: Angry plays anger and nothing else drives the face.
    ASSERT_EQ(robot->face.drives.size(), 1u);
    EXPECT_EQ(robot->face.targets[std::size_t(robot->face.drives[0].target)].name, "Angry");
    EXPECT_TRUE(robot->face.joints.empty());
}

// ---- files the reader cannot decode -------------------------------------------------------------------

fs::path writeText(const std::string& name, const std::string& text)
{
    const fs::path path = scratch(name);
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

// One triangle, its positions in a buffer of 36 bytes given inline, read through `view`.
struct Triangle {
    std::string extensions;          ///< top-level "extensionsUsed" … with a trailing comma
    std::string primitiveExtensions; ///< ", \"extensions\": {…}" of the primitive
    bool positionView = true;        ///< false: the positions accessor has no buffer view
    std::string otherBuffers;        ///< ", {…}" after the inline buffer
    std::string view = R"({"buffer": 0, "byteLength": 36})";

    std::string text() const
    {
        return R"({"asset": {"version": "2.0"}, )" + extensions +
               R"("buffers": [{"byteLength": 36, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"})" +
               otherBuffers + R"(], "bufferViews": [)" + view + R"(], "accessors": [{)" +
               (positionView ? R"("bufferView": 0, )" : "") +
               R"("componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]}],
"meshes": [{"primitives": [{"attributes": {"POSITION": 0})" + primitiveExtensions + R"(}]}],
"nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}], "scene": 0})";
    }
};

TEST(GltfFace, AFileThatCannotBeDecodedSaysWhichExtension)
{
    // A plain triangle loads: the files below differ from it only by their extensions.
    ASSERT_TRUE(loadGltfCharacter(writeText("plain.gltf", Triangle{}.text())));
    const auto refusedNaming = [](const Result<Character>& result, const char* extension) -> ::testing::AssertionResult {
        if (result)
            return ::testing::AssertionFailure() << "loaded";
        if (result.error().code != ErrorCode::NotOurFormat || result.error().message.find(extension) == std::string::npos)
            return ::testing::AssertionFailure() << describe(result.error());
        return ::testing::AssertionSuccess();
    };
    for (const char* extension : {"EXT_meshopt_compression", "KHR_draco_mesh_compression", "KHR_meshopt_compression"}) {
        const std::string list = std::string(R"(")") + extension + R"(")";
        Triangle required;
        required.extensions = R"("extensionsUsed": [)" + list + R"(], "extensionsRequired": [)" + list + "], ";
        EXPECT_TRUE(refusedNaming(loadGltfCharacter(writeText("required.gltf", required.text())), extension));
    }
    // Draco used but not required, and a primitive whose positions are only in the compressed
    // stream (no fallback data): not a blank triangle at the origin, a refusal naming Draco.
    Triangle draco;
    draco.extensions = R"("extensionsUsed": ["KHR_draco_mesh_compression"], )";
    draco.primitiveExtensions =
        R"(, "extensions": {"KHR_draco_mesh_compression": {"bufferView": 0, "attributes": {"POSITION": 0}}})";
    draco.positionView = false;
    EXPECT_TRUE(refusedNaming(loadGltfCharacter(writeText("draco.gltf", draco.text())), "KHR_draco_mesh_compression"));
    // Meshopt used but not required, the view's own buffer a placeholder without data.
    Triangle meshopt;
    meshopt.extensions = R"("extensionsUsed": ["EXT_meshopt_compression"], )";
    meshopt.otherBuffers = R"(, {"byteLength": 36, "extensions": {"EXT_meshopt_compression": {"fallback": true}}})";
    meshopt.view = R"({"buffer": 1, "byteLength": 36, "extensions": {"EXT_meshopt_compression": )"
                   R"({"buffer": 0, "byteLength": 36, "byteStride": 12, "count": 3, "mode": "ATTRIBUTES"}}})";
    EXPECT_TRUE(refusedNaming(loadGltfCharacter(writeText("meshopt.gltf", meshopt.text())), "EXT_meshopt_compression"));
}

} // namespace
} // namespace thespis::core::scene
