#pragma once
// The body of a scenario character, for the renderer and the bake: its glTF model (path relative
// to the scenario's folder) or, without one, the built-in procedural humanoid bound to the
// character's H-Anim skeleton level; the scenario's segment tags applied. Errors name the
// character and the field ("characters[0].model: …"). A glTF model's face follows the table the
// character names (Character::faceMapping) or, without one, the table recognised from the
// model's names. And how the character's animation skeleton drives that body's own rig.

#include <filesystem>
#include <optional>

#include "anim/retarget.h"
#include "scenario/asset_resolver.h"
#include "scenario/scenario.h"
#include "scene/character.h"
#include "scene/face_mapping.h"
#include "util/error.h"

namespace thespis::core::scenario {

/// The body. A face mapping table that cannot be used (missing, malformed, or named by a
/// character on the built-in humanoid) does not stop it: the body's warnings say so, naming the
/// field and the file, and its face follows the recognised table; so do the table's targets and
/// joints the model lacks (scene::applyFaceMapping).
Result<scene::Character> loadCharacterBody(const Scenario& scenario, std::size_t characterIndex,
                                           const Assets& assets);

/// The face mapping table the character names, read through `assets`; nullopt when it names none
/// (its face follows the table recognised from its model's names). Errors name the field and the
/// file ("characters[0].faceMapping (Robot): tables/robot.json: …"), and say when the character
/// has no glTF model for a table to drive.
Result<std::optional<scene::FaceMapping>> readCharacterFaceMapping(const Scenario& scenario, std::size_t characterIndex,
                                                                  const Assets& assets);

/// The retarget of frames of a character's animation skeleton onto its body's rig: the body's
/// soles (from its mesh) stay on the floor where the animation's feet are. What the renderer
/// poses and `bake-motion` writes to glTF.
anim::FrameRetarget retargetOntoBody(const anim::Skeleton& animation, const scene::Character& body);

} // namespace thespis::core::scenario
