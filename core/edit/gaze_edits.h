#pragma once
// Gaze on the timeline (format 10): an action of a character's gaze layer turns its eyes, head
// and body toward a target while it lasts (scenario.h's GazeSpec; the Stage plays it).

#include <string>

#include "edit/scenario_edit.h"
#include "util/tick.h"

namespace thespis::core::edit {

/// The layer gaze actions go to when a character has none: "Gaze".
inline constexpr const char* kGazeLayer = "Gaze";

/// The action that looks at `gaze` from `start` for `seconds` (a time stretch of
/// scenario::kGazeActionSeconds gives it its length).
scenario::ActionSpec gazeAction(std::string name, scenario::GazeSpec gaze, Tick start, double seconds);

/// Adds that action, named after its target, to the character's "Gaze" layer (added when it has
/// none): one undo step. Errors: no such character, a negative start or a length not above 0,
/// the layer locked.
Result<Edit> addGaze(const scenario::Scenario& scenario, int character, scenario::GazeSpec gaze, Tick start,
                     double seconds);

} // namespace thespis::core::edit
