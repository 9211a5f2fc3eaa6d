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
// Face tracks: a mesh morph target named after a face scalar (glTF's mesh.extras.targetNames, as
// Blender and three.js write them, "fap19" …, case ignored) gets that scalar as its weight, on a
// weights channel of each node showing the mesh. Targets without a scalar keep their weight.

#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "anim/frame.h"
#include "anim/skeleton.h"
#include "util/error.h"

namespace thespis::core::scene {

struct GltfMotion {
    std::string name = "baked";        ///< the animation's name
    double fps = 30;
    /// Whole frames of `skeleton`'s layout, one after another (frame i at i / fps seconds).
    std::span<const float> bodyFrames;
    /// Face frames (same count) of `faceLayout`, or empty.
    std::span<const float> faceFrames;
    anim::FrameLayoutPtr faceLayout;
};

struct GltfMotionResult {
    std::size_t animatedNodes = 0;     ///< nodes with rotation channels
    std::vector<std::string> morphTargets; ///< targets given weights ("mesh Head: fap19")
};

/// Writes `motion` of `skeleton` (read from the glTF file `model`) as `output` (.glb),
/// atomically. Errors: the model cannot be read; a skeleton joint has no node of its source name;
/// the model's rest pose is not the skeleton's (the character was read from another file); the
/// frames do not fit the layouts.
Result<GltfMotionResult> writeGltfMotion(const std::filesystem::path& output, const std::filesystem::path& model,
                                         const anim::Skeleton& skeleton, const GltfMotion& motion,
                                         bool animationOnly = false);

} // namespace thespis::core::scene
