// Blending schedules: the normalized blend, rest-pose fill, modes, masks, cut-off, edits while
// playing, nesting, and that evaluation allocates nothing.
#include <gtest/gtest.h>

#include "anim/blending_schedule.h"
#include "anim/hanim.h"
#include "anim/modifiers.h"
#include "allocation_counter.h"
#include "anim_test_support.h"

using namespace thespis::core::anim;
using thespis::test::angle;
using thespis::test::makeLayout;
using thespis::test::makeTurningClip;

namespace {

Quat rot(std::span<const float> frame, int r) { return rotationAt(frame, r); }

BlendingAction action(BlendablePtr source, double start = 0, Curve weight = {}, BlendMode mode = BlendMode::Normalized)
{
    BlendingAction a;
    a.name = "action";
    a.source = std::move(source);
    a.start = start;
    a.params.weight = std::move(weight);
    a.params.mode = mode;
    return a;
}

} // namespace

TEST(BlendingSchedule, SingleActionAtFullWeightEqualsItsSource)
{
    const auto layout = makeLayout(5);
    const auto clip = makeTurningClip(layout, 2.0, 30, 1.5f);
    BlendingSchedule schedule(layout);
    ASSERT_TRUE(schedule.addAction(action(clip, 0.5)));
    std::vector<float> expected(layout->floatCount()), out(layout->floatCount());
    for (double t = 0.5; t <= 2.5; t += 0.037) {
        clip->evaluate(t - 0.5, expected);
        schedule.evaluate(t, out);
        for (std::size_t k = 0; k < out.size(); ++k)
            ASSERT_NEAR(out[k], expected[k], 1e-6) << "t=" << t << " k=" << k;
    }
}

TEST(BlendingSchedule, RenderingOutsideTheDomainHoldsThroughAnyFadeOrRelease)
{
    // A held pose (or a synthesizer) must not be ended by its weight curve's fade-out at its
    // source's end: with the flag, the curves have no end; cut-off is what ends it.
    const auto layout = makeLayout(3);
    const auto clip = makeTurningClip(layout, 1.0, 30, 1.2f);
    std::vector<float> last(layout->floatCount()), out(layout->floatCount());
    clip->evaluate(1.0, last);
    for (const Curve& weight : {Curve::cubicFade(0.2, 0.0), Curve::cubicFade(0.2, 0.4),
                                Curve::linearAdsr(0.1, 0.1, 1.0, 0.3), Curve::cubicAdsr(0.1, 0.1, 1.0, 0.0)}) {
        BlendingSchedule schedule(layout);
        BlendingAction held = action(clip, 0.0, weight);
        held.renderOutsideDomain = true;
        auto id = schedule.addAction(held);
        ASSERT_TRUE(id);
        for (const double t : {1.0, 1.5, 10.0}) {
            schedule.evaluate(t, out);
            for (std::size_t k = 0; k < out.size(); ++k)
                ASSERT_NEAR(out[k], last[k], 1e-5) << "t=" << t << " k=" << k;
        }
        EXPECT_FALSE(schedule.isFinished(*id, 10.0));
        ASSERT_TRUE(schedule.cutOffAction(*id, 10.0, 0.5));
        schedule.evaluate(10.5, out);
        EXPECT_EQ(out, neutralFrame(*layout)); // cut off: gone, rest pose
    }
}

TEST(BlendingSchedule, UndrivenJointsKeepTheRestPose)
{
    const Skeleton& skeleton = hanim::skeleton(hanim::Level::Loa1);
    BlendingSchedule schedule(skeleton);
    std::vector<float> out(skeleton.frameLayout()->floatCount());
    schedule.evaluate(1.0, out);
    EXPECT_EQ(out, skeleton.restFrame());
}

TEST(BlendingSchedule, EqualWeightsAverageRotations)
{
    const auto layout = makeLayout(1, false);
    const Quat a = Quat::fromAxisAngle({0, 0, 1}, 0.2f), b = Quat::fromAxisAngle({0, 0, 1}, 1.0f);
    auto clipA = KeyframeClip::create(layout, 1.0, {a.x, a.y, a.z, a.w});
    // The same rotation as b but stored with the opposite sign: must not cancel.
    auto clipB = KeyframeClip::create(layout, 1.0, {-b.x, -b.y, -b.z, -b.w});
    BlendingSchedule schedule(layout);
    BlendingAction first = action(*clipA), second = action(*clipB);
    first.renderOutsideDomain = second.renderOutsideDomain = true;
    ASSERT_TRUE(schedule.addAction(first));
    ASSERT_TRUE(schedule.addAction(second));
    std::vector<float> out(4);
    schedule.evaluate(0.0, out);
    EXPECT_NEAR(angle(rot(out, 0), Quat::fromAxisAngle({0, 0, 1}, 0.6f)), 0.0, 1e-6);
}

