// Blending real motion capture: the CMU walk 02_01 with the CMU wave 141_16 layered over its
// upper body (paper §4.2: a gesture on top of a locomotion), nesting, and cut-off.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "anim/blending_schedule.h"
#include "anim/bvh.h"
#include "anim/joint_mask.h"
#include "anim/simd.h"
#include "test_support.h"

using namespace thespis::core;
using namespace thespis::core::anim;

namespace {

constexpr double kWaveStart = 0.3; // seconds into the walk
constexpr double kFade = 0.4;      // cubic fade in and out of the wave

struct Clips {
    bvh::ImportedClip walk;
    std::shared_ptr<const KeyframeClip> wave; // on the walk's layout
};

const Clips& clips()
{
    static const Clips loaded = [] {
        auto walk = bvh::load(thespis::test::sharedData("mocap/cmu/02_01.bvh"));
        auto wave = bvh::load(thespis::test::sharedData("mocap/cmu/141_16.bvh"));
        if (!walk || !wave) {
            ADD_FAILURE() << "cannot load the walk or the wave";
            std::abort();
        }
        std::shared_ptr<const KeyframeClip> waveClip = wave->clip;
        // Both are the cgspeed CMU skeleton; should a file differ, the wave is brought onto the
        // walk's layout by joint name.
        if (!(*wave->clip->layout() == *walk->clip->layout())) {
            auto remapped = remapClip(*wave->clip, walk->skeleton.frameLayout(), walk->skeleton.restFrame());
            if (!remapped)
                std::abort();
            waveClip = *remapped;
        }
        return Clips{std::move(*walk), waveClip};
    }();
    return loaded;
}

BlendingAction walkAction(double start = 0)
{
    BlendingAction action;
    action.name = "walk";
    action.source = clips().walk.clip;
    action.start = start;
    return action; // Normalized, weight 1
}

BlendingAction waveAction(double start, Curve weight = Curve::cubicFade(kFade, kFade))
{
    BlendingAction action;
    action.name = "wave";
    action.source = clips().wave;
    action.start = start;
    action.params.mode = BlendMode::Override;
    action.params.weight = std::move(weight);
    action.params.mask = std::make_shared<JointMask>(JointMask::preset(MaskPreset::UpperBody));
    return action;
}

std::vector<float> sample(const BlendableObject& b, double t)
{
    std::vector<float> out(b.layout()->floatCount());
    b.evaluate(t, out);
    return out;
}

Quatd toDouble(const Quat& q) { return normalize(Quatd{q.x, q.y, q.z, q.w}); }

/// Rotation angle between two rotations, accurate for small angles too (acos of a float dot
/// product loses half of the digits there): 2·atan2(|v|, |w|) of a⁻¹·b.
double angle(const Quat& a, const Quat& b)
{
    const Quatd d = conjugate(toDouble(a)) * toDouble(b);
    return 2.0 * std::atan2(std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z), std::abs(d.w));
}

Quat rotation(const std::vector<float>& frame, int r) { return rotationAt(std::span<const float>(frame), r); }

/// Mask weight per layout element, as the schedule resolves it on the walk's skeleton.
std::vector<float> upperBodyWeights()
{
    const Clips& c = clips();
    return JointMask::preset(MaskPreset::UpperBody).resolve(*c.walk.skeleton.frameLayout(), c.walk.skeleton.parents());
}

} // namespace

