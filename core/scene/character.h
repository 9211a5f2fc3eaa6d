#pragma once
// A character (paper §6.1.3 and §4): a skeleton, a skinned mesh split into named segments, its
// materials and the clips that came with it. Every part is in the rest pose, and the rest pose is
// "world aligned" as in H-Anim and BVH: at rest every joint's world rotation is the identity, so
// a joint's frame rotation (anim::Skeleton, identity = rest) is also its rotation relative to
// rest. Skinning therefore needs no inverse bind matrices: joint j moves a rest-pose point p to
// Q_j·(p − restPosition_j) + P_j, with (Q_j, P_j) its world rotation and position in the pose.
// Importers that read files with other conventions (glTF joints with rest rotations and inverse
// bind matrices) convert to this one on the way in.

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "anim/keyframe_clip.h"
#include "anim/skeleton.h"
#include "scene/character_mesh.h"
#include "scene/face_rig.h"
#include "util/error.h"

namespace thespis::core::scene {

/// The largest number of joint influences per vertex (glTF's JOINTS_0 + JOINTS_1).
inline constexpr int kMaxInfluences = 8;

/// Skin weights, a fixed number of influences per vertex (unused slots have weight 0 and joint
/// 0), stored flat: vertex v's influences are [v·influences, (v+1)·influences).
struct Skin {
    int influences = 0; ///< 1 … kMaxInfluences; 0 = no skin (the mesh is rigid)
    std::vector<std::uint16_t> joints; ///< skeleton joint indices
    std::vector<float> weights;        ///< non-negative, summing to 1 per vertex
    bool empty() const { return influences == 0; }
    /// Checks sizes, joint indices below `jointCount`, weights finite, ≥ 0 and summing to 1
    /// (within 1e-3); says which vertex is wrong.
    Result<void> validate(std::size_t vertexCount, int jointCount) const;
};

/// RGBA8 pixels, rows from the top (as glTF images are stored).
struct TextureImage {
    std::string name;
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;
};

/// The part of glTF's metallic-roughness material Thespis shades with: base colour and its
/// texture. PRT shading multiplies the transferred radiance by the albedo.
struct Material {
    std::string name;
    std::array<float, 4> baseColor{0.8f, 0.8f, 0.8f, 1.0f}; ///< linear RGBA
    int baseColorTexture = -1; ///< index into Character::textures, or -1
};

struct Character {
    std::string name;
    anim::Skeleton skeleton;   ///< world-aligned rest pose (see above); joints H-Anim named where mapped
    CharacterMesh mesh;        ///< rest pose; segment.joint names a skeleton joint ("" = root)
    Skin skin;                 ///< empty: every segment follows its joint rigidly
    /// Per vertex (u, v) with v down as in glTF, or empty.
    std::vector<std::array<float, 2>> texcoords;
    /// Material of each segment (index into materials), one per segment, or empty (default material).
    std::vector<int> segmentMaterials;
    std::vector<Material> materials;
    std::vector<TextureImage> textures;
    /// How its face moves with a face frame (face_rig.h); empty: it does not.
    FaceRig face;
    /// Animations that came with the file, on `skeleton`'s frame layout.
    std::vector<std::shared_ptr<anim::KeyframeClip>> clips;
    /// What the importer could not map or had to drop (unmapped joints, ignored channels …), one
    /// sentence each, for the user to read.
    std::vector<std::string> warnings;

    /// Checks that the parts agree: mesh valid, skin sized and in range, texcoords and
    /// segment materials sized, every segment.joint naming a skeleton joint.
    Result<void> validate() const;
    /// Checks the face rig against the mesh and skeleton (vertices, targets, channels, joints).
    Result<void> validateFace() const;
    /// Skeleton joint a segment follows (its joint, or the root when it names none).
    int segmentJoint(std::size_t segment) const;
};

} // namespace thespis::core::scene
