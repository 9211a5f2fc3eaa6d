#pragma once
// The built-in demo character, made procedurally by the project (no external asset): a smooth
// humanoid of about 20k triangles standing in the H-Anim rest pose (hanim.h: +Y up, facing +Z,
// +X its left, metres, arms at the sides), about 1.8 m tall with its soles on y = 0. It wears a
// shirt, trousers and shoes; its hair is a separate segment lying 3 to 9 mm above the skull over
// the top and back of the head (the case of paper Fig. 14).
//
// Segments are named after H-Anim 2.0 body segments (sacrum, pelvis, l5 … t1, c4, skull,
// l_clavicle, l_upperarm, l_forearm, l_carpal, l_thigh, l_calf, l_talus …, and for LOA 2 the
// finger and toe bones such as l_carpal_distal_phalanx_2) plus "hair"; each follows its H-Anim
// joint (Segment.joint, bindRotation identity, bindTranslation = the joint's rest position).
// Limbs and torso are continuous surfaces cut at the joints: the cut rings are repeated in both
// segments with the same positions, normals and skin weights, so the skinned surface stays shut
// and smooth. Every body part is closed, wound counter-clockwise seen from outside. Skin
// weights blend the two joints on either side of a joint over a few centimetres.
// Deterministic: the same call gives the same mesh.

#include <array>

#include "anim/hanim.h"
#include "scene/character.h"
#include "util/error.h"

namespace thespis::core::scene {

struct DefaultHumanoidOptions {
    /// Skeleton to bind to; segments and weights of joints the level lacks go to the nearest
    /// ancestor it has (fingers to the wrist for LOA 1, …).
    anim::hanim::Level level = anim::hanim::Level::Subset25;
    /// Tessellation scale, 0.1 to 4: 1 gives about 20k triangles; 0.5 about a quarter of that.
    double detail = 1.0;
    /// Linear RGB of the shirt, so that several humanoids in one scene can be told apart.
    std::array<float, 3> shirtColor{0.07f, 0.17f, 0.45f};
};

/// Segment tags follow the paper's defaults: PI for skull, T1/clavicles, sacrum, pelvis, thighs
/// and hands (and the hair, rigid on the skull), PD otherwise; every role None. Materials
/// "skin", "hair", "shirt", "trousers" and "shoes", one per segment; no textures or texture
/// coordinates. Fails (InvalidArgument) only for a detail out of range.
Result<Character> makeDefaultHumanoid(const DefaultHumanoidOptions& options = {});

} // namespace thespis::core::scene