TEST(MocapBlend, UpperBodyMaskSplitsTheCmuSkeleton)
{
    // The mask names H-Anim joints; the import mapped the CMU names onto them, so the split
    // follows the body: legs and root below, spine, arms and head above.
    const Clips& c = clips();
    const FrameLayout& layout = *c.walk.skeleton.frameLayout();
    const std::vector<float> w = upperBodyWeights();
    auto weightOf = [&](const char* name) { return w[std::size_t(layout.find(name, ElementKind::Rotation))]; };
    for (const char* lower : {"humanoid_root", "l_hip", "r_hip", "l_knee", "r_knee", "l_talocrural", "r_metatarsophalangeal",
                              "LHipJoint", "RHipJoint"})
        EXPECT_EQ(weightOf(lower), 0.0f) << lower;
    for (const char* upper : {"vl5", "vl1", "vt1", "vc4", "skullbase", "l_sternoclavicular", "r_shoulder", "r_elbow",
                              "r_radiocarpal", "r_carpometacarpal_1", "l_metacarpophalangeal_2"})
        EXPECT_EQ(weightOf(upper), 1.0f) << upper;
    const int rootTranslation = layout.find("humanoid_root", ElementKind::Translation);
    ASSERT_GE(rootTranslation, 0);
    EXPECT_EQ(w[std::size_t(rootTranslation)], 0.0f);
    for (float x : w)
        EXPECT_TRUE(x == 0.0f || x == 1.0f);
}

TEST(MocapBlend, WaveOverWalk)
{
    const Clips& c = clips();
    const FrameLayout& layout = *c.walk.skeleton.frameLayout();
    BlendingSchedule walkOnly(c.walk.skeleton);
    ASSERT_TRUE(walkOnly.addAction(walkAction()));
    BlendingSchedule schedule(c.walk.skeleton);
    ASSERT_TRUE(schedule.addAction(walkAction()));
    auto waveId = schedule.addAction(waveAction(kWaveStart));
    ASSERT_TRUE(waveId) << describe(waveId.error());
    const double waveEnd = schedule.endTime(*waveId);
    EXPECT_NEAR(waveEnd, kWaveStart + c.wave->domain().duration(), 1e-12);

    const std::vector<float> mask = upperBodyWeights();
    const double dt = 1.0 / 120.0; // the clips' key rate
    const int steps = int(std::floor(c.walk.clip->domain().end / dt));
    int heldSamples = 0, fadeSamples = 0;
    double worstRatio = 0; // largest dB / bound: how close the blend comes to the bound

    std::vector<float> previousB, previousA, previousC;
    for (int k = 0; k <= steps; ++k) {
        const double t = k * dt;
        const std::vector<float> blended = sample(schedule, t);
        const std::vector<float> walk = sample(walkOnly, t);
        const std::vector<float> rawWalk = sample(*c.walk.clip, t);
        const std::vector<float> wave = sample(*c.wave, t - kWaveStart);
        const double local = t - kWaveStart;
        const bool held = local > kFade && local < c.wave->domain().duration() - kFade;

        for (int e = 0; e < layout.elementCount(); ++e) {
            const std::size_t at = layout.floatOffset(e);
            const int width = floatsPerElement(layout.kind(e));
            if (mask[std::size_t(e)] == 0.0f) {
                // Lower body, root rotation and root translation: the walk, bit for bit as the
                // schedule renders it alone; against the clip itself, translations are exact and
                // rotations differ only by the blender's renormalization (a float rounding).
                for (int i = 0; i < width; ++i)
                    ASSERT_EQ(blended[at + std::size_t(i)], walk[at + std::size_t(i)])
                        << "t=" << t << " " << layout.name(e);
                if (layout.kind(e) == ElementKind::Translation) {
                    for (int i = 0; i < width; ++i)
                        ASSERT_EQ(blended[at + std::size_t(i)], rawWalk[at + std::size_t(i)]) << "t=" << t;
                } else {
                    ASSERT_LE(angle(rotation(blended, e), rotation(rawWalk, e)), 1e-6) << "t=" << t << " " << layout.name(e);
                }
            } else if (held) {
                // Upper body where the wave's weight is 1: the wave, bit for bit.
                for (int i = 0; i < width; ++i)
                    ASSERT_EQ(blended[at + std::size_t(i)], wave[at + std::size_t(i)]) << "t=" << t << " " << layout.name(e);
            } else if (local < 0 || local > c.wave->domain().duration()) {
                for (int i = 0; i < width; ++i)
                    ASSERT_EQ(blended[at + std::size_t(i)], walk[at + std::size_t(i)]) << "t=" << t << " " << layout.name(e);
            }
        }
        heldSamples += held ? 1 : 0;

        // No pops. Per step, a masked joint B = slerp(A, C, w) between the walk A and the wave C
        // turns by at most
        //   max(ΔA, ΔC) / cos(θ/4)  +  |Δw|·θ(A, C)  +  ε
        // The first term is the inputs' own motion carried through slerp: moving an end of a
        // slerp moves the blend by at most the end's move times sin(wφ)/sin φ (Jacobi fields on
        // the quaternion sphere, φ = θ/2 the quaternion arc between the ends), and the two
        // coefficients sum to at most 1/cos(φ/2); θ is taken as the largest A–C angle of the
        // step plus the step's motion, which covers the finite step. The second term is the
        // cross-fade itself: the cubic fade's weight changes by at most 1.5·dt/fade per step.
        // ε = 1e-5 rad absorbs float storage of the quaternions (about 1e-7 rad each). A pop (a
        // weight jump, a slerp the long way round, a hemisphere flip) breaks the bound by far.
        if (k > 0 && local >= 0 && local <= c.wave->domain().duration() + dt) {
            const double maxWeightStep = 1.5 * dt / kFade;
            for (int r = 0; r < layout.rotationCount(); ++r) {
                if (mask[std::size_t(r)] == 0.0f)
                    continue;
                const double dB = angle(rotation(blended, r), rotation(previousB, r));
                const double dA = angle(rotation(walk, r), rotation(previousA, r));
                const double dC = angle(rotation(wave, r), rotation(previousC, r));
                const double theta1 = angle(rotation(walk, r), rotation(wave, r));
                const double theta0 = angle(rotation(previousA, r), rotation(previousC, r));
                const double theta = std::min(std::numbers::pi, std::max(theta0, theta1) + std::max(dA, dC));
                const double bound = std::max(dA, dC) / std::cos(theta / 4) + maxWeightStep * theta1 + 1e-5;
                worstRatio = std::max(worstRatio, dB / bound);
                ASSERT_LE(dB, bound) << "t=" << t << " " << layout.name(r) << " walk " << dA << " wave " << dC
                                     << " apart " << theta1;
                if (!held)
                    ++fadeSamples;
            }
        }
        previousB = blended;
        previousA = walk;
        previousC = wave;
    }
    EXPECT_GT(heldSamples, 150);
    EXPECT_GT(fadeSamples, 1000); // both fades, every masked joint
    ::testing::Test::RecordProperty("worst_ratio_to_bound", std::to_string(worstRatio));
}

