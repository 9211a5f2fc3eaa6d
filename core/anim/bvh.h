#pragma once
// BVH (Biovision hierarchy) motion capture: import onto H-Anim joint names and export.
//
// Import keeps every joint of the file (so export → import is lossless) and renames the joints
// it can map to H-Anim 2.0 names: by a built-in table for the skeleton convention it detects
// (CMU/MotionBuilder, CMU 3ds Max, DAZ/Poser, MakeHuman, and others listed in bvh.cpp), or by a
// user mapping file. Joints that cannot be mapped keep their file name and are listed in the
// report, never dropped silently. A file that is not a body (e.g. a face rig) imports with its
// own joint names. Rotations become quaternions in each joint's parent frame (BVH rest pose =
// identity); the root's (and any other 6-channel joint's) position becomes a translation
// element. Values stay in the file's units; a body lying down or facing away in the file is
// stood up in H-Anim's axes (ImportOptions::upright).

#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "anim/keyframe_clip.h"
#include "anim/skeleton.h"
#include "util/error.h"

namespace thespis::core::anim::bvh {

/// File joint name → H-Anim name.
using JointMapping = std::map<std::string, std::string>;

struct ImportOptions {
    bool mapToHAnim = true;              ///< rename joints onto H-Anim names
    std::optional<JointMapping> mapping; ///< user table; replaces the built-in tables
    std::optional<double> frameRate;     ///< overrides the header's Frame Time (e.g. CMU 77_02 is 60 fps)
    /// Stand a body that lies down or faces away (a Z-up export) up in H-Anim's axes (+Y up,
    /// facing +Z), by quarter turns (anim/rig_orientation.h).
    bool upright = true;
    /// Leave out a first frame that is a calibration pose (ImportReport::calibrationFrame).
    bool dropCalibrationFrame = false;
};

struct ImportReport {
    std::string convention;            ///< detected naming ("cmu", "cmu-3dsmax", "daz", "makehuman", …, or "none")
    bool isBody = false;               ///< a humanoid body was recognised and mapped
    int jointCount = 0;                ///< ROOT and JOINT entries in the header (End Sites excluded)
    int channelCount = 0;              ///< channels per frame
    int frameCount = 0;                ///< "Frames:" of the header
    double frameTime = 0;              ///< "Frame Time:" of the header, seconds
    int extraFrameLines = 0;           ///< frame lines past "Frames:", well-formed but skipped
    std::vector<std::string> unmapped; ///< file joint names that kept their own name
    std::string turnedFrom;            ///< how the body lay before it was stood up ("+Z up, facing −Y"), or empty
    /// The first frame is a calibration pose (CMU's MB2 T-pose): it jumps to the second by far
    /// more than the motion moves. Left out with ImportOptions::dropCalibrationFrame.
    bool calibrationFrame = false;
};

struct ImportedClip {
    Skeleton skeleton;
    std::shared_ptr<KeyframeClip> clip; ///< on skeleton.frameLayout()
    ImportReport report;
};

/// Parses BVH text. Errors are CorruptData with a message naming the line ("line 42: expected
/// 'OFFSET'"), NotOurFormat when the text does not start with HIERARCHY.
Result<ImportedClip> parse(std::string_view text, const ImportOptions& options = {}, std::string_view clipName = {});
Result<ImportedClip> load(const std::filesystem::path& path, const ImportOptions& options = {});
/// load() on the text of `path` read elsewhere (from a package): errors name the file.
Result<ImportedClip> parseFile(std::string_view text, const std::filesystem::path& path, const ImportOptions& options = {});

/// Writes `clip` (on `skeleton`'s layout) as BVH text: each joint's source name when it has one
/// (else its name), its rotation order, its End Site; 9 significant digits, so that a round
/// trip reproduces every rotation within 1e-5.
std::string write(const Skeleton& skeleton, const KeyframeClip& clip);
/// Writes atomically (temporary file, then rename).
Result<void> save(const std::filesystem::path& path, const Skeleton& skeleton, const KeyframeClip& clip);

/// Reads a user mapping file: one "file_joint_name  hanim_name" pair per line, '#' comments.
/// Errors name the line.
Result<JointMapping> loadMapping(const std::filesystem::path& path);
Result<JointMapping> parseMapping(std::string_view text);

} // namespace thespis::core::anim::bvh