// The same through the eight-joint blocks of the vectorized blend: every joint, every lane, the
// second rotation stored with the opposite sign (as two layers' root rotations often are).
TEST(BlendingSchedule, EqualWeightsAverageOppositeSignsInEveryLane)
{
    constexpr int Joints = 19; // two blocks of eight and three left over
    const auto layout = makeLayout(Joints, false);
    std::vector<float> valuesA, valuesB;
    std::vector<Quat> expected;
    for (int j = 0; j < Joints; ++j) {
        const Vec3 tilt{float(j % 3), 1.0f, float(j % 5) - 2.0f};
        const Vec3 axis = tilt * (1.0f / std::sqrt(tilt.x * tilt.x + tilt.y * tilt.y + tilt.z * tilt.z));
        const Quat a = Quat::fromAxisAngle(axis, 0.1f * float(j)), b = Quat::fromAxisAngle(axis, 0.1f * float(j) + 0.4f);
        valuesA.insert(valuesA.end(), {a.x, a.y, a.z, a.w});
        valuesB.insert(valuesB.end(), {-b.x, -b.y, -b.z, -b.w});
        expected.push_back(Quat::fromAxisAngle(axis, 0.1f * float(j) + 0.2f));
    }
    BlendingAction first = action(*KeyframeClip::create(layout, 1.0, valuesA));
    BlendingAction second = action(*KeyframeClip::create(layout, 1.0, valuesB));
    first.renderOutsideDomain = second.renderOutsideDomain = true;
    BlendingSchedule schedule(layout);
    ASSERT_TRUE(schedule.addAction(first));
    ASSERT_TRUE(schedule.addAction(second));
    std::vector<float> out(layout->floatCount());
    schedule.evaluate(0.0, out);
    for (int j = 0; j < Joints; ++j)
        EXPECT_NEAR(angle(rot(out, j), expected[j]), 0.0, 1e-5) << "joint " << j;
}

TEST(BlendingSchedule, FadingWeightReachesRestPoseWithoutAPop)
{
    const auto layout = makeLayout(3);
    const auto clip = makeTurningClip(layout, 2.0, 30, 0.0f, 1.0f); // a still pose 1 rad from rest
    BlendingSchedule schedule(layout);
    ASSERT_TRUE(schedule.addAction(action(clip, 0, Curve::linearFade(0.0, 1.0))));
    std::vector<float> previous(layout->floatCount()), out(layout->floatCount());
    schedule.evaluate(0.9, previous);
    double largestStep = 0;
    for (double t = 0.9 + 1e-3; t <= 2.2; t += 1e-3) {
        schedule.evaluate(t, out);
        for (int r = 0; r < 3; ++r)
            largestStep = std::max(largestStep, angle(rot(out, r), rot(previous, r)));
        previous = out;
    }
    // 1 rad over a 1 s fade in 1 ms steps: about 1e-3 rad a step; a pop would be ~1 rad.
    EXPECT_LT(largestStep, 3e-3);
    schedule.evaluate(2.1, out);
    EXPECT_EQ(out, neutralFrame(*layout));
}

TEST(BlendingSchedule, OverrideAtFullWeightReplacesAndMaskLimitsIt)
{
    const Skeleton& skeleton = hanim::skeleton(hanim::Level::Loa1);
    const auto layout = skeleton.frameLayout();
    const auto base = makeTurningClip(layout, 2.0, 30, 0.5f);
    const auto gesture = makeTurningClip(layout, 2.0, 30, -2.0f, 0.3f);
    BlendingSchedule schedule(skeleton);
    ASSERT_TRUE(schedule.addAction(action(base)));
    BlendingAction wave = action(gesture, 0, {}, BlendMode::Override);
    wave.params.mask = std::make_shared<JointMask>(JointMask::preset(MaskPreset::RightArm));
    ASSERT_TRUE(schedule.addAction(wave));
    std::vector<float> out(layout->floatCount()), b(layout->floatCount()), g(layout->floatCount());
    schedule.evaluate(1.0, out);
    base->evaluate(1.0, b);
    gesture->evaluate(1.0, g);
    for (int r = 0; r < skeleton.jointCount(); ++r) {
        const bool rightArm = skeleton.joint(r).name.starts_with("r_") && skeleton.joint(r).name != "r_hip"
                              && skeleton.joint(r).name != "r_knee" && skeleton.joint(r).name != "r_talocrural"
                              && skeleton.joint(r).name != "r_metatarsophalangeal";
        const Quat expected = rightArm ? rot(g, r) : rot(b, r);
        EXPECT_NEAR(angle(rot(out, r), expected), 0.0, 1e-6) << skeleton.joint(r).name;
    }
}