TEST(MocapBlend, NestedScheduleEqualsFlattened)
{
    const Clips& c = clips();
    const double shift = 0.5;
    // Flat: walk at 0.5, wave at 0.8.
    BlendingSchedule flat(c.walk.skeleton);
    ASSERT_TRUE(flat.addAction(walkAction(shift)));
    ASSERT_TRUE(flat.addAction(waveAction(shift + kWaveStart)));

    // Nested 1: the whole walk+wave schedule played as one action at 0.5.
    auto inner = std::make_shared<BlendingSchedule>(c.walk.skeleton);
    ASSERT_TRUE(inner->addAction(walkAction()));
    ASSERT_TRUE(inner->addAction(waveAction(kWaveStart)));
    BlendingSchedule outer(c.walk.skeleton);
    BlendingAction nested;
    nested.name = "walk and wave";
    nested.source = inner;
    nested.start = shift;
    ASSERT_TRUE(outer.addAction(nested));

    // Nested 2: a walk-only schedule at 0.5, the wave layered over it in the outer schedule.
    auto walkSchedule = std::make_shared<BlendingSchedule>(c.walk.skeleton);
    ASSERT_TRUE(walkSchedule->addAction(walkAction()));
    BlendingSchedule layered(c.walk.skeleton);
    BlendingAction walkNested;
    walkNested.name = "walk schedule";
    walkNested.source = walkSchedule;
    walkNested.start = shift;
    ASSERT_TRUE(layered.addAction(walkNested));
    ASSERT_TRUE(layered.addAction(waveAction(shift + kWaveStart)));

    EXPECT_DOUBLE_EQ(outer.domain().end, flat.domain().end);
    const double end = flat.domain().end;
    const FrameLayout& layout = *c.walk.skeleton.frameLayout();
    double worst = 0;
    for (double t = 0; t <= end + 0.1; t += 1.0 / 97.0) { // off the key grid too
        const std::vector<float> f = sample(flat, t);
        for (const BlendingSchedule* nestedSchedule : {&outer, &layered}) {
            const std::vector<float> n = sample(*nestedSchedule, t);
            for (int r = 0; r < layout.rotationCount(); ++r) {
                const double d = angle(rotation(f, r), rotation(n, r));
                worst = std::max(worst, d);
                ASSERT_LE(d, 1e-6) << "t=" << t << " " << layout.name(r); // one more renormalization
            }
            for (std::size_t k = layout.translationOffset(); k < layout.floatCount(); ++k)
                ASSERT_NEAR(f[k], n[k], 1e-5 * std::max(1.0f, std::abs(f[k]))) << "t=" << t;
        }
    }
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", worst);
    ::testing::Test::RecordProperty("worst_nested_difference_rad", text);
}

