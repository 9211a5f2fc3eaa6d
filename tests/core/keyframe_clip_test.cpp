// Keyframe clips: sampling by slerp, validation, remapping.
#include <gtest/gtest.h>

#include "anim_test_support.h"
#include "anim/hanim.h"

using namespace thespis::core::anim;
using thespis::test::angle;

TEST(KeyframeClip, SamplesKeysExactlyAndSlerpsBetween)
{
    const auto layout = FrameLayout::create({"a"}, {"a"}, {"s"});
    const Quat q0 = Quat::identity();
    const Quat q1 = Quat::fromAxisAngle({0, 0, 1}, 1.2f);
    std::vector<float> data = {q0.x, q0.y, q0.z, q0.w, 0, 0, 0, 0, q1.x, q1.y, q1.z, q1.w, 2, 4, 6, 1};
    auto clip = KeyframeClip::create(layout, 10.0, data, "two keys");
    ASSERT_TRUE(clip) << clip.error().message;
    EXPECT_DOUBLE_EQ((*clip)->domain().end, 0.1);
    std::vector<float> out(layout->floatCount());
    for (double u : {0.0, 0.25, 0.5, 0.9, 1.0}) {
        (*clip)->evaluate(0.1 * u, out);
        const Quatd expected = slerp(Quatd{}, Quatd{q1.x, q1.y, q1.z, q1.w}, u);
        EXPECT_NEAR(angle(rotationAt(std::span<const float>(out), 0), Quat{float(expected.x), float(expected.y), float(expected.z), float(expected.w)}), 0.0, 2e-6) << u;
        EXPECT_NEAR(out[4], 2 * u, 1e-6);
        EXPECT_NEAR(out[7], u, 1e-6);
    }
    // Outside the domain the clip holds its ends.
    (*clip)->evaluate(-5, out);
    EXPECT_FLOAT_EQ(out[4], 0.0f);
    (*clip)->evaluate(5, out);
    EXPECT_FLOAT_EQ(out[4], 2.0f);
}

TEST(KeyframeClip, TakesTheShortArcEvenWhenKeysFlipSign)
{
    const auto layout = FrameLayout::create({"a"});
    const Quat q0 = Quat::fromAxisAngle({0, 1, 0}, 0.3f);
    const Quat q1 = negate(Quat::fromAxisAngle({0, 1, 0}, 0.5f)); // same rotation as +q, opposite sign
    auto clip = KeyframeClip::create(layout, 1.0, {q0.x, q0.y, q0.z, q0.w, q1.x, q1.y, q1.z, q1.w});
    ASSERT_TRUE(clip);
    std::vector<float> out(4);
    (*clip)->evaluate(0.5, out);
    EXPECT_NEAR(angle(rotationAt(std::span<const float>(out), 0), Quat::fromAxisAngle({0, 1, 0}, 0.4f)), 0.0, 1e-6);
}

TEST(KeyframeClip, RefusesBadInput)
{
    const auto layout = FrameLayout::create({"a"});
    EXPECT_FALSE(KeyframeClip::create(layout, 0.0, {0, 0, 0, 1}));
    EXPECT_FALSE(KeyframeClip::create(layout, 30.0, {0, 0, 1}));          // not a whole frame
    EXPECT_FALSE(KeyframeClip::create(layout, 30.0, {0, 0, 0, 0}));       // zero quaternion
    EXPECT_FALSE(KeyframeClip::create(layout, 30.0, {0, 0, std::nanf(""), 1}));
    EXPECT_FALSE(KeyframeClip::create(nullptr, 30.0, {0, 0, 0, 1}));
}

