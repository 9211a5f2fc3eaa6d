#pragma once
// The edits of how a scenario plays over tracked video (its ArSpec, format 5): where its world
// sits on the tracked target (offset on the target's plane, heading about its normal, scale), the
// phantom occluders and the shadow catcher. As content_edits.h: each looks at the document as it
// is and returns the Edit that makes the change (apply it, or push it as one undoable command;
// successive placement edits merge into one step when pushed with the same merge key), or an
// error saying why it cannot be made.

#include <array>

#include "edit/scenario_edit.h"
#include "scenario/scenario.h"

namespace thespis::core::edit {

/// Moves, turns and scales the world on the target, keeping the occluders and the shadow
/// catcher. Rules: offset (metres) and heading (degrees) finite; scale finite, above 0 and at
/// most 1000.
Result<Edit> setArPlacement(const scenario::Scenario& scenario, std::array<double, 2> offset, double heading,
                            double scale);
/// Turns the shadow catcher (the characters' soft shadows on the real ground) on or off.
Result<Edit> setArShadowCatcher(const scenario::Scenario& scenario, bool on);
/// Replaces the whole AR section (placement as setArPlacement; each occluder with a finite
/// position and heading, sizes above 0, and a model file when it is a model).
Result<Edit> setArSpec(const scenario::Scenario& scenario, scenario::ArSpec spec);

} // namespace thespis::core::edit
