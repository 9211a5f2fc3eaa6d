// glTF → Character (core/scene/gltf_character.h) on the real characters of ../shared/data and a
// hand-made file: skeleton, H-Anim names, skin weights, materials and textures, and the clips
// checked against the glTF reference pose. The reference is computed here from tinygltf's parse
// of the file (its own accessor reading, sampler interpolation and node composition), not by
// core/scene's reader.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <numeric>
#include <set>
#include <string>
#include <vector>

#include <unistd.h>

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include "anim/keyframe_clip.h"
#include "scene/gltf_character.h"
#include "scene/gltf_mesh.h"
#include "test_support.h"

namespace thespis::core::scene {
namespace {

using test::sharedData;
using test::testData;

const char* const kCesiumMan = "characters/CesiumMan/CesiumMan.glb";
const char* const kRiggedFigure = "characters/RiggedFigure/RiggedFigure.gltf";
const char* const kRiggedSimple = "characters/RiggedSimple/RiggedSimple.gltf";
const char* const kRobot = "characters/RobotExpressive/RobotExpressive.glb";

// The file's own rig (not stood as H-Anim, IK feet where the file has them), as tinygltf's
// reference sees it; GltfCharacter.StandardRig checks what standardRig changes.
Character load(const std::filesystem::path& path, GltfCharacterOptions options = {})
{
    options.standardRig = false;
    Result<Character> character = loadGltfCharacter(path, options);
    EXPECT_TRUE(character.ok()) << (character.ok() ? "" : describe(character.error()));
    return character.ok() ? std::move(*character) : Character{};
}

std::string allWarnings(const Character& character)
{
    std::string all;
    for (const std::string& warning : character.warnings)
        all += warning + "\n";
    return all;
}

std::map<std::string, std::string> namesBySource(const Character& character)
{
    std::map<std::string, std::string> names;
    for (const anim::Joint& joint : character.skeleton.joints())
        names[joint.sourceName] = joint.name;
    return names;
}

// ---- the glTF reference, straight from tinygltf -----------------------------------------------

using Mat = std::array<std::array<double, 4>, 4>; // row-major

Mat identity()
{
    Mat m{};
    for (int i = 0; i < 4; ++i)
        m[i][i] = 1;
    return m;
}

Mat operator*(const Mat& a, const Mat& b)
{
    Mat c{};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            for (int k = 0; k < 4; ++k)
                c[i][j] += a[i][k] * b[k][j];
    return c;
}

/// Rotation matrix of a unit quaternion (x, y, z, w).
std::array<std::array<double, 3>, 3> rotationMatrix(double x, double y, double z, double w)
{
    return {{{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
             {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
             {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}}};
}

class Reference {
public:
    explicit Reference(const std::filesystem::path& path)
    {
        tinygltf::TinyGLTF loader;
        std::string error, warning;
        const bool binary = path.extension() == ".glb";
        const bool loaded = binary ? loader.LoadBinaryFromFile(&m_model, &error, &warning, path.string())
                                   : loader.LoadASCIIFromFile(&m_model, &error, &warning, path.string());
        EXPECT_TRUE(loaded) << error;
        m_parent.assign(m_model.nodes.size(), -1);
        for (std::size_t n = 0; n < m_model.nodes.size(); ++n)
            for (int child : m_model.nodes[n].children)
                m_parent[std::size_t(child)] = int(n);
    }

    const tinygltf::Model& model() const { return m_model; }

    /// An accessor's values, component after component (no sparse accessors in these files).
    std::vector<double> values(int index) const
    {
        const tinygltf::Accessor& accessor = m_model.accessors[std::size_t(index)];
        const tinygltf::BufferView& view = m_model.bufferViews[std::size_t(accessor.bufferView)];
        const unsigned char* data = m_model.buffers[std::size_t(view.buffer)].data.data() + view.byteOffset +
                                    accessor.byteOffset;
        const int components = tinygltf::GetNumComponentsInType(std::uint32_t(accessor.type));
        const int size = tinygltf::GetComponentSizeInBytes(std::uint32_t(accessor.componentType));
        const std::size_t stride = view.byteStride ? view.byteStride : std::size_t(components * size);
        std::vector<double> out;
        for (std::size_t i = 0; i < accessor.count; ++i)
            for (int c = 0; c < components; ++c) {
                const unsigned char* p = data + i * stride + std::size_t(c * size);
                double v = 0;
                if (accessor.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT) {
                    float f;
                    std::memcpy(&f, p, 4);
                    v = f;
                } else if (accessor.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) {
                    v = accessor.normalized ? *p / 255.0 : *p;
                } else if (accessor.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) {
                    std::uint16_t u;
                    std::memcpy(&u, p, 2);
                    v = accessor.normalized ? u / 65535.0 : u;
                } else {
                    ADD_FAILURE() << "component type " << accessor.componentType << " not read by the test";
                }
                out.push_back(v);
            }
        return out;
    }

    /// A sampler's value at time t, as glTF 2.0 defines it (Appendix C for CUBICSPLINE).
    std::vector<double> sample(const tinygltf::AnimationSampler& sampler, int components, bool rotation, double t) const
    {
        const std::vector<double> times = values(sampler.input);
        const std::vector<double> keys = values(sampler.output);
        const bool cubic = sampler.interpolation == "CUBICSPLINE";
        auto key = [&](std::size_t k, int part) { // part: 0 in-tangent, 1 value, 2 out-tangent (cubic)
            const std::size_t element = cubic ? 3 * k + std::size_t(part) : k;
            return std::vector<double>(keys.begin() + std::ptrdiff_t(element * std::size_t(components)),
                                       keys.begin() + std::ptrdiff_t((element + 1) * std::size_t(components)));
        };
        const std::size_t n = times.size();
        if (t <= times.front())
            return key(0, 1);
        if (t >= times.back())
            return key(n - 1, 1);
        std::size_t k = 0;
        while (times[k + 1] <= t)
            ++k;
        const double span = times[k + 1] - times[k];
        const double u = (t - times[k]) / span;
        if (sampler.interpolation == "STEP")
            return key(k, 1);
        std::vector<double> out(static_cast<std::size_t>(components));
        if (cubic) {
            const std::vector<double> v0 = key(k, 1), b0 = key(k, 2), a1 = key(k + 1, 0), v1 = key(k + 1, 1);
            for (std::size_t c = 0; c < out.size(); ++c)
                out[c] = (2 * u * u * u - 3 * u * u + 1) * v0[c] + (u * u * u - 2 * u * u + u) * span * b0[c] +
                         (-2 * u * u * u + 3 * u * u) * v1[c] + (u * u * u - u * u) * span * a1[c];
        } else if (rotation) {
            std::vector<double> a = key(k, 1), b = key(k + 1, 1);
            double d = 0;
            for (std::size_t c = 0; c < 4; ++c)
                d += a[c] * b[c];
            if (d < 0) {
                for (double& c : b)
                    c = -c;
                d = -d;
            }
            const double theta = std::acos(std::min(1.0, d));
            const double wa = theta < 1e-9 ? 1 - u : std::sin((1 - u) * theta) / std::sin(theta);
            const double wb = theta < 1e-9 ? u : std::sin(u * theta) / std::sin(theta);
            for (std::size_t c = 0; c < 4; ++c)
                out[c] = wa * a[c] + wb * b[c];
        } else {
            const std::vector<double> a = key(k, 1), b = key(k + 1, 1);
            for (std::size_t c = 0; c < out.size(); ++c)
                out[c] = a[c] + (b[c] - a[c]) * u;
        }
        if (rotation) {
            const double norm = std::sqrt(out[0] * out[0] + out[1] * out[1] + out[2] * out[2] + out[3] * out[3]);
            for (double& c : out)
                c /= norm;
        }
        return out;
    }

    /// Every node's world matrix with the translation and rotation channels of `animations` at
    /// time t (scale channels are left out: Thespis does not import them).
    std::vector<Mat> worldAt(const std::vector<int>& animations, double t) const
    {
        std::vector<std::vector<double>> translation(m_model.nodes.size()), rotation(m_model.nodes.size());
        for (std::size_t n = 0; n < m_model.nodes.size(); ++n) {
            const tinygltf::Node& node = m_model.nodes[n];
            translation[n] = node.translation.size() == 3 ? node.translation : std::vector<double>{0, 0, 0};
            rotation[n] = node.rotation.size() == 4 ? node.rotation : std::vector<double>{0, 0, 0, 1};
        }
        for (int a : animations)
            for (const tinygltf::AnimationChannel& channel : m_model.animations[std::size_t(a)].channels) {
                const auto& sampler = m_model.animations[std::size_t(a)].samplers[std::size_t(channel.sampler)];
                if (channel.target_path == "translation")
                    translation[std::size_t(channel.target_node)] = sample(sampler, 3, false, t);
                else if (channel.target_path == "rotation")
                    rotation[std::size_t(channel.target_node)] = sample(sampler, 4, true, t);
            }
        std::vector<Mat> world(m_model.nodes.size());
        std::vector<bool> done(m_model.nodes.size(), false);
        for (std::size_t n = 0; n < m_model.nodes.size(); ++n)
            compose(int(n), translation, rotation, world, done);
        return world;
    }

    /// The skin joint node with that name ("node<i>" for an unnamed node).
    int jointNode(const std::string& name) const
    {
        for (const tinygltf::Skin& skin : m_model.skins)
            for (int joint : skin.joints)
                if (m_model.nodes[std::size_t(joint)].name == name ||
                    (m_model.nodes[std::size_t(joint)].name.empty() && name == "node" + std::to_string(joint)))
                    return joint;
        return -1;
    }

    /// Animations a clip of the character plays: all of them for the merged "animation".
    std::vector<int> animationsOf(const std::string& clip) const
    {
        std::vector<int> found;
        for (std::size_t a = 0; a < m_model.animations.size(); ++a)
            if (clip == "animation" || m_model.animations[a].name == clip)
                found.push_back(int(a));
        return found;
    }

private:
    void compose(int n, const std::vector<std::vector<double>>& translation,
                 const std::vector<std::vector<double>>& rotation, std::vector<Mat>& world,
                 std::vector<bool>& done) const
    {
        if (done[std::size_t(n)])
            return;
        const tinygltf::Node& node = m_model.nodes[std::size_t(n)];
        Mat local = identity();
        if (node.matrix.size() == 16) {
            for (int r = 0; r < 4; ++r)
                for (int c = 0; c < 4; ++c)
                    local[r][c] = node.matrix[std::size_t(c * 4 + r)];
        } else {
            const std::vector<double>& q = rotation[std::size_t(n)];
            const double norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
            const auto r = rotationMatrix(q[0] / norm, q[1] / norm, q[2] / norm, q[3] / norm);
            const std::vector<double> s = node.scale.size() == 3 ? node.scale : std::vector<double>{1, 1, 1};
            for (int i = 0; i < 3; ++i) {
                for (int j = 0; j < 3; ++j)
                    local[i][j] = r[i][j] * s[std::size_t(j)];
                local[i][3] = translation[std::size_t(n)][std::size_t(i)];
            }
        }
        const int parent = m_parent[std::size_t(n)];
        if (parent >= 0)
            compose(parent, translation, rotation, world, done);
        world[std::size_t(n)] = parent >= 0 ? world[std::size_t(parent)] * local : local;
        done[std::size_t(n)] = true;
    }

    tinygltf::Model m_model;
    std::vector<int> m_parent;
};

/// Largest difference between the glTF joints' world matrices G_j(t) and ours, O_j·C_j (C_j:
/// the glTF joint's rest world rotation and scale), over the frames `frames` of every clip.
/// Linear parts are compared per unit of scale, translations in scene units.
double largestPoseError(const Character& character, const Reference& reference, const std::vector<int>& frames)
{
    const anim::Skeleton& skeleton = character.skeleton;
    const std::vector<Mat> rest = reference.worldAt({}, 0);
    std::vector<float> frame(skeleton.frameLayout()->floatCount());
    std::vector<Vec3d> positions(std::size_t(skeleton.jointCount()));
    std::vector<Quatd> orientations(std::size_t(skeleton.jointCount()));
    double largest = 0;
    for (const auto& clip : character.clips) {
        const std::vector<int> animations = reference.animationsOf(clip->name());
        EXPECT_FALSE(animations.empty()) << clip->name();
        for (int f : frames) {
            if (f >= clip->frameCount())
                continue;
            const double t = f / clip->frameRate();
            clip->evaluate(t, frame);
            skeleton.worldTransforms(frame, positions, orientations);
            const std::vector<Mat> world = reference.worldAt(animations, t);
            for (int j = 0; j < skeleton.jointCount(); ++j) {
                const int node = reference.jointNode(skeleton.joint(j).sourceName);
                EXPECT_GE(node, 0) << skeleton.joint(j).sourceName;
                if (node < 0)
                    continue;
                const Quatd& q = orientations[std::size_t(j)];
                const auto r = rotationMatrix(q.x, q.y, q.z, q.w);
                const Mat& g = world[std::size_t(node)];
                const Mat& c = rest[std::size_t(node)];
                const double scale = std::cbrt(std::abs(c[0][0] * (c[1][1] * c[2][2] - c[1][2] * c[2][1]) -
                                                        c[0][1] * (c[1][0] * c[2][2] - c[1][2] * c[2][0]) +
                                                        c[0][2] * (c[1][0] * c[2][1] - c[1][1] * c[2][0])));
                for (int row = 0; row < 3; ++row) {
                    for (int col = 0; col < 3; ++col) {
                        double ours = 0;
                        for (int k = 0; k < 3; ++k)
                            ours += r[std::size_t(row)][std::size_t(k)] * c[k][col];
                        largest = std::max(largest, std::abs(ours - g[row][col]) / scale);
                    }
                    const double p[3] = {positions[std::size_t(j)].x, positions[std::size_t(j)].y,
                                         positions[std::size_t(j)].z};
                    largest = std::max(largest, std::abs(p[row] - g[row][3]));
                }
            }
        }
    }
    return largest;
}

// ---- the real characters ----------------------------------------------------------------------

struct Expected {
    const char* path;
    int joints;
    std::size_t clips;
    int influences;
    std::size_t textures;
};

const Expected kCharacters[] = {
    {kCesiumMan, 19, 1, 4, 1},    // 19 per-node animations merged into one walk
    {kRiggedFigure, 19, 1, 4, 0}, // likewise
    {kRiggedSimple, 2, 1, 4, 0},  // two per-node animations merged
    {kRobot, 43, 14, 4, 0},
};

TEST(GltfCharacter, LoadsTheRealCharacters)
{
    for (const Expected& expected : kCharacters) {
        SCOPED_TRACE(expected.path);
        const Character character = load(sharedData(expected.path));
        EXPECT_TRUE(character.validate().ok());
        EXPECT_EQ(character.skeleton.jointCount(), expected.joints);
        EXPECT_EQ(character.clips.size(), expected.clips);
        EXPECT_EQ(character.skin.influences, expected.influences);
        EXPECT_EQ(character.textures.size(), expected.textures);
        EXPECT_EQ(character.name, std::filesystem::path(expected.path).stem().string());
        // Weights: normalized, and the mesh is the one loadGltfMesh builds with the same options.
        for (std::size_t v = 0; v < character.mesh.vertexCount(); ++v) {
            double sum = 0;
            for (int k = 0; k < character.skin.influences; ++k)
                sum += character.skin.weights[v * std::size_t(character.skin.influences) + std::size_t(k)];
            ASSERT_NEAR(sum, 1.0, 1e-6) << v;
        }
        const Result<CharacterMesh> mesh = loadGltfMesh(sharedData(expected.path), GltfCharacterOptions{}.mesh);
        ASSERT_TRUE(mesh.ok());
        ASSERT_EQ(mesh->vertexCount(), character.mesh.vertexCount());
        EXPECT_TRUE(std::equal(mesh->positions.begin(), mesh->positions.end(), character.mesh.positions.begin()));
        EXPECT_EQ(mesh->indices, character.mesh.indices);
        // Skinning with the skeleton's rest frame, Σ w·(Q_j (p − rest_j) + P_j), leaves that mesh as it is.
        const anim::Skeleton& skeleton = character.skeleton;
        std::vector<Vec3d> positions(std::size_t(skeleton.jointCount()));
        std::vector<Quatd> orientations(std::size_t(skeleton.jointCount()));
        skeleton.worldTransforms(skeleton.restFrame(), positions, orientations);
        const std::vector<Vec3d> rest = skeleton.worldPositions(skeleton.restFrame());
        double largest = 0;
        for (std::size_t v = 0; v < character.mesh.vertexCount(); ++v) {
            const Vec3& p = mesh->positions[v];
            Vec3d skinned;
            for (int k = 0; k < character.skin.influences; ++k) {
                const std::size_t i = v * std::size_t(character.skin.influences) + std::size_t(k);
                const std::size_t j = character.skin.joints[i];
                skinned = skinned + (anim::rotate(orientations[j], Vec3d{p.x, p.y, p.z} - rest[j]) + positions[j]) *
                                        double(character.skin.weights[i]);
            }
            largest = std::max(
                {largest, std::abs(skinned.x - p.x), std::abs(skinned.y - p.y), std::abs(skinned.z - p.z)});
        }
        EXPECT_LT(largest, 1e-6);
        // Every segment follows a joint of the skeleton and has one of the file's materials.
        ASSERT_EQ(character.segmentMaterials.size(), character.mesh.segments.size());
        for (std::size_t s = 0; s < character.mesh.segments.size(); ++s) {
            EXPECT_GE(character.skeleton.find(character.mesh.segments[s].joint), 0) << character.mesh.segments[s].name;
            EXPECT_GE(character.segmentMaterials[s], 0);
        }
        // Clips are on the skeleton's layout at the asked rate, as long as the animation.
        for (const auto& clip : character.clips) {
            EXPECT_EQ(*clip->layout(), *character.skeleton.frameLayout());
            EXPECT_DOUBLE_EQ(clip->frameRate(), 30.0);
            EXPECT_GT(clip->frameCount(), 1);
        }
    }
}

TEST(GltfCharacter, RobotExpressiveHasItsNamedClips)
{
    const Character robot = load(sharedData(kRobot));
    std::vector<std::string> names;
    for (const auto& clip : robot.clips)
        names.push_back(clip->name());
    const std::vector<std::string> expected = {"Dance",   "Death",   "Idle",     "Jump",    "No",
                                               "Punch",   "Running", "Sitting",  "Standing", "ThumbsUp",
                                               "Walking", "WalkJump", "Wave",    "Yes"};
    EXPECT_EQ(names, expected);
    // Walking lasts 0.958 s in the file: 30 fps keys over [0, 0.958] round up to 30 frames.
    EXPECT_EQ(robot.clips[10]->frameCount(), 30);
    // "Death" moves the head and the clavicles off their rest offsets: those joints translate.
    for (const char* joint : {"humanoid_root", "skullbase", "l_sternoclavicular", "r_sternoclavicular"})
        EXPECT_TRUE(robot.skeleton.joint(robot.skeleton.find(joint)).translates) << joint;
    EXPECT_FALSE(robot.skeleton.joint(robot.skeleton.find("l_elbow")).translates);
    // The head's morph target animation is reported, not imported.
    EXPECT_NE(allWarnings(robot).find("Morph target animation is not imported: Head"), std::string::npos)
        << allWarnings(robot);
}

// The Khronos sample rigs have unnamed joints: they are named by their shape.
const std::map<std::string, std::string> kKhronosRig = {
    {"node2", "humanoid_root"},
    {"node11", "vl1"},
    {"node12", "vt1"},
    {"node19", "vc4"},
    {"node20", "skullbase"},
    {"node16", "l_shoulder"},
    {"node17", "l_elbow"},
    {"node18", "l_radiocarpal"},
    {"node13", "r_shoulder"},
    {"node14", "r_elbow"},
    {"node15", "r_radiocarpal"},
    {"node7", "l_hip"},
    {"node8", "l_knee"},
    {"node9", "l_talocrural"},
    {"node10", "l_metatarsophalangeal"},
    {"node3", "r_hip"},
    {"node4", "r_knee"},
    {"node5", "r_talocrural"},
    {"node6", "r_metatarsophalangeal"},
};

TEST(GltfCharacter, KhronosRigsMapToHAnimByTheirShape)
{
    for (const char* path : {kCesiumMan, kRiggedFigure}) {
        SCOPED_TRACE(path);
        const Character character = load(sharedData(path));
        EXPECT_EQ(namesBySource(character), kKhronosRig);
        EXPECT_EQ(allWarnings(character).find("no H-Anim name"), std::string::npos) << allWarnings(character);
        // Left is the character's left: RiggedFigure faces +Z (its left is +X), CesiumMan walks
        // along +X (its left is −Z).
        const std::vector<Vec3d> rest = character.skeleton.worldPositions(character.skeleton.restFrame());
        const Vec3d leftHip = rest[std::size_t(character.skeleton.find("l_hip"))];
        const Vec3d rightHip = rest[std::size_t(character.skeleton.find("r_hip"))];
        if (std::string(path) == kRiggedFigure)
            EXPECT_GT(leftHip.x, rightHip.x);
        else
            EXPECT_LT(leftHip.z, rightHip.z);
        // Split segments are named after their joints.
        const Segment* skull = character.mesh.findSegment("skullbase");
        ASSERT_NE(skull, nullptr);
        EXPECT_EQ(skull->joint, "skullbase");
        ASSERT_NE(character.mesh.findSegment("l_elbow"), nullptr);
    }
}

TEST(GltfCharacter, RobotExpressiveMapsByItsNames)
{
    const Character robot = load(sharedData(kRobot));
    const std::map<std::string, std::string> names = namesBySource(robot);
    const std::map<std::string, std::string> expected = {
        {"Body", "humanoid_root"}, {"Hips", "vl5"}, {"Abdomen", "vl1"}, {"Torso", "vt6"}, {"Neck", "vc4"},
        {"Head", "skullbase"}, {"Shoulder.L", "l_sternoclavicular"}, {"UpperArm.L", "l_shoulder"},
        {"LowerArm.L", "l_elbow"}, {"Palm1.L", "l_carpometacarpal_2"}, {"Index.L", "l_metacarpophalangeal_2"},
        {"Index2.L", "l_carpal_proximal_interphalangeal_2"}, {"Thumb.L", "l_carpometacarpal_1"},
        {"Ring2.R", "r_carpal_proximal_interphalangeal_4"}, {"UpperLeg.L", "l_hip"}, {"LowerLeg.L", "l_knee"},
        {"UpperLeg.R", "r_hip"}, {"LowerLeg.R", "r_knee"},
        // Unmapped: the armature root, the IK targets and the IK feet (under the armature root,
        // not under the knees: their H-Anim names would break the hierarchy).
        {"Bone", "Bone"}, {"PoleTarget.L", "PoleTarget.L"}, {"Foot.L", "Foot.L"}, {"Foot.R", "Foot.R"}};
    for (const auto& [source, name] : expected)
        EXPECT_EQ(names.at(source), name) << source;
    const std::string warnings = allWarnings(robot);
    EXPECT_NE(warnings.find("5 of 43 joints have no H-Anim name and keep their own: Bone, Foot.L, PoleTarget.L, "
                            "Foot.R, PoleTarget.R."),
              std::string::npos)
        << warnings;
    EXPECT_NE(warnings.find("Foot.L (l_talocrural)"), std::string::npos) << warnings;
    // The rigid mesh nodes follow the joints above them.
    EXPECT_EQ(robot.mesh.findSegment("Leg.L")->joint, "l_hip");
    EXPECT_EQ(robot.mesh.findSegment("Head/Black")->joint, "skullbase");
    EXPECT_EQ(robot.mesh.findSegment("Foot.R")->joint, "Foot.R");
}

TEST(GltfCharacter, RiggedSimpleIsNotAHumanoid)
{
    const Character simple = load(sharedData(kRiggedSimple));
    EXPECT_EQ(simple.skeleton.joint(0).name, "node2");
    EXPECT_EQ(simple.skeleton.joint(1).name, "node3");
    EXPECT_NE(allWarnings(simple).find("2 of 2 joints have no H-Anim name and keep their own: node2, node3."),
              std::string::npos)
        << allWarnings(simple);
}

TEST(GltfCharacter, AutomaticNamesOfCommonRigs)
{
    const std::map<std::string, std::string> expected = {
        {"mixamorig:Hips", "humanoid_root"},
        {"mixamorig:LeftUpLeg", "l_hip"},
        {"mixamorig_RightForeArm", "r_elbow"},
        {"mixamorig:Spine2", "vt6"},
        {"mixamorig:LeftShoulder", "l_sternoclavicular"},
        {"mixamorig:LeftHandIndex1", "l_metacarpophalangeal_2"},
        {"mixamorig:LeftHandIndex2", "l_carpal_proximal_interphalangeal_2"},
        {"mixamorig:LeftHandIndex3", "l_carpal_distal_interphalangeal_2"},
        {"LeftToeBase", "l_metatarsophalangeal"},
        {"Neck", "vc4"},
        {"Head", "skullbase"},
        {"Armature_thigh.L", "l_hip"},
        {"shin_R", "r_knee"},
        {"upper_arm.L", "l_shoulder"},
        {"forearm.R", "r_elbow"},
        {"hand.L", "l_radiocarpal"},
        {"DEF-spine.001", "vl1"},
        {"LeftUpperLeg", "l_hip"},
        {"RightLowerArm", "r_elbow"},
        {"HumanoidRoot", "humanoid_root"},
        {"l_wrist", "l_radiocarpal"},
        {"vt6", "vt6"},
        {"Palm1.L", "l_carpometacarpal_2"},
        {"HeadTop_End", ""},
        {"Bone", ""},
        {"node3", ""},
        {"", ""},
    };
    for (const auto& [source, name] : expected)
        EXPECT_EQ(automaticHAnimName(source), name) << source;
}

TEST(GltfCharacter, TheUserMappingOverrides)
{
    GltfCharacterOptions options;
    options.jointMapping = {{"node2", "humanoid_root"}, {"node3", "vl5"}, {"Missing", "vc4"}};
    const Character simple = load(sharedData(kRiggedSimple), options);
    EXPECT_EQ(simple.skeleton.joint(0).name, "humanoid_root");
    EXPECT_EQ(simple.skeleton.joint(0).sourceName, "node2");
    EXPECT_EQ(simple.skeleton.joint(1).name, "vl5");
    EXPECT_EQ(allWarnings(simple).find("no H-Anim name"), std::string::npos) << allWarnings(simple);
    EXPECT_NE(allWarnings(simple).find("does not have: Missing"), std::string::npos) << allWarnings(simple);

    // Over an automatic mapping: the user's name wins, the automatic joint it takes keeps its own.
    options.jointMapping = {{"node11", "vt1"}, {"node20", "vc2"}};
    const Character cesium = load(sharedData(kCesiumMan), options);
    std::map<std::string, std::string> expected = kKhronosRig;
    expected["node11"] = "vt1";
    expected["node12"] = "node12";
    expected["node20"] = "vc2";
    EXPECT_EQ(namesBySource(cesium), expected);
    EXPECT_NE(allWarnings(cesium).find("node12 (vt1)"), std::string::npos) << allWarnings(cesium);

    options.jointMapping.clear();
    options.automaticMapping = false;
    const Character unmapped = load(sharedData(kCesiumMan), options);
    for (const anim::Joint& joint : unmapped.skeleton.joints())
        EXPECT_EQ(joint.name, joint.sourceName);
}

TEST(GltfCharacter, ClipsMatchTheGltfReferencePose)
{
    // Frames 0, 0.1 s (between CesiumMan's 24 fps keys), 0.5 s, 1 s, 1.5 s and 2 s: times where the
    // 30 fps clip holds a sample, so resampling adds no error.
    const std::vector<int> frames = {0, 3, 15, 30, 45, 60};
    for (const char* path : {kCesiumMan, kRiggedFigure, kRiggedSimple, kRobot}) {
        SCOPED_TRACE(path);
        const Character character = load(sharedData(path));
        EXPECT_LT(largestPoseError(character, Reference(sharedData(path)), frames), 1e-4);
    }
    // At the file's own key rate (CesiumMan keys 24 times a second over 2 s) every key is a frame.
    GltfCharacterOptions keyRate;
    keyRate.clipFrameRate = 24;
    const Character cesium = load(sharedData(kCesiumMan), keyRate);
    ASSERT_EQ(cesium.clips.size(), 1u);
    EXPECT_EQ(cesium.clips[0]->frameCount(), 49);
    EXPECT_LT(largestPoseError(cesium, Reference(sharedData(kCesiumMan)), {0, 5, 12, 24, 37, 48}), 1e-4);
}

TEST(GltfCharacter, SkinningFollowsTheGltfSkin)
{
    // Unsplit, one material: the mesh keeps the file's vertex order, so vertex v is POSITION[v].
    GltfCharacterOptions options;
    options.mesh = {.splitSkinnedByJoint = false, .splitByMaterial = false};
    for (const char* path : {kCesiumMan, kRiggedFigure}) {
        SCOPED_TRACE(path);
        const Character character = load(sharedData(path), options);
        const Reference reference(sharedData(path));
        const tinygltf::Model& model = reference.model();
        ASSERT_EQ(model.meshes.size(), 1u);
        ASSERT_EQ(model.meshes[0].primitives.size(), 1u);
        const tinygltf::Primitive& primitive = model.meshes[0].primitives[0];
        const std::vector<double> filePositions = reference.values(primitive.attributes.at("POSITION"));
        const std::vector<double> fileJoints = reference.values(primitive.attributes.at("JOINTS_0"));
        const std::vector<double> fileWeights = reference.values(primitive.attributes.at("WEIGHTS_0"));
        const tinygltf::Skin& skin = model.skins[0];
        const std::vector<double> inverseBind = reference.values(skin.inverseBindMatrices);
        ASSERT_EQ(character.mesh.vertexCount() * 3, filePositions.size());

        const anim::Skeleton& skeleton = character.skeleton;
        const std::vector<Vec3d> rest = skeleton.worldPositions(skeleton.restFrame());
        std::vector<float> frame(skeleton.frameLayout()->floatCount());
        std::vector<Vec3d> positions(rest.size());
        std::vector<Quatd> orientations(rest.size());
        double largest = 0;
        for (double t : {0.0, 0.5, 1.0}) {
            character.clips[0]->evaluate(t, frame);
            skeleton.worldTransforms(frame, positions, orientations);
            const std::vector<Mat> world = reference.worldAt(reference.animationsOf("animation"), t);
            for (std::size_t v = 0; v < character.mesh.vertexCount(); ++v) {
                // glTF: Σ w · G_joint(t) · inverse bind · POSITION, weights normalized (CesiumMan's
                // sum to as little as 0.18; the importer normalizes them).
                double expected[3] = {0, 0, 0};
                const double total = fileWeights[4 * v] + fileWeights[4 * v + 1] + fileWeights[4 * v + 2] +
                                     fileWeights[4 * v + 3];
                for (std::size_t k = 0; k < 4; ++k) {
                    const double w = fileWeights[4 * v + k] / total;
                    const auto slot = std::size_t(fileJoints[4 * v + k]);
                    Mat bind;
                    for (int r = 0; r < 4; ++r)
                        for (int c = 0; c < 4; ++c)
                            bind[r][c] = inverseBind[16 * slot + std::size_t(c * 4 + r)];
                    const Mat m = world[std::size_t(skin.joints[slot])] * bind;
                    for (int r = 0; r < 3; ++r)
                        expected[r] += w * (m[r][0] * filePositions[3 * v] + m[r][1] * filePositions[3 * v + 1] +
                                            m[r][2] * filePositions[3 * v + 2] + m[r][3]);
                }
                // Ours: Σ w · (Q_j (p − rest_j) + P_j) on the rest-pose mesh.
                double ours[3] = {0, 0, 0};
                const Vec3& p = character.mesh.positions[v];
                for (int k = 0; k < character.skin.influences; ++k) {
                    const std::size_t i = v * std::size_t(character.skin.influences) + std::size_t(k);
                    const std::size_t j = character.skin.joints[i];
                    const Vec3d moved =
                        anim::rotate(orientations[j], Vec3d{p.x, p.y, p.z} - rest[j]) + positions[j];
                    ours[0] += character.skin.weights[i] * moved.x;
                    ours[1] += character.skin.weights[i] * moved.y;
                    ours[2] += character.skin.weights[i] * moved.z;
                }
                for (int r = 0; r < 3; ++r)
                    largest = std::max(largest, std::abs(ours[r] - expected[r]));
            }
        }
        EXPECT_LT(largest, 1e-4);
    }
}

TEST(GltfCharacter, TexturesMaterialsAndTexcoords)
{
    const Character cesium = load(sharedData(kCesiumMan));
    ASSERT_EQ(cesium.materials.size(), 1u);
    ASSERT_EQ(cesium.textures.size(), 1u);
    EXPECT_EQ(cesium.materials[0].baseColorTexture, 0);
    const TextureImage& texture = cesium.textures[0];
    EXPECT_EQ(texture.width, 1024);
    EXPECT_EQ(texture.height, 1024);
    // A real picture: opaque, and not one flat colour.
    std::set<std::uint8_t> reds;
    for (std::size_t p = 0; p < texture.rgba.size(); p += 4) {
        reds.insert(texture.rgba[p]);
        ASSERT_EQ(texture.rgba[p + 3], 255);
    }
    EXPECT_GT(reds.size(), 50u);
    ASSERT_EQ(cesium.texcoords.size(), cesium.mesh.vertexCount());
    for (const auto& uv : cesium.texcoords) {
        EXPECT_GE(uv[0], 0.0f);
        EXPECT_LE(uv[0], 1.0f);
    }
    GltfCharacterOptions untextured;
    untextured.loadTextures = false;
    const Character plain = load(sharedData(kCesiumMan), untextured);
    EXPECT_TRUE(plain.textures.empty());
    EXPECT_EQ(plain.materials[0].baseColorTexture, -1);

    // RobotExpressive: three colours; its multi-material meshes are split by material.
    const Character robot = load(sharedData(kRobot));
    ASSERT_EQ(robot.materials.size(), 3u);
    EXPECT_EQ(robot.materials[2].name, "Black");
    EXPECT_NEAR(robot.materials[1].baseColor[0], 0.5903, 1e-4);
    const auto segment = std::size_t(robot.mesh.findSegment("Head/Black") - robot.mesh.segments.data());
    EXPECT_EQ(robot.segmentMaterials[segment], 2);
    EXPECT_TRUE(robot.texcoords.empty());
}

// ---- the hand-made file: 8 influences, CUBICSPLINE and STEP samplers ---------------------------

TEST(GltfCharacter, EightInfluencesAndEverySampler)
{
    const std::filesystem::path path = testData("formats/gltf/eight_influences.gltf");
    const Character character = load(path);
    ASSERT_EQ(character.skeleton.jointCount(), 8);
    ASSERT_EQ(character.skin.influences, 8);
    const Reference reference(path);
    const tinygltf::Primitive& primitive = reference.model().meshes[0].primitives[0];

    // Vertex 0: 4 float weights and 4 normalized bytes, over 8 joints, normalized together.
    std::vector<double> fileWeights = reference.values(primitive.attributes.at("WEIGHTS_0"));
    const std::vector<double> second = reference.values(primitive.attributes.at("WEIGHTS_1"));
    std::map<int, double> expected;
    double total = 0;
    for (std::size_t k = 0; k < 4; ++k) {
        expected[int(reference.values(primitive.attributes.at("JOINTS_0"))[k])] += fileWeights[k];
        expected[int(reference.values(primitive.attributes.at("JOINTS_1"))[k])] += second[k];
        total += fileWeights[k] + second[k];
    }
    std::map<int, double> ours;
    for (std::size_t k = 0; k < 8; ++k)
        if (character.skin.weights[k] > 0)
            ours[character.skin.joints[k]] += character.skin.weights[k];
    ASSERT_EQ(ours.size(), 8u);
    for (const auto& [joint, weight] : expected) // the chain j0 … j7 is joints 0 … 7
        EXPECT_NEAR(ours[joint], weight / total, 1e-6) << joint;

    // TEXCOORD_0 as normalized shorts, the base colour factor.
    ASSERT_EQ(character.texcoords.size(), 4u);
    EXPECT_FLOAT_EQ(character.texcoords[3][0], 1.0f);
    EXPECT_NEAR(character.texcoords[2][1], 32768.0 / 65535.0, 1e-7);
    EXPECT_FLOAT_EQ(character.materials[0].baseColor[1], 0.4f);

    // Clips: "Cubic" (CUBICSPLINE rotation, LINEAR root translation, STEP translation of j2)
    // and "Step"; "Scaled" only scales and is reported.
    ASSERT_EQ(character.clips.size(), 2u);
    EXPECT_EQ(character.clips[0]->name(), "Cubic");
    EXPECT_TRUE(character.skeleton.joint(2).translates);
    EXPECT_FALSE(character.skeleton.joint(3).translates);
    EXPECT_NE(allWarnings(character).find("Scale animation is not imported (clips rotate and translate joints): j4"),
              std::string::npos)
        << allWarnings(character);
    // Every frame of both clips, on the hierarchy under a rotated armature scaled by 2.
    std::vector<int> frames(31);
    std::iota(frames.begin(), frames.end(), 0);
    EXPECT_LT(largestPoseError(character, reference, frames), 1e-4);
}

// ---- files the tests edit: broken ones, and other rigs ---------------------------------------------

class EditedGltf : public ::testing::Test {
protected:
    void SetUp() override
    {
        m_folder = std::filesystem::temp_directory_path() /
                   ("thespis_gltf_character_test_" +
                    std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "_" +
                    std::to_string(::getpid()));
        std::filesystem::create_directories(m_folder);
    }
    void TearDown() override { std::filesystem::remove_all(m_folder); }

    std::filesystem::path write(const std::string& name, const std::string& content)
    {
        std::ofstream(m_folder / name, std::ios::binary) << content;
        return m_folder / name;
    }
    static std::string readAll(const std::filesystem::path& path)
    {
        std::ifstream in(path, std::ios::binary);
        return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    }
    /// A .gltf character of ../shared/data (its buffer is "<stem>0.bin"), edited, written as `name`
    /// beside a copy of its buffer.
    template <class Edit>
    std::filesystem::path edited(const char* source, const std::string& name, Edit&& edit)
    {
        const std::filesystem::path path = sharedData(source);
        nlohmann::json gltf = nlohmann::json::parse(readAll(path));
        edit(gltf);
        const std::string buffer = path.stem().string() + "0.bin";
        write(buffer, readAll(path.parent_path() / buffer));
        return write(name, gltf.dump());
    }
    template <class Edit>
    std::filesystem::path riggedSimple(const std::string& name, Edit&& edit)
    {
        return edited(kRiggedSimple, name, std::forward<Edit>(edit));
    }
    static std::string messageOf(const Result<Character>& result)
    {
        return result.ok() ? std::string("(loaded)") : result.error().message + " | " + result.error().detail;
    }

    std::filesystem::path m_folder;
};

TEST_F(EditedGltf, GarbageAndMissingFiles)
{
    const Result<Character> missing = loadGltfCharacter(m_folder / "none.glb");
    ASSERT_FALSE(missing.ok());
    EXPECT_EQ(missing.error().code, ErrorCode::FileNotFound);

    for (const std::string& garbage : {std::string("glTF\x02\0\0\0garbage", 15), std::string("{ not json"),
                                       std::string(4096, '\xff'), std::string()}) {
        const Result<Character> character = loadGltfCharacter(write("garbage.gltf", garbage));
        ASSERT_FALSE(character.ok());
        EXPECT_NE(character.error().message.find("garbage.gltf"), std::string::npos) << messageOf(character);
    }
    const std::string glb = readAll(sharedData(kCesiumMan));
    for (std::size_t size : {std::size_t(20), glb.size() / 3, glb.size() - 1})
        EXPECT_FALSE(loadGltfCharacter(write("cut.glb", glb.substr(0, size))).ok()) << size;
}

TEST_F(EditedGltf, UnsupportedExtensionsAreNamed)
{
    const Result<Character> draco = loadGltfCharacter(riggedSimple("draco.gltf", [](nlohmann::json& gltf) {
        gltf["extensionsUsed"] = {"KHR_draco_mesh_compression"};
        gltf["extensionsRequired"] = {"KHR_draco_mesh_compression"};
    }));
    ASSERT_FALSE(draco.ok());
    EXPECT_EQ(draco.error().code, ErrorCode::NotOurFormat);
    EXPECT_NE(draco.error().message.find("KHR_draco_mesh_compression"), std::string::npos) << messageOf(draco);
}

TEST_F(EditedGltf, BrokenAnimationsAreRefused)
{
    struct Case {
        const char* what;
        void (*edit)(nlohmann::json&);
        const char* message;
    };
    const Case cases[] = {
        {"values of the wrong type", [](nlohmann::json& gltf) { gltf["animations"][0]["samplers"][1]["output"] = 0; },
         "values do not hold"},
        {"an unknown interpolation",
         [](nlohmann::json& gltf) { gltf["animations"][0]["samplers"][0]["interpolation"] = "BEZIER"; },
         "unknown interpolation"},
        {"a missing sampler", [](nlohmann::json& gltf) { gltf["animations"][0]["channels"][0]["sampler"] = 7; },
         "sampler that does not exist"},
        {"a missing accessor", [](nlohmann::json& gltf) { gltf["animations"][0]["samplers"][0]["input"] = 999; },
         "999"},
    };
    for (const Case& c : cases) {
        const Result<Character> character = loadGltfCharacter(riggedSimple("broken.gltf", c.edit));
        ASSERT_FALSE(character.ok()) << c.what;
        EXPECT_EQ(character.error().code, ErrorCode::CorruptData) << c.what;
        EXPECT_NE(messageOf(character).find(c.message), std::string::npos) << c.what << ": " << messageOf(character);
    }
}

TEST_F(EditedGltf, AFileWithoutSkinIsOneRigidBody)
{
    const Result<Character> character = loadGltfCharacter(riggedSimple("rigid.gltf", [](nlohmann::json& gltf) {
        gltf["nodes"][1].erase("skin");
        gltf.erase("skins");
    }));
    ASSERT_TRUE(character.ok()) << messageOf(character);
    EXPECT_EQ(character->skeleton.jointCount(), 1);
    EXPECT_EQ(character->skeleton.joint(0).name, "humanoid_root");
    EXPECT_TRUE(character->skin.empty());
    EXPECT_TRUE(character->clips.empty());
    for (const Segment& segment : character->mesh.segments)
        EXPECT_EQ(segment.joint, "humanoid_root");
    EXPECT_NE(allWarnings(*character).find("no skin"), std::string::npos) << allWarnings(*character);
}

TEST_F(EditedGltf, AMixamoRigIsNamedByItsConvention)
{
    // RiggedFigure's skeleton with the names Mixamo gives these joints.
    const std::map<int, std::string> mixamo = {
        {2, "Hips"},      {11, "Spine"},       {12, "Spine2"},      {19, "Neck"},         {20, "Head"},
        {16, "LeftArm"},  {17, "LeftForeArm"}, {18, "LeftHand"},    {13, "RightArm"},     {14, "RightForeArm"},
        {15, "RightHand"}, {7, "LeftUpLeg"},   {8, "LeftLeg"},      {9, "LeftFoot"},      {10, "LeftToeBase"},
        {3, "RightUpLeg"}, {4, "RightLeg"},    {5, "RightFoot"},    {6, "RightToeBase"}};
    const Result<Character> character = loadGltfCharacter(edited(kRiggedFigure, "mixamo.gltf", [&](nlohmann::json& gltf) {
        for (const auto& [node, name] : mixamo)
            gltf["nodes"][node]["name"] = "mixamorig:" + name;
    }));
    ASSERT_TRUE(character.ok()) << messageOf(character);
    const std::map<std::string, std::string> names = namesBySource(*character);
    const std::map<std::string, std::string> expected = {
        {"Hips", "humanoid_root"}, {"Spine", "vl5"}, {"Spine2", "vt6"}, {"Neck", "vc4"}, {"Head", "skullbase"},
        {"LeftArm", "l_shoulder"}, {"LeftForeArm", "l_elbow"}, {"LeftHand", "l_radiocarpal"},
        {"RightArm", "r_shoulder"}, {"LeftUpLeg", "l_hip"}, {"LeftLeg", "l_knee"}, {"LeftFoot", "l_talocrural"},
        {"LeftToeBase", "l_metatarsophalangeal"}, {"RightToeBase", "r_metatarsophalangeal"}};
    for (const auto& [source, name] : expected)
        EXPECT_EQ(names.at("mixamorig:" + source), name) << source;
    EXPECT_TRUE(character->warnings.empty()) << allWarnings(*character);
}

// standardRig: CesiumMan (its root node turns it to face +X) is turned to face +Z; the robot's IK
// feet hang from its knees. Nothing the file shows changes: every joint of every clip frame is
// where the file's own rig puts it (turned), and every vertex keeps its joints.
TEST(GltfCharacter, StandardRig)
{
    for (const char* path : {kCesiumMan, kRobot, kRiggedFigure}) {
        SCOPED_TRACE(path);
        const Character raw = load(sharedData(path));
        Result<Character> standard = loadGltfCharacter(sharedData(path));
        ASSERT_TRUE(standard.ok());
        const anim::Skeleton& s = standard->skeleton;
        const std::vector<Vec3d> rest = s.worldPositions(s.restFrame());
        EXPECT_GT(rest[std::size_t(s.find("l_hip"))].x, rest[std::size_t(s.find("r_hip"))].x); // faces +Z
        ASSERT_GE(s.find("l_talocrural"), 0);
        EXPECT_EQ(s.joint(s.joint(s.find("l_talocrural")).parent).name, "l_knee");
        const bool turned = std::string(path) == kCesiumMan;
        EXPECT_EQ(allWarnings(*standard).find("facing +X; it is turned") != std::string::npos, turned);
        // The turn CesiumMan gets: a quarter turn about +Y taking +X to +Z.
        const auto turn = [&](const Vec3d& v) { return turned ? Vec3d{-v.z, v.y, v.x} : v; };
        for (std::size_t v = 0; v < raw.mesh.vertexCount(); ++v) {
            const Vec3d a = turn({raw.mesh.positions[v].x, raw.mesh.positions[v].y, raw.mesh.positions[v].z});
            ASSERT_NEAR(standard->mesh.positions[v].x, a.x, 1e-6);
            ASSERT_NEAR(standard->mesh.positions[v].z, a.z, 1e-6);
        }
        // Joints by source name: same world place in every frame of every clip.
        ASSERT_EQ(standard->clips.size(), raw.clips.size());
        std::vector<Vec3d> rp(std::size_t(raw.skeleton.jointCount())), sp(rp.size());
        std::vector<Quatd> ro(rp.size()), so(rp.size());
        double largest = 0;
        for (std::size_t c = 0; c < raw.clips.size(); ++c)
            for (int f = 0; f < raw.clips[c]->frameCount(); ++f) {
                raw.skeleton.worldTransforms(raw.clips[c]->frame(f), rp, ro);
                s.worldTransforms(standard->clips[c]->frame(f), sp, so);
                for (int j = 0; j < s.jointCount(); ++j) {
                    int r = 0;
                    while (raw.skeleton.joint(r).sourceName != s.joint(j).sourceName)
                        ++r;
                    const Vec3d d = sp[std::size_t(j)] - turn(rp[std::size_t(r)]);
                    largest = std::max(largest, std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z));
                }
            }
        EXPECT_LT(largest, 1e-4);
        for (std::size_t k = 0; k < raw.skin.joints.size(); ++k)
            ASSERT_EQ(s.joint(standard->skin.joints[k]).sourceName, raw.skeleton.joint(raw.skin.joints[k]).sourceName);
    }
}

} // namespace
} // namespace thespis::core::scene