TEST(BlendingSchedule, OverrideAtHalfWeightSlerps)
{
    const auto layout = makeLayout(1, false);
    const Quat a = Quat::identity(), b = Quat::fromAxisAngle({1, 0, 0}, 1.0f);
    BlendingSchedule schedule(layout);
    auto base = KeyframeClip::create(layout, 1.0, {a.x, a.y, a.z, a.w, a.x, a.y, a.z, a.w});
    auto top = KeyframeClip::create(layout, 1.0, {b.x, b.y, b.z, b.w, b.x, b.y, b.z, b.w});
    ASSERT_TRUE(schedule.addAction(action(*base)));
    ASSERT_TRUE(schedule.addAction(action(*top, 0, Curve::constant(0.5), BlendMode::Override)));
    std::vector<float> out(4);
    schedule.evaluate(0.5, out);
    EXPECT_NEAR(angle(rot(out, 0), Quat::fromAxisAngle({1, 0, 0}, 0.5f)), 0.0, 1e-6);
}

TEST(BlendingSchedule, AdditiveAddsTheChangeFromItsFirstFrame)
{
    const auto layout = makeLayout(1, true);
    const Quat base = Quat::fromAxisAngle({0, 1, 0}, 0.4f);
    auto still = KeyframeClip::create(layout, 1.0, {base.x, base.y, base.z, base.w, 1, 2, 3, base.x, base.y, base.z, base.w, 1, 2, 3});
    // Additive clip: starts at some pose and turns 0.3 rad more about z, and moves +1 in x.
    const Quat first = Quat::fromAxisAngle({1, 0, 0}, 0.9f);
    const Quat last = first * Quat::fromAxisAngle({0, 0, 1}, 0.3f);
    auto delta = KeyframeClip::create(layout, 1.0, {first.x, first.y, first.z, first.w, 5, 5, 5, last.x, last.y, last.z, last.w, 6, 5, 5});
    BlendingSchedule schedule(layout);
    ASSERT_TRUE(schedule.addAction(action(*still)));
    ASSERT_TRUE(schedule.addAction(action(*delta, 0, {}, BlendMode::Additive)));
    std::vector<float> out(layout->floatCount());
    schedule.evaluate(1.0, out);
    EXPECT_NEAR(angle(rot(out, 0), base * Quat::fromAxisAngle({0, 0, 1}, 0.3f)), 0.0, 1e-6);
    EXPECT_NEAR(out[4], 2.0f, 1e-6);
    schedule.evaluate(0.0, out); // no change yet at the reference frame
    EXPECT_NEAR(angle(rot(out, 0), base), 0.0, 1e-6);
}

TEST(BlendingSchedule, ScaleCurveScalesMotionFromRest)
{
    const auto layout = makeLayout(1, false);
    const Quat q = Quat::fromAxisAngle({0, 0, 1}, 0.8f);
    auto clip = KeyframeClip::create(layout, 1.0, {q.x, q.y, q.z, q.w});
    BlendingSchedule schedule(layout);
    BlendingAction a = action(*clip);
    a.renderOutsideDomain = true;
    a.params.scale = Curve::constant(0.5);
    ASSERT_TRUE(schedule.addAction(a));
    std::vector<float> out(4);
    schedule.evaluate(0.0, out);
    EXPECT_NEAR(angle(rot(out, 0), Quat::fromAxisAngle({0, 0, 1}, 0.4f)), 0.0, 1e-6);
}

TEST(BlendingSchedule, CutOffFadesOutOverExactlyTheGivenTime)
{
    const auto layout = makeLayout(2);
    const auto clip = makeTurningClip(layout, 10.0, 30, 0.0f, 1.2f);
    BlendingSchedule schedule(layout);
    const ActionId id = *schedule.addAction(action(clip));
    ASSERT_TRUE(schedule.cutOffAction(id, 2.0, 3.0));
    std::vector<float> out(layout->floatCount());
    const Quat full = Quat::fromAxisAngle({1, 0, 0}, 1.2f);
    schedule.evaluate(2.0, out);
    EXPECT_NEAR(angle(rot(out, 0), full), 0.0, 1e-6);
    schedule.evaluate(3.5, out); // halfway: cubic fade at 0.5 → weight 0.5
    EXPECT_NEAR(angle(rot(out, 0), Quat::identity()), 0.6, 1e-4);
    schedule.evaluate(5.0 - 1e-3, out);
    EXPECT_GT(angle(rot(out, 0), Quat::identity()), 0.0);
    EXPECT_FALSE(schedule.isFinished(id, 5.0 - 1e-3));
    schedule.evaluate(5.0, out);
    EXPECT_EQ(out, neutralFrame(*layout));
    EXPECT_TRUE(schedule.isFinished(id, 5.0));
    EXPECT_DOUBLE_EQ(schedule.endTime(id), 5.0);
}

