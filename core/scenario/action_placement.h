#pragma once
// Where each action of a body layer plays (ActionSpec::placement), for the runtime builder.

#include <optional>
#include <vector>

#include "anim/blending_schedule.h"
#include "scenario/scenario.h"

namespace thespis::core::scenario {

/// In start order, moves each built action of `layer` (`actions`, per ActionSpec; empty for one not
/// built) that starts at the character's place (and heading) or where the layer's previous action
/// leaves the body at its start, on the floor, so that its first frame's root stands there.
void placeActions(const Layer& layer, std::vector<std::optional<anim::BlendingAction>>& actions);

} // namespace thespis::core::scenario
