#pragma once
// The body of a scenario character, for the renderer and the bake: its glTF model (path relative
// to the scenario's folder) or, without one, the built-in procedural humanoid bound to the
// character's H-Anim skeleton level; the scenario's segment tags applied. Errors name the
// character and the field ("characters[0].model: …").

#include <filesystem>

#include "scenario/asset_resolver.h"
#include "scenario/scenario.h"
#include "scene/character.h"
#include "util/error.h"

namespace thespis::core::scenario {

Result<scene::Character> loadCharacterBody(const Scenario& scenario, std::size_t characterIndex,
                                           const Assets& assets);

} // namespace thespis::core::scenario
