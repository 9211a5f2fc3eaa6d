// Skinning: LBS and DQS against references computed in double, the rest and rigid poses, the
// candy-wrapper twist, joint transforms against the skeleton, rigid segments, and the worker
// threads (bit-identical results, no allocation per frame).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "allocation_counter.h"
#include "anim/hanim.h"
#include "scene/skinning.h"

using namespace thespis::core;
using namespace thespis::core::scene;
using anim::Quat;
using anim::Quatd;
using anim::Vec3;
using anim::Vec3d;

namespace {

constexpr double kPi = std::numbers::pi;

Vec3d toDouble(Vec3 v) { return {v.x, v.y, v.z}; }
Quatd toDouble(Quat q) { return {q.x, q.y, q.z, q.w}; }
double length(Vec3d v) { return std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z); }
double distance(Vec3 a, Vec3d b) { return length(toDouble(a) - b); }

Quat randomRotation(std::mt19937& rng, float maxAngle = float(kPi))
{
    std::normal_distribution<float> gaussian;
    std::uniform_real_distribution<float> angle(-maxAngle, maxAngle);
    const Vec3 axis{gaussian(rng), gaussian(rng), gaussian(rng)};
    const float norm = std::sqrt(axis.x * axis.x + axis.y * axis.y + axis.z * axis.z);
    return Quat::fromAxisAngle(axis * (1.0f / norm), angle(rng));
}

/// A chain of joints "j0" … along +Y, one every `boneLength` metres from the origin.
anim::Skeleton chainSkeleton(int joints, double boneLength)
{
    std::vector<anim::Joint> chain;
    for (int j = 0; j < joints; ++j)
        chain.push_back({.name = "j" + std::to_string(j), .parent = j - 1, .offset = {0, j == 0 ? 0 : boneLength, 0}});
    return std::move(anim::Skeleton::create(std::move(chain))).value();
}

/// Appends a segment: a tube of `rings` rings of `around` vertices about the Y axis from y0 to y1.
void addTube(CharacterMesh& mesh, const std::string& joint, float y0, float y1, int rings, int around, float radius)
{
    Segment segment{.name = "tube" + std::to_string(mesh.segments.size()), .joint = joint};
    segment.firstVertex = std::uint32_t(mesh.positions.size());
    segment.firstTriangle = std::uint32_t(mesh.triangleCount());
    for (int r = 0; r < rings; ++r)
        for (int a = 0; a < around; ++a) {
            const float phi = float(2 * kPi) * float(a) / float(around);
            const float y = y0 + (y1 - y0) * float(r) / float(rings - 1);
            mesh.positions.push_back({radius * std::cos(phi), y, radius * std::sin(phi)});
            mesh.normals.push_back({std::cos(phi), 0, std::sin(phi)});
        }
    for (int r = 0; r + 1 < rings; ++r)
        for (int a = 0; a < around; ++a) {
            const auto vertex = [&](int ring, int k) {
                return segment.firstVertex + std::uint32_t(ring * around + k % around);
            };
            mesh.indices.insert(mesh.indices.end(), {vertex(r, a), vertex(r + 1, a), vertex(r + 1, a + 1),
                                                     vertex(r, a), vertex(r + 1, a + 1), vertex(r, a + 1)});
        }
    segment.vertexCount = std::uint32_t(mesh.positions.size()) - segment.firstVertex;
    segment.triangleCount = std::uint32_t(mesh.triangleCount()) - segment.firstTriangle;
    mesh.segments.push_back(segment);
}

/// A tube over a chain of `joints` joints, one segment per bone, skinned with `influences` slots:
/// each vertex is weighted by its height to the nearest bones (up to 4 non-zero weights, fewer at
/// the ends; unused slots are padding), or left without skin when influences is 0.
Character chainCharacter(int joints, int ringsPerBone, int around, int influences)
{
    const float bone = 0.5f;
    Character character;
    character.name = "chain";
    character.skeleton = chainSkeleton(joints, bone);
    for (int b = 0; b < joints; ++b)
        addTube(character.mesh, "j" + std::to_string(b), float(b) * bone, float(b + 1) * bone, ringsPerBone, around,
                0.1f);
    if (influences == 0)
        return character;
    character.skin.influences = influences;
    for (const Vec3& p : character.mesh.positions) {
        // Bone b pulls with (1 − |y − middle of b| / 1.6 bones)², the nearest `influences` of them.
        std::vector<std::pair<float, int>> pulls;
        for (int b = 0; b < joints; ++b) {
            const float d = std::abs(p.y - (float(b) + 0.5f) * bone) / (1.6f * bone);
            pulls.push_back({d < 1 ? (1 - d) * (1 - d) : 0.0f, b});
        }
        std::sort(pulls.rbegin(), pulls.rend());
        pulls.resize(std::size_t(influences));
        float sum = 0;
        for (const auto& pull : pulls)
            sum += pull.first;
        for (const auto& [weight, joint] : pulls) {
            character.skin.weights.push_back(weight / sum);
            character.skin.joints.push_back(std::uint16_t(weight > 0 ? joint : 0));
        }
    }
    EXPECT_TRUE(character.validate()) << character.validate().error().message;
    return character;
}

