#pragma once
// Sizes of a humanoid skeleton taken from its rest pose and its H-Anim joint names, in the
// skeleton's own units: what retargeting needs to play one body's motion on another of another
// size (anim/retarget.h) and to put its feet on the ground (anim/clip_retarget.h).

#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

#include "anim/skeleton.h"

namespace thespis::core::anim {

struct BodyMeasure {
    /// Hip → knee → ankle bone lengths (l_hip, l_knee, l_talocrural and the right side), the
    /// mean of the sides the skeleton has; 0 when it has no complete leg.
    double legLength = 0;
    /// The ankles (l_ / r_talocrural) and every joint below them.
    std::vector<int> footJoints;
    /// A point of a sole, fixed to a foot joint: where the foot meets the floor.
    struct SolePoint {
        int joint = 0;
        Vec3d offset; ///< from the joint, in its frame (at rest the world's)
    };
    /// The soles: a point on the floor under each foot joint, and under each foot its heel
    /// (behind the ankle) and, when the foot has no toe joint, its toes. The floor is y = 0 for a
    /// body that stands on it at rest, else the height of its lowest foot joint.
    std::vector<SolePoint> soles;
    /// How high the soles are at rest (footHeight() of their heights); 0 without feet.
    double footRestHeight = 0;
    /// The softness of footHeight() for this body: 3 mm on a human.
    double footSoftness = 0.003;
    /// The rest world position of every joint.
    std::vector<Vec3d> restPositions;

    bool hasLegs() const { return legLength > 0; }
    bool hasFeet() const { return !footJoints.empty(); }
    /// True when the rest pose stands on the plane y = 0 (its feet are not below it), as
    /// H-Anim and glTF characters do; motion capture rigs often hang from the root at y = 0.
    bool standsOnGround() const { return groundedAtRest; }
    bool groundedAtRest = false;
};

BodyMeasure measureBody(const Skeleton& skeleton);

/// The world height of every sole point of `body` for joint transforms of its skeleton.
void soleHeights(const BodyMeasure& body, std::span<const Vec3d> positions, std::span<const Quatd> orientations,
                 std::span<double> heights);

/// How high a set of sole points is: a smooth minimum of their heights (at most `softness`·ln n
/// below the lowest), so that it does not jump when another joint becomes the lowest (heel
/// down, then the ball of the foot).
template <class T>
T footHeight(std::span<const T> heights, T softness)
{
    T lowest = heights.front();
    for (T h : heights)
        lowest = std::min(lowest, h);
    T sum = 0;
    for (T h : heights)
        sum += std::exp(-(h - lowest) / softness);
    return lowest - softness * std::log(sum);
}

} // namespace thespis::core::anim
