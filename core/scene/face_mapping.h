#pragma once
// A face mapping table: how a model's own morph targets and face joints follow the channels of a
// face frame (fap.h: the 68 FAPs, the 14 visemes' and 6 expressions' weights). Each drive gives a
// target (by name) coefficient × a channel's value as weight — of the value's positive or negative
// part only when one-sided — and each joint drive turns a skeleton joint (by name) about an axis
// by radiansPerUnit × a channel's value: the eyes with FAPs 23–26, a jaw with FAP 3, the head with
// FAPs 48–50. Applying a table to a Character fills its FaceRig's drives and joints.
//
// Tables for the naming schemes Thespis knows (ARKit, Oculus visemes, expression names, eye and
// jaw bones) are made from the model (face_naming.h); any other table is written by hand or saved
// from one of those, as a versioned JSON file (util/json_document.h):
//
//     {"format": "thespis-face-mapping", "version": 1, "name": "my rig",
//      "drives": [{"target": "Blink_L", "channel": "close_t_l_eyelid",
//                  "coefficient": 0.0009765625, "side": "positive"}, …],
//      "joints": [{"joint": "LeftEye", "channel": "yaw_l_eyeball", "axis": [0, 1, 0],
//                  "radiansPerUnit": 1e-05}, …]}
//
// "channel" is a face channel's name as findFaceChannel reads it, case ignored ("open_jaw",
// "fap3", "viseme1", "anger", "expression3"), or a FAP's number (1 … 68). "side" is "both" (the
// default), "positive" or "negative". "axis" is in the joint's rest frame, which the import makes
// world-aligned (+Y up, facing +Z: +X turns the face down, +Y to its left, +Z rolls it to its
// right); it is normalized on reading (one of length 1 within 1e-12 is kept as written). "name", "drives" and "joints" may be left out; any other
// field is refused, so that a misspelt one is not silently ignored. Errors name the file and the
// field ("drives[3].target: must not be empty").

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "anim/quat.h"
#include "scene/face_rig.h"
#include "util/error.h"

namespace thespis::core::scene {

struct Character;

inline constexpr std::string_view kFaceMappingFormat = "thespis-face-mapping";
/// Version 1: drives and joints. A new version adds an upgrade step in face_mapping.cpp.
inline constexpr int kFaceMappingVersion = 1;

struct FaceMappingDrive {
    std::string target;      ///< the morph target's name (every target of that name)
    int channel = 0;         ///< face channel (fap.h)
    double coefficient = 0;  ///< weight per unit of the channel
    MorphDrive::Side side = MorphDrive::Side::Both;
    bool operator==(const FaceMappingDrive&) const = default;
};

struct FaceMappingJoint {
    std::string joint;         ///< the skeleton joint's name, or its source name in the file
    int channel = 0;           ///< face channel (fap.h)
    anim::Vec3d axis;          ///< unit, in the joint's rest frame
    double radiansPerUnit = 0; ///< turn per unit of the channel
    bool operator==(const FaceMappingJoint&) const = default;
};

struct FaceMapping {
    std::string name; ///< what the table is for ("ARKit blendshapes, Oculus visemes"); may be empty
    std::vector<FaceMappingDrive> drives;
    std::vector<FaceMappingJoint> joints;
    bool empty() const { return drives.empty() && joints.empty(); }
    bool operator==(const FaceMapping&) const = default;
};

/// A face channel's name as tables write it: the FAP's standard name ("open_jaw"), "viseme1" …
/// "viseme14", or the expression's name ("anger").
std::string faceChannelName(int channel);

/// The table as JSON text (the current version, every number exact).
std::string serializeFaceMapping(const FaceMapping& mapping);
/// Reads a table from JSON text. Errors: NotOurFormat (not a face mapping), NewerVersion,
/// CorruptData naming the field path ("drives[3].channel: …").
Result<FaceMapping> parseFaceMapping(std::string_view text);
/// Reads a table file; error messages start with the file's path.
Result<FaceMapping> loadFaceMapping(const std::filesystem::path& path);
/// Writes a table file atomically.
Result<void> saveFaceMapping(const std::filesystem::path& path, const FaceMapping& mapping);

/// Makes `mapping` the character's: face.drives and face.joints become the table's (a drive goes
/// to every target of its name, a joint drive to the joint of its name or source name), and the
/// visemes' and expressions' FAP vectors are cleared for those the table drives itself (a drive or
/// joint on their channel), so that they do not move the face twice. Returns a warning, one
/// sentence each, for every target and joint the table names that the character lacks; those
/// drives are left out.
std::vector<std::string> applyFaceMapping(const FaceMapping& mapping, Character& character);

/// The distinct names of the character's morph targets, in target order.
std::vector<std::string> morphTargetNames(const Character& character);

} // namespace thespis::core::scene
