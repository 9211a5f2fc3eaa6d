#pragma once
// A gesture of a character's gesticon (scenario.h's Gesture) as the action that plays it: its
// clip over its body part (mask), faded in and out with the engine's cubic fade; with the
// dependent-joint filter on (paper §4.4), through the filter, and over the upper body the filter
// moves as well as the gesture's own part, so that the spine and neck follow the gesture.
// The runtime builds every gesture this way into the Stage's library (a script activates it by
// name, the studio's gesture preview plays it live); speech-driven gestures will.

#include <optional>
#include <string>

#include "scenario/scenario.h"
#include "util/tick.h"

namespace thespis::core::scenario {

/// The action of a gesture and, with the filter on and a mask, the widened mask it plays over
/// (its part plus the upper body, named after the part) when the scenario has no mask of that
/// name yet.
struct GestureSpec {
    ActionSpec action;
    std::optional<NamedMask> widenedMask;
};
GestureSpec gestureSpec(const Scenario& scenario, const Gesture& gesture, Tick start);

/// The action of `gesture` from `start`, with its widened mask added to `scenario` when it needs
/// one (an action of the document plays it).
ActionSpec gestureAction(Scenario& scenario, const Gesture& gesture, Tick start);

} // namespace thespis::core::scenario
