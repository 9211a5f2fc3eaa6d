#include "edit/document_edits.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>
#include <set>

#include "anim/modifiers.h"
#include "edit/lexicon_edits.h"
#include "util/text.h"

namespace thespis::core::edit {

using namespace scenario;

namespace {

Error invalid(std::string message)
{
    return makeError(ErrorCode::InvalidArgument, std::move(message));
}


const Layer* layerAt(const Scenario& s, const LayerPath& p)
{
    if (p.character < 0 || std::size_t(p.character) >= s.characters.size())
        return nullptr;
    const Character& c = s.characters[std::size_t(p.character)];
    return p.layer >= 0 && std::size_t(p.layer) < c.layers.size() ? &c.layers[std::size_t(p.layer)] : nullptr;
}

const ActionSpec* actionAt(const Scenario& s, const ActionPath& p)
{
    const Layer* layer = layerAt(s, p.layerPath());
    return layer && p.action >= 0 && std::size_t(p.action) < layer->actions.size()
               ? &layer->actions[std::size_t(p.action)]
               : nullptr;
}

Result<const ActionSpec*> requireAction(const Scenario& s, const ActionPath& p)
{
    const ActionSpec* action = actionAt(s, p);
    if (!action)
        return invalid("There is no action at character " + std::to_string(p.character) + ", layer "
                       + std::to_string(p.layer) + ", index " + std::to_string(p.action) + ".");
    return action;
}

Edit replaceActionEdit(const ActionPath& p, const ActionSpec& before, ActionSpec after)
{
    return Edit(ActionChange{p, before, std::move(after)});
}

// A curve with its fades set; nullopt keeps that side. Errors for curves without fades.
Result<anim::Curve> withFades(const anim::Curve& curve, std::optional<double> fadeIn, std::optional<double> fadeOut)
{
    const anim::EnvelopeParams& e = curve.envelope();
    const double in = fadeIn.value_or(e.attack), out = fadeOut.value_or(e.release);
    if (!std::isfinite(in) || !std::isfinite(out) || in < 0 || out < 0)
        return invalid("Fade times must be zero or more seconds.");
    switch (curve.kind()) {
    case anim::CurveKind::Constant:
        return anim::Curve::cubicFade(fadeIn.value_or(0), fadeOut.value_or(0), curve.constantValue());
    case anim::CurveKind::LinearFade: return anim::Curve::linearFade(in, out, e.peak);
    case anim::CurveKind::CubicFade: return anim::Curve::cubicFade(in, out, e.peak);
    case anim::CurveKind::LinearAdsr: return anim::Curve::linearAdsr(in, e.decay, e.sustain, out, e.peak);
    case anim::CurveKind::CubicAdsr: return anim::Curve::cubicAdsr(in, e.decay, e.sustain, out, e.peak);
    case anim::CurveKind::Keyframed:
        return invalid("A keyframed weight curve has no fade handles: move its keys in the curve editor.");
    case anim::CurveKind::Dominance: break;
    }
    return invalid("A dominance weight curve has no fade handles: it rises and falls over the whole action.");
}

// A keyframed curve's keys moved `seconds` earlier (for the second part of a split).
anim::Curve shiftedKeys(const anim::Curve& curve, double seconds)
{
    if (curve.kind() != anim::CurveKind::Keyframed)
        return curve;
    std::vector<anim::CurveKey> keys = curve.keys();
    for (anim::CurveKey& key : keys)
        key.time -= seconds;
    auto shifted = anim::Curve::keyframed(std::move(keys));
    return shifted ? *shifted : curve; // same spacing as before, so it cannot fail
}

std::vector<std::string> actionNames(const Layer& layer)
{
    std::vector<std::string> names;
    for (const ActionSpec& a : layer.actions)
        names.push_back(a.name);
    return names;
}

// The outermost Trim of an action's modifier chain, added when missing (covering `source`).
ModifierSpec& outerTrim(ActionSpec& action, const anim::TimeDomain& source)
{
    if (action.modifiers.empty() || action.modifiers.back().kind != ModifierKind::Trim) {
        ModifierSpec trim;
        trim.kind = ModifierKind::Trim;
        trim.start = source.start;
        trim.end = source.end;
        action.modifiers.push_back(trim);
    }
    return action.modifiers.back();
}

} // namespace

std::optional<ActionSpan> actionSpan(const Scenario& scenario, const ScenarioRuntime& runtime, const ActionPath& path)
{
    const ActionSpec* spec = actionAt(scenario, path);
    if (!spec || std::size_t(path.character) >= runtime.characters.size())
        return std::nullopt;
    const CharacterRuntime& character = runtime.characters[std::size_t(path.character)];
    if (character.name != scenario.characters[std::size_t(path.character)].name
        || std::size_t(path.layer) >= character.layers.size()
        || std::size_t(path.action) >= character.actionIds[std::size_t(path.layer)].size())
        return std::nullopt;
    const anim::BlendingAction* action =
        character.layers[std::size_t(path.layer)]->action(character.actionIds[std::size_t(path.layer)][std::size_t(path.action)]);
    if (!action || !action->source)
        return std::nullopt;
    ActionSpan span;
    span.start = spec->start;
    span.source = action->source->domain();
    span.untrimmed = span.source;
    if (const auto* trim = dynamic_cast<const anim::Trim*>(action->source.get()))
        span.untrimmed = trim->source()->domain();
    span.openEnded = span.source.openEnded();
    span.end = span.openEnded ? std::numeric_limits<Tick>::max() : spec->start + secondsToTicks(span.source.duration());
    return span;
}

std::string uniqueName(const std::string& base, std::span<const std::string> taken)
{
    const std::set<std::string> used(taken.begin(), taken.end());
    if (!used.count(base))
        return base;
    for (int n = 2;; ++n)
        if (std::string name = base + " " + std::to_string(n); !used.count(name))
            return name;
}

Result<ActionSpec> actionFromClip(const Scenario& scenario, const LayerPath& layerPath, const std::string& clip,
                                  Tick start)
{
    const Layer* layer = layerAt(scenario, layerPath);
    if (!layer)
        return invalid("There is no such layer to put the action on.");
    const Character& character = scenario.characters[std::size_t(layerPath.character)];
    if (!character.findClip(clip))
        return invalid("Character " + inQuotes(character.name) + " has no clip named " + inQuotes(clip) + ".");
    ActionSpec action;
    action.clip = clip;
    action.name = clip;
    action.start = std::max<Tick>(0, start);
    action.weight = anim::Curve::cubicFade(0.3, 0.3);
    // Motion capture goes on from where the layer's previous action leaves the body (or from
    // where the character stands); inline clips are made for where they play.
    if (!character.findClip(clip)->file.empty())
        action.placement = Placement::Continue;
    return action;
}

Result<Edit> insertActions(const Scenario& scenario, const LayerPath& layerPath, std::vector<ActionSpec> actions)
{
    const Layer* layer = layerAt(scenario, layerPath);
    if (!layer)
        return invalid("There is no such layer to put the actions on.");
    if (layer->lock)
        return invalid("Layer " + inQuotes(layer->name) + " is locked.");
    std::vector<std::string> names = actionNames(*layer);
    Edit edit;
    int index = int(layer->actions.size());
    for (ActionSpec& action : actions) {
        action.name = uniqueName(action.name.empty() ? action.clip : action.name, names);
        names.push_back(action.name);
        edit.add(ActionChange{{layerPath.character, layerPath.layer, index++}, std::nullopt, std::move(action)});
    }
    return edit;
}

namespace {

// moveActions()'s edit and where each action lands (in the order given).
struct PlannedMove {
    Edit edit;
    std::vector<ActionPath> landed;
};

Result<PlannedMove> planMove(const Scenario& scenario, std::span<const ActionPath> paths, Tick delta, int layerDelta)
{
    Tick earliest = std::numeric_limits<Tick>::max();
    std::set<ActionPath> moving;
    for (const ActionPath& p : paths) {
        auto action = requireAction(scenario, p);
        if (!action)
            return action.error();
        const std::string& name = (*action)->name;
        if (!moving.insert(p).second)
            return invalid("Action " + inQuotes(name) + " is listed twice in the move.");
        const Layer& from = *layerAt(scenario, p.layerPath());
        if (from.lock)
            return invalid("Layer " + inQuotes(from.name) + " is locked.");
        if (layerDelta != 0) {
            const Layer* to = layerAt(scenario, {p.character, p.layer + layerDelta});
            if (!to) {
                const Character& character = scenario.characters[std::size_t(p.character)];
                return invalid("Action " + inQuotes(name) + " cannot move " + std::to_string(std::abs(layerDelta))
                               + (std::abs(layerDelta) == 1 ? " layer " : " layers ") + (layerDelta > 0 ? "down" : "up")
                               + ": character " + inQuotes(character.name) + " has no layer there.");
            }
            if (to->lock)
                return invalid("Layer " + inQuotes(to->name) + " is locked.");
            if (to->kind != from.kind)
                return invalid("Action " + inQuotes(name) + " is a " + layerKindName(from.kind) + " action: it cannot go to "
                               + layerKindName(to->kind) + " layer " + inQuotes(to->name) + ".");
        }
        earliest = std::min(earliest, (*action)->start);
    }
    PlannedMove plan;
    if (paths.empty())
        return plan;
    delta = std::max(delta, -earliest);
    if (layerDelta == 0) {
        for (const ActionPath& p : paths) {
            const ActionSpec& before = *actionAt(scenario, p);
            ActionSpec after = before;
            after.start += delta;
            plan.edit.add(ActionChange{p, before, std::move(after)});
        }
        plan.landed.assign(paths.begin(), paths.end());
        return plan;
    }
    // Removals first, highest index first (each leaves the indices of the next ones valid); then
    // the actions are added at the end of their target layers, in the order given.
    for (auto it = moving.rbegin(); it != moving.rend(); ++it)
        plan.edit.add(ActionChange{*it, *actionAt(scenario, *it), std::nullopt});
    std::map<LayerPath, std::vector<std::string>> names; // per target layer: the names it will hold
    std::map<LayerPath, int> sizes;
    for (const ActionPath& p : paths) {
        const LayerPath to{p.character, p.layer + layerDelta};
        if (!sizes.count(to)) {
            const Layer& target = *layerAt(scenario, to);
            int kept = 0;
            for (int a = 0; a < int(target.actions.size()); ++a)
                if (!moving.count({to.character, to.layer, a})) {
                    names[to].push_back(target.actions[std::size_t(a)].name);
                    ++kept;
                }
            sizes[to] = kept;
        }
        ActionSpec after = *actionAt(scenario, p);
        after.start += delta;
        after.name = uniqueName(after.name, names[to]);
        names[to].push_back(after.name);
        const ActionPath at{to.character, to.layer, sizes[to]++};
        plan.landed.push_back(at);
        plan.edit.add(ActionChange{at, std::nullopt, std::move(after)});
    }
    return plan;
}

} // namespace

Result<Edit> moveActions(const Scenario& scenario, std::span<const ActionPath> paths, Tick delta, int layerDelta)
{
    auto plan = planMove(scenario, paths, delta, layerDelta);
    if (!plan)
        return plan.error();
    return std::move(plan->edit);
}

std::vector<ActionPath> movedActionPaths(const Scenario& scenario, std::span<const ActionPath> paths, int layerDelta)
{
    auto plan = planMove(scenario, paths, 0, layerDelta);
    return plan ? std::move(plan->landed) : std::vector<ActionPath>{};
}

Result<Edit> trimAction(const Scenario& scenario, const ActionPath& path, const ActionSpan& span, Edge edge, Tick time,
                        Tick minimumLength)
{
    auto found = requireAction(scenario, path);
    if (!found)
        return found.error();
    if (layerAt(scenario, path.layerPath())->lock)
        return invalid("Layer " + inQuotes(layerAt(scenario, path.layerPath())->name) + " is locked.");
    const ActionSpec& before = **found;
    ActionSpec after = before;
    ModifierSpec& trim = outerTrim(after, span.source);
    const double minimum = ticksToSeconds(std::max<Tick>(1, minimumLength));
    const double elapsed = ticksToSeconds(time - before.start); // the edge's new local time
    if (edge == Edge::Start) {
        if (!std::isfinite(trim.end))
            return invalid("An open-ended action's start cannot be trimmed before its end is.");
        // Local time 0 shows source time trim.start: the start edge moves both by the same
        // amount, so the motion stays where it was on the timeline. It cannot pass the clip's
        // first frame, the timeline's start, or come nearer than `minimum` to the end.
        const double lowest = std::max(span.untrimmed.start, trim.start - ticksToSeconds(before.start));
        const double newStart = std::clamp(trim.start + elapsed, lowest, trim.end - minimum);
        const Tick delta = secondsToTicks(newStart - trim.start);
        trim.start += ticksToSeconds(delta);
        after.start = before.start + delta;
    } else {
        trim.end = std::clamp(trim.start + elapsed, trim.start + minimum,
                              std::max(span.untrimmed.end, trim.start + minimum));
    }
    if (!(trim.start < trim.end))
        return invalid("The action would have no length left.");
    if (after == before)
        return Edit{};
    return replaceActionEdit(path, before, std::move(after));
}

Result<Edit> setActionFades(const Scenario& scenario, const ActionPath& path, std::optional<double> fadeIn,
                            std::optional<double> fadeOut)
{
    auto found = requireAction(scenario, path);
    if (!found)
        return found.error();
    auto weight = withFades((*found)->weight, fadeIn, fadeOut);
    if (!weight)
        return weight.error();
    return setActionCurves(scenario, path, std::move(weight).value(), std::nullopt);
}

Result<Edit> setActionCurves(const Scenario& scenario, const ActionPath& path, std::optional<anim::Curve> weight,
                             std::optional<anim::Curve> scale)
{
    auto found = requireAction(scenario, path);
    if (!found)
        return found.error();
    if (layerAt(scenario, path.layerPath())->lock)
        return invalid("Layer " + inQuotes(layerAt(scenario, path.layerPath())->name) + " is locked.");
    ActionSpec after = **found;
    if (weight) {
        if (auto ok = weight->validate(); !ok)
            return makeError(ok.error().code, "Weight curve: " + ok.error().message);
        after.weight = std::move(*weight);
    }
    if (scale) {
        if (auto ok = scale->validate(); !ok)
            return makeError(ok.error().code, "Scale curve: " + ok.error().message);
        after.scale = std::move(*scale);
    }
    return replaceActionEdit(path, **found, std::move(after));
}

Result<Edit> replaceAction(const Scenario& scenario, const ActionPath& path, ActionSpec spec)
{
    auto found = requireAction(scenario, path);
    if (!found)
        return found.error();
    const Layer& layer = *layerAt(scenario, path.layerPath());
    if (layer.lock)
        return invalid("Layer " + inQuotes(layer.name) + " is locked.");
    if (spec.name.empty())
        return invalid("An action needs a name.");
    if (layer.kind == LayerKind::Gaze) {
        if (!spec.gaze || spec.gaze->target.empty())
            return invalid("An action of a gaze layer needs a target to look at.");
    } else if (!scenario.characters[std::size_t(path.character)].findClip(spec.clip)) {
        return invalid("The character has no clip named " + inQuotes(spec.clip) + ".");
    }
    if (!spec.mask.empty() && !scenario.findMask(spec.mask))
        return invalid("The scenario has no mask named " + inQuotes(spec.mask) + ".");
    return replaceActionEdit(path, **found, std::move(spec));
}

Result<Edit> splitAction(const Scenario& scenario, const ActionPath& path, const ActionSpan& span, Tick time)
{
    auto found = requireAction(scenario, path);
    if (!found)
        return found.error();
    const ActionSpec& original = **found;
    const Layer& layer = *layerAt(scenario, path.layerPath());
    if (layer.lock)
        return invalid("Layer " + inQuotes(layer.name) + " is locked.");
    if (time <= span.start || (!span.openEnded && time >= span.end))
        return invalid("The split point must lie inside the action.");
    const double cut = ticksToSeconds(time - span.start);

    ActionSpec first = original;
    ModifierSpec& firstTrim = outerTrim(first, span.source);
    const double sourceCut = firstTrim.start + cut;
    ActionSpec second = first;
    firstTrim.end = sourceCut;
    ModifierSpec& secondTrim = second.modifiers.back();
    secondTrim.start = sourceCut;
    second.start = time;
    if (auto w = withFades(first.weight, std::nullopt, 0.0))
        first.weight = *w;
    if (auto w = withFades(second.weight, 0.0, std::nullopt))
        second.weight = *w;
    second.weight = shiftedKeys(second.weight, cut);
    second.scale = shiftedKeys(second.scale, cut);
    std::vector<std::string> names = actionNames(layer);
    second.name = uniqueName(original.name, names);

    Edit edit(ActionChange{path, original, std::move(first)});
    edit.add(ActionChange{{path.character, path.layer, int(layer.actions.size())}, std::nullopt, std::move(second)});
    return edit;
}

Result<Edit> removeActions(const Scenario& scenario, std::span<const ActionPath> paths, const ScenarioRuntime* rippleWith)
{
    std::set<ActionPath> removed;
    for (const ActionPath& p : paths) {
        if (auto found = requireAction(scenario, p); !found)
            return found.error();
        if (layerAt(scenario, p.layerPath())->lock)
            return invalid("Layer " + inQuotes(layerAt(scenario, p.layerPath())->name) + " is locked.");
        removed.insert(p);
    }
    Edit edit;
    if (rippleWith) {
        // Per layer: the removed spans, then every kept action after them moves left by the
        // length of those that ended at or before its start.
        std::map<LayerPath, std::vector<ActionSpan>> gaps;
        for (const ActionPath& p : removed) {
            auto span = actionSpan(scenario, *rippleWith, p);
            if (!span)
                return invalid("The timeline is out of date; try again.");
            if (!span->openEnded)
                gaps[p.layerPath()].push_back(*span);
        }
        for (const auto& [layerPath, spans] : gaps) {
            const Layer& layer = *layerAt(scenario, layerPath);
            for (int a = 0; a < int(layer.actions.size()); ++a) {
                const ActionPath p{layerPath.character, layerPath.layer, a};
                if (removed.count(p))
                    continue;
                const ActionSpec& action = layer.actions[std::size_t(a)];
                Tick shift = 0;
                for (const ActionSpan& gap : spans)
                    if (gap.end <= action.start)
                        shift += gap.end - gap.start;
                if (shift > 0) {
                    ActionSpec after = action;
                    after.start = std::max<Tick>(0, action.start - shift);
                    edit.add(ActionChange{p, action, std::move(after)});
                }
            }
        }
    }
    // Highest index first, so that each removal leaves the indices of the next ones valid.
    for (auto it = removed.rbegin(); it != removed.rend(); ++it)
        edit.add(ActionChange{*it, *actionAt(scenario, *it), std::nullopt});
    return edit;
}

Result<Edit> setLayerFlag(const Scenario& scenario, const LayerPath& path, LayerFlag flag, bool on)
{
    const Layer* layer = layerAt(scenario, path);
    if (!layer)
        return invalid("There is no such layer.");
    Layer after = *layer;
    (flag == LayerFlag::Mute ? after.mute : flag == LayerFlag::Solo ? after.solo : after.lock) = on;
    return Edit(LayerChange{path, *layer, std::move(after)});
}

Result<Edit> addMarker(const Scenario& scenario, Marker marker)
{
    if (marker.time < 0)
        return invalid("A marker cannot lie before the start of the timeline.");
    const auto at = std::upper_bound(scenario.markers.begin(), scenario.markers.end(), marker.time,
                                     [](Tick t, const Marker& m) { return t < m.time; });
    return Edit(MarkerChange{int(at - scenario.markers.begin()), std::nullopt, std::move(marker)});
}

Result<Edit> moveMarker(const Scenario& scenario, int index, Tick time)
{
    if (index < 0 || std::size_t(index) >= scenario.markers.size())
        return invalid("There is no marker " + std::to_string(index) + ".");
    const Marker& before = scenario.markers[std::size_t(index)];
    Marker after = before;
    after.time = std::max<Tick>(0, time);
    return Edit(MarkerChange{index, before, std::move(after)});
}

Result<Edit> removeMarker(const Scenario& scenario, int index)
{
    if (index < 0 || std::size_t(index) >= scenario.markers.size())
        return invalid("There is no marker " + std::to_string(index) + ".");
    return Edit(MarkerChange{index, scenario.markers[std::size_t(index)], std::nullopt});
}

Result<Edit> setMask(const Scenario& scenario, int index, anim::JointMask mask)
{
    if (index < 0 || std::size_t(index) >= scenario.masks.size())
        return invalid("There is no mask " + std::to_string(index) + ".");
    if (auto ok = mask.validate(); !ok)
        return ok.error();
    const NamedMask& before = scenario.masks[std::size_t(index)];
    NamedMask after = before;
    after.mask = std::move(mask);
    return Edit(MaskChange{index, before, std::move(after)});
}

Result<Edit> setMaskWeights(const Scenario& scenario, int index, std::span<const std::string> joints, float weight)
{
    if (index < 0 || std::size_t(index) >= scenario.masks.size())
        return invalid("There is no mask " + std::to_string(index) + ".");
    anim::JointMask mask = scenario.masks[std::size_t(index)].mask;
    for (const std::string& joint : joints)
        mask.setWeight(joint, weight);
    return setMask(scenario, index, std::move(mask));
}

Result<Edit> addMask(const Scenario& scenario, std::string name, anim::JointMask mask)
{
    if (name.empty())
        return invalid("A mask needs a name.");
    if (scenario.findMask(name))
        return invalid("There is already a mask named " + inQuotes(name) + ".");
    if (auto ok = mask.validate(); !ok)
        return ok.error();
    NamedMask named;
    named.name = std::move(name);
    named.mask = std::move(mask);
    return Edit(MaskChange{int(scenario.masks.size()), std::nullopt, std::move(named)});
}

Result<Edit> renameMask(const Scenario& scenario, int index, const std::string& name)
{
    if (index < 0 || std::size_t(index) >= scenario.masks.size())
        return invalid("There is no mask " + std::to_string(index) + ".");
    const NamedMask& before = scenario.masks[std::size_t(index)];
    if (name.empty())
        return invalid("A mask needs a name.");
    if (name == before.name)
        return Edit{};
    if (scenario.findMask(name))
        return invalid("There is already a mask named " + inQuotes(name) + ".");
    NamedMask renamed = before;
    renamed.name = name;
    Edit edit(MaskChange{index, before, std::move(renamed)});
    for (int c = 0; c < int(scenario.characters.size()); ++c) {
        const Character& character = scenario.characters[std::size_t(c)];
        for (int l = 0; l < int(character.layers.size()); ++l)
            for (int a = 0; a < int(character.layers[std::size_t(l)].actions.size()); ++a) {
                const ActionSpec& action = character.layers[std::size_t(l)].actions[std::size_t(a)];
                if (action.mask == before.name) {
                    ActionSpec after = action;
                    after.mask = name;
                    edit.add(ActionChange{{c, l, a}, action, std::move(after)});
                }
            }
        for (int g = 0; g < int(character.gestures.size()); ++g)
            if (character.gestures[std::size_t(g)].mask == before.name) {
                Gesture after = character.gestures[std::size_t(g)];
                after.mask = name;
                edit.add(GestureChange{{c, g}, character.gestures[std::size_t(g)], std::move(after)});
            }
    }
    return edit;
}

Result<Edit> removeMask(const Scenario& scenario, int index)
{
    if (index < 0 || std::size_t(index) >= scenario.masks.size())
        return invalid("There is no mask " + std::to_string(index) + ".");
    const std::string& name = scenario.masks[std::size_t(index)].name;
    std::vector<std::string> users;
    for (const Character& character : scenario.characters) {
        for (const Layer& layer : character.layers)
            for (const ActionSpec& action : layer.actions)
                if (action.mask == name)
                    users.push_back("action " + inQuotes(action.name));
        for (const Gesture& gesture : character.gestures)
            if (gesture.mask == name)
                users.push_back("gesture " + inQuotes(gesture.name));
    }
    if (!users.empty()) {
        std::string list;
        for (std::size_t i = 0; i < users.size() && i < 5; ++i)
            list += (i ? ", " : "") + users[i];
        if (users.size() > 5)
            list += " and " + std::to_string(users.size() - 5) + " more";
        return invalid("Mask " + inQuotes(name) + " is still used by " + list + ".");
    }
    return Edit(MaskChange{index, scenario.masks[std::size_t(index)], std::nullopt});
}

namespace {

Result<void> checkGesture(const Scenario& scenario, int characterIndex, const Gesture& gesture, int replacing)
{
    const Character& character = scenario.characters[std::size_t(characterIndex)];
    if (gesture.name.empty())
        return invalid("A gesture needs a name.");
    for (int g = 0; g < int(character.gestures.size()); ++g)
        if (g != replacing && character.gestures[std::size_t(g)].name == gesture.name)
            return invalid("Character " + inQuotes(character.name) + " already has a gesture named " + inQuotes(gesture.name) + ".");
    if (!character.findClip(gesture.clip))
        return invalid("Character " + inQuotes(character.name) + " has no clip named " + inQuotes(gesture.clip) + ".");
    if (!gesture.mask.empty() && !scenario.findMask(gesture.mask))
        return invalid("The scenario has no mask named " + inQuotes(gesture.mask) + ".");
    if (gesture.fadeIn < 0 || gesture.fadeOut < 0)
        return invalid("Fade times must not be negative.");
    if (gesture.filterFadeFrom < 1 || gesture.filterMuteAbove > 78 || gesture.filterMuteAbove < gesture.filterFadeFrom)
        return invalid("The dependent-joint filter's band must be two PC numbers from 1 to 78, the second not below the "
                       "first (found " + std::to_string(gesture.filterFadeFrom) + "–" +
                       std::to_string(gesture.filterMuteAbove) + ").");
    return {};
}

bool validCharacter(const Scenario& scenario, int character)
{
    return character >= 0 && std::size_t(character) < scenario.characters.size();
}

} // namespace

Result<Edit> addGesture(const Scenario& scenario, int character, Gesture gesture)
{
    if (!validCharacter(scenario, character))
        return invalid("There is no character " + std::to_string(character) + ".");
    if (auto ok = checkGesture(scenario, character, gesture, -1); !ok)
        return ok.error();
    const int index = int(scenario.characters[std::size_t(character)].gestures.size());
    return Edit(GestureChange{{character, index}, std::nullopt, std::move(gesture)});
}

Result<Edit> replaceGesture(const Scenario& scenario, const CharacterItemPath& path, Gesture value)
{
    if (!validCharacter(scenario, path.character)
        || path.index < 0 || std::size_t(path.index) >= scenario.characters[std::size_t(path.character)].gestures.size())
        return invalid("There is no such gesture.");
    if (auto ok = checkGesture(scenario, path.character, value, path.index); !ok)
        return ok.error();
    const Character& who = scenario.characters[std::size_t(path.character)];
    const Gesture& before = who.gestures[std::size_t(path.index)];
    Edit edit(GestureChange{path, before, value});
    // A renamed gesture keeps the lexemes it played: the character's own rows, or the defaults'
    // (it then gets its own table, as when a row is set).
    if (before.name != value.name) {
        auto rows = who.bmlLexicon ? *who.bmlLexicon : bmlLexiconRows(who);
        bool renamed = false;
        for (auto& [lexeme, entry] : rows)
            if (entry == before.name) {
                entry = value.name;
                renamed = true;
            }
        if (renamed)
            edit.add(BmlLexiconChange{path.character, who.bmlLexicon, std::move(rows)});
    }
    return edit;
}

Result<Edit> removeGesture(const Scenario& scenario, const CharacterItemPath& path)
{
    if (!validCharacter(scenario, path.character)
        || path.index < 0 || std::size_t(path.index) >= scenario.characters[std::size_t(path.character)].gestures.size())
        return invalid("There is no such gesture.");
    return Edit(GestureChange{path, scenario.characters[std::size_t(path.character)].gestures[std::size_t(path.index)],
                              std::nullopt});
}

Result<Edit> setSegmentTags(const Scenario& scenario, int character, std::vector<scene::SegmentTag> tags)
{
    if (!validCharacter(scenario, character))
        return invalid("There is no character " + std::to_string(character) + ".");
    std::set<std::string> names;
    for (const scene::SegmentTag& tag : tags)
        if (tag.segment.empty() || !names.insert(tag.segment).second)
            return invalid("Segment tags need distinct, non-empty segment names (" + inQuotes(tag.segment) + ").");
    return Edit(SegmentTagsChange{character, scenario.characters[std::size_t(character)].segmentTags, std::move(tags)});
}

Result<Edit> setCharacterBake(const Scenario& scenario, int character, std::string path)
{
    if (!validCharacter(scenario, character))
        return invalid("There is no character " + std::to_string(character) + ".");
    return Edit(CharacterBakeChange{character, scenario.characters[std::size_t(character)].bake, std::move(path)});
}

} // namespace thespis::core::edit
