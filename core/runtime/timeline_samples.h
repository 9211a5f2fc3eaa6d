#pragma once
// The one sweep over a scenario's timeline: every character's authored motion sampled from 0 to
// the runtime's duration, as a stage of its own plays it (live actions are not in it, and the
// stage that plays live is not touched). Views that frame the whole scenario — the 3D view's
// camera, the stick figures' box, the CLI's render — measure these poses.

#include <vector>

#include "runtime/pose_set.h"
#include "scenario/scenario_runtime.h"

namespace thespis::core::runtime {

/// Poses every `step` seconds over [0, duration], the end included.
std::vector<PoseSet> sampleTimeline(const scenario::ScenarioRuntime& runtime, double step = 0.1);

} // namespace thespis::core::runtime
