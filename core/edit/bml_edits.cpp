#include "edit/bml_edits.h"

#include <algorithm>
#include <cmath>

#include "edit/content_edits.h"
#include "edit/document_edits.h"
#include "edit/gaze_edits.h"
#include "edit/gesture_insert.h"
#include "edit/layer_insert.h"
#include "edit/speech_edits.h"
#include "anim/frame.h"
#include "motion/head_gesture.h"
#include "speech/speech_plan.h"
#include "util/text.h"

namespace thespis::core::edit {
namespace {

using scenario::ActionSpec;
using scenario::ClipAsset;
using scenario::LayerKind;
using scenario::Scenario;
using speech::BmlBehavior;
using speech::BmlBehaviorKind;
using speech::BmlPlanned;

constexpr std::size_t kStart = 0;
constexpr double kHeadFramesPerSecond = 30;

// The name of a clip of the character with the same content as `clip`, added under a name not
// taken (from clip.name) when it has none: blocks that nod alike share their clip.
Result<std::string> clipFor(Scenario& after, int character, ClipAsset clip)
{
    std::vector<std::string> taken;
    for (const ClipAsset& existing : after.characters[std::size_t(character)].clips) {
        ClipAsset same = clip;
        same.name = existing.name;
        if (same == existing)
            return existing.name;
        taken.push_back(existing.name);
    }
    clip.name = uniqueName(clip.name, taken);
    std::string name = clip.name;
    if (auto added = take(addClips(after, character, {std::move(clip)}), after); !added)
        return added.error();
    return name;
}

// A head gesture sampled on the neck and head joints of `skeleton` (an additive frame: their
// turns from no turn), as keyframes.
Result<ClipAsset> headClip(const anim::Skeleton& skeleton, const BmlPlanned& planned, const std::string& lexeme)
{
    auto motion = motion::HeadGesture::create(skeleton, planned.head);
    if (!motion)
        return motion.error();
    ClipAsset clip;
    clip.name = "head " + lexeme;
    clip.frameRate = kHeadFramesPerSecond;
    std::vector<int> joints;
    for (const char* name : {"vc4", "skullbase"})
        if (const int j = skeleton.find(name); j >= 0) {
            joints.push_back(j);
            clip.joints.emplace_back(name);
        }
    const double seconds = (*motion)->domain().duration();
    const int frames = std::max(2, int(std::ceil(seconds * kHeadFramesPerSecond)) + 1);
    std::vector<float> frame(std::size_t(skeleton.frameLayout()->floatCount()));
    for (int f = 0; f < frames; ++f) {
        (*motion)->evaluate(std::min(seconds, f / kHeadFramesPerSecond), frame);
        for (int j : joints) {
            const anim::Quat q = anim::rotationAt(std::span<const float>(frame), j);
            clip.frames.insert(clip.frames.end(), {q.x, q.y, q.z, q.w});
        }
    }
    return clip;
}

// A faceLexeme's FAPs held for a second (stretched to its length, like a viseme's clip).
ClipAsset faceLexemeClip(const BmlPlanned& planned, const std::string& lexeme)
{
    ClipAsset clip;
    clip.name = "faceLexeme " + uppercase(lexeme);
    clip.frameRate = 1;
    for (const auto& [fap, value] : planned.faps)
        clip.scalars.push_back("fap" + std::to_string(fap));
    for (int f = 0; f < 2; ++f)
        for (const auto& [fap, value] : planned.faps)
            clip.frames.push_back(float(value));
    return clip;
}

} // namespace

Result<BmlInsertion> insertBml(const Scenario& scenario, const scenario::ScenarioRuntime& runtime, int character,
                               const speech::BmlBlock& block, const std::map<std::string, speech::Utterance>& spoken,
                               const BmlInsertOptions& options, Tick at)
{
    if (character < 0 || character >= int(scenario.characters.size()) ||
        character >= int(runtime.characters.size()))
        return makeError(ErrorCode::InvalidArgument, "There is no character " + std::to_string(character) + " to play BML.");
    if (at < 0)
        return makeError(ErrorCode::InvalidArgument, "BML cannot start before the timeline does.");
    const scenario::Character& who = scenario.characters[std::size_t(character)];
    const scenario::CharacterRuntime& built = runtime.characters[std::size_t(character)];

    std::map<std::string, speech::SpeechTiming> timings;
    for (const auto& [id, utterance] : spoken)
        timings[id] = utterance.timing;
    auto plan = speech::planBml(block, timings, timelineGesticon(who, built),
                                options.lexicon ? *options.lexicon : speech::BmlLexicon::of(who.bmlLexicon));
    if (!plan)
        return plan.error();

    BmlInsertion result;
    result.seconds = plan->end;
    Scenario after = scenario;
    const auto startOf = [&](const BmlPlanned& p) { return at + secondsToTicks(p.times.at[kStart]); };
    // An action of the behaviour playing the clip `clip`, from its start.
    const auto clipAction = [&](const BmlPlanned& p, const BmlBehavior& b, std::string clip) {
        ActionSpec action;
        action.name = b.id + " " + uppercase(b.lexeme);
        action.clip = std::move(clip);
        action.start = startOf(p);
        return action;
    };
    std::vector<ActionSpec> gestures, heads, faces, gazes;
    for (const BmlPlanned& planned : plan->behaviors) {
        const BmlBehavior& b = block.behaviors[planned.behavior];
        const auto failed = [&](const Error& e) { return speech::bmlBehaviorError(e.code, b, e.message); };
        switch (b.kind) {
        case BmlBehaviorKind::Speech: {
            const speech::Utterance& u = spoken.at(b.id);
            scenario::SpeechLine line = speechLine(b.text, options.voice, u.timing, {}, startOf(planned));
            line.name = b.id;
            auto inserted = insertSpeech(after, character, std::move(line), speech::visemeCues(u.timing, options.visemes), {});
            if (!inserted)
                return failed(inserted.error());
            if (auto applied = inserted->edit.apply(after); !applied)
                return applied.error();
            ++result.speeches;
            result.visemeActions += inserted->visemeActions;
            break;
        }
        case BmlBehaviorKind::Gesture:
        case BmlBehaviorKind::Pointing: {
            auto action = plannedGestureAction(after, *who.findGesture(planned.gesture), b.id, planned, at);
            if (!action)
                return failed(action.error());
            if (b.kind == BmlBehaviorKind::Pointing) // the Stage aims the entry's arm while it plays
                action->pointing = scenario::PointingSpec{b.target, motion::pointingHandName(planned.hand)};
            (planned.entry.face ? faces : gestures).push_back(std::move(action).value());
            break;
        }
        case BmlBehaviorKind::Head: {
            auto clip = headClip(built.skeleton, planned, uppercase(b.lexeme));
            if (!clip)
                return failed(clip.error());
            auto name = clipFor(after, character, std::move(clip).value());
            if (!name)
                return failed(name.error());
            heads.push_back(clipAction(planned, b, *name));
            break;
        }
        case BmlBehaviorKind::FaceLexeme: {
            auto name = clipFor(after, character, faceLexemeClip(planned, b.lexeme));
            if (!name)
                return failed(name.error());
            ActionSpec action = clipAction(planned, b, *name);
            action.modifiers.push_back(stretchTo(std::max(planned.length(), 0.05), 1.0));
            action.weight = planned.weight;
            faces.push_back(std::move(action));
            break;
        }
        case BmlBehaviorKind::Gaze: {
            const double from = planned.times.at[kStart];
            const double until = planned.gazeLetsGo ? planned.gazeLetGo : plan->end;
            gazes.push_back(gazeAction(b.id + " at " + b.target,
                                       {b.target, std::string(motion::gazeInfluenceName(planned.gaze.influence)),
                                        b.offsetAngle, b.offsetDirection},
                                       startOf(planned), std::max(until - from, speech::kBmlGazeShiftSeconds)));
            break;
        }
        case BmlBehaviorKind::Wait: break;
        }
    }
    // Gestures replace what the body part does (as speech's do); head gestures and faceLexemes
    // add to whatever the neck, head and face do; gaze turns it all.
    const struct {
        std::vector<ActionSpec>& actions;
        const char* layer;
        LayerKind kind;
        anim::BlendMode mode;
        int& count;
    } groups[] = {{gestures, "Gestures", LayerKind::Body, anim::BlendMode::Override, result.gestures},
                  {heads, "Head", LayerKind::Body, anim::BlendMode::Additive, result.headGestures},
                  {faces, "Face lexemes", LayerKind::Face, anim::BlendMode::Additive, result.faceLexemes},
                  {gazes, kGazeLayer, LayerKind::Gaze, anim::BlendMode::Normalized, result.gazes}};
    for (const auto& group : groups) {
        if (group.actions.empty())
            continue;
        auto layer = layerNamed(after, character, group.layer, group.kind, group.mode);
        if (!layer)
            return layer.error();
        group.count = int(group.actions.size());
        if (auto added = take(insertActions(after, *layer, std::move(group.actions)), after); !added)
            return added.error();
    }
    if (after == scenario)
        return makeError(ErrorCode::InvalidArgument, "There is nothing to insert: the block \"" + block.id +
                                                         "\" has no behaviour that shows.");
    result.edit = characterEdit(scenario, after, character);
    return result;
}

} // namespace thespis::core::edit
