#include "motion/eye_ray.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "scene/fap.h"

namespace thespis::core::motion {

EyeRay eyeRay(const GazeRig& rig, const anim::Skeleton& skeleton, std::span<const float> body,
              std::span<const float> face)
{
    std::vector<anim::Vec3d> positions(std::size_t(skeleton.jointCount()));
    std::vector<anim::Quatd> orientations(positions.size());
    skeleton.worldTransforms(body, positions, orientations);
    const auto head = std::size_t(skeleton.find("skullbase"));
    const auto fap = [&](int n) {
        const auto channel = std::size_t(scene::fapChannel(n));
        return channel < face.size() ? double(face[channel]) * 1e-5 : 0.0;
    };
    const double yaw = fap(23), pitch = fap(25);
    const anim::Quatd eye = anim::Quatd{0, std::sin(yaw / 2), 0, std::cos(yaw / 2)} *
                            anim::Quatd{std::sin(pitch / 2), 0, 0, std::cos(pitch / 2)};
    return {positions[head] + anim::rotate(orientations[head], rig.eyes),
            anim::rotate(orientations[head] * eye, anim::Vec3d{0, 0, 1})};
}

EyeRay placed(const EyeRay& ray, const anim::Placement& placement)
{
    const anim::Quat& r = placement.rotation;
    const anim::Quatd turn{r.x, r.y, r.z, r.w};
    const anim::Vec3d shift{placement.translation.x, placement.translation.y, placement.translation.z};
    return {anim::rotate(turn, ray.origin) + shift, anim::rotate(turn, ray.direction)};
}

double degreesOff(const EyeRay& ray, const anim::Vec3d& target)
{
    const anim::Vec3d to = target - ray.origin;
    const double norm = std::sqrt(anim::dot(to, to) * anim::dot(ray.direction, ray.direction));
    if (!(norm > 0))
        return 0;
    return std::acos(std::clamp(anim::dot(to, ray.direction) / norm, -1.0, 1.0)) * 180 / std::numbers::pi;
}

} // namespace thespis::core::motion
