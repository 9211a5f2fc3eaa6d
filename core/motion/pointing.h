#pragma once
// Pointing at a target (BML's <pointing target mode>, issue 33). The gesticon's point entry
// gives the arm its shape and its timing; this aims it: the shoulder turns so that the line from
// the shoulder to the index fingertip goes through the target, as far as the gesture's weight
// says (the aim comes and goes with the gesture's fades). It turns the pose the body shows, after
// every other layer, so that idle sway, a turning chest or a moving target do not throw the
// finger off; a turn at the shoulder alone keeps the entry's elbow and hand as they were drawn.

#include <span>
#include <string_view>
#include <vector>

#include "anim/quat.h"
#include "anim/skeleton.h"
#include "util/error.h"

namespace thespis::core::motion {

/// BML's mode: RIGHT_HAND, LEFT_HAND, BOTH_HANDS.
enum class PointingHand { Right, Left, Both };

/// Reads BML's mode, any case; empty is the right hand. InvalidArgument names what does not read.
Result<PointingHand> parsePointingHand(std::string_view mode);

/// The mode that parsePointingHand() reads as `hand`: "RIGHT_HAND", "LEFT_HAND", "BOTH_HANDS".
const char* pointingHandName(PointingHand hand);

/// One arm that points: the joint that turns and the joint whose end aims.
struct PointingArm {
    int shoulder = -1; ///< the H-Anim shoulder (l_ or r_shoulder)
    int tip = -1;      ///< the index finger's last joint; the wrist on a rig without fingers
};

/// The arms `hand` names on the skeleton. NotFound names the joint a rig without that arm lacks.
Result<std::vector<PointingArm>> pointingArms(const anim::Skeleton& skeleton, PointingHand hand);

/// Turns the arm's shoulder in `body` (the skeleton's layout, before placement) toward `target`
/// (in the same space) by `weight`: 0 leaves it, 1 puts the target on the shoulder–tip line.
/// No allocation.
void aimArm(const anim::Skeleton& skeleton, const PointingArm& arm, std::span<float> body, const anim::Vec3d& target,
            double weight);

/// Degrees between where the arm points (shoulder to tip) and the target, seen from the shoulder.
double pointingError(const anim::Skeleton& skeleton, const PointingArm& arm, std::span<const float> body,
                     const anim::Vec3d& target);

} // namespace thespis::core::motion
