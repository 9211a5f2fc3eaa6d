#pragma once
// One joint's place in a body frame, walking its ancestors alone: for the layers that turn a
// few joints of a finished pose every frame (gaze, pointing) without allocating.

#include <span>

#include "anim/quat.h"
#include "anim/skeleton.h"

namespace thespis::core::anim {

/// The joint's position and orientation in `body` (the skeleton's layout; before placement).
void jointTransform(const Skeleton& skeleton, std::span<const float> body, int joint, Vec3d& position,
                    Quatd& orientation);

} // namespace thespis::core::anim
