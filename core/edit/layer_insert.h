#pragma once
// What edits that put generated actions on a character's timeline share (speech_edits.cpp,
// bml_edits.cpp): steps applied to the document as it grows, layers found or added by name, and
// a clip stretched to a length.

#include <string>

#include "anim/blending_params.h"
#include "edit/scenario_edit.h"

namespace thespis::core::edit {

/// Applies `step` to `after`: later steps are made for the document as the earlier ones leave it.
Result<void> take(Result<Edit> step, scenario::Scenario& after);

/// The character's layer of that name and kind, added (with `mode`) when it has none. Error: the
/// layer is locked.
Result<LayerPath> layerNamed(scenario::Scenario& after, int character, const std::string& name,
                             scenario::LayerKind kind, anim::BlendMode mode);

/// A time stretch that makes `clipSeconds` last `seconds`.
scenario::ModifierSpec stretchTo(double seconds, double clipSeconds);

/// The edit of `before` into `after` for `character` alone: the masks `after` added, then the
/// character — what the steps applied to `after` amount to, as one change.
Edit characterEdit(const scenario::Scenario& before, const scenario::Scenario& after, int character);

} // namespace thespis::core::edit