TEST(MocapBlend, CutOffFadesOutOverExactlyTheGivenTime)
{
    const Clips& c = clips();
    const FrameLayout& layout = *c.walk.skeleton.frameLayout();
    BlendingSchedule walkOnly(c.walk.skeleton);
    ASSERT_TRUE(walkOnly.addAction(walkAction()));
    BlendingSchedule schedule(c.walk.skeleton);
    ASSERT_TRUE(schedule.addAction(walkAction()));
    auto wave = schedule.addAction(waveAction(kWaveStart, Curve::constant(1.0)));
    ASSERT_TRUE(wave);

    const double at = 1.25, fade = 0.5; // exact in binary: at + fade is 1.75 exactly
    ASSERT_TRUE(schedule.cutOffAction(*wave, at, fade));
    EXPECT_EQ(schedule.endTime(*wave), at + fade);
    EXPECT_FALSE(schedule.isFinished(*wave, at + fade - 1e-9));
    EXPECT_TRUE(schedule.isFinished(*wave, at + fade));
    const std::vector<float> mask = upperBodyWeights();

    // The blend of walk and wave at weight w, computed here independently in double.
    auto expectBlendAt = [&](double t, double w) {
        const std::vector<float> out = sample(schedule, t);
        const std::vector<float> walk = sample(walkOnly, t);
        const std::vector<float> waveFrame = sample(*c.wave, t - kWaveStart);
        double largestEffect = 0;
        for (int r = 0; r < layout.rotationCount(); ++r) {
            if (mask[std::size_t(r)] == 0.0f) {
                EXPECT_EQ(rotation(out, r), rotation(walk, r));
                continue;
            }
            const Quatd expected = slerp(toDouble(rotation(walk, r)), toDouble(rotation(waveFrame, r)), w);
            const Quat e{float(expected.x), float(expected.y), float(expected.z), float(expected.w)};
            EXPECT_LE(angle(rotation(out, r), e), 2e-5) << "t=" << t << " w=" << w << " " << layout.name(r);
            largestEffect = std::max(largestEffect, angle(rotation(out, r), rotation(walk, r)));
        }
        return largestEffect;
    };

    EXPECT_GT(expectBlendAt(at - 0.1, 1.0), 0.1);                  // before: the wave, whole
    EXPECT_GT(expectBlendAt(at, 1.0), 0.1);                        // the fade starts at `at`
    expectBlendAt(at + 0.5 * fade, 0.5);                           // cubic: half way, half weight
    expectBlendAt(at + 0.25 * fade, 1.0 - smoothStep(0.25));
    const double nearEnd = 1.0 - smoothStep(0.95);                 // 0.00725
    EXPECT_GT(expectBlendAt(at + 0.95 * fade, nearEnd), 1e-4);     // still there just before the end

    // From at + fade on: the walk alone, bit for bit, every element.
    for (double t : {at + fade, at + fade + 1.0 / 120, at + fade + 0.3}) {
        const std::vector<float> out = sample(schedule, t);
        const std::vector<float> walk = sample(walkOnly, t);
        for (std::size_t k = 0; k < out.size(); ++k)
            ASSERT_EQ(out[k], walk[k]) << "t=" << t << " float " << k;
    }
    EXPECT_EQ(schedule.removeFinishedActions(at + fade), 1);
    EXPECT_EQ(schedule.actionCount(), 1);
}

