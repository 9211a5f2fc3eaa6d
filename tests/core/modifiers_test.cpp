// Modifiers (time stretch / warp, loop, mirror, global transform, offset, trim, split) and the
// frame cache.
#include <gtest/gtest.h>

#include "anim/blending_schedule.h"
#include "anim/frame_cache.h"
#include "anim/hanim.h"
#include "anim/modifiers.h"
#include "anim_test_support.h"

using namespace thespis::core::anim;
using thespis::test::angle;
using thespis::test::makeLayout;
using thespis::test::makeTurningClip;

namespace {

std::vector<float> sample(const BlendableObject& b, double t)
{
    std::vector<float> out(b.layout()->floatCount());
    b.evaluate(t, out);
    return out;
}

void expectFramesNear(const std::vector<float>& a, const std::vector<float>& b, double tolerance, const std::string& where)
{
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t k = 0; k < a.size(); ++k)
        ASSERT_NEAR(a[k], b[k], tolerance) << where << " k=" << k;
}

} // namespace

TEST(Modifiers, TimeStretchPlaysSlower)
{
    const auto clip = makeTurningClip(makeLayout(3), 2.0, 30, 1.0f);
    auto stretched = TimeStretch::create(clip, 2.0);
    ASSERT_TRUE(stretched);
    EXPECT_DOUBLE_EQ((*stretched)->domain().end, 4.0);
    expectFramesNear(sample(**stretched, 3.0), sample(*clip, 1.5), 1e-6, "stretch");
    EXPECT_FALSE(TimeStretch::create(clip, 0.0));
    EXPECT_FALSE(TimeStretch::create(nullptr, 1.0));
}

TEST(Modifiers, TimeWarpFollowsItsCurve)
{
    const auto clip = makeTurningClip(makeLayout(3), 2.0, 30, 1.0f);
    // Plays the clip backwards over 1 s: local u → source 2 − 2u.
    auto warp = Curve::keyframed({{0, 2, TangentMode::Linear}, {1, 0, TangentMode::Linear}});
    auto warped = TimeWarp::create(clip, *warp, 1.0);
    ASSERT_TRUE(warped);
    EXPECT_DOUBLE_EQ((*warped)->domain().duration(), 1.0);
    expectFramesNear(sample(**warped, 0.25), sample(*clip, 1.5), 1e-6, "warp");
}

TEST(Modifiers, LoopRepeatsOrRunsForever)
{
    const auto clip = makeTurningClip(makeLayout(2), 1.0, 30, 1.0f);
    auto thrice = Loop::create(clip, 3);
    ASSERT_TRUE(thrice);
    EXPECT_DOUBLE_EQ((*thrice)->domain().end, 3.0);
    expectFramesNear(sample(**thrice, 2.25), sample(*clip, 0.25), 1e-6, "loop");
    expectFramesNear(sample(**thrice, 7.0), sample(*clip, 1.0), 1e-6, "after the last loop");
    auto forever = Loop::create(clip, 0);
    ASSERT_TRUE(forever);
    EXPECT_TRUE((*forever)->domain().openEnded());
    expectFramesNear(sample(**forever, 1000.5), sample(*clip, 0.5), 1e-5, "forever");
    EXPECT_FALSE(Loop::create(*forever, 2)); // open-ended cannot loop
}

TEST(Modifiers, MirrorSwapsSidesAndReflects)
{
    const Skeleton& skeleton = hanim::skeleton(hanim::Level::Loa1);
    const auto clip = makeTurningClip(skeleton.frameLayout(), 1.0, 30, 1.3f, 0.2f);
    auto mirrored = Mirror::create(clip);
    ASSERT_TRUE(mirrored);
    const auto original = sample(*clip, 0.4);
    const auto flipped = sample(**mirrored, 0.4);
    const int left = skeleton.find("l_elbow"), right = skeleton.find("r_elbow"), spine = skeleton.find("vl5");
    const Quat l = rotationAt(std::span<const float>(original), left);
    const Quat r = rotationAt(std::span<const float>(flipped), right);
    EXPECT_NEAR(r.x, l.x, 1e-7);
    EXPECT_NEAR(r.y, -l.y, 1e-7);
    EXPECT_NEAR(r.z, -l.z, 1e-7);
    EXPECT_NEAR(r.w, l.w, 1e-7);
    const Quat s = rotationAt(std::span<const float>(original), spine), sm = rotationAt(std::span<const float>(flipped), spine);
    EXPECT_NEAR(sm.y, -s.y, 1e-7);
    const std::size_t t = skeleton.frameLayout()->translationOffset();
    EXPECT_NEAR(flipped[t], -original[t], 1e-7);
    // Mirroring twice gives the clip back.
    auto twice = Mirror::create(*mirrored);
    for (double time = 0; time <= 1.0; time += 0.1)
        expectFramesNear(sample(**twice, time), sample(*clip, time), 0.0, "mirror twice");
}

