#pragma once
// Gaze targets and settings as scripts, BML and the command line write them: one reader for all.
//   target:    "camera" | "Antigone" (between her eyes) | "Antigone:l_radiocarpal" | "0.5 1.6 2" (a point, metres)
//   influence: BML's EYES | HEAD (or NECK) | SHOULDER | WAIST (or WHOLE), any case
//   offset:    BML's offsetAngle (degrees) toward offsetDirection RIGHT | LEFT | UP | DOWN |
//              UPRIGHT | UPLEFT | DOWNRIGHT | DOWNLEFT (POLAR n: n degrees from up, clockwise)

#include <string>
#include <string_view>

#include "motion/gaze.h"
#include "runtime/stage.h"
#include "util/error.h"

namespace thespis::core::runtime {

/// InvalidArgument naming what does not read.
Result<GazeTarget> parseGazeTarget(std::string_view text);
std::string gazeTargetString(const GazeTarget& target);

Result<motion::GazeInfluence> parseGazeInfluence(std::string_view text);
std::string_view gazeInfluenceName(motion::GazeInfluence influence);

/// Sets settings.offsetHeading and offsetPitch from BML's offset angle and direction.
Result<void> setGazeOffset(motion::GazeSettings& settings, double angleDegrees, std::string_view direction);

} // namespace thespis::core::runtime
