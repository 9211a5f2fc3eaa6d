#pragma once
// Gaze targets and settings as scripts, BML and the command line write them: one reader for all.
//   target:    "camera" | "Antigone" (between her eyes) | "Antigone:l_radiocarpal" | "0.5 1.6 2" (a point, metres)
//   influence: BML's EYES | HEAD (or NECK) | SHOULDER | WAIST (or WHOLE), any case
//   offset:    BML's offsetAngle (degrees) toward offsetDirection RIGHT | LEFT | UP | DOWN |
//              UPRIGHT | UPLEFT | DOWNRIGHT | DOWNLEFT (POLAR n: n degrees from up, clockwise)

#include <string>
#include <string_view>

#include "anim/quat.h"
#include "motion/gaze.h"
#include "util/error.h"

namespace thespis::core::motion {

/// Where a character looks (Stage::gaze, a scenario's gaze actions).
struct GazeTarget {
    enum class Kind { Point, Joint, Camera };
    Kind kind = Kind::Camera;
    anim::Vec3d point;        ///< Point: in the scene, metres
    std::string character;    ///< Joint: whose
    std::string joint;        ///< Joint: which; empty for the point between its eyes
    bool operator==(const GazeTarget&) const = default;
};

/// InvalidArgument naming what does not read.
Result<GazeTarget> parseGazeTarget(std::string_view text);
std::string gazeTargetString(const GazeTarget& target);

Result<GazeInfluence> parseGazeInfluence(std::string_view text);
std::string_view gazeInfluenceName(GazeInfluence influence);

/// Sets settings.offsetHeading and offsetPitch from BML's offset angle and direction.
Result<void> setGazeOffset(GazeSettings& settings, double angleDegrees, std::string_view direction);

} // namespace thespis::core::motion