TEST(Modifiers, GlobalTransformMovesTheRoot)
{
    const Skeleton& skeleton = hanim::skeleton(hanim::Level::Loa1);
    const auto clip = makeTurningClip(skeleton.frameLayout(), 1.0, 30, 0.5f);
    const Quat turn = Quat::fromAxisAngle({0, 1, 0}, 1.5707963f);
    auto moved = GlobalTransform::create(clip, turn, {1, 0, 2});
    ASSERT_TRUE(moved);
    const auto a = sample(*clip, 0.5), b = sample(**moved, 0.5);
    EXPECT_NEAR(angle(rotationAt(std::span<const float>(b), 0), turn * rotationAt(std::span<const float>(a), 0)), 0.0, 1e-6);
    const std::size_t t = skeleton.frameLayout()->translationOffset();
    const Vec3 expected = rotate(turn, Vec3{a[t], a[t + 1], a[t + 2]}) + Vec3{1, 0, 2};
    EXPECT_NEAR(b[t], expected.x, 1e-5);
    EXPECT_NEAR(b[t + 2], expected.z, 1e-5);
    EXPECT_NEAR(angle(rotationAt(std::span<const float>(b), 5), rotationAt(std::span<const float>(a), 5)), 0.0, 1e-7);
}

TEST(Modifiers, OffsetTrimAndSplit)
{
    const auto clip = makeTurningClip(makeLayout(2), 2.0, 30, 1.0f);
    TimeOffset later(clip, 1.0);
    EXPECT_DOUBLE_EQ(later.domain().start, 1.0);
    expectFramesNear(sample(later, 1.5), sample(*clip, 0.5), 1e-7, "offset");

    auto trimmed = Trim::create(clip, 0.5, 1.5);
    ASSERT_TRUE(trimmed);
    EXPECT_DOUBLE_EQ((*trimmed)->domain().duration(), 1.0);
    expectFramesNear(sample(**trimmed, 0.0), sample(*clip, 0.5), 1e-7, "trim start");
    expectFramesNear(sample(**trimmed, 9.0), sample(*clip, 1.5), 1e-7, "trim end");
    EXPECT_FALSE(Trim::create(clip, 1.5, 0.5));
    EXPECT_FALSE(Trim::create(clip, 0.0, 3.0));

    auto parts = split(clip, 0.8);
    ASSERT_TRUE(parts);
    EXPECT_DOUBLE_EQ(parts->first->domain().end, 0.8);
    EXPECT_DOUBLE_EQ(parts->second->domain().start, 0.8);
    // Played back to back in a schedule, the two parts give the clip again.
    BlendingSchedule schedule(clip->layout());
    ASSERT_TRUE(schedule.addAction({"a", parts->first, {}, 0.0}));
    ASSERT_TRUE(schedule.addAction({"b", parts->second, {}, 0.8 + 1e-9}));
    for (double t : {0.1, 0.5, 1.0, 1.9})
        expectFramesNear(sample(schedule, t), sample(*clip, t), 1e-5, "split at " + std::to_string(t));
    EXPECT_FALSE(split(clip, 2.0));
}

TEST(FrameCache, ReturnsIdenticalFramesAndIsInvalidatedByEdits)
{
    const auto layout = makeLayout(6);
    auto schedule = std::make_shared<BlendingSchedule>(layout);
    const ActionId id = *schedule->addAction({"walk", makeTurningClip(layout, 2.0, 30, 1.0f), {}, 0.0});
    CachedBlendable cache(schedule, 64);
    std::vector<float> direct(layout->floatCount()), cached(layout->floatCount());
    for (int pass = 0; pass < 2; ++pass)
        for (int f = 0; f < 30; ++f) {
            cache.evaluate(f / 30.0, cached);
            schedule->evaluate(f / 30.0, direct);
            ASSERT_EQ(cached, direct);
        }
    EXPECT_GT(cache.hits(), 0u);
    EXPECT_LE(cache.size(), cache.capacity());

    // An edit changes what the schedule plays: the cache must not serve the old frame.
    cache.evaluate(0.5, cached);
    const auto stale = cached;
    schedule->removeAction(id);
    cache.evaluate(0.5, cached);
    schedule->evaluate(0.5, direct);
    EXPECT_EQ(cached, direct);
    EXPECT_NE(cached, stale);
}

TEST(FrameCache, ACachedNestedScheduleBlendsLikeTheUncachedOne)
{
    // A nested schedule passes on its coverage; cached, it must too, or its parent would blend
    // it as if it drove every joint fully (and fill in rest where it fades).
    const auto layout = makeLayout(6);
    auto nested = std::make_shared<BlendingSchedule>(layout);
    BlendingAction fading{"wave", makeTurningClip(layout, 2.0, 30, 2.0f), {}, 0.0};
    fading.params.weight = Curve::cubicFade(1.0, 1.0);
    ASSERT_TRUE(nested->addAction(fading));
    const auto base = makeTurningClip(layout, 2.0, 30, -1.0f, 0.4f);
    BlendingSchedule plain(layout), cached(layout);
    ASSERT_TRUE(plain.addAction({"base", base, {}, 0.0}));
    ASSERT_TRUE(plain.addAction({"nested", nested, {}, 0.0}));
    auto cache = std::make_shared<CachedBlendable>(nested, 64);
    ASSERT_TRUE(cached.addAction({"base", base, {}, 0.0}));
    ASSERT_TRUE(cached.addAction({"nested", cache, {}, 0.0}));
    EXPECT_TRUE(cache->hasCoverage());
    std::vector<float> a(layout->floatCount()), b(layout->floatCount());
    for (int pass = 0; pass < 2; ++pass)
        for (int f = 0; f <= 60; f += 3) {
            plain.evaluate(f / 30.0, a);
            cached.evaluate(f / 30.0, b);
            ASSERT_EQ(a, b) << "t=" << f / 30.0 << " pass " << pass;
        }
    EXPECT_GT(cache->hits(), 0u);
}
