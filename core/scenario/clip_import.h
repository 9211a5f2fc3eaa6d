#pragma once
// Importing motion files into a character, as the studio's File ▸ Import Motion… and
// thespis.edit do it: each file becomes scenario clips of the character (a BVH file one, a glTF
// file one per animation), with paths relative to the scenario's folder, and a report of what
// was found — the joint naming convention, joints left unmapped, the mapping table (which the
// user may correct), how the body was stood up, and whether the file moves the character at all.
// Nothing is added here: anim::edit::addClips() adds what the user keeps.

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "anim/bvh.h"
#include "anim/skeleton.h"
#include "scenario/clip_file.h"
#include "scenario/scenario.h"
#include "util/error.h"

namespace thespis::core::scenario {

struct ClipImport {
    std::filesystem::path path;      ///< the file, as given
    std::vector<ClipAsset> clips;    ///< one per BVH file, one per animation of a glTF file
    ClipFileReport report;           ///< of the first clip's reading
    /// File joint name → the name it plays as (its H-Anim name, else its own): the table the
    /// user corrects; set as ClipAsset::mapping it replaces the automatic naming.
    std::map<std::string, std::string> mapping;
    int jointsMoved = 0;             ///< the character's joints the file moves
    std::vector<std::string> unmoved; ///< the character's joints it does not (they keep their rest)
    /// Joints without an H-Anim name whose motion reaches nothing of the character
    /// (unmappedJointsMovingNothing): worth a look at the mapping.
    std::vector<std::string> movingNothing;
    /// Why the clips cannot go on the character (empty: they can): e.g. no joint in common.
    std::string problem;
};

/// Reads `file` to import it into a character whose skeleton is `skeleton`; clips are named
/// after the file (BVH) or their animations (glTF) and their paths named as `assets` finds them.
/// `mapping` (optional) replaces the automatic joint naming. Errors: the reader's (file, line).
Result<ClipImport> planClipImport(const std::filesystem::path& file, const Assets& assets,
                                  const anim::Skeleton& skeleton, const std::map<std::string, std::string>& mapping = {});

/// True for the files an import reads: .bvh, .gltf, .glb.
bool isMotionFile(const std::filesystem::path& path);

/// Writes a joint mapping as a mapping file (anim::bvh::loadMapping reads it back), atomically.
Result<void> saveMapping(const std::filesystem::path& path, const std::map<std::string, std::string>& mapping);

} // namespace thespis::core::scenario
