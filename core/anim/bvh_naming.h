#pragma once
// Private to core's importers (the BVH reader; the glTF rig naming of scene/rig_naming.h reuses
// these tables and helpers, so that both read names alike): the built-in joint naming
// conventions of motion capture files and their tables onto H-Anim 2.0 joint names. Each table
// lists every joint name the convention uses; names with no sensible H-Anim counterpart (pelvis
// side bones, twist helpers, end bones) are listed with an empty H-Anim name, so that they count
// when the convention is detected but keep their own name on import. The BVH reader's naming
// decision and its user mapping files (bvh::parseMapping) are here too.

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "anim/bvh.h"

namespace thespis::core::anim::bvh::naming {

struct NameEntry {
    std::string_view file;  ///< joint name as the convention writes it
    std::string_view hanim; ///< H-Anim 2.0 name, or empty when there is none
};

// Table rows for a left/right pair: the file names of both sides and the H-Anim name without its
// side prefix (THESPIS_LR_NONE: a pair with no H-Anim joint). For the naming tables of the BVH
// and glTF readers.
#define THESPIS_LR(left, right, hanim) {left, "l_" hanim}, {right, "r_" hanim}
#define THESPIS_LR_NONE(left, right) {left, ""}, {right, ""}

struct Convention {
    std::string_view id; ///< reported as ImportReport::convention
    std::span<const NameEntry> entries;
};

/// Every built-in convention, in the order ties are broken.
std::span<const Convention> conventions();

/// The name without a "namespace:" prefix ("mixamorig:Hips" → "Hips").
std::string_view stripNamespace(std::string_view name);

/// The H-Anim 2.0 name when `name` is an H-Anim 1.1 or 2.0 joint name, else "".
std::string_view hanimJointName(std::string_view name);

/// The fewest of `nameCount` names a convention must know to be taken: 4, and a quarter of them.
int minimumKnown(std::size_t nameCount);

struct Detection {
    std::string convention; ///< "none" when no convention knows enough of the names
    int known = 0;          ///< how many of the names the convention knows
    JointMapping mapping;   ///< file name → H-Anim name for the names it maps
};

/// Picks the convention that knows the most of `names` (namespace prefixes ignored), or the
/// "hanim" convention for files already written with H-Anim 1.1 / 2.0 names. A convention is
/// only taken when it knows minimumKnown of the file's joints.
Detection detect(std::span<const std::string> names);

/// The joint names of an imported file, and what the report says about them.
struct Naming {
    std::vector<std::string> names; ///< final joint names, in file order
    ImportReport report;            ///< convention, isBody, unmapped
};

/// Decides the joint names: the user's table or the detected convention's; a mapped name that
/// is taken (by an earlier joint, or as the own name of another joint of the file) is refused
/// and that joint keeps its own name, so names stay unique. Joints map only when the file is a
/// body; `rotationRange` (per joint, radians: the most it turns away from its first frame) tells
/// a face clip on a body rig from body motion.
Naming nameJoints(std::span<const std::string> fileNames, std::span<const double> rotationRange,
                  const ImportOptions& options);

/// True for joints of a face rig (eyes, jaw, tongue, lips, brows and the MakeHuman face muscle
/// bones): a clip that moves only such joints is a face clip, not a body motion.
bool isFacialName(std::string_view name);

} // namespace thespis::core::anim::bvh::naming