TEST(BlendingSchedule, EditsWhilePlayingAndFinishedQuery)
{
    const auto layout = makeLayout(2);
    const auto clip = makeTurningClip(layout, 1.0, 30, 1.0f);
    BlendingSchedule schedule(layout);
    const ActionId first = *schedule.addAction(action(clip, 0));
    std::vector<float> out(layout->floatCount());
    schedule.evaluate(0.5, out);
    const ActionId second = *schedule.addAction(action(clip, 0.6));
    EXPECT_FALSE(schedule.isFinished(first, 0.9));
    EXPECT_TRUE(schedule.isFinished(first, 1.01));
    EXPECT_FALSE(schedule.isFinished(second, 1.01));
    EXPECT_EQ(schedule.actionIds(), (std::vector<ActionId>{first, second}));
    ASSERT_TRUE(schedule.setActionStart(first, 2.0));
    EXPECT_EQ(schedule.actionIds(), (std::vector<ActionId>{second, first}));
    EXPECT_EQ(schedule.removeFinishedActions(1.7), 1); // `second` ended at 1.6
    EXPECT_EQ(schedule.actionIds(), std::vector<ActionId>{first});
    EXPECT_TRUE(schedule.removeAction(first));
    EXPECT_FALSE(schedule.removeAction(first));
    schedule.evaluate(0.5, out);
    EXPECT_EQ(out, neutralFrame(*layout));
}

TEST(BlendingSchedule, RefusesActionsItCannotPlay)
{
    BlendingSchedule schedule(makeLayout(3));
    auto noSource = schedule.addAction(action(nullptr));
    ASSERT_FALSE(noSource);
    EXPECT_EQ(noSource.error().code, thespis::core::ErrorCode::InvalidSchedule);
    auto wrongLayout = schedule.addAction(action(makeTurningClip(makeLayout(4), 1, 30, 1)));
    ASSERT_FALSE(wrongLayout);
    EXPECT_NE(wrongLayout.error().message.find("another skeleton"), std::string::npos);
    auto badCurve = schedule.addAction(action(makeTurningClip(makeLayout(3), 1, 30, 1), 0, Curve::linearFade(-1, 0)));
    EXPECT_FALSE(badCurve);
    BlendingAction badMask = action(makeTurningClip(makeLayout(3), 1, 30, 1));
    badMask.params.mask = std::make_shared<JointMask>(std::map<std::string, float>{{"joint1", 2.0f}});
    auto refused = schedule.addAction(badMask);
    ASSERT_FALSE(refused);
    EXPECT_NE(refused.error().message.find("joint1"), std::string::npos);
}

TEST(BlendingSchedule, RefusesCyclesThroughNestingAndModifiers)
{
    const auto layout = makeLayout(2);
    auto a = std::make_shared<BlendingSchedule>(layout);
    auto b = std::make_shared<BlendingSchedule>(layout);
    EXPECT_FALSE(a->addAction(action(a)));
    ASSERT_TRUE(a->addAction(action(b)));
    auto cycle = b->addAction(action(a));
    ASSERT_FALSE(cycle);
    EXPECT_NE(cycle.error().message.find("inside itself"), std::string::npos);
    // Also through a modifier, and through setActionSource.
    auto looped = Loop::create(a, 2);
    ASSERT_TRUE(looped);
    EXPECT_FALSE(b->addAction(action(*looped)));
    const ActionId id = *b->addAction(action(makeTurningClip(layout, 1, 30, 1)));
    EXPECT_FALSE(b->setActionSource(id, a));
}

TEST(BlendingSchedule, FinishedAtTheEndTimeForNaturalEndsAndCutOffsAlike)
{
    const auto layout = makeLayout(2);
    BlendingSchedule schedule(layout);
    const ActionId natural = *schedule.addAction(action(makeTurningClip(layout, 1.0, 30, 1), 0.5));
    const ActionId cut = *schedule.addAction(action(makeTurningClip(layout, 5.0, 30, 1), 0.0));
    schedule.cutOffAction(cut, 1.0, 0.5);
    EXPECT_DOUBLE_EQ(schedule.endTime(natural), 1.5);
    EXPECT_DOUBLE_EQ(schedule.endTime(cut), 1.5);
    EXPECT_FALSE(schedule.isFinished(natural, 1.4999));
    EXPECT_FALSE(schedule.isFinished(cut, 1.4999));
    EXPECT_TRUE(schedule.isFinished(natural, 1.5));
    EXPECT_TRUE(schedule.isFinished(cut, 1.5));
}

