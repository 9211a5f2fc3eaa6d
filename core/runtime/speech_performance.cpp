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
        if (cue.viseme < 1 || cue.viseme > scene::kVisemeCount || !(cue.duration > 0))
            return makeError(ErrorCode::InvalidArgument,
                             "The viseme \"" + cue.name + "\" is not one of MPEG-4's 14 the face shows.");
        // The viseme held over its cue: two frames one cue apart, as the timeline's stretched clip.
        frames = neutral;
        frames[std::size_t(scene::visemeChannel(cue.viseme))] = 1.0f;
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

Result<SpeechPerformance> performSpeech(Stage& stage, const std::string& character, const std::string& name,
                                        const std::vector<speech::VisemeCue>& cues,
                                        const std::vector<speech::GestureCue>& gestures, Tick at)
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
    for (const speech::GestureCue& cue : gestures) {
        if (stage.activateAction(character, Track::Face, cue.animation, at + secondsToTicks(cue.start))) {
            ++performance.gestures;
            continue;
        }
        // A body gesture spans its words with its fades, its clip fitted to them.
        auto found = stage.actionTemplate(character, Track::Body, cue.animation);
        if (!found || !*found) {
            performance.unknownGestures.push_back(cue.animation);
            continue;
        }
        ActionTemplate gesture = std::move(**found);
        const anim::TimeDomain domain = gesture.source->domain();
        const speech::GestureFit fit = speech::fitGesture(cue, domain.openEnded() ? 0 : domain.duration(),
                                                          gesture.fadeIn, gesture.fadeOut, gesture.shape);
        if (!domain.openEnded() && domain.duration() > 0) {
            if (fit.warp.empty()) {
                auto stretched = anim::TimeStretch::create(gesture.source, fit.stretch);
                if (!stretched)
                    return stretched.error();
                gesture.source = std::move(stretched).value();
            } else {
                auto warp = anim::Curve::keyframed(fit.warp);
                if (!warp)
                    return warp.error();
                auto warped = anim::TimeWarp::create(gesture.source, std::move(warp).value(), fit.duration);
                if (!warped)
                    return warped.error();
                gesture.source = std::move(warped).value();
            }
        }
        if (auto played = stage.playAction(character, Track::Body, cue.animation, gesture,
                                           at + secondsToTicks(fit.start), {.fadeIn = 0});
            !played)
            return played.error();
        ++performance.gestures;
    }
    return performance;
}

} // namespace thespis::core::runtime