TEST(KeyframeClip, RemapFillsMissingJointsWithRestAndReportsExtras)
{
    const Skeleton& skeleton = hanim::skeleton(hanim::Level::Loa1);
    const auto partial = FrameLayout::create({"r_shoulder", "tail"});
    const Quat q = Quat::fromAxisAngle({1, 0, 0}, 0.7f);
    auto clip = KeyframeClip::create(partial, 30.0, {q.x, q.y, q.z, q.w, 0, 0, 0, 1});
    ASSERT_TRUE(clip);
    std::vector<std::string> dropped;
    const std::vector<float> rest = skeleton.restFrame();
    auto remapped = remapClip(**clip, skeleton.frameLayout(), rest, &dropped);
    ASSERT_TRUE(remapped) << remapped.error().message;
    EXPECT_EQ(dropped, std::vector<std::string>{"tail"});
    std::vector<float> out(skeleton.frameLayout()->floatCount());
    (*remapped)->evaluate(0, out);
    const int shoulder = skeleton.find("r_shoulder");
    EXPECT_NEAR(angle(rotationAt(std::span<const float>(out), shoulder), q), 0.0, 1e-6);
    EXPECT_FLOAT_EQ(out[skeleton.frameLayout()->translationOffset() + 1], rest[skeleton.frameLayout()->translationOffset() + 1]);
}

TEST(HAnim, LevelsHaveTheStandardJointCounts)
{
    EXPECT_EQ(hanim::skeleton(hanim::Level::Loa1).jointCount(), 18);
    EXPECT_EQ(hanim::skeleton(hanim::Level::Loa2).jointCount(), 71);
    EXPECT_EQ(hanim::skeleton(hanim::Level::Subset25).jointCount(), 25);
    const Skeleton& loa1 = hanim::skeleton(hanim::Level::Loa1);
    EXPECT_EQ(loa1.joint(0).name, "humanoid_root");
    // In LOA 1 the skull hangs directly under vl5 (vl3 … vc2 are LOA 2).
    EXPECT_EQ(loa1.joint(loa1.joint(loa1.find("skullbase")).parent).name, "vl5");
    // Rest pose: the skull is above the hips, the left hand on +x.
    const auto positions = loa1.worldPositions(loa1.restFrame());
    EXPECT_GT(positions[std::size_t(loa1.find("skullbase"))].y, 1.5);
    EXPECT_GT(positions[std::size_t(loa1.find("l_radiocarpal"))].x, 0.1);
    EXPECT_NEAR(positions[std::size_t(loa1.find("l_radiocarpal"))].x, -positions[std::size_t(loa1.find("r_radiocarpal"))].x, 1e-12);
}

TEST(HAnim, NamesMirrorAndTranslateFromVersion11)
{
    EXPECT_EQ(hanim::mirrorName("l_elbow"), "r_elbow");
    EXPECT_EQ(hanim::mirrorName("vt1"), "vt1");
    EXPECT_EQ(hanim::mirrorName("LeftForeArm"), "RightForeArm");
    EXPECT_EQ(hanim::mirrorName("lCollar"), "rCollar");
    EXPECT_EQ(hanim::mirrorName("upperarm01.L"), "upperarm01.R");
    EXPECT_EQ(hanim::mirrorName("__Clavicle_L"), "__Clavicle_R");
    EXPECT_EQ(hanim::mirrorName("Eye_r"), "Eye_l");
    EXPECT_EQ(hanim::mirrorName("Head"), "Head");
    EXPECT_EQ(hanim::fromHAnim11("HumanoidRoot"), "humanoid_root");
    EXPECT_EQ(hanim::fromHAnim11("l_wrist"), "l_radiocarpal");
    EXPECT_TRUE(hanim::isJointName("l_carpal_distal_interphalangeal_5"));
    EXPECT_FALSE(hanim::isJointName("LeftArm"));
}

TEST(Skeleton, RefusesBrokenHierarchies)
{
    EXPECT_FALSE(Skeleton::create({}));
    EXPECT_FALSE(Skeleton::create({{"a", "", -1}, {"a", "", 0}}));   // duplicate
    EXPECT_FALSE(Skeleton::create({{"a", "", -1}, {"b", "", 2}, {"c", "", 1}})); // child before parent
    EXPECT_FALSE(Skeleton::create({{"a", "", 0}}));                   // root with a parent
}