std::vector<RigidTransform> transformsFor(const anim::Skeleton& skeleton, std::span<const float> frame)
{
    const auto joints = std::size_t(skeleton.jointCount());
    std::vector<Vec3d> positions(joints);
    std::vector<Quatd> orientations(joints);
    std::vector<RigidTransform> transforms(joints);
    computeSkinningTransforms(skeleton, frame, skeleton.worldPositions(skeleton.restFrame()), positions,
                              orientations, transforms);
    return transforms;
}

std::vector<float> randomFrame(const anim::Skeleton& skeleton, std::mt19937& rng, float maxAngle)
{
    std::vector<float> frame = skeleton.restFrame();
    for (int j = 0; j < skeleton.jointCount(); ++j)
        anim::rotationAt(std::span<float>(frame), j) = randomRotation(rng, maxAngle);
    const std::size_t t = skeleton.frameLayout()->floatOffset(skeleton.translationElement(0));
    frame[t] = 0.3f;
    frame[t + 1] = -1.2f;
    frame[t + 2] = 2.0f;
    return frame;
}

struct Skinned {
    std::vector<Vec3> positions, normals;
};

Skinned skin(const Character& character, std::span<const RigidTransform> joints, SkinningMethod method)
{
    SkinningPalette palette;
    palette.update(joints);
    const std::size_t n = character.mesh.vertexCount();
    Skinned out{std::vector<Vec3>(n), std::vector<Vec3>(n)};
    skinVertices(character.skin, character.mesh.positions, character.mesh.normals, palette, method, 0, n,
                 out.positions, out.normals);
    return out;
}

/// Where a joint moves a rest point, and how it turns a rest normal, in double.
Vec3d moved(const RigidTransform& joint, Vec3 p)
{
    return anim::rotate(toDouble(joint.rotation), toDouble(p)) + toDouble(joint.translation);
}
Vec3d turned(const RigidTransform& joint, Vec3 n)
{
    return anim::rotate(toDouble(joint.rotation), toDouble(n));
}

std::vector<RigidTransform> randomPose(const anim::Skeleton& skeleton, std::mt19937& rng, float maxAngle)
{
    return transformsFor(skeleton, randomFrame(skeleton, rng, maxAngle));
}

} // namespace

TEST(Skinning, RestPoseGivesTheRestMesh)
{
    const Character character = chainCharacter(4, 6, 8, 4);
    const std::vector<RigidTransform> rest = transformsFor(character.skeleton, character.skeleton.restFrame());
    for (SkinningMethod method : {SkinningMethod::Linear, SkinningMethod::DualQuaternion}) {
        const Skinned out = skin(character, rest, method);
        for (std::size_t v = 0; v < character.mesh.vertexCount(); ++v) {
            ASSERT_EQ(out.positions[v], character.mesh.positions[v]) << skinningMethodName(method) << " vertex " << v;
            ASSERT_LT(distance(out.normals[v], toDouble(character.mesh.normals[v])), 1e-6);
        }
    }
}

