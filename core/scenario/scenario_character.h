#pragma once
// The body of a scenario character, for the renderer and the bake: its glTF model (path relative
// to the scenario's folder) or, without one, the built-in procedural humanoid bound to the
// character's H-Anim skeleton level; the scenario's segment tags applied. Errors name the
// character and the field ("characters[0].model: …"). And how the character's animation
// skeleton drives that body's own rig.

#include <filesystem>

#include "anim/retarget.h"
#include "scenario/asset_resolver.h"
#include "scenario/scenario.h"
#include "scene/character.h"
#include "util/error.h"

namespace thespis::core::scenario {

Result<scene::Character> loadCharacterBody(const Scenario& scenario, std::size_t characterIndex,
                                           const Assets& assets);

/// The retarget of frames of a character's animation skeleton onto its body's rig: the body's
/// soles (from its mesh) stay on the floor where the animation's feet are. What the renderer
/// poses and `bake-motion` writes to glTF.
anim::FrameRetarget retargetOntoBody(const anim::Skeleton& animation, const scene::Character& body);

} // namespace thespis::core::scenario
