#include "motion/pointing.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numbers>
#include <string>

#include "anim/frame.h"
#include "anim/joint_transform.h"

namespace thespis::core::motion {

namespace {

using anim::Quatd;
using anim::Vec3d;

Vec3d cross(const Vec3d& a, const Vec3d& b)
{
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
double length(const Vec3d& v) { return std::sqrt(anim::dot(v, v)); }

// Where the shoulder is and how the arm points from it (shoulder to tip), in the body frame.
void armLine(const anim::Skeleton& skeleton, const PointingArm& arm, std::span<const float> body, Vec3d& shoulder,
             Vec3d& direction)
{
    Quatd orientation;
    Vec3d tip;
    anim::jointTransform(skeleton, body, arm.shoulder, shoulder, orientation);
    anim::jointTransform(skeleton, body, arm.tip, tip, orientation);
    direction = tip - shoulder;
}

} // namespace

Result<PointingHand> parsePointingHand(std::string_view mode)
{
    std::string upper(mode);
    std::transform(upper.begin(), upper.end(), upper.begin(), [](unsigned char c) { return char(std::toupper(c)); });
    if (upper.empty() || upper == "RIGHT_HAND")
        return PointingHand::Right;
    if (upper == "LEFT_HAND")
        return PointingHand::Left;
    if (upper == "BOTH_HANDS")
        return PointingHand::Both;
    return makeError(ErrorCode::InvalidArgument,
                     "mode \"" + std::string(mode) + "\" is no hand to point with (RIGHT_HAND, LEFT_HAND, BOTH_HANDS).");
}

const char* pointingHandName(PointingHand hand)
{
    switch (hand) {
    case PointingHand::Left: return "LEFT_HAND";
    case PointingHand::Both: return "BOTH_HANDS";
    case PointingHand::Right: break;
    }
    return "RIGHT_HAND";
}

Result<std::vector<PointingArm>> pointingArms(const anim::Skeleton& skeleton, PointingHand hand)
{
    std::vector<PointingArm> arms;
    for (const char side : {'r', 'l'}) {
        if ((side == 'r' && hand == PointingHand::Left) || (side == 'l' && hand == PointingHand::Right))
            continue;
        const std::string prefix(1, side);
        PointingArm arm;
        arm.shoulder = skeleton.find(prefix + "_shoulder");
        if (arm.shoulder < 0)
            return makeError(ErrorCode::NotFound, "the skeleton has no " + prefix + "_shoulder to point with.");
        for (const char* tip : {"_carpal_distal_interphalangeal_2", "_wrist", "_radiocarpal"})
            if (arm.tip < 0)
                arm.tip = skeleton.find(prefix + tip);
        if (arm.tip < 0)
            return makeError(ErrorCode::NotFound, "the skeleton has no " + prefix +
                                                      "_carpal_distal_interphalangeal_2 or " + prefix +
                                                      "_wrist to point with.");
        arms.push_back(arm);
    }
    return arms;
}

void aimArm(const anim::Skeleton& skeleton, const PointingArm& arm, std::span<float> body, const Vec3d& target,
            double weight)
{
    if (!(weight > 0))
        return;
    Vec3d shoulder, pointing;
    armLine(skeleton, arm, body, shoulder, pointing);
    const Vec3d wanted = target - shoulder;
    // The shortest turn taking the arm's line onto the target's, in the body frame, scaled.
    const Vec3d axis = cross(pointing, wanted);
    const double sine = length(axis), cosine = anim::dot(pointing, wanted);
    if (sine < 1e-12)
        return; // on the line already (or the target at the shoulder, or opposite: no one turn)
    const double angle = std::atan2(sine, cosine) * std::min(weight, 1.0);
    const Quatd turn = Quatd::fromAxisAngle(axis * (1 / sine), angle);
    // In the shoulder's parent's frame: local' = parent⁻¹ · turn · parent · local.
    Vec3d position;
    Quatd parent;
    anim::jointTransform(skeleton, body, skeleton.joint(arm.shoulder).parent, position, parent);
    anim::Quat& local = anim::rotationAt(body, arm.shoulder);
    const Quatd turned =
        anim::normalize(anim::conjugate(parent) * turn * parent * Quatd{local.x, local.y, local.z, local.w});
    local = {float(turned.x), float(turned.y), float(turned.z), float(turned.w)};
}

double pointingError(const anim::Skeleton& skeleton, const PointingArm& arm, std::span<const float> body,
                     const Vec3d& target)
{
    Vec3d shoulder, pointing;
    armLine(skeleton, arm, body, shoulder, pointing);
    const Vec3d wanted = target - shoulder;
    return std::atan2(length(cross(pointing, wanted)), anim::dot(pointing, wanted)) * 180 / std::numbers::pi;
}

} // namespace thespis::core::motion
