// Retargeting real motion capture (anim/retarget.h, anim/clip_retarget.h): every body clip in
// ../shared/data/mocap and the glTF sample characters' own animations, played on the H-Anim
// skeletons and on the glTF rigs. What a person would look at: the limbs point where the
// performer's limbs point, the feet are on the ground, the body is its own height.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <numbers>
#include <string>
#include <vector>

#include "anim/body_measure.h"
#include "anim/bvh.h"
#include "anim/clip_retarget.h"
#include "anim/hanim.h"
#include "scene/gltf_character.h"
#include "test_support.h"

namespace thespis::core::anim {
namespace {

using test::sharedData;

struct BodyClipFile {
    const char* path;
    bool airborne; ///< jumps, a cartwheel, a run: frames without a foot near the ground are expected
    bool crouched; ///< a stance lower than standing (CMU 140_xx "ready" idles)
};

const BodyClipFile kBodyClips[] = {
    {"mocap/cmu/01_01.bvh", true, false},   {"mocap/cmu/02_01.bvh", false, false},
    {"mocap/cmu/05_06.bvh", true, false},   {"mocap/cmu/77_02.bvh", false, false},
    {"mocap/cmu/111_28.bvh", false, false}, {"mocap/cmu/113_21.bvh", false, false},
    {"mocap/cmu/131_01.bvh", false, false}, {"mocap/cmu/131_02.bvh", false, false},
    {"mocap/cmu/131_03.bvh", true, false},  {"mocap/cmu/140_06.bvh", false, true},
    {"mocap/cmu/140_07.bvh", false, true},  {"mocap/cmu/141_16.bvh", false, false},
    {"mocap/cmu/141_20.bvh", false, false}, {"mocap/threejs/pirouette.bvh", true, false},
    {"mocap/makehuman/walk1.bvh", false, false}, {"mocap/other/Boxing_Toes.bvh", false, false},
};

double angleDegrees(const Vec3d& a, const Vec3d& b)
{
    const double d = a.x * b.x + a.y * b.y + a.z * b.z;
    const double n = std::sqrt((a.x * a.x + a.y * a.y + a.z * a.z) * (b.x * b.x + b.y * b.y + b.z * b.z));
    return std::acos(std::clamp(d / n, -1.0, 1.0)) * 180.0 / std::numbers::pi;
}

// Limb bones both rigs have (parent joint, child joint).
const std::pair<const char*, const char*> kLimbs[] = {
    {"l_hip", "l_knee"},         {"l_knee", "l_talocrural"},   {"r_hip", "r_knee"},
    {"r_knee", "r_talocrural"},  {"l_shoulder", "l_elbow"},    {"l_elbow", "l_radiocarpal"},
    {"r_shoulder", "r_elbow"},   {"r_elbow", "r_radiocarpal"},
};

struct Measured {
    double worstLimbDegrees = 0;
    double worstFootMismatch = 0; // |target feet − scaled source feet over its floor|, target units
    double groundedShare = 0;     // frames whose feet are within 8 cm of the floor (joints, not soles:
                                  // a heel strike holds the ankle a few cm up)
    double sunkShare = 0;         // frames whose feet are more than 3 cm below it
    double headHeightRatio = 0;   // highest head over the clip / rest head height
};

// Sizes in the target's units: a centimetre is legLength / 84 (H-Anim's legs are 0.84 m).
Measured measure(const KeyframeClip& sourceClip, const Skeleton& sourceSkeleton, const Skeleton& target,
                 const RetargetedClip& result)
{
    Measured m;
    const BodyMeasure body = measureBody(target);
    const double cm = body.legLength / 84.0;
    std::vector<Vec3d> sp(std::size_t(sourceSkeleton.jointCount())), tp(std::size_t(target.jointCount()));
    std::vector<Quatd> so(sp.size()), to(tp.size());
    const std::vector<double> sourceFeet = footHeights(sourceClip, sourceSkeleton);
    const std::vector<double> targetFeet = footHeights(*result.clip, target);
    const int head = target.find("skullbase");
    double highestHead = 0;
    int grounded = 0, sunk = 0;
    for (int f = 0; f < sourceClip.frameCount(); ++f) {
        sourceSkeleton.worldTransforms(sourceClip.frame(f), sp, so);
        target.worldTransforms(result.clip->frame(f), tp, to);
        for (const auto& [a, b] : kLimbs) {
            const int sa = sourceSkeleton.find(a), sb = sourceSkeleton.find(b);
            const int ta = target.find(a), tb = target.find(b);
            if (sa < 0 || sb < 0 || ta < 0 || tb < 0)
                continue;
            m.worstLimbDegrees = std::max(m.worstLimbDegrees, angleDegrees(sp[std::size_t(sb)] - sp[std::size_t(sa)],
                                                                           tp[std::size_t(tb)] - tp[std::size_t(ta)]));
        }
        const double feet = targetFeet[std::size_t(f)] - body.footRestHeight;
        const double floor = result.report.sourceFloors[std::size_t(f)];
        const double wanted = std::max(0.0, sourceFeet[std::size_t(f)] - floor) * result.report.scale;
        m.worstFootMismatch = std::max(m.worstFootMismatch, std::abs(feet - wanted));
        grounded += std::abs(feet) < 8 * cm;
        sunk += feet < -3 * cm;
        if (head >= 0)
            highestHead = std::max(highestHead, tp[std::size_t(head)].y);
    }
    m.groundedShare = double(grounded) / sourceClip.frameCount();
    m.sunkShare = double(sunk) / sourceClip.frameCount();
    if (head >= 0)
        m.headHeightRatio = highestHead / body.restPositions[std::size_t(head)].y;
    return m;
}

// What a person sees: the limbs as the performer's, the feet on the floor where the performer's
// are (all the time for a walk or a stance, most of the time with jumps), the body its own size.
void expectPlaysRight(const BodyClipFile& file, const bvh::ImportedClip& source, const Skeleton& target,
                      const std::string& targetName, double limbDegrees = 0.5)
{
    SCOPED_TRACE(std::string(file.path) + " on " + targetName);
    auto result = retargetClip(*source.clip, source.skeleton, target);
    ASSERT_TRUE(result.ok()) << describe(result.error());
    ASSERT_TRUE(result->report.groundFitted);
    const Measured m = measure(*source.clip, source.skeleton, target, *result);
    std::printf("%-30s on %-16s scale %.4f  limbs %.2f°  feet %.1f mm  grounded %.2f  sunk %.3f  head %.3f\n",
                file.path, targetName.c_str(), result->report.scale, m.worstLimbDegrees, 1000 * m.worstFootMismatch,
                m.groundedShare, m.sunkShare, m.headHeightRatio);
    EXPECT_LT(m.worstLimbDegrees, limbDegrees);
    EXPECT_LT(m.worstFootMismatch, 0.005 * measureBody(target).legLength / 0.84);
    EXPECT_GE(m.groundedShare, file.airborne ? 0.2 : 0.8);
    EXPECT_LE(m.sunkShare, 0.05);
    if (target.find("skullbase") >= 0) {
        EXPECT_GT(m.headHeightRatio, file.crouched ? 0.8 : 0.95);
        EXPECT_LT(m.headHeightRatio, file.airborne ? 1.6 : 1.1);
    }
}

const bvh::ImportedClip& importedBody(const std::string& path)
{
    static std::map<std::string, bvh::ImportedClip> cache;
    auto it = cache.find(path);
    if (it == cache.end()) {
        auto loaded = bvh::load(sharedData(path), {.dropCalibrationFrame = true});
        if (!loaded) {
            ADD_FAILURE() << path << ": " << describe(loaded.error());
            std::abort();
        }
        it = cache.emplace(path, std::move(*loaded)).first;
    }
    return it->second;
}

TEST(MocapRetarget, EveryClipOnTheHAnimSkeletons)
{
    const std::pair<hanim::Level, const char*> levels[] = {
        {hanim::Level::Loa1, "H-Anim LOA 1"}, {hanim::Level::Subset25, "H-Anim 25"}, {hanim::Level::Loa2, "H-Anim LOA 2"}};
    for (const auto& [level, name] : levels)
        for (const BodyClipFile& file : kBodyClips)
            expectPlaysRight(file, importedBody(file.path), hanim::skeleton(level), name);
}

TEST(MocapRetarget, EveryClipOnTheGltfCharacters)
{
    for (const char* path : {"characters/RobotExpressive/RobotExpressive.glb", "characters/CesiumMan/CesiumMan.glb",
                             "characters/RiggedFigure/RiggedFigure.gltf"}) {
        auto character = scene::loadGltfCharacter(sharedData(path), {.loadTextures = false});
        ASSERT_TRUE(character.ok()) << describe(character.error());
        for (const BodyClipFile& file : kBodyClips)
            expectPlaysRight(file, importedBody(file.path), character->skeleton,
                             std::filesystem::path(path).stem().string());
    }
}

// The glTF samples' own animations, on their own rig and on the H-Anim skeleton: their feet on
// the floor, their limbs as the file moves them.
TEST(MocapRetarget, GltfAnimationsOnTheirOwnRigAndOnHAnim)
{
    // Clips that leave the ground: jumps, a run, and CesiumMan's cartoon walk, whose feet both
    // hang up to 9 cm over the floor as they pass each other.
    const std::set<std::string> airborne = {"RobotExpressive Jump", "RobotExpressive WalkJump", "RobotExpressive Running",
                                            "CesiumMan animation"};
    for (const char* path : {"characters/RobotExpressive/RobotExpressive.glb", "characters/CesiumMan/CesiumMan.glb",
                             "characters/RiggedFigure/RiggedFigure.gltf"}) {
        auto character = scene::loadGltfCharacter(sharedData(path), {.loadTextures = false});
        ASSERT_TRUE(character.ok()) << describe(character.error());
        for (const auto& clip : character->clips) {
            const std::string name = std::filesystem::path(path).stem().string() + " " + clip->name();
            const BodyClipFile file{name.c_str(), airborne.count(name) > 0, false};
            const bvh::ImportedClip source{character->skeleton, clip, {}};
            expectPlaysRight(file, source, character->skeleton, "its own rig");
            // The robot's IK feet are not always at the end of its shins (they stretch by a
            // few millimetres), which the H-Anim shin cannot follow exactly.
            expectPlaysRight(file, source, hanim::skeleton(hanim::Level::Loa1), "H-Anim LOA 1", 2.5);
        }
    }
}

} // namespace
} // namespace thespis::core::anim
