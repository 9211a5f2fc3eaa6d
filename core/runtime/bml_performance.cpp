#include "runtime/bml_performance.h"

#include <algorithm>

#include "anim/curve.h"
#include "anim/keyframe_clip.h"
#include "anim/modifiers.h"
#include "motion/head_gesture.h"
#include "runtime/speech_performance.h"
#include "scene/fap.h"
#include "speech/speech_plan.h"

namespace thespis::core::runtime {

namespace {

using speech::BmlBehavior;
using speech::BmlBehaviorKind;
using speech::BmlPoint;
constexpr std::size_t kStart = std::size_t(BmlPoint::Start), kEnd = std::size_t(BmlPoint::End);
constexpr double kReplaceFade = 0.2; // seconds: what a replaced block still plays fades out over this

} // namespace

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
    auto skeleton = stage.skeleton(character);
    if (!skeleton)
        return skeleton.error();

    // The speeches' audio (spoken before, or synthesised now), then the plan.
    std::map<std::string, speech::Utterance> synthesised;
    std::map<std::string, const speech::Utterance*> spoken;
    std::map<std::string, speech::SpeechTiming> timings;
    for (const BmlBehavior& b : block.behaviors) {
        if (b.kind != BmlBehaviorKind::Speech)
            continue;
        if (options.spoken && options.spoken->contains(b.id)) {
            spoken[b.id] = &options.spoken->at(b.id);
        } else {
            auto said = speech::speak(b.text, options.voice);
            if (!said)
                return speech::bmlBehaviorError(said.error().code, b, said.error().message);
            spoken[b.id] = &(synthesised[b.id] = std::move(said).value());
        }
        timings[b.id] = spoken[b.id]->timing;
    }
    std::map<std::string, ActionTemplate> gestures;
    const speech::BmlGesticon gesticon = stageGesticon(stage, character, gestures);
    auto lexicon = options.lexicon ? Result<speech::BmlLexicon>(*options.lexicon) : stage.bmlLexicon(character);
    if (!lexicon)
        return lexicon.error();
    auto plan = speech::planBml(block, timings, gesticon, *lexicon, options.gaze);
    if (!plan)
        return plan.error();

