#include "scenario/runtime_gestures.h"

#include "scenario/gesture_action.h"

namespace thespis::core::scenario {

void buildGestures(const Scenario& scenario, const Character& character, const BuildGestureAction& build,
                   bool basesReadable, CharacterRuntime& runtime)
{
    for (const Gesture& gesture : character.gestures) {
        if (gesture.name.empty() || runtime.gestures.contains(gesture.name))
            continue; // reported by the builder's checks
        GestureActions actions;
        actions.face = !runtime.clips.contains(gesture.clip) && runtime.faceClips.contains(gesture.clip);
        actions.filter = gesture.dependentJointFilter && !actions.face;
        actions.fadeIn = ticksToSeconds(gesture.fadeIn);
        actions.fadeOut = ticksToSeconds(gesture.fadeOut);
        actions.hold = gesture.hold;
        actions.stroke = gesture.stroke;
        const std::string where = "Character \"" + character.name + "\", gesture \"" + gesture.name + "\"";
        for (const bool filter : {false, true}) {
            if (filter && (!basesReadable || actions.face))
                continue;
            Gesture variant = gesture;
            variant.dependentJointFilter = filter;
            GestureSpec spec = gestureSpec(scenario, variant, 0);
            const LayerKind kind = actions.face ? LayerKind::Face : LayerKind::Body;
            if (auto built = build(spec.action, kind, spec.widenedMask ? &*spec.widenedMask : nullptr, where))
                (filter ? actions.withFilter : actions.withoutFilter) = std::move(*built);
        }
        if (actions.played().source) {
            runtime.gestures.emplace(gesture.name, std::move(actions));
        } else if (actions.filter && !basesReadable) {
            runtime.warnings.push_back(where + ": its dependent-joint filter needs the scenario's posture bases, which "
                                               "cannot be read; scripts cannot play this gesture.");
            runtime.warningClips.resize(runtime.warnings.size(), gesture.clip);
        }
    }
}

void buildBmlLexicon(const Character& character, CharacterRuntime& runtime)
{
    runtime.bmlLexicon = speech::BmlLexicon::of(character.bmlLexicon);
    if (!character.bmlLexicon)
        return;
    for (const auto& [lexeme, entry] : *character.bmlLexicon)
        if (!character.findGesture(entry)) {
            runtime.warnings.push_back("Character \"" + character.name + "\", BML lexicon, " + lexeme
                                       + ": the character has no gesture named \"" + entry + "\" to play it.");
            runtime.warningClips.resize(runtime.warnings.size());
        }
}

} // namespace thespis::core::scenario