TEST(Skinning, RigidPoseMovesTheMeshRigidlyAndBothMethodsAgree)
{
    Character character = chainCharacter(4, 6, 8, 4);
    const anim::Skeleton& skeleton = character.skeleton;
    // Only the root turns and moves: every joint then has the same rigid transform.
    std::vector<float> frame = skeleton.restFrame();
    const Quat turn = Quat::fromAxisAngle(Vec3{0.48f, 0.6f, 0.64f}, 2.1f);
    anim::rotationAt(std::span<float>(frame), 0) = turn;
    const std::size_t t = skeleton.frameLayout()->floatOffset(skeleton.translationElement(0));
    frame[t] = 1.5f;
    frame[t + 1] = -0.25f;
    frame[t + 2] = 3.0f;
    const std::vector<RigidTransform> joints = transformsFor(skeleton, frame);
    // Weights may sum to 1 only within 1e-3 (Skin::validate): that must not scale the mesh.
    for (float& w : character.skin.weights)
        w *= 1.0008f;
    ASSERT_TRUE(character.validate());

    const Skinned lbs = skin(character, joints, SkinningMethod::Linear);
    const Skinned dqs = skin(character, joints, SkinningMethod::DualQuaternion);
    for (std::size_t v = 0; v < character.mesh.vertexCount(); ++v) {
        const Vec3d expected =
            anim::rotate(toDouble(turn), toDouble(character.mesh.positions[v])) + Vec3d{1.5, -0.25, 3.0};
        const Vec3d expectedNormal = anim::rotate(toDouble(turn), toDouble(character.mesh.normals[v]));
        ASSERT_LT(distance(lbs.positions[v], expected), 1e-5) << "vertex " << v;
        ASSERT_LT(distance(dqs.positions[v], expected), 1e-5) << "vertex " << v;
        ASSERT_LT(distance(lbs.normals[v], expectedNormal), 1e-5) << "vertex " << v;
        ASSERT_LT(distance(dqs.normals[v], expectedNormal), 1e-5) << "vertex " << v;
    }
}

TEST(Skinning, SingleInfluenceVerticesFollowTheirJoint)
{
    Character character = chainCharacter(5, 4, 6, 1);
    std::mt19937 rng(7);
    const std::vector<RigidTransform> joints = randomPose(character.skeleton, rng, 2.5f);
    for (SkinningMethod method : {SkinningMethod::Linear, SkinningMethod::DualQuaternion}) {
        const Skinned out = skin(character, joints, method);
        for (std::size_t v = 0; v < character.mesh.vertexCount(); ++v) {
            const RigidTransform& joint = joints[character.skin.joints[v]];
            ASSERT_LT(distance(out.positions[v], moved(joint, character.mesh.positions[v])), 1e-5);
            ASSERT_LT(distance(out.normals[v], turned(joint, character.mesh.normals[v])), 1e-5);
        }
    }
}

// Every influence count against the definitions, in double: LBS = Σ wᵢ·Mᵢ applied to the point;
// DQS = normalised Σ ±wᵢ·q̂ᵢ with the signs of the dominant influence's hemisphere. Half the
// joints carry −q for their rotation (the same rotation), which DQS must not notice.
TEST(Skinning, MatchesTheDefinitionsForEveryInfluenceCount)
{
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    const anim::Skeleton skeleton = chainSkeleton(12, 0.3);
    std::vector<RigidTransform> joints = randomPose(skeleton, rng, 3.0f);
    for (std::size_t j = 0; j < joints.size(); j += 2)
        joints[j].rotation = anim::negate(joints[j].rotation);
    SkinningPalette palette;
    palette.update(joints);
    const Vec3 p{0.2f, 1.1f, -0.4f};
    const Vec3 n{0.6f, 0.0f, 0.8f};
    for (int influences = 1; influences <= kMaxInfluences; ++influences)
        for (int trial = 0; trial < 20; ++trial) {
            Skin skin{.influences = influences};
            float sum = 0;
            for (int i = 0; i < influences; ++i) {
                skin.joints.push_back(std::uint16_t(rng() % 12));
                skin.weights.push_back(0.05f + unit(rng));
                sum += skin.weights.back();
            }
            for (float& w : skin.weights)
                w /= sum;

            Vec3d lbs, lbsNormal;
            Quatd real{0, 0, 0, 0}, dual{0, 0, 0, 0};
            const auto dominant = std::max_element(skin.weights.begin(), skin.weights.end()) - skin.weights.begin();
            const Quatd pivot = toDouble(joints[skin.joints[std::size_t(dominant)]].rotation);
            for (std::size_t i = 0; i < std::size_t(influences); ++i) {
                const RigidTransform& joint = joints[skin.joints[i]];
                const double w = skin.weights[i];
                lbs = lbs + moved(joint, p) * w;
                lbsNormal = lbsNormal + turned(joint, n) * w;
                const Quatd q = toDouble(joint.rotation);
                const Vec3d t = toDouble(joint.translation);
                const Quatd d = Quatd{t.x / 2, t.y / 2, t.z / 2, 0} * q;
                const double s = anim::dot(q, pivot) < 0 ? -w : w;
                real = {real.x + s * q.x, real.y + s * q.y, real.z + s * q.z, real.w + s * q.w};
                dual = {dual.x + s * d.x, dual.y + s * d.y, dual.z + s * d.z, dual.w + s * d.w};
            }
            lbsNormal = lbsNormal * (1 / length(lbsNormal));
            const double norm = std::sqrt(anim::dot(real, real));
            real = {real.x / norm, real.y / norm, real.z / norm, real.w / norm};
            dual = {dual.x / norm, dual.y / norm, dual.z / norm, dual.w / norm};
            const Quatd translation = dual * anim::conjugate(real);
            const Vec3d dqs =
                anim::rotate(real, toDouble(p)) + Vec3d{translation.x, translation.y, translation.z} * 2.0;
            const Vec3d dqsNormal = anim::rotate(real, toDouble(n));

            Vec3 position, normal;
            const auto skinOne = [&](SkinningMethod method) {
                skinVertices(skin, {&p, 1}, {&n, 1}, palette, method, 0, 1, {&position, 1}, {&normal, 1});
            };
            skinOne(SkinningMethod::Linear);
            ASSERT_LT(distance(position, lbs), 1e-5) << influences << " influences, trial " << trial;
            ASSERT_LT(distance(normal, lbsNormal), 1e-5) << influences << " influences, trial " << trial;
            skinOne(SkinningMethod::DualQuaternion);
            ASSERT_LT(distance(position, dqs), 1e-5) << influences << " influences, trial " << trial;
            ASSERT_LT(distance(normal, dqsNormal), 1e-5) << influences << " influences, trial " << trial;
        }
}

