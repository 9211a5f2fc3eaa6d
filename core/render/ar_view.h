#pragma once
// Where the scenario's world is seen from when it plays over tracked video: the real camera's
// intrinsics, the target's pose in the frame (tracking) and where the world sits on the target
// (the scenario's ArSpec) make the CameraView the renderer draws with, so that a point of the
// world lands on the pixel where the real camera would see it.
//
// The world on the target: its up (+y) is the target's printed side's normal, its origin is the
// target's centre moved by ArSpec::offset in the target's plane, its +x is the target's +x turned
// ArSpec::heading degrees about the normal (towards the target's +y for a target whose printed
// side faces its +z), and one metre of the world is ArSpec::scale metres of the real one.

#include <array>

#include "ar/camera_file.h"
#include "ar/pose.h"
#include "ar/tracker.h"
#include "render/camera.h"
#include "scenario/scenario.h"

namespace thespis::core::render {

/// A world point (metres, y up) in the target's frame (metres).
std::array<double, 3> worldToTarget(const anim::Vec3d& world, const ar::TargetGeometry& target,
                                    const scenario::ArSpec& placement);

CameraView arCameraView(const ar::CameraIntrinsics& camera, const ar::TargetPose& pose,
                        const ar::TargetGeometry& target, const scenario::ArSpec& placement);

/// The world's rotation into the camera's frame (OpenCV's: x right, y down, z forward), row by
/// row: turns a light captured in the camera's frame (a mirror ball) back into the world.
std::array<double, 9> worldToCameraRotation(const ar::TargetPose& pose, const ar::TargetGeometry& target,
                                            const scenario::ArSpec& placement);

} // namespace thespis::core::render
