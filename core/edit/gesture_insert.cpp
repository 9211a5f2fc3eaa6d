#include "edit/gesture_insert.h"

#include "edit/layer_insert.h"
#include "scenario/gesture_action.h"

namespace thespis::core::edit {

speech::BmlGesticon timelineGesticon(const scenario::Character& who, const scenario::CharacterRuntime& built)
{
    speech::BmlGesticon gesticon;
    for (const scenario::Gesture& g : who.gestures)
        gesticon.names.push_back(g.name);
    gesticon.entry = [&who, &built](const std::string& name) -> std::optional<speech::BmlGestureEntry> {
        const scenario::Gesture* gesture = who.findGesture(name);
        if (!gesture)
            return std::nullopt;
        const auto found = built.gestures.find(name);
        if (found == built.gestures.end())
            return std::nullopt;
        const anim::BlendablePtr& source = found->second.played().source;
        if (!source || source->domain().openEnded())
            return std::nullopt;
        return speech::BmlGestureEntry{source->domain().duration(), ticksToSeconds(gesture->fadeIn),
                                       ticksToSeconds(gesture->fadeOut), {gesture->hold, gesture->stroke}, found->second.face};
    };
    return gesticon;
}

Result<scenario::ActionSpec> plannedGestureAction(scenario::Scenario& after, const scenario::Gesture& gesture,
                                                  const std::string& id, const speech::BmlPlanned& planned, Tick at)
{
    const speech::GestureFit& fit = planned.fit;
    scenario::ActionSpec action = scenario::gestureAction(after, gesture, at + secondsToTicks(fit.start));
    action.name = id + " " + gesture.name;
    action.weight = planned.weight;
    if (planned.entry.seconds <= 0)
        return action;
    if (fit.warp.empty()) {
        action.modifiers.insert(action.modifiers.begin(), stretchTo(fit.duration, planned.entry.seconds));
        return action;
    }
    auto curve = anim::Curve::keyframed(fit.warp);
    if (!curve)
        return curve.error();
    scenario::ModifierSpec warp{.kind = scenario::ModifierKind::TimeWarp};
    warp.warp = std::move(curve).value();
    warp.duration = fit.duration;
    action.modifiers.insert(action.modifiers.begin(), std::move(warp));
    return action;
}

} // namespace thespis::core::edit
