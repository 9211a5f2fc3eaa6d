#pragma once
// glTF 2.0 → Character: the skeleton from the skin's joints (converted to the world-aligned rest
// convention of character.h), the mesh split into segments (gltf_mesh.h), skin weights (up to
// 8 per vertex, JOINTS_0/WEIGHTS_0 + JOINTS_1/WEIGHTS_1), texture coordinates, base colour
// materials and textures, and the file's animations as clips resampled to a fixed rate.
//
// Skeleton: every joint of every skin (several skins sharing joints give their union), plus the
// nodes between them, rooted at their nearest common node. Nodes above that root (an armature
// node with a transform) are folded into it: the root joint's offset is its rest world position.
// Joint.offset is the world-space rest vector from the parent joint (scale of the rest pose
// included); Joint.sourceName is the glTF node name ("node<index>" for an unnamed node, which is
// also the name a user mapping table uses). A glTF joint's world transform G_j is O_j·C_j, with
// O_j the Thespis joint's rotation and position and C_j the constant rest world rotation (and
// scale) of the glTF joint, so a glTF local rotation r_j(t) becomes the frame rotation
// Rw·r_j(t)·rrest_j⁻¹·Rw⁻¹ (Rw: rest world rotation of the glTF parent, rrest_j: rest local
// rotation). Scale in the hierarchy is assumed uniform, as it is in practice.
// A file without skin gets a skeleton of one joint, "humanoid_root", at the origin: every mesh
// segment follows it rigidly, the Skin is empty and animations are not imported (a warning says so).
//
// Mesh: the rest-pose mesh of loadGltfMesh with `options.mesh` (by default split by dominant
// joint and by material, so that every segment has one material). Split segments are named
// after their joint's (mapped) name; Segment.joint is the skeleton joint a segment follows (its
// joint when split from a skinned mesh, the nearest joint above a mesh node, the skin's root
// joint for an unsplit skinned mesh, the root when none). When a mesh is skinned, every vertex has weights: the skinned ones as the file
// gives them (normalized; 4 or 8 influences as the file needs), those of rigid mesh nodes weight 1
// on their segment's joint. Texture coordinates are the set the base colour texture reads.
// Materials: every glTF material, same indices, with its base colour factor (glTF's default is
// white) and base colour texture decoded to RGBA8 (by tinygltf's stb_image; an image that cannot
// be decoded leaves its material untextured, with a warning).
//
// Animations: one clip per glTF animation, named after it (or "animation<i>"), sampled at
// `clipFrameRate` over [0, last key time]; LINEAR (slerp for rotations), STEP and CUBICSPLINE
// (Hermite) samplers. Files that split one motion into unnamed per-node animations (COLLADA2GLTF:
// CesiumMan, RiggedFigure) have them merged into one clip named "animation". A translation
// channel on a joint other than the root marks that joint `translates` when it moves it off its
// rest offset (channels that hold the rest translation are dropped). Scale and morph weight
// channels, and channels on nodes outside the skeleton, are not imported; warnings name them.
//
// Joint names map onto H-Anim 2.0: a user mapping table (source name → H-Anim name) first; then,
// unless `automaticMapping` is off, the naming convention that knows most of the rig's names (at
// least 4 and a quarter of them; H-Anim 1.1 / 2.0 names, Mixamo "mixamorig:LeftUpLeg", Unity /
// VRM humanoid "LeftUpperLeg", Blender "thigh.L", Rigify "DEF-spine.001", Quaternius /
// RobotExpressive "UpperLeg.L", and the motion capture conventions of anim/bvh_naming.h). A rig
// whose names no convention knows (the Khronos sample rigs have unnamed joints) is named by its
// shape: the joint where two legs and a spine branch is humanoid_root, then hips, knees, ankles
// and toes down the legs, vertebrae of the paper's set by relative height (as in the H-Anim rest
// pose) up to the joint where the arms and the neck branch, clavicles (when an arm chain has four
// joints before the hand branches), shoulders, elbows and wrists, then the neck and the skull
// base. Left is the character's left given its up axis (+Y) and its facing (where the toes point,
// else glTF's +Z). When neither finds anything, each name is asked on its own
// (automaticHAnimName). Automatic names that break the H-Anim hierarchy (a joint whose nearest
// named ancestor is not an H-Anim ancestor of its name, e.g. an IK foot control under the
// armature root) are dropped. Names stay unique: when two joints want one name, the user's table
// wins, then the first in joint order. Joints without an H-Anim name keep their source name;
// Character::warnings lists them (and the dropped and duplicate names).
//
// Face: the meshes' morph targets become the face's targets (FaceRig::targets, rest-space offsets
// of the vertices they move; gltf_mesh.h), named after mesh.extras.targetNames or "<mesh>:<index>",
// one target per name across meshes and primitives. A mesh's default weights stay in the rest
// shape, so a face frame moves the model from the shape the file shows. The face mapping table
// (face_mapping.h) then drives the targets and the face joints: `faceMapping` when given, else the
// one the naming schemes of face_naming.h recognise (ARKit, Oculus visemes, expression names, eye
// and jaw bones). A table naming targets or joints the model lacks adds a warning for each.
//
// Unsupported files (Draco, meshopt …) are refused by loadGltfMesh's rules with the feature named.

#include <filesystem>
#include <map>
#include <optional>
#include <string>

#include "scene/character.h"
#include "scene/face_mapping.h"
#include "scene/gltf_mesh.h"
#include "util/error.h"

namespace thespis::core::scene {

struct GltfCharacterOptions {
    GltfMeshOptions mesh{.splitSkinnedByJoint = true, .splitByMaterial = true};
    /// Source joint name → H-Anim name; overrides the automatic mapping for the names it has.
    std::map<std::string, std::string> jointMapping;
    bool automaticMapping = true;
    double clipFrameRate = 30.0; ///< animations are resampled at this rate
    /// Decode the base colour textures (off: materials keep their colours, no textures).
    bool loadTextures = true;
    /// Stand the rig as H-Anim does (+Y up, facing +Z) and hang IK-control feet from their
    /// knees (rig_repair.h), so that any H-Anim motion plays on it. Off: the file's rig as it is.
    bool standardRig = true;
    /// The table driving the face (see above); none: the recognised schemes'.
    std::optional<FaceMapping> faceMapping;
};

/// The H-Anim name the automatic mapping gives a source joint name on its own, or "" when it
/// knows none: namespace and exporter prefixes ("mixamorig:", "mixamorig_", "Armature_", "DEF-")
/// are stripped and case, '.', '-' and ' ' ignored, then the conventions above are asked in turn
/// (H-Anim, Mixamo, Unity, Blender, Rigify, Quaternius, then the motion capture ones). Loading a
/// file first looks at all its names together, which settles names that conventions share
/// ("Hips" is the root for Mixamo, the lower spine for Quaternius).
std::string automaticHAnimName(const std::string& sourceName);

Result<Character> loadGltfCharacter(const std::filesystem::path& path, const GltfCharacterOptions& options = {});

} // namespace thespis::core::scene
