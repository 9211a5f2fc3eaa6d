#pragma once
// Baked motion written as a glTF 2.0 animation (`thespis-cli bake-motion --out M.glb`), for
// Blender, three.js and other engines: the frames of a character's skeleton as rotation (and,
// for the root and translating joints, translation) channels on the nodes of the glTF model the
// character was read from, LINEAR-sampled at the bake's rate. The output is one .glb: the model
// with its meshes, skins, materials and images (external buffers and images taken in) and the
// baked animation instead of its own, or with `animationOnly` just the model's node hierarchy and
// the animation, which plays onto the model by node name (three.js's AnimationMixer, Blender's
// action on the same armature).
//
// Import (gltf_character.h) turns a glTF joint's local rotation into the skeleton's world-aligned
// frame and may stand the rig up (a quarter-turn about its rest pose) and hang IK feet from their
// knees; export undoes this through world transforms: each frame's joint world rotations and
// positions, turned back by the rig's turn (found from the rest poses), times each node's rest
// world rotation, and made local to the node's glTF parent. Importing the file again gives the
// baked frames back (to float precision).
//
// Face tracks: the model's own morph targets get the weights its face mapping table gives them
// (GltfMotion::face: the character's FaceRig as imported, face_mapping.h), frame by frame: the
// face frame's visemes and expressions expanded as the rig expands them, then the drives summed —
// what the studio shows. A mesh's targets are matched by the names the import gives them
// (mesh.extras.targetNames, else "<mesh>:<index>"); each driven target's weight is its default
// weight (kept in the rest shape on import) plus the driven weight, on a weights channel of each
// node showing the mesh whose driven targets move in some frame. Targets nothing drives keep
// their default weight.

#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "anim/frame.h"
#include "anim/skeleton.h"
#include "scene/face_rig.h"
#include "util/error.h"

namespace thespis::core::scene {

struct GltfMotion {
    std::string name = "baked";        ///< the animation's name
    double fps = 30;
    /// Whole frames of `skeleton`'s layout, one after another (frame i at i / fps seconds).
    std::span<const float> bodyFrames;
    /// Face frames (same count) of `faceLayout`, or empty; its scalars are read by their names
    /// in anim::FrameLayout::mpeg4Face ("fap1" … "expression6").
    std::span<const float> faceFrames;
    anim::FrameLayoutPtr faceLayout;
    /// The face the frames drive: the character's, read from the same model. None: no weights.
    const FaceRig* face = nullptr;
};

struct GltfMotionResult {
    std::size_t animatedNodes = 0;     ///< nodes with rotation channels
    std::vector<std::string> morphTargets; ///< targets given weights ("mesh Head: Angry")
};

/// Writes `motion` of `skeleton` (read from the glTF file `model`) as `output` (.glb),
/// atomically. Errors: the model cannot be read; a skeleton joint has no node of its source name;
/// the model's rest pose is not the skeleton's (the character was read from another file); the
/// frames do not fit the layouts.
Result<GltfMotionResult> writeGltfMotion(const std::filesystem::path& output, const std::filesystem::path& model,
                                         const anim::Skeleton& skeleton, const GltfMotion& motion,
                                         bool animationOnly = false);

} // namespace thespis::core::scene
