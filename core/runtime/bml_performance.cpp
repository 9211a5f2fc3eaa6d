#include "runtime/bml_performance.h"

#include <algorithm>
#include <cctype>

#include "anim/curve.h"
#include "anim/keyframe_clip.h"
#include "anim/modifiers.h"
#include "motion/head_gesture.h"
#include "runtime/gaze_target.h"
#include "runtime/speech_performance.h"
#include "scene/fap.h"
#include "speech/face_lexemes.h"
#include "speech/speech_plan.h"
#include "util/text.h"

namespace thespis::core::runtime {

namespace {

using speech::BmlBehavior;
using speech::BmlBehaviorKind;
using speech::BmlPoint;
constexpr std::size_t kStart = std::size_t(BmlPoint::Start), kReady = std::size_t(BmlPoint::Ready),
                      kStroke = std::size_t(BmlPoint::Stroke), kRelax = std::size_t(BmlPoint::Relax),
                      kEnd = std::size_t(BmlPoint::End);
constexpr double kFaceLexemeSeconds = 1.0, kGazeShiftSeconds = 0.4;

Error behaviorError(ErrorCode code, const BmlBehavior& b, const std::string& what)
{
    return makeError(code, "line " + std::to_string(b.line) + ", column " + std::to_string(b.column) + ": " +
                               std::string(speech::bmlKindName(b.kind)) + " \"" + b.id + "\": " + what);
}

// Ready … relax inside [start, end] as a curve's fades, in seconds.
anim::Curve fades(const std::array<double, speech::kBmlPointCount>& at)
{
    return anim::Curve::cubicFade(std::max(0.0, at[kReady] - at[kStart]), std::max(0.0, at[kEnd] - at[kRelax]));
}

// The points of a clip of `seconds` with `fadeIn`/`fadeOut`: stroke in the middle of the held part.
std::array<double, speech::kBmlPointCount> phases(double seconds, double fadeIn, double fadeOut)
{
    fadeIn = std::min(fadeIn, seconds / 2);
    fadeOut = std::min(fadeOut, seconds - fadeIn);
    const double ready = fadeIn, relax = seconds - fadeOut, stroke = (ready + relax) / 2;
    return {0, ready, stroke, stroke, stroke, relax, seconds};
}

} // namespace

BmlLexicon BmlLexicon::defaults()
{
    return {{{"BEAT", "agree"}, {"NOD", "agree"}, {"AGREE", "agree"}, {"WAVE", "greet"}, {"GREET", "greet"},
             {"POINT", "point"}}};
}

std::string BmlLexicon::entryFor(const std::string& lexeme, const std::vector<std::string>& gesticon) const
{
    const std::string wanted = uppercase(lexeme);
    for (const std::string& g : gesticon)
        if (uppercase(g) == wanted)
            return g;
    if (const auto row = gestures.find(wanted); row != gestures.end())
        if (std::find(gesticon.begin(), gesticon.end(), row->second) != gesticon.end())
            return row->second;
    return {};
}

BmlRealizer::BmlRealizer(std::shared_ptr<Stage> stage, std::shared_ptr<SoundService> sound)
    : m_stage(std::move(stage)), m_sound(std::move(sound))
{
}

Result<BmlPerformance> BmlRealizer::perform(const std::string& character, const speech::BmlBlock& block,
                                            const BmlOptions& options, Tick at)
{
    const std::lock_guard lock(m_mutex);
    Stage& stage = *m_stage;
    const int index = stage.findCharacter(character);
    if (index < 0)
        return makeError(ErrorCode::NotFound, "There is no character \"" + character + "\" to play BML.");
    const anim::Skeleton skeleton = [&] {
        const scenario::ScenarioRuntime runtime = stage.runtimeCopy();
        const scenario::CharacterRuntime* who = runtime.findCharacter(character);
        return who ? who->skeleton : anim::Skeleton{};
    }();
    auto bodyActions = stage.actionNames(character, Track::Body);
    if (!bodyActions)
        return bodyActions.error();

    // What each behaviour needs before timing: the speeches' audio and the gestures' clips.
    std::map<std::string, speech::Utterance> synthesised;
    std::map<std::string, const speech::Utterance*> spoken;
    std::map<std::string, speech::SpeechTiming> timings;
    std::map<std::string, ActionTemplate> gestures;
    for (const BmlBehavior& b : block.behaviors) {
        if (b.kind == BmlBehaviorKind::Speech) {
            if (options.spoken && options.spoken->contains(b.id)) {
                spoken[b.id] = &options.spoken->at(b.id);
            } else {
                auto said = speech::speak(b.text, options.voice);
                if (!said)
                    return behaviorError(said.error().code, b, said.error().message);
                spoken[b.id] = &(synthesised[b.id] = std::move(said).value());
            }
            timings[b.id] = spoken[b.id]->timing;
        } else if (b.kind == BmlBehaviorKind::Gesture || b.kind == BmlBehaviorKind::Pointing) {
            const std::string lexeme = b.kind == BmlBehaviorKind::Pointing ? std::string("POINT") : b.lexeme;
            const std::string entry = b.byName ? b.lexeme : options.lexicon.entryFor(lexeme, *bodyActions);
            auto found = entry.empty() ? Result<std::optional<ActionTemplate>>(std::nullopt)
                                       : stage.actionTemplate(character, Track::Body, entry);
            if (!found || !*found || (*found)->source->domain().openEnded())
                return behaviorError(ErrorCode::NotFound, b,
                                     character + " has no gesture for \"" + lexeme + "\" (the lexicon and the "
                                         "gesticon name none it can play).");
            gestures[b.id] = std::move(**found);
        } else if (b.kind == BmlBehaviorKind::FaceLexeme) {
            if (auto faps = speech::faceLexemeFaps(b.lexeme); !faps)
                return behaviorError(faps.error().code, b, faps.error().message);
        } else if (b.kind == BmlBehaviorKind::Head && !motion::headLexemeNamed(b.lexeme)) {
            return behaviorError(ErrorCode::NotFound, b, "\"" + b.lexeme + "\" is no head lexeme (NOD, SHAKE, TILT).");
        }
    }
    const speech::BmlNaturalTiming natural = [&](const BmlBehavior& b) -> std::array<double, speech::kBmlPointCount> {
        switch (b.kind) {
        case BmlBehaviorKind::Gesture:
        case BmlBehaviorKind::Pointing: {
            const ActionTemplate& g = gestures.at(b.id);
            return phases(g.source->domain().duration(), g.fadeIn, g.fadeOut);
        }
        case BmlBehaviorKind::Head: {
            const motion::HeadGestureOptions head{*motion::headLexemeNamed(b.lexeme), b.repetition, b.amount, 0};
            return phases(motion::naturalHeadGestureSeconds(head), 0, 0);
        }
        case BmlBehaviorKind::FaceLexeme: return phases(kFaceLexemeSeconds, 0.2, 0.3);
        case BmlBehaviorKind::Gaze: return {0, kGazeShiftSeconds, kGazeShiftSeconds, kGazeShiftSeconds,
                                            kGazeShiftSeconds, kGazeShiftSeconds, kGazeShiftSeconds};
        case BmlBehaviorKind::Speech:
        case BmlBehaviorKind::Wait: break;
        }
        return {};
    };
    auto resolved = speech::resolveBml(block, timings, natural);
    if (!resolved)
        return resolved.error();

    // Composition: append waits for the last block; replace stops it.
    Played& played = m_played[character];
    double start = ticksToSeconds(at);
    if (block.composition == speech::BmlComposition::Append)
        start = std::max(start, played.end);
    if (block.composition == speech::BmlComposition::Replace) {
        for (const auto& [track, name] : played.actions)
            (void)stage.cutOffAction(character, track, name, at, 0.2);
        for (const std::string& sound : played.sounds)
            if (m_sound)
                m_sound->stop(sound);
        if (played.gaze)
            (void)stage.stopGaze(character, at);
        played = {};
    }

    BmlPerformance performance;
    performance.block = block.id;
    performance.start = start;
    performance.end = start;
    const auto startOf = [&](const speech::BmlTimes& t) { return secondsToTicks(start + t.at[kStart]); };
    // Plays an action of the block live, kept to be stopped should a later block replace this one.
    const auto play = [&](const BmlBehavior& b, Track track, const std::string& name, const ActionTemplate& action,
                          Tick when) -> Result<void> {
        if (auto ok = stage.playAction(character, track, name, action, when, {.fadeIn = 0}); !ok)
            return behaviorError(ok.error().code, b, ok.error().message);
        played.actions.emplace_back(track, name);
        return {};
    };
    for (std::size_t i = 0; i < block.behaviors.size(); ++i) {
        const BmlBehavior& b = block.behaviors[i];
        speech::BmlTimes times = (*resolved)[i];
        const double length = times.at[kEnd] - times.at[kStart];
        const std::string name = block.id + ":" + b.id;
        switch (b.kind) {
        case BmlBehaviorKind::Speech: {
            const speech::Utterance& u = *spoken.at(b.id);
            auto performed = performSpeech(stage, character, name, speech::visemeCues(u.timing), {}, startOf(times));
            if (!performed)
                return behaviorError(performed.error().code, b, performed.error().message);
            played.actions.emplace_back(Track::Face, performed->action);
            if (m_sound) {
                auto clip = std::make_shared<SoundClip>(SoundClip{u.rate, u.samples});
                const std::string sound = speechSoundName(character, name);
                m_sound->playClip(sound, std::move(clip), startOf(times), 1.0, character);
                played.sounds.push_back(sound);
            }
            break;
        }
        case BmlBehaviorKind::Gesture:
        case BmlBehaviorKind::Pointing: {
            ActionTemplate g = gestures.at(b.id);
            const double clip = g.source->domain().duration();
            if (length > 0 && clip > 0) {
                auto stretched = anim::TimeStretch::create(g.source, length / clip);
                if (!stretched)
                    return stretched.error();
                g.source = std::move(stretched).value();
            }
            g.params.weight = fades(times.at);
            if (auto ok = play(b, Track::Body, name, g, startOf(times)); !ok)
                return ok.error();
            break;
        }
        case BmlBehaviorKind::Head: {
            const motion::HeadGestureOptions head{*motion::headLexemeNamed(b.lexeme), b.repetition, b.amount,
                                                  std::max(length, 0.05)};
            auto motion = motion::HeadGesture::create(skeleton, head);
            if (!motion)
                return behaviorError(motion.error().code, b, motion.error().message);
            ActionTemplate action{std::move(motion).value(), {}, false};
            action.params.mode = anim::BlendMode::Additive;
            action.params.additiveReference = anim::AdditiveReference::RestPose; // turns from no turn
            if (auto ok = play(b, Track::Body, name, action, startOf(times)); !ok)
                return ok.error();
            break;
        }
        case BmlBehaviorKind::FaceLexeme: {
            const auto layout = anim::FrameLayout::mpeg4Face();
            std::vector<float> frames = anim::neutralFrame(*layout);
            const auto faps = speech::faceLexemeFaps(b.lexeme); // checked above
            for (const auto& [fap, value] : *faps)
                frames[std::size_t(scene::fapChannel(fap))] = float(value * b.amount);
            frames.insert(frames.end(), frames.begin(), frames.end());
            auto clip = anim::KeyframeClip::create(layout, 1.0 / std::max(length, 0.05), frames, b.lexeme);
            if (!clip)
                return clip.error();
            ActionTemplate action{std::move(clip).value(), {}, false};
            action.params.mode = anim::BlendMode::Additive;
            action.params.additiveReference = anim::AdditiveReference::RestPose; // moves from the neutral face
            action.params.weight = fades(times.at);
            if (auto ok = play(b, Track::Face, name, action, startOf(times)); !ok)
                return ok.error();
            break;
        }
        case BmlBehaviorKind::Gaze: {
            auto target = parseGazeTarget(b.target);
            if (!target)
                return behaviorError(target.error().code, b, target.error().message);
            motion::GazeSettings settings = options.gaze;
            if (!b.influence.empty()) {
                auto influence = parseGazeInfluence(b.influence);
                if (!influence)
                    return behaviorError(influence.error().code, b, influence.error().message);
                settings.influence = *influence;
            }
            if (auto offset = setGazeOffset(settings, b.offsetAngle, b.offsetDirection); !offset)
                return behaviorError(offset.error().code, b, offset.error().message);
            if (auto ok = stage.gaze(character, *target, settings, startOf(times)); !ok)
                return behaviorError(ok.error().code, b, ok.error().message);
            // A gaze whose end the block constrains lets go there; otherwise it holds.
            if (b.sync.contains(BmlPoint::End) || b.sync.contains(BmlPoint::Relax))
                (void)stage.stopGaze(character, secondsToTicks(start + times.at[kRelax]));
            played.gaze = true;
            break;
        }
        case BmlBehaviorKind::Wait: break;
        }
        for (double& t : times.at)
            t += start;
        performance.end = std::max(performance.end, times.at[kEnd]);
        for (std::size_t p = 0; p < speech::kBmlPointCount; ++p)
            performance.events.push_back({times.at[p], b.id + ":" + std::string(speech::bmlPointName(BmlPoint(p)))});
        if (b.kind == BmlBehaviorKind::Speech)
            for (const auto& [mark, offset] : b.syncMarks) {
                const speech::SpeechTiming& timing = timings.at(b.id);
                double when = timing.words.empty() ? 0 : timing.words.back().end;
                for (const speech::WordTiming& w : timing.words)
                    if (w.textBegin >= offset) {
                        when = w.start;
                        break;
                    }
                performance.events.push_back({times.at[kStart] + when, b.id + ":" + mark});
            }
        performance.times.push_back(std::move(times));
    }
    performance.events.push_back({performance.start, block.id + ":start"});
    performance.events.push_back({performance.end, block.id + ":end"});
    std::stable_sort(performance.events.begin(), performance.events.end(),
                     [](const BmlEvent& a, const BmlEvent& b) { return a.time < b.time; });
    played.end = std::max(played.end, performance.end);
    return performance;
}

} // namespace thespis::core::runtime
