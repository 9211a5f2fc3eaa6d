#include "runtime/speech_performance.h"

#include <algorithm>

#include "anim/keyframe_clip.h"
#include "anim/modifiers.h"
#include "scene/face_mask.h"
#include "scene/fap.h"

namespace thespis::core::runtime {

Result<std::shared_ptr<anim::BlendingSchedule>> speechFace(const std::vector<speech::VisemeCue>& cues)
{
    const auto layout = anim::FrameLayout::mpeg4Face();
    auto face = std::make_shared<anim::BlendingSchedule>(layout);
    const auto mask = std::make_shared<const anim::JointMask>(scene::faceMaskPreset(scene::FaceMaskPreset::Speech));
    const std::vector<float> neutral = anim::neutralFrame(*layout);
    std::vector<float> frames;
    for (const speech::VisemeCue& cue : cues) {
        if (cue.mpeg4 < 0 || cue.mpeg4 > scene::kVisemeCount || !(cue.duration > 0))
            return makeError(ErrorCode::InvalidArgument,
                             "The viseme \"" + cue.name + "\" shows as none of MPEG-4's 14 the face has.");
        if (cue.mpeg4 == 0)
            continue; // the mouth at rest
        // The viseme held over its cue: two frames one cue apart, as the timeline's stretched clip.
        frames = neutral;
        frames[std::size_t(scene::visemeChannel(cue.mpeg4))] = 1.0f;
        frames.resize(2 * neutral.size());
        std::copy_n(frames.begin(), neutral.size(), frames.begin() + std::ptrdiff_t(neutral.size()));
        auto clip = anim::KeyframeClip::create(layout, 1.0 / cue.duration, frames, "viseme " + cue.name);
        if (!clip)
            return clip.error();
        anim::BlendingAction action;
        action.name = cue.phoneme;
        action.source = std::move(clip).value();
        action.start = cue.start;
        // Overlapping visemes blend by their dominance (Normalized), as on the timeline's layer.
        action.params.weight = cue.weight;
        action.params.mask = mask;
        if (auto added = face->addAction(std::move(action)); !added)
            return added.error();
    }
    return face;
}

speech::SpeechTiming timingOf(const scenario::SpeechLine& line, std::string_view spoken)
{
    speech::SpeechTiming timing;
    std::size_t from = 0;
    for (const scenario::SpeechLine::Word& w : line.words) {
        const std::size_t at = spoken.find(w.text, from);
        const std::size_t begin = at == std::string_view::npos ? from : at;
        const std::size_t end = at == std::string_view::npos ? from : at + w.text.size();
        timing.words.push_back({w.text, w.start, w.end, begin, end});
        from = end;
    }
    for (const scenario::SpeechLine::Phoneme& p : line.phonemes) {
        timing.phonemes.push_back({p.phoneme, p.start, p.end});
        timing.duration = std::max(timing.duration, p.end);
    }
    return timing;
}

speech::BmlGesticon stageGesticon(const Stage& stage, const std::string& character,
                                  std::map<std::string, ActionTemplate>& asked)
{
    speech::BmlGesticon gesticon;
    for (const Track track : {Track::Body, Track::Face})
        if (auto names = stage.actionNames(character, track))
            gesticon.names.insert(gesticon.names.end(), names->begin(), names->end());
    gesticon.entry = [&stage, &asked, character](const std::string& name) -> std::optional<speech::BmlGestureEntry> {
        for (const Track track : {Track::Body, Track::Face}) {
            auto found = stage.actionTemplate(character, track, name);
            if (!found || !*found)
                continue;
            if ((*found)->source->domain().openEnded())
                return std::nullopt;
            const ActionTemplate& g = asked[name] = std::move(**found);
            return speech::BmlGestureEntry{g.source->domain().duration(), g.fadeIn, g.fadeOut, g.shape,
                                           track == Track::Face};
        }
        return std::nullopt;
    };
    return gesticon;
}

Result<ActionTemplate> fittedGesture(ActionTemplate gesture, const speech::BmlPlanned& planned)
{
    const speech::GestureFit& fit = planned.fit;
    gesture.params.weight = planned.weight;
    if (planned.entry.seconds <= 0)
        return gesture;
    if (fit.warp.empty()) {
        auto stretched = anim::TimeStretch::create(gesture.source, fit.stretch);
        if (!stretched)
            return stretched.error();
        gesture.source = std::move(stretched).value();
        return gesture;
    }
    auto warp = anim::Curve::keyframed(fit.warp);
    if (!warp)
        return warp.error();
    auto warped = anim::TimeWarp::create(gesture.source, std::move(warp).value(), fit.duration);
    if (!warped)
        return warped.error();
    gesture.source = std::move(warped).value();
    return gesture;
}

Result<SpeechPerformance> performSpeech(Stage& stage, const std::string& character, const std::string& name,
                                        const std::vector<speech::VisemeCue>& cues,
                                        const speech::TaggedBml& gestures, Tick at)
{
    if (stage.findCharacter(character) < 0)
        return makeError(ErrorCode::NotFound, "There is no character \"" + character + "\" to speak.");
    if (cues.empty() && gestures.empty())
        return makeError(ErrorCode::InvalidArgument, "\"" + name + "\" has nothing to say: it has no phonemes.");
    SpeechPerformance performance;
    performance.action = "speech " + name;
    if (!cues.empty()) {
        auto face = speechFace(cues);
        if (!face)
            return face.error();
        ActionTemplate action;
        action.source = std::move(face).value();
        action.params.mode = anim::BlendMode::Override;
        (void)stage.removeAction(character, Track::Face, performance.action);
        if (auto played = stage.playAction(character, Track::Face, performance.action, action, at, {.fadeIn = 0});
            !played)
            return played.error();
        performance.visemes = int(cues.size());
    }
    if (gestures.empty())
        return performance;
    // Tags naming what the character cannot play are told, not played; the rest as BML's gestures.
    std::map<std::string, ActionTemplate> templates;
    const speech::BmlGesticon gesticon = stageGesticon(stage, character, templates);
    speech::BmlBlock block = gestures.block;
    std::erase_if(block.behaviors, [&](const speech::BmlBehavior& b) {
        if (b.kind != speech::BmlBehaviorKind::Gesture || gesticon.entry(b.lexeme))
            return false;
        performance.unknownGestures.push_back(b.lexeme);
        return true;
    });
    auto plan = speech::planBml(block, gestures.speech, gesticon, speech::BmlLexicon::defaults());
    if (!plan)
        return plan.error();
    for (const speech::BmlPlanned& planned : plan->behaviors) {
        if (planned.gesture.empty())
            continue; // the speech
        auto gesture = fittedGesture(templates.at(planned.gesture), planned);
        if (!gesture)
            return gesture.error();
        const std::string action = name + ":" + block.behaviors[planned.behavior].id;
        const Track track = planned.entry.face ? Track::Face : Track::Body;
        (void)stage.removeAction(character, track, action);
        if (auto played = stage.playAction(character, track, action, *gesture, at + secondsToTicks(planned.fit.start),
                                           {.fadeIn = 0});
            !played)
            return played.error();
        ++performance.gestures;
    }
    return performance;
}

} // namespace thespis::core::runtime
