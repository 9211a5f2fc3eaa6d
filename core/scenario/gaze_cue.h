#pragma once
// A gaze action's GazeSpec read into what the Stage plays (scenario_runtime.h's GazeCue): its
// target, influence and offset, each checked so that a wrong one names its field.

#include <span>
#include <vector>

#include "scenario/scenario_runtime.h"

namespace thespis::core::scenario {

/// `target` read as a gaze or pointing target of `scenario`. InvalidSchedule naming `field` for
/// one that does not read or names no character of the scenario.
Result<motion::GazeTarget> readStageTarget(const char* field, const std::string& target, const Scenario& scenario);

/// The cue of `gaze` (start and end left at 0). InvalidSchedule naming the field
/// ("gaze.target: the scenario has no character named "Ismene".") for a target that does not read
/// or names no character of `scenario`, an influence or an offset direction that does not read.
Result<GazeCue> readGazeCue(const GazeSpec& gaze, const Scenario& scenario);

/// Adds the cues of gaze layer `layer`'s actions that `schedule` built (`ids`, per action; 0 for
/// one not built) to `cues`, kept in start order.
void addGazeCues(const Layer& layer, const anim::BlendingSchedule& schedule, std::span<const anim::ActionId> ids,
                 const Scenario& scenario, std::vector<GazeCue>& cues);

/// What every gaze action plays: kGazeActionSeconds of the neutral face (never blended), which its
/// modifiers stretch to the action's length. Made once, shared.
anim::BlendablePtr gazeSpanClip();

} // namespace thespis::core::scenario
