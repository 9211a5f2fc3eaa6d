#pragma once
// Where a target is seen from the camera, as OpenCV writes it: the rotation as a Rodrigues vector
// (axis × angle, radians) and the translation in metres, both mapping the target's frame to the
// camera's (x right, y down, z forward).

#include <array>

namespace thespis::core::ar {

struct TargetPose {
    std::array<double, 3> rotation{};    ///< Rodrigues vector, target → camera
    std::array<double, 3> translation{}; ///< metres, the target's origin in the camera frame
    bool operator==(const TargetPose&) const = default;
};

/// The pose's rotation as a matrix, row by row (target → camera).
std::array<double, 9> rotationMatrix(const TargetPose& pose);
/// A point of the target's plane (metres) as the camera sees it (metres, camera frame).
std::array<double, 3> toCamera(const TargetPose& pose, const std::array<double, 3>& point);
/// The angle (radians) of the rotation between two poses.
double rotationDifference(const TargetPose& a, const TargetPose& b);
/// The distance (metres) between two poses' origins.
double translationDifference(const TargetPose& a, const TargetPose& b);

} // namespace thespis::core::ar
