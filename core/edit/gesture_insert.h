#pragma once
// Planned gestures (speech/bml_plan.h) as timeline actions, the same for tagged text
// (edit::insertSpeech) and BML (edit::insertBml): the gesticon as the planner sees it, from the
// built runtime, and each planned gesture as its entry's action (mask, dependent-joint filter)
// with its clip fitted to the planned time and the plan's fades.

#include <map>
#include <string>

#include "edit/scenario_edit.h"
#include "scenario/scenario_runtime.h"
#include "speech/bml_plan.h"
#include "util/tick.h"

namespace thespis::core::edit {

/// `who`'s gestures as the planner sees them: each one's clip length from `built` (file and
/// inline clips alike), its fades, stroke and hold; a face gesture is one whose clip moves face
/// channels only. Refers to `who` and `built`, which must outlive it.
speech::BmlGesticon timelineGesticon(const scenario::Character& who, const scenario::CharacterRuntime& built);

/// The action of a planned gesture from `at`: `gesture`'s action with its clip fitted to the
/// planned time (stretched, or warped to keep its stroke) and the plan's fades, named
/// "ID GESTURE". Adds the widened mask of a filtered gesture to `after` when it has none.
Result<scenario::ActionSpec> plannedGestureAction(scenario::Scenario& after, const scenario::Gesture& gesture,
                                                  const std::string& id, const speech::BmlPlanned& planned, Tick at);

} // namespace thespis::core::edit
