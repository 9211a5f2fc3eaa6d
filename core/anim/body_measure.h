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
    /// The ankles (l_ / r_talocrural) and every joint below them: what touches the ground.
    std::vector<int> footJoints;
    /// How high the feet are at rest (footHeight() of the foot joints' world y); 0 without feet.
    double footRestHeight = 0;
    /// The softness of footHeight() for this body: about a centimetre on a human.
    double footSoftness = 0.01;
    /// The rest world position of every joint.
    std::vector<Vec3d> restPositions;

    bool hasLegs() const { return legLength > 0; }
    bool hasFeet() const { return !footJoints.empty(); }
    /// True when the rest pose stands on the plane y = 0 (its feet are not below it), as
    /// H-Anim and glTF characters do; motion capture rigs often hang from the root at y = 0.
    bool standsOnGround() const;
};

BodyMeasure measureBody(const Skeleton& skeleton);

/// How high a set of foot joints is: a smooth minimum of their heights (at most `softness`·ln n
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
