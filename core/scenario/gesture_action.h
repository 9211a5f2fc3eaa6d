#pragma once
// A gesture of a character's gesticon (scenario.h's Gesture) as the action that plays it: its
// clip over its body part (mask), faded in and out with the engine's cubic fade; with the
// dependent-joint filter on (paper §4.4), through the filter, and over the upper body the filter
// moves as well as the gesture's own part, so that the spine and neck follow the gesture.
// The studio's gesture preview plays it; speech-driven gestures will.

#include <string>

#include "scenario/scenario.h"
#include "util/tick.h"

namespace thespis::core::scenario {

/// The action of `gesture` from `start`. With the filter on and a mask, the mask it plays over is
/// added to `scenario` (named after the gesture) unless it is there already.
ActionSpec gestureAction(Scenario& scenario, const Gesture& gesture, Tick start);

} // namespace thespis::core::scenario