// The blend is the same bit for bit on every CPU and in both builds (AVX2 clone, baseline): it
// rounds exactly as this plain scalar reference of its rules does, with plain arithmetic (the
// scalar simd::reciprocalSqrt, no hardware estimate). A walk frame and a wave frame, weights
// over every lane.
TEST(MocapBlend, BlendRoundsAsTheScalarReferenceOnEveryJoint)
{
    const KeyframeClip& walk = *clips().walk.clip;
    const KeyframeClip& wave = *clips().wave;
    const FrameLayout& layout = *walk.layout();
    const int rotations = layout.rotationCount();
    ASSERT_GE(rotations, 17) << "the CMU skeleton fills two eight-joint blocks";
    const std::span<const float> a = walk.frame(40), b = wave.frame(200);
    const std::vector<float> rest = clips().walk.skeleton.restFrame();
    std::vector<float> weightsA(layout.floatCount()), weightsB(layout.floatCount());
    for (int j = 0; j < rotations; ++j) {
        weightsA[j] = j % 7 == 3 ? 0.0f : 0.15f + 0.05f * float(j % 9); // some joints under 1, some undriven
        weightsB[j] = j % 7 == 3 ? 0.0f : (j % 2 == 0 ? 0.3f + 0.1f * float(j % 5) : 0.0f);
    }
    const BlendInput inputs[] = {{a.data(), weightsA.data()}, {b.data(), weightsB.data()}};
    std::vector<float> out(layout.floatCount()), totals(layout.floatCount());
    QuaternionBlender().blend(layout, inputs, rest, out, totals);

    int undriven = 0;
    for (int j = 0; j < rotations; ++j) {
        const float* qa = a.data() + 4 * j;
        const float* qb = b.data() + 4 * j;
        const float* r = rest.data() + 4 * j;
        float q[4];
        for (int c = 0; c < 4; ++c)
            q[c] = weightsA[j] * qa[c];
        const float d = (q[0] * qb[0] + q[1] * qb[1]) + (q[2] * qb[2] + q[3] * qb[3]);
        const float s = std::signbit(d) ? -weightsB[j] : weightsB[j];
        for (int c = 0; c < 4; ++c)
            q[c] = q[c] + s * qb[c];
        const float t = weightsA[j] + weightsB[j];
        if (t < 1.0f) {
            const float dr = (q[0] * r[0] + q[1] * r[1]) + (q[2] * r[2] + q[3] * r[3]);
            const float restWeight = dr < 0.0f ? t - 1.0f : 1.0f - t;
            for (int c = 0; c < 4; ++c)
                q[c] = q[c] + restWeight * r[c];
        }
        const float norm2 = (q[0] * q[0] + q[1] * q[1]) + (q[2] * q[2] + q[3] * q[3]);
        const float inv = simd::reciprocalSqrt(norm2);
        for (int c = 0; c < 4; ++c) {
            const float expected = t == 0.0f ? r[c] : q[c] * inv;
            EXPECT_EQ(out[4 * j + c], expected) << "joint " << j << " component " << c;
        }
        undriven += t == 0.0f;
    }
    EXPECT_GT(undriven, 1) << "the rest pose comes back exactly where nothing drives a joint";
}
