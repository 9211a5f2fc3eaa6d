#pragma once
// The H-Anim standard humanoid (ISO/IEC 19774-1:2019, H-Anim 2.0): joint names, hierarchy of
// levels of articulation 1 and 2, a default rest pose, and the 25-joint subset the paper's
// posture space uses (3·25 + 3 = 78 dimensions). Axes as in H-Anim: +Y up, the humanoid faces
// +Z, +X is its left; units are metres, standing with arms at the sides.

#include <string>
#include <string_view>
#include <vector>

#include "anim/skeleton.h"

namespace thespis::core::anim::hanim {

enum class Level {
    Loa1,     ///< 18 joints
    Loa2,     ///< 71 joints, hands with fingers
    Subset25, ///< LOA 1 plus spine, neck and clavicles: 25 joints
};

/// The standard skeleton of a level, in its default rest pose.
const Skeleton& skeleton(Level level);

/// Joint names of a level, parents first.
std::vector<std::string> jointNames(Level level);

/// True when `name` is an H-Anim 2.0 joint name (any level up to LOA 2).
bool isJointName(std::string_view name);

/// The H-Anim 2.0 name for an H-Anim 1.1 name the paper's era used ("HumanoidRoot",
/// "l_ankle", "l_wrist", …); other names are returned unchanged.
std::string_view fromHAnim11(std::string_view name);

/// The name of the joint on the other side ("l_elbow" ↔ "r_elbow"), or the name itself for a
/// joint on the mid-line. Also understands common Left/Right spellings (LeftArm, lCollar,
/// upperarm.L, Eye_L) for joints that were not mapped to H-Anim.
std::string mirrorName(std::string_view name);

/// LOA 2 parent of an H-Anim joint name ("" for humanoid_root or an unknown name).
std::string_view parentName(std::string_view name);

} // namespace thespis::core::anim::hanim
