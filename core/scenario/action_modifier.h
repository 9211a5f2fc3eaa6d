#pragma once
// One modifier of an action's chain (scenario.h's ModifierSpec) built over its source: the
// runtime wraps an action's clip in each of its modifiers in turn with it.

#include <functional>
#include <memory>

#include "anim/blendable.h"
#include "anim/skeleton.h"
#include "motion/posture_bases.h"
#include "scenario/scenario.h"
#include "util/error.h"

namespace thespis::core::scenario {

/// The scenario's posture bases, asked for only by a dependent-joint filter.
using PostureBasesSource = std::function<Result<std::shared_ptr<const motion::PostureBases>>()>;

/// `source` plays on `skeleton` (a body layer) or the MPEG-4 face layout (`kind` Face). Errors
/// say what is wrong with the spec, for the runtime to place.
Result<anim::BlendablePtr> applyModifier(anim::BlendablePtr source, const ModifierSpec& m, const anim::Skeleton& skeleton,
                                         LayerKind kind, const PostureBasesSource& bases);

} // namespace thespis::core::scenario
