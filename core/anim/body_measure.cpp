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

void soleHeights(const BodyMeasure& body, std::span<const Vec3d> positions, std::span<const Quatd> orientations,
                 std::span<double> heights)
{
    for (std::size_t k = 0; k < body.soles.size(); ++k) {
        const auto j = std::size_t(body.soles[k].joint);
        heights[k] = positions[j].y + rotate(orientations[j], body.soles[k].offset).y;
    }
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
    // A few millimetres on a human (legs of 0.84 m), in the skeleton's own units: enough to
    // smooth the change of lowest point, little below the lowest with many points near it.
    if (measure.hasLegs())
        measure.footSoftness = 0.0036 * measure.legLength;
    if (measure.footJoints.empty())
        return measure;

    double lowest = rest[std::size_t(measure.footJoints.front())].y;
    for (int j : measure.footJoints)
        lowest = std::min(lowest, rest[std::size_t(j)].y);
    // A foot a few millimetres below the plane (rounding, a sole's thickness) still stands on it.
    measure.groundedAtRest = lowest > -0.02 * std::max(measure.legLength, 1e-9);
    const double floor = measure.groundedAtRest ? 0.0 : lowest;
    for (int j : measure.footJoints)
        measure.soles.push_back({j, {0.0, floor - rest[std::size_t(j)].y, 0.0}});
    // Heels behind the ankles, toes ahead of a foot without toe joints: the foot's extent along
    // where it points (to its farthest joint, else the body's facing, +Z).
    for (const char* side : {"l_", "r_"}) {
        const int ankle = skeleton.find(std::string(side) + "talocrural");
        if (ankle < 0)
            continue;
        const Vec3d& at = rest[std::size_t(ankle)];
        Vec3d forward{0, 0, 1};
        double length = 0;
        for (int j : measure.footJoints) {
            const Vec3d d{rest[std::size_t(j)].x - at.x, 0.0, rest[std::size_t(j)].z - at.z};
            if (const double l = std::hypot(d.x, d.z); l > length) {
                length = l;
                forward = d * (1.0 / l);
            }
        }
        const double leg = measure.hasLegs() ? measure.legLength : 1.0;
        const double heel = length > 0 ? 0.35 * length : 0.08 * leg;
        measure.soles.push_back({ankle, {-forward.x * heel, floor - at.y, -forward.z * heel}});
        if (length == 0)
            measure.soles.push_back({ankle, {forward.x * 0.2 * leg, floor - at.y, forward.z * 0.2 * leg}});
    }
    std::vector<double> heights(measure.soles.size());
    for (std::size_t k = 0; k < heights.size(); ++k)
        heights[k] = rest[std::size_t(measure.soles[k].joint)].y + measure.soles[k].offset.y;
    measure.footRestHeight = footHeight<double>(heights, measure.footSoftness);
    return measure;
}

} // namespace thespis::core::anim
