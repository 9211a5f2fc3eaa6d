#include "motion/posture.h"

#include <algorithm>
#include <cmath>

#include "anim/hanim.h"
#include "anim/simd.h"
#include "motion/exp_map.h"

namespace thespis::core::motion {

namespace {

bool isLowerBody(std::string_view joint)
{
    constexpr std::string_view kLower[] = {"humanoid_root", "sacroiliac", "l_hip", "l_knee", "l_talocrural",
                                           "l_metatarsophalangeal", "r_hip", "r_knee", "r_talocrural",
                                           "r_metatarsophalangeal"};
    return std::find(std::begin(kLower), std::end(kLower), joint) != std::end(kLower);
}

PostureLayout makeLayout(PostureSet set)
{
    PostureLayout layout;
    layout.set = set;
    layout.rootTranslation = set == PostureSet::WholeBody;
    for (std::string& joint : anim::hanim::jointNames(anim::hanim::Level::Subset25))
        if (set == PostureSet::WholeBody || !isLowerBody(joint))
            layout.joints.push_back(std::move(joint));
    return layout;
}

} // namespace

const anim::Skeleton& postureSkeleton()
{
    return anim::hanim::skeleton(anim::hanim::Level::Subset25);
}

const PostureLayout& PostureLayout::of(PostureSet set)
{
    static const PostureLayout whole = makeLayout(PostureSet::WholeBody);
    static const PostureLayout upper = makeLayout(PostureSet::UpperBody);
    return set == PostureSet::WholeBody ? whole : upper;
}

std::string_view postureSetName(PostureSet set)
{
    return set == PostureSet::WholeBody ? "whole body" : "upper body";
}

Result<PostureMap> PostureMap::create(const anim::Skeleton& skeleton, PostureSet set)
{
    PostureMap map;
    map.m_layout = &PostureLayout::of(set);
    map.m_skeleton = skeleton;
    std::vector<std::string> missing;
    for (const std::string& joint : map.m_layout->joints) {
        const int index = skeleton.find(joint);
        if (index < 0)
            missing.push_back(joint);
        else
            map.m_rotationOffsets.push_back(skeleton.frameLayout()->floatOffset(index));
    }
    if (!missing.empty()) {
        std::string names;
        for (const std::string& name : missing)
            names += (names.empty() ? "" : ", ") + name;
        return makeError(ErrorCode::InvalidArgument,
                         "The skeleton lacks " + std::to_string(missing.size()) + " of the " +
                             std::string(postureSetName(set)) + "'s " + std::to_string(map.m_layout->joints.size()) +
                             " posture joints: " + names + ".");
    }
    if (map.m_layout->rootTranslation) {
        const int element = skeleton.translationElement(0);
        if (skeleton.joint(0).name != "humanoid_root" || element < 0)
            return makeError(ErrorCode::InvalidArgument,
                             "The skeleton's root is " + skeleton.joint(0).name + ", not humanoid_root.");
        map.m_rootTranslation = skeleton.frameLayout()->floatOffset(element);
        map.m_leftAnkle = skeleton.find("l_talocrural");
        map.m_rightAnkle = skeleton.find("r_talocrural");
    }
    return map;
}

void PostureMap::toPosture(std::span<const float> frame, std::span<float> posture) const
{
    const std::size_t joints = m_rotationOffsets.size();
    for (std::size_t j = 0; j < joints; ++j) {
        const anim::Vec3 v = logMap(*reinterpret_cast<const anim::Quat*>(frame.data() + m_rotationOffsets[j]));
        posture[3 * j] = v.x;
        posture[3 * j + 1] = v.y;
        posture[3 * j + 2] = v.z;
    }
    if (!m_layout->rootTranslation)
        return;
    // The stance frame: origin on the floor between the ankles, the feet facing +Z (H-Anim's +X is
    // the body's left, so left ankle − right ankle points along +X when it faces +Z).
    const std::vector<anim::Vec3d> world = m_skeleton.worldPositions(frame);
    const anim::Vec3d left = world[std::size_t(m_leftAnkle)], right = world[std::size_t(m_rightAnkle)];
    const double heading = std::atan2(-(left.z - right.z), left.x - right.x);
    const anim::Quatd unturn = anim::Quatd::fromAxisAngle({0, 1, 0}, -heading);
    const anim::Vec3d middle{(left.x + right.x) / 2, 0, (left.z + right.z) / 2};
    const anim::Vec3d root{frame[m_rootTranslation], frame[m_rootTranslation + 1], frame[m_rootTranslation + 2]};
    const anim::Vec3d local = anim::rotate(unturn, root - middle);
    const anim::Quat& rootRotation = *reinterpret_cast<const anim::Quat*>(frame.data() + m_rotationOffsets[0]);
    const anim::Quatd turned = unturn * anim::Quatd{rootRotation.x, rootRotation.y, rootRotation.z, rootRotation.w};
    const anim::Vec3d v = logMap(turned);
    posture[0] = float(v.x);
    posture[1] = float(v.y);
    posture[2] = float(v.z);
    const std::size_t t = 3 * joints;
    posture[t] = float(local.x);
    posture[t + 1] = float(local.y);
    posture[t + 2] = float(local.z);
}

void PostureMap::toFrame(std::span<const float> posture, std::span<float> frame) const
{
    using namespace anim::simd;
    const std::size_t joints = m_rotationOffsets.size();
    const float* p = posture.data();
    // Four joints at a time (this runs for every idle frame): the exponential map with sine and
    // cosine of θ/2 from those of θ/4 ≤ π/2 (Taylor to x¹¹ and x¹², 6·10⁻⁸ there).
    std::size_t j = 0;
    for (; j + 4 <= joints; j += 4, p += 12) {
        const F4 x{p[0], p[3], p[6], p[9]}, y{p[1], p[4], p[7], p[10]}, z{p[2], p[5], p[8], p[11]};
        const F4 theta2 = x * x + y * y + z * z;
        const F4 theta = sqrt(theta2);
        const F4 q = splat(0.25f) * theta, q2 = q * q;
        const F4 s = q * (1 + q2 * (splat(-1.0f / 6) + q2 * (splat(1.0f / 120) + q2 * (splat(-1.0f / 5040) +
                                     q2 * (splat(1.0f / 362880) + q2 * splat(-1.0f / 39916800))))));
        const F4 c = 1 + q2 * (splat(-0.5f) + q2 * (splat(1.0f / 24) + q2 * (splat(-1.0f / 720) +
                               q2 * (splat(1.0f / 40320) + q2 * (splat(-1.0f / 3628800) + q2 * splat(1.0f / 479001600))))));
        const F4 sine = 2 * s * c, cosine = 1 - 2 * s * s;
        // sin(θ/2)/θ, by its series where θ is tiny: 1/2 − θ²/48.
        const F4 k = select(theta > splat(1e-4f), sine / select(theta > 0, theta, splat(1.0f)),
                            splat(0.5f) - theta2 * splat(1.0f / 48));
        F4 qx = x * k, qy = y * k, qz = z * k, qw = cosine;
        // Normalized as every frame's rotations are (the exponential map is unit only to
        // rounding), so that blending a frame with itself gives it back bit for bit.
        const F4 inverse = 1 / sqrt(qx * qx + qy * qy + qz * qz + qw * qw);
        qx *= inverse, qy *= inverse, qz *= inverse, qw *= inverse;
        F4 rows[4];
        transpose(qx, qy, qz, qw, rows[0], rows[1], rows[2], rows[3]);
        for (int r = 0; r < 4; ++r)
            store(frame.data() + m_rotationOffsets[j + std::size_t(r)], rows[r]);
    }
    for (; j < joints; ++j, p += 3)
        *reinterpret_cast<anim::Quat*>(frame.data() + m_rotationOffsets[j]) =
            anim::normalize(expMap(anim::Vec3{p[0], p[1], p[2]}));
    if (m_layout->rootTranslation)
        std::copy_n(posture.data() + 3 * joints, 3, frame.data() + m_rootTranslation);
}

} // namespace thespis::core::motion
