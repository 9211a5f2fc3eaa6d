#pragma once
// The face naming schemes Thespis recognises in a model, and the face mapping table
// (face_mapping.h) each one gives, so that a model with any of them plays face clips with no table
// written. Names are compared without case, separators ('_', '-', ' ', '.') or a namespace
// prefix ("blendShape1.", "mixamorig:").
//
//   - ARKit's 52 blendshapes (jawOpen, eyeBlinkLeft, mouthSmileLeft …; Left is the face's own
//     left, as MPEG-4's l_). Each follows the low-level FAPs that make the same motion, one-sided,
//     at weight 1 when a FAP reaches the value listed in face_naming.cpp (in FAP units: eyeBlinkLeft
//     at close_t_l_eyelid 1024 IRISD, a lid lowered by the whole eye opening; lids closing halfway
//     each also give 1). mouthLeft, mouthRight and mouthDimpleLeft / Right follow no FAP: MPEG-4
//     has none that moves the whole mouth sideways or pulls the corners back.
//     The 14 visemes and the 6 expressions are given as ARKit weights too, where the model has no
//     targets of their own.
//   - The 15 Oculus visemes (viseme_sil, viseme_PP … viseme_U): each drives its MPEG-4 viseme's
//     channel (PP → p_b_m … U → U); viseme_sil is silence and drives nothing.
//   - Expression-named targets: Happy / Joy / Smile / Happiness, Sad / Sadness, Angry / Anger,
//     Fear / Afraid / Scared / Fearful, Disgust / Disgusted, Surprised / Surprise → the expression's
//     channel, weight = its intensity (RobotExpressive's Angry, Surprised, Sad).
//   - Targets named after a face channel ("fap19", "open_jaw", "viseme3", "expression2"): that
//     channel's value is the weight.
//   - Eye bones (LeftEye / RightEye, l_eyeball_joint, eye.L, CC_Base_L_Eye …): yaw (FAPs 23, 24)
//     about +Y and pitch (25, 26) about +X, 1e-5 rad per unit (AU); the eyes then follow the bones,
//     and the ARKit eyeLook targets are left alone so that the eyes do not turn twice.
//   - A jaw bone (Jaw, jaw_root, temporomandibular …), when no target follows open_jaw: FAP 3 turns
//     it about +X by 0.22 rad per 1024 MNS units (a chin about 4.5 MNS in front of the hinge drops
//     one MNS), so that jawOpen's 1536 units open it about 19°.
//   - The H-Anim head (skullbase): head_pitch, head_yaw, head_roll (FAPs 48–50) about +X, +Y, +Z.

#include "scene/face_mapping.h"

namespace thespis::core::scene {

struct Character;

/// The table the recognised schemes give `character` (its morph targets and skeleton joints);
/// its name lists the schemes found ("ARKit blendshapes, eye bones"); empty when none is found.
FaceMapping recogniseFaceMapping(const Character& character);

} // namespace thespis::core::scene
