#pragma once
// The edits the studio and scripts make to a scenario: timeline (move, trim, fade, split,
// insert, delete with ripple, markers, layer mute / solo / lock), curves, joint masks, the
// gesticon, segment tags and bakes. Each function looks at the document as it is and returns the Edit
// that makes the change (apply it, or push it as one undoable command), or an error saying why
// the change cannot be made. None of them changes the document itself.
//
// Times are ticks; an action's extent comes from the runtime built from the same document
// (ActionSpan), because modifiers (loops, stretches, trims) decide how long an action plays.

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "anim/blendable.h"
#include "edit/scenario_edit.h"
#include "scenario/scenario.h"
#include "scenario/scenario_runtime.h"

namespace thespis::core::edit {

enum class Edge { Start, End };

/// Where an action plays on its layer.
struct ActionSpan {
    Tick start = 0;
    Tick end = 0;                 ///< start + duration; meaningless when openEnded
    bool openEnded = false;       ///< plays until cut off (a loop forever, a synthesizer)
    anim::TimeDomain source;      ///< the domain of the action's clip with its modifiers (seconds)
    /// The domain under the outermost Trim modifier (how far trimming can reach); `source` when
    /// the action has no trim.
    anim::TimeDomain untrimmed;
};

/// The span of the action at `path`, from `runtime` built from `scenario`; nullopt when the path
/// leads nowhere or the runtime does not match.
std::optional<ActionSpan> actionSpan(const scenario::Scenario& scenario, const scenario::ScenarioRuntime& runtime,
                                     const ActionPath& path);

// ---- Actions ---------------------------------------------------------------------------------

/// A new action playing `clip` of the character from `start`, faded in and out over 0.3 s
/// (cubic), named after the clip and unique in the layer; a clip read from a file (motion
/// capture) continues from where the layer's previous action leaves the body.
Result<scenario::ActionSpec> actionFromClip(const scenario::Scenario& scenario, const LayerPath& layer,
                                            const std::string& clip, Tick start);
/// Adds actions to a layer (names made unique in the layer: "wave", "wave 2", …).
Result<Edit> insertActions(const scenario::Scenario& scenario, const LayerPath& layer,
                           std::vector<scenario::ActionSpec> actions);
/// Moves actions in time by `delta` (the earliest cannot go before 0: the move stops there) and,
/// with `layerDelta`, to the layer that many places further down (up when negative) in their own
/// character. An action moved to another layer is removed from its layer and added at the end of
/// the target layer (as insertActions() adds), keeping its name unless the target layer already
/// has an action of that name ("wave" becomes "wave 2"). Refused when an action is not there or is
/// listed twice, a layer (source or target) is locked, a target layer is outside the character, or
/// a target layer is of another kind (a face action cannot go to a body layer).
Result<Edit> moveActions(const scenario::Scenario& scenario, std::span<const ActionPath> actions, Tick delta,
                         int layerDelta = 0);
/// Where moveActions(scenario, actions, delta, layerDelta) puts each of `actions` (same order): the
/// paths in the document after that edit. Empty when the move is refused.
std::vector<ActionPath> movedActionPaths(const scenario::Scenario& scenario, std::span<const ActionPath> actions,
                                         int layerDelta);
/// Moves one edge of an action to `time`, keeping its motion in place (NLE trimming: the start
/// edge cuts into the clip, the end edge shortens or lengthens it within the clip). Uses the
/// action's outermost Trim modifier, adding one when it has none. An action keeps at least
/// `minimumLength` ticks and cannot reach outside its clip.
Result<Edit> trimAction(const scenario::Scenario& scenario, const ActionPath& action, const ActionSpan& span,
                        Edge edge, Tick time, Tick minimumLength);
/// Sets the fade-in and / or fade-out of the action's weight curve (fades and ADSR envelopes; a
/// constant weight becomes a cubic fade at that level). Keyframed weights have no fades.
Result<Edit> setActionFades(const scenario::Scenario& scenario, const ActionPath& action,
                            std::optional<double> fadeInSeconds, std::optional<double> fadeOutSeconds);
/// Replaces the action's weight and / or scale curve (validated).
Result<Edit> setActionCurves(const scenario::Scenario& scenario, const ActionPath& action,
                             std::optional<anim::Curve> weight, std::optional<anim::Curve> scale);
/// Replaces the whole action (properties panel: name, clip, mask, mode…).
Result<Edit> replaceAction(const scenario::Scenario& scenario, const ActionPath& action, scenario::ActionSpec spec);
/// Cuts an action in two at `time` (strictly inside it). The first part keeps the fade-in, the
/// second the fade-out; keyframed curves of the second part are shifted to its own local time.
Result<Edit> splitAction(const scenario::Scenario& scenario, const ActionPath& action, const ActionSpan& span,
                         Tick time);
/// Removes actions. With `rippleWith`, later actions of each layer move earlier to close the gaps
/// left (by the length of the removed actions that ended before them).
Result<Edit> removeActions(const scenario::Scenario& scenario, std::span<const ActionPath> actions,
                           const scenario::ScenarioRuntime* rippleWith = nullptr);

// ---- Layers and markers ----------------------------------------------------------------------

enum class LayerFlag { Mute, Solo, Lock };
Result<Edit> setLayerFlag(const scenario::Scenario& scenario, const LayerPath& layer, LayerFlag flag, bool on);
/// Adds a marker, keeping markers ordered by time.
Result<Edit> addMarker(const scenario::Scenario& scenario, scenario::Marker marker);
Result<Edit> moveMarker(const scenario::Scenario& scenario, int index, Tick time);
Result<Edit> removeMarker(const scenario::Scenario& scenario, int index);

// ---- Masks -----------------------------------------------------------------------------------

/// Replaces the weights of mask `index` (validated: every weight in [0, 1]).
Result<Edit> setMask(const scenario::Scenario& scenario, int index, anim::JointMask mask);
/// Sets the weight of some joints of mask `index`, leaving the others as they are.
Result<Edit> setMaskWeights(const scenario::Scenario& scenario, int index, std::span<const std::string> joints,
                            float weight);
Result<Edit> addMask(const scenario::Scenario& scenario, std::string name, anim::JointMask mask);
/// Renames a mask and every action and gesture that uses it.
Result<Edit> renameMask(const scenario::Scenario& scenario, int index, const std::string& name);
/// Removes a mask no action or gesture uses (the error names those that do).
Result<Edit> removeMask(const scenario::Scenario& scenario, int index);

// ---- Gesticon and segments -------------------------------------------------------------------

Result<Edit> addGesture(const scenario::Scenario& scenario, int character, scenario::Gesture gesture);
/// Replaces a gesture (validated as addGesture: a unique name, a clip of the character, a mask
/// of the scenario). Renamed, it keeps the BML lexemes it played: the rows of the character's own
/// lexicon that name it, or, for a character on the defaults, the defaults' (it then gets its
/// own table, as edit::setBmlLexeme gives).
Result<Edit> replaceGesture(const scenario::Scenario& scenario, const CharacterItemPath& gesture,
                            scenario::Gesture value);
Result<Edit> removeGesture(const scenario::Scenario& scenario, const CharacterItemPath& gesture);
/// Sets the receiver / occluder and posture tags of one character's segments.
Result<Edit> setSegmentTags(const scenario::Scenario& scenario, int character, std::vector<scene::SegmentTag> tags);
/// Sets the bake file of a character (a path relative to the scenario's folder, as the bake
/// panel writes it; empty: no bake, unshadowed transfer).
Result<Edit> setCharacterBake(const scenario::Scenario& scenario, int character, std::string path);

/// `base`, or "base 2", "base 3"… the first not in `taken`.
std::string uniqueName(const std::string& base, std::span<const std::string> taken);

} // namespace thespis::core::edit