TEST(BlendingSchedule, NestedScheduleEqualsFlattened)
{
    const auto layout = makeLayout(4);
    const auto walk = makeTurningClip(layout, 3.0, 30, 0.7f);
    const auto wave = makeTurningClip(layout, 1.5, 30, -1.3f, 0.4f);
    const auto nod = makeTurningClip(layout, 1.0, 30, 2.0f, -0.2f);

    BlendingSchedule flat(layout);
    ASSERT_TRUE(flat.addAction(action(walk, 0.0)));
    ASSERT_TRUE(flat.addAction(action(wave, 1.0 + 0.5, Curve::cubicFade(0.3, 0.3))));
    ASSERT_TRUE(flat.addAction(action(nod, 1.0 + 2.1, Curve::linearAdsr(0.2, 0.1, 0.7, 0.2))));

    auto inner = std::make_shared<BlendingSchedule>(layout);
    ASSERT_TRUE(inner->addAction(action(wave, 0.5, Curve::cubicFade(0.3, 0.3))));
    ASSERT_TRUE(inner->addAction(action(nod, 2.1, Curve::linearAdsr(0.2, 0.1, 0.7, 0.2))));
    BlendingSchedule outer(layout);
    ASSERT_TRUE(outer.addAction(action(walk, 0.0)));
    ASSERT_TRUE(outer.addAction(action(inner, 1.0)));

    std::vector<float> a(layout->floatCount()), b(layout->floatCount());
    for (double t = 0; t <= 4.5; t += 0.01) {
        flat.evaluate(t, a);
        outer.evaluate(t, b);
        for (int r = 0; r < 4; ++r)
            ASSERT_NEAR(angle(rot(a, r), rot(b, r)), 0.0, 2e-6) << "t=" << t << " r=" << r;
        for (std::size_t k = layout->translationOffset(); k < a.size(); ++k)
            ASSERT_NEAR(a[k], b[k], 1e-5) << "t=" << t;
    }
}

TEST(BlendingSchedule, RevisionChangesWithEveryEditIncludingNestedOnes)
{
    const auto layout = makeLayout(2);
    auto inner = std::make_shared<BlendingSchedule>(layout);
    BlendingSchedule outer(layout);
    ASSERT_TRUE(outer.addAction(action(inner)));
    auto r0 = outer.revision();
    const ActionId id = *inner->addAction(action(makeTurningClip(layout, 1, 30, 1)));
    auto r1 = outer.revision();
    EXPECT_NE(r0, r1);
    inner->removeAction(id);
    EXPECT_NE(outer.revision(), r1);
}

TEST(BlendingSchedule, EvaluationAllocatesNothing)
{
    const Skeleton& skeleton = hanim::skeleton(hanim::Level::Loa2);
    const auto layout = skeleton.frameLayout();
    BlendingSchedule schedule(skeleton);
    BlendingAction masked = action(makeTurningClip(layout, 2.0, 30, 1.0f), 0.0, Curve::cubicFade(0.5, 0.5));
    masked.params.mask = std::make_shared<JointMask>(JointMask::preset(MaskPreset::UpperBody));
    ASSERT_TRUE(schedule.addAction(masked));
    ASSERT_TRUE(schedule.addAction(action(makeTurningClip(layout, 2.0, 30, -1.0f), 0.2, Curve::cubicAdsr(0.2, 0.2, 0.5, 0.3))));
    ASSERT_TRUE(schedule.addAction(action(makeTurningClip(layout, 2.0, 30, 2.0f), 0.4, {}, BlendMode::Override)));
    ASSERT_TRUE(schedule.addAction(action(makeTurningClip(layout, 2.0, 30, 0.5f), 0.6, {}, BlendMode::Additive)));
    const ActionId cut = *schedule.addAction(action(makeTurningClip(layout, 2.0, 30, 0.3f), 0.1));
    schedule.cutOffAction(cut, 1.0, 0.5);
    std::vector<float> out(layout->floatCount());
    const long before = thespis::test::allocationCount();
    for (int frame = 0; frame < 120; ++frame)
        schedule.evaluate(frame / 60.0, out);
    EXPECT_EQ(thespis::test::allocationCount() - before, 0);
}
