#include "scenario/gesture_action.h"

#include "motion/posture.h"

namespace thespis::core::scenario {

GestureSpec gestureSpec(const Scenario& scenario, const Gesture& gesture, Tick start)
{
    GestureSpec spec;
    ActionSpec& action = spec.action;
    action.name = gesture.name;
    action.clip = gesture.clip;
    action.mask = gesture.mask;
    action.start = start;
    action.weight = anim::Curve::cubicFade(ticksToSeconds(gesture.fadeIn), ticksToSeconds(gesture.fadeOut));
    if (!gesture.dependentJointFilter)
        return spec;
    action.modifiers.push_back({.kind = ModifierKind::DependentJointFilter,
                                .fadeFrom = gesture.filterFadeFrom,
                                .muteAbove = gesture.filterMuteAbove});
    const NamedMask* part = gesture.mask.empty() ? nullptr : scenario.findMask(gesture.mask);
    if (!part)
        return spec; // the whole body, or a mask the runtime will report missing
    NamedMask widened{part->name + " + dependent joints", part->mask};
    for (const std::string& joint : motion::PostureLayout::of(motion::PostureSet::UpperBody).joints)
        widened.mask.setWeight(joint, 1.0f);
    action.mask = widened.name;
    if (!scenario.findMask(widened.name))
        spec.widenedMask = std::move(widened);
    return spec;
}

ActionSpec gestureAction(Scenario& scenario, const Gesture& gesture, Tick start)
{
    GestureSpec spec = gestureSpec(scenario, gesture, start);
    if (spec.widenedMask)
        scenario.masks.push_back(std::move(*spec.widenedMask));
    return std::move(spec.action);
}

} // namespace thespis::core::scenario
