// FrameRetarget: playing an H-Anim frame on another skeleton by joint name.

#include <gtest/gtest.h>

#include "anim/hanim.h"
#include "anim/retarget.h"

namespace {

using namespace thespis::core::anim;

Quat turn(float angle)
{
    return Quat::fromAxisAngle(Vec3{0, 0, 1}, angle);
}

TEST(FrameRetarget, SameSkeletonCopiesTheFrame)
{
    const Skeleton& skeleton = hanim::skeleton(hanim::Level::Subset25);
    std::vector<float> from = skeleton.restFrame();
    for (int j = 0; j < skeleton.jointCount(); ++j)
        rotationAt(std::span<float>(from), j) = turn(0.1f * float(j));
    from[skeleton.frameLayout()->floatOffset(skeleton.translationElement(0)) + 1] = 1.2f;
    std::vector<float> to(from.size(), -7.0f);
    FrameRetarget retarget(skeleton, skeleton);
    EXPECT_EQ(retarget.mappedJointCount(), skeleton.jointCount());
    retarget.apply(from, to);
    // Rotations are copied exactly; the root is placed by the hips and the feet, within rounding.
    const std::size_t rotations = 4 * std::size_t(skeleton.jointCount());
    EXPECT_TRUE(std::equal(from.begin(), from.begin() + std::ptrdiff_t(rotations), to.begin()));
    for (std::size_t k = rotations; k < from.size(); ++k)
        EXPECT_NEAR(to[k], from[k], 1e-6f);
}

TEST(FrameRetarget, JointsByNameOthersAtRestTranslationScaled)
{
    const Skeleton& source = hanim::skeleton(hanim::Level::Loa1);
    // A smaller character with an extra joint the source lacks and one H-Anim joint renamed.
    std::vector<Joint> joints;
    joints.push_back({"humanoid_root", "Hips", -1, {0, 0.49, 0}, "ZXY", {}, true});
    joints.push_back({"vl5", "Spine", 0, {0, 0.05, 0}});
    joints.push_back({"skullbase", "Head", 1, {0, 0.3, 0}});
    joints.push_back({"ponytail", "Ponytail", 2, {0, 0.05, -0.05}});
    auto target = Skeleton::create(joints);
    ASSERT_TRUE(target.ok());

    std::vector<float> from = source.restFrame();
    const int skull = source.find("skullbase");
    const int vl5 = source.find("vl5");
    ASSERT_GE(skull, 0);
    ASSERT_GE(vl5, 0);
    rotationAt(std::span<float>(from), skull) = turn(0.5f);
    rotationAt(std::span<float>(from), vl5) = turn(-0.25f);
    const std::size_t sourceRoot = source.frameLayout()->floatOffset(source.translationElement(0));
    from[sourceRoot] = 0.98f * 0.5f + 0.1f; // 0.1 m to the side: the half-size character moves 0.05
    from[sourceRoot + 1] = 0.98f + 0.2f;

    std::vector<float> to(target->frameLayout()->floatCount(), -7.0f);
    FrameRetarget retarget(source, *target);
    EXPECT_EQ(retarget.mappedJointCount(), 3);
    retarget.apply(from, to);
    EXPECT_EQ(rotationAt(std::span<const float>(to), 2).z, turn(0.5f).z);
    EXPECT_EQ(rotationAt(std::span<const float>(to), 1).z, turn(-0.25f).z);
    const Quat ponytail = rotationAt(std::span<const float>(to), 3);
    EXPECT_EQ(ponytail.w, 1.0f);
    EXPECT_EQ(ponytail.x, 0.0f);
    const std::size_t targetRoot = target->frameLayout()->floatOffset(target->translationElement(0));
    EXPECT_NEAR(to[targetRoot], 0.05 + 0.5 * (0.98 * 0.5), 1e-6);
    EXPECT_NEAR(to[targetRoot + 1], 0.49 + 0.1, 1e-6);
    EXPECT_NEAR(to[targetRoot + 2], 0.0, 1e-6);
}

} // namespace
