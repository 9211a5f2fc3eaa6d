#pragma once
// Where a character looks, as a viewer checks it: the line of sight from between its eyes along
// the head's forward turned by the face's eyeball FAPs (23: heading, + left; 25: pitch, + down;
// in MPEG-4's units of 1e-5 rad) — what the gaze controller (motion/gaze.h) drives. Tests,
// scripts (AnimationService.eye_ray) and the AR checks all measure gaze through here.

#include <span>

#include "anim/quat.h"
#include "anim/root_motion.h"
#include "anim/skeleton.h"
#include "motion/gaze.h"

namespace thespis::core::motion {

struct EyeRay {
    anim::Vec3d origin;    ///< between the eyes
    anim::Vec3d direction; ///< unit
};

/// The line of sight of the pose `body` (the skeleton's layout) with the eyes of `face` (MPEG-4
/// FAPs), in the body frame's space, `rig` made for `skeleton`.
EyeRay eyeRay(const GazeRig& rig, const anim::Skeleton& skeleton, std::span<const float> body,
              std::span<const float> face);

/// The same where the character stands: turned and shifted by `placement`.
EyeRay placed(const EyeRay& ray, const anim::Placement& placement);

/// Degrees between the line of sight and the line from its origin to `target`.
double degreesOff(const EyeRay& ray, const anim::Vec3d& target);

} // namespace thespis::core::motion
