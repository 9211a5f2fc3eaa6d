#include "anim/body_measure.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace thespis::core::anim {

namespace {

double distance(const Vec3d& a, const Vec3d& b)
{
    const Vec3d d = a - b;
    return std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
}

} // namespace

bool BodyMeasure::standsOnGround() const
{
    // A foot a few millimetres below the plane (rounding, a sole's thickness) still stands on it.
    return hasFeet() && footRestHeight > -0.02 * std::max(legLength, 1e-9);
}

BodyMeasure measureBody(const Skeleton& skeleton)
{
    BodyMeasure measure;
    measure.restPositions = skeleton.worldPositions(skeleton.restFrame());
    const auto& rest = measure.restPositions;

    double legs = 0;
    int sides = 0;
    for (const char* side : {"l_", "r_"}) {
        const int hip = skeleton.find(std::string(side) + "hip");
        const int knee = skeleton.find(std::string(side) + "knee");
        const int ankle = skeleton.find(std::string(side) + "talocrural");
        if (hip < 0 || knee < 0 || ankle < 0)
            continue;
        legs += distance(rest[std::size_t(hip)], rest[std::size_t(knee)])
                + distance(rest[std::size_t(knee)], rest[std::size_t(ankle)]);
        ++sides;
    }
    measure.legLength = sides > 0 ? legs / sides : 0.0;

    // Joints are stored parents first: a joint is in a foot when it is an ankle or its parent is.
    std::vector<bool> inFoot(std::size_t(skeleton.jointCount()), false);
    for (int j = 0; j < skeleton.jointCount(); ++j) {
        const Joint& joint = skeleton.joint(j);
        inFoot[std::size_t(j)] = joint.name == "l_talocrural" || joint.name == "r_talocrural"
                                 || (joint.parent >= 0 && inFoot[std::size_t(joint.parent)]);
        if (inFoot[std::size_t(j)])
            measure.footJoints.push_back(j);
    }
    // About a centimetre on a human (legs of 0.84 m); in the skeleton's own units.
    if (measure.hasLegs())
        measure.footSoftness = 0.012 * measure.legLength;
    if (!measure.footJoints.empty()) {
        std::vector<double> heights;
        for (int j : measure.footJoints)
            heights.push_back(rest[std::size_t(j)].y);
        measure.footRestHeight = footHeight<double>(heights, measure.footSoftness);
    }
    return measure;
}

} // namespace thespis::core::anim
