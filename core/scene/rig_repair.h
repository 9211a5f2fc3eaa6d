#pragma once
// Two fixes that let an imported character play any H-Anim motion, made after a glTF import
// (gltf_character.h) on the finished character, exactly (nothing it shows at rest moves):
//
// - Facing: H-Anim stands up along +Y and faces +Z. A rig that faces elsewhere (CesiumMan's
//   root node turns it to face +X) is turned by quarter turns about its rest pose: skeleton,
//   mesh, the face's morph target offsets, segment frames and clips together
//   (anim/rig_orientation.h).
// - IK feet: game rigs often drive the feet by inverse kinematics, with the foot bone an IK
//   control under the armature root instead of under the shin (RobotExpressive's Foot.L). Motion
//   from another body moves the shins and would leave such feet on the floor where they rest. A
//   leaf joint whose name says it is an ankle, in a rig whose knee of that side is not its
//   parent, is moved under that knee as its ankle (same rest place, same world motion in every
//   clip), so it follows the leg.

#include <string>
#include <vector>

#include "scene/character.h"

namespace thespis::core::scene {

/// Turns the character to face +Z, +Y up; returns what it was (e.g. "+Y up, facing +X"), or ""
/// when it already stood so.
std::string turnToFaceForward(Character& character);

/// Moves IK-control feet under their knees (see above); returns the source names of the joints
/// moved. `hanimName` gives the H-Anim name a source joint name stands for ("Foot.L" →
/// "l_talocrural"; gltf_character.h's automaticHAnimName).
std::vector<std::string> attachIkFeet(Character& character, std::string (*hanimName)(const std::string&));

} // namespace thespis::core::scene