    // Composition: append waits for the last block; replace stops it.
    Played& played = m_played[character];
    double start = ticksToSeconds(at);
    if (block.composition == speech::BmlComposition::Append)
        start = std::max(start, played.end);
    if (block.composition == speech::BmlComposition::Replace) {
        cutOff(character, start);
        for (const auto& [track, name] : played.actions)
            (void)stage.cutOffAction(character, track, name, at, kReplaceFade);
        for (const std::string& sound : played.sounds)
            if (m_sound)
                m_sound->stop(sound);
        if (played.gaze)
            (void)stage.stopGaze(character, at);
        if (played.pointing)
            (void)stage.stopPointing(character, at, kReplaceFade);
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
            return speech::bmlBehaviorError(ok.error().code, b, ok.error().message);
        played.actions.emplace_back(track, name);
        return {};
    };
    for (const speech::BmlPlanned& planned : plan->behaviors) {
        const BmlBehavior& b = block.behaviors[planned.behavior];
        speech::BmlTimes times = planned.times;
        const double length = planned.length();
        const std::string name = block.id + ":" + b.id;
        switch (b.kind) {
        case BmlBehaviorKind::Speech: {
            const speech::Utterance& u = *spoken.at(b.id);
            auto performed = performSpeech(stage, character, name, speech::visemeCues(u.timing), {}, startOf(times));
            if (!performed)
                return speech::bmlBehaviorError(performed.error().code, b, performed.error().message);
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
            auto g = fittedGesture(gestures.at(planned.gesture), planned);
            if (!g)
                return speech::bmlBehaviorError(g.error().code, b, g.error().message);
            if (auto ok = play(b, planned.entry.face ? Track::Face : Track::Body, name, *g,
                               secondsToTicks(start + planned.fit.start));
                !ok)
                return ok.error();
            if (b.kind == BmlBehaviorKind::Pointing) {
                // The entry's arm, aimed at the target with the entry's fades.
                if (auto ok = stage.point(character, planned.target, planned.hand, planned.weight, startOf(times), length); !ok)
                    return speech::bmlBehaviorError(ok.error().code, b, ok.error().message);
                played.pointing = true;
            }
            break;
        }
        case BmlBehaviorKind::Head: {
            auto motion = motion::HeadGesture::create(*skeleton, planned.head);
            if (!motion)
                return speech::bmlBehaviorError(motion.error().code, b, motion.error().message);
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
            for (const auto& [fap, value] : planned.faps)
                frames[std::size_t(scene::fapChannel(fap))] = float(value);
            frames.insert(frames.end(), frames.begin(), frames.end());
            auto clip = anim::KeyframeClip::create(layout, 1.0 / std::max(length, 0.05), frames, b.lexeme);
            if (!clip)
                return clip.error();
            ActionTemplate action{std::move(clip).value(), {}, false};
            action.params.mode = anim::BlendMode::Additive;
            action.params.additiveReference = anim::AdditiveReference::RestPose; // moves from the neutral face
            action.params.weight = planned.weight;
            if (auto ok = play(b, Track::Face, name, action, startOf(times)); !ok)
                return ok.error();
            break;
        }
        case BmlBehaviorKind::Gaze: {
            if (auto ok = stage.gaze(character, planned.target, planned.gaze, startOf(times)); !ok)
                return speech::bmlBehaviorError(ok.error().code, b, ok.error().message);
            if (planned.gazeLetsGo)
                (void)stage.stopGaze(character, secondsToTicks(start + planned.gazeLetGo));
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
        for (std::size_t m = 0; m < times.marks.size(); ++m) {
            times.marks[m] += start;
            performance.events.push_back({times.marks[m], b.id + ":" + b.syncMarks[m].first});
        }
        performance.times.push_back(std::move(times));
    }
    performance.events.push_back({performance.start, block.id + ":start"});
    performance.events.push_back({performance.end, block.id + ":end"});
    std::stable_sort(performance.events.begin(), performance.events.end(),
                     [](const BmlEvent& a, const BmlEvent& b) { return a.time < b.time; });
    played.end = std::max(played.end, performance.end);
    remember(character, performance);
    return performance;
}

void BmlRealizer::cutOff(const std::string& character, double at)
{
    for (Feedback& f : m_feedback) {
        if (f.character != character || f.events.empty() || f.events.back().time <= at)
            continue;
        const auto first = std::upper_bound(f.events.begin() + std::ptrdiff_t(f.taken), f.events.end(), at,
                                            [](double t, const BmlEvent& e) { return t < e.time; });
        f.events.erase(first, f.events.end());
        f.events.push_back({at, f.block + ":end"});
    }
}

void BmlRealizer::remember(const std::string& character, const BmlPerformance& performance)
{
    std::erase_if(m_feedback, [&](const Feedback& f) { return f.character == character && f.block == performance.block; });
    if (m_feedback.size() >= kRememberedBlocks)
        m_feedback.erase(m_feedback.begin());
    m_feedback.push_back({character, performance.block, performance.events, 0});
}

std::vector<BmlEvent> BmlRealizer::events(const std::string& character, const std::string& block) const
{
    const std::lock_guard lock(m_mutex);
    for (const Feedback& f : m_feedback)
        if (f.character == character && f.block == block)
            return f.events;
    return {};
}

std::vector<std::pair<std::string, BmlEvent>> BmlRealizer::takeEvents(double now)
{
    const std::lock_guard lock(m_mutex);
    std::vector<std::pair<std::string, BmlEvent>> due;
    for (Feedback& f : m_feedback)
        for (; f.taken < f.events.size() && f.events[f.taken].time <= now; ++f.taken)
            due.emplace_back(f.character, f.events[f.taken]);
    std::stable_sort(due.begin(), due.end(), [](const auto& a, const auto& b) { return a.second.time < b.second.time; });
    return due;
}

} // namespace thespis::core::runtime