// Twisting the second joint of a tube by 180° about the bone: LBS averages opposite points of
// the middle ring and collapses it ("candy wrapper"); DQS turns it by 90° and keeps its radius.
TEST(Skinning, DualQuaternionsKeepATwistedTubeRoundWhereLinearBlendingCollapses)
{
    const float radius = 0.1f;
    Character character;
    character.skeleton = chainSkeleton(2, 1.0);
    addTube(character.mesh, "j0", 0.0f, 2.0f, 21, 16, radius);
    character.skin.influences = 2;
    for (const Vec3& p : character.mesh.positions) {
        const float upper = std::clamp(p.y - 0.5f, 0.0f, 1.0f);
        character.skin.joints.insert(character.skin.joints.end(), {0, 1});
        character.skin.weights.insert(character.skin.weights.end(), {1 - upper, upper});
    }
    ASSERT_TRUE(character.validate());
    std::vector<float> frame = character.skeleton.restFrame();
    anim::rotationAt(std::span<float>(frame), 1) = Quat::fromAxisAngle(Vec3{0, 1, 0}, float(kPi));
    const std::vector<RigidTransform> joints = transformsFor(character.skeleton, frame);

    const Skinned lbs = skin(character, joints, SkinningMethod::Linear);
    const Skinned dqs = skin(character, joints, SkinningMethod::DualQuaternion);
    int middleRing = 0;
    for (std::size_t v = 0; v < character.mesh.vertexCount(); ++v) {
        if (std::abs(character.mesh.positions[v].y - 1.0f) > 1e-4f)
            continue;
        ++middleRing;
        const auto radial = [](Vec3 p) { return std::hypot(p.x, p.z); };
        EXPECT_NEAR(radial(dqs.positions[v]), radius, 1e-3) << "vertex " << v;
        EXPECT_LT(radial(lbs.positions[v]), 0.5f * radius) << "vertex " << v;
        EXPECT_NEAR(dqs.positions[v].y, 1.0f, 1e-5);
    }
    EXPECT_EQ(middleRing, 16);
}

TEST(Skinning, TransformsAgreeWithTheSkeletonsWorldTransforms)
{
    const anim::Skeleton& skeleton = anim::hanim::skeleton(anim::hanim::Level::Loa2);
    const auto n = std::size_t(skeleton.jointCount());
    const std::vector<Vec3d> rest = skeleton.worldPositions(skeleton.restFrame());
    std::mt19937 rng(3);
    const std::vector<float> frame = randomFrame(skeleton, rng, float(kPi));
    std::vector<Vec3d> positions(n);
    std::vector<Quatd> orientations(n);
    skeleton.worldTransforms(frame, positions, orientations);

    const std::vector<RigidTransform> joints = transformsFor(skeleton, frame);
    for (std::size_t j = 0; j < n; ++j) {
        const std::string& name = skeleton.joint(int(j)).name;
        EXPECT_LT(anim::angleBetween(toDouble(joints[j].rotation), orientations[j]), 1e-6) << name;
        const Vec3 restPosition{float(rest[j].x), float(rest[j].y), float(rest[j].z)};
        EXPECT_LT(length(moved(joints[j], restPosition) - positions[j]), 1e-5) << name;
        // A joint sits rigidly on its parent's bone, so the parent's transform moves it too.
        if (const int parent = skeleton.joint(int(j)).parent; parent >= 0) {
            EXPECT_LT(length(moved(joints[std::size_t(parent)], restPosition) - positions[j]), 1e-5) << name;
        }
    }
}

