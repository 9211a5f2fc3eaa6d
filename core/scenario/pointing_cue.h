#pragma once
// A body action's PointingSpec (format 11) read into what the Stage plays: its target and the
// arms that aim, each checked so that a wrong one names its field.

#include <span>
#include <vector>

#include "anim/blending_schedule.h"
#include "anim/skeleton.h"
#include "motion/gaze_target.h"
#include "motion/pointing.h"
#include "scenario/scenario.h"
#include "util/error.h"

namespace thespis::core::scenario {

/// A pointing body action that plays: from `start` to `end` (seconds) the character's `hand` aims
/// at `target` (Stage::point) as far as `weight` (the action's weight curve over that span) says.
struct PointingCue {
    double start = 0, end = 0;
    motion::GazeTarget target;
    motion::PointingHand hand = motion::PointingHand::Right;
    anim::Curve weight;
};

/// The cue of `pointing` on `skeleton` (start, end and weight left as they are). InvalidSchedule
/// naming the field ("pointing.target: the scenario has no character named "Ismene".") for a
/// target that does not read or names no character of `scenario`, a hand that does not read or
/// that the skeleton has no arm for.
Result<PointingCue> readPointingCue(const PointingSpec& pointing, const Scenario& scenario,
                                    const anim::Skeleton& skeleton);

/// Adds the cues of body layer `layer`'s pointing actions that `schedule` built (`ids`, per
/// action; 0 for one not built) to `cues`, kept in start order.
void addPointingCues(const Layer& layer, const anim::BlendingSchedule& schedule, std::span<const anim::ActionId> ids,
                     const Scenario& scenario, const anim::Skeleton& skeleton, std::vector<PointingCue>& cues);

} // namespace thespis::core::scenario