TEST(Skinning, RigidSegmentsFollowTheirJoints)
{
    const Character character = chainCharacter(3, 5, 8, 0);
    std::mt19937 rng(5);
    const std::vector<RigidTransform> joints = randomPose(character.skeleton, rng, 2.0f);
    const std::size_t n = character.mesh.vertexCount();
    std::vector<Vec3> positions(n), normals(n);
    skinRigidSegments(character, joints, positions, normals);
    for (std::size_t s = 0; s < character.mesh.segments.size(); ++s) {
        const Segment& segment = character.mesh.segments[s];
        const RigidTransform& joint = joints[s]; // segment s follows joint j<s>
        for (std::size_t v = segment.firstVertex; v < segment.firstVertex + segment.vertexCount; ++v) {
            ASSERT_LT(distance(positions[v], moved(joint, character.mesh.positions[v])), 1e-5);
            ASSERT_LT(distance(normals[v], turned(joint, character.mesh.normals[v])), 1e-5);
        }
    }
    // The workers hand a skinless character to skinRigidSegments.
    SkinningWorkers workers(2);
    std::vector<Vec3> workerPositions(n), workerNormals(n);
    workers.skin(character, joints, SkinningMethod::DualQuaternion, workerPositions, workerNormals);
    EXPECT_EQ(workerPositions, positions);
    EXPECT_EQ(workerNormals, normals);
}

TEST(Skinning, WorkersMatchOneThreadBitForBitAndAllocateNothingPerFrame)
{
    const Character character = chainCharacter(10, 40, 48, 4); // 19 200 vertices, many chunks
    const std::size_t n = character.mesh.vertexCount();
    std::mt19937 rng(9);
    for (int threads : {1, 2, 3, 0}) {
        SkinningWorkers workers(threads);
        EXPECT_EQ(workers.threadCount(), threads > 0 ? threads : std::max(1, int(std::thread::hardware_concurrency())));
        std::vector<Vec3> positions(n), normals(n), expectedPositions(n), expectedNormals(n);
        SkinningPalette palette;
        for (int frame = 0; frame < 4; ++frame) {
            const std::vector<RigidTransform> joints = randomPose(character.skeleton, rng, 1.5f);
            const SkinningMethod method = frame % 2 ? SkinningMethod::DualQuaternion : SkinningMethod::Linear;
            const long before = thespis::test::allocationCount();
            workers.skin(character, joints, method, positions, normals);
            palette.update(joints);
            skinVertices(character.skin, character.mesh.positions, character.mesh.normals, palette, method, 0, n,
                         expectedPositions, expectedNormals);
            if (frame > 0) { // the palettes allocate on their first frame
                EXPECT_EQ(thespis::test::allocationCount() - before, 0) << threads << " threads";
            }
            ASSERT_EQ(positions, expectedPositions) << threads << " threads, frame " << frame;
            ASSERT_EQ(normals, expectedNormals) << threads << " threads, frame " << frame;
        }
    }
}

TEST(Skinning, AnySplitOfTheVertexRangeGivesTheSameBits)
{
    const Character character = chainCharacter(6, 5, 7, 3); // 210 vertices
    const std::size_t n = character.mesh.vertexCount();
    std::mt19937 rng(13);
    SkinningPalette palette;
    palette.update(randomPose(character.skeleton, rng, 2.0f));
    for (SkinningMethod method : {SkinningMethod::Linear, SkinningMethod::DualQuaternion}) {
        std::vector<Vec3> whole(n), wholeNormals(n), pieces(n), pieceNormals(n);
        skinVertices(character.skin, character.mesh.positions, character.mesh.normals, palette, method, 0, n, whole,
                     wholeNormals);
        for (std::size_t begin = 0, size = 1; begin < n; begin += size, size = size % 7 + 1)
            skinVertices(character.skin, character.mesh.positions, character.mesh.normals, palette, method, begin,
                         std::min(n, begin + size), pieces, pieceNormals);
        EXPECT_EQ(pieces, whole) << skinningMethodName(method);
        EXPECT_EQ(pieceNormals, wholeNormals) << skinningMethodName(method);
    }
}
