#include "edit/speech_edits.h"

#include <algorithm>

#include "edit/content_edits.h"
#include "edit/document_edits.h"
#include "scenario/gesture_action.h"
#include "scene/face_mask.h"
#include "scene/fap.h"
#include "util/text.h"

namespace thespis::core::edit {
namespace {

using scenario::ActionSpec;
using scenario::ClipAsset;
using scenario::LayerKind;
using scenario::Scenario;

constexpr const char* kSpeechLayer = "Speech";
constexpr const char* kGestureLayer = "Gestures";
constexpr const char* kSpeechMask = "Speech";

Error invalid(std::string message) { return makeError(ErrorCode::InvalidArgument, std::move(message)); }

// Applies `step` to `after` and appends it to `edit`: later steps are made for the document as
// the earlier ones leave it.
Result<void> take(Result<Edit> step, Scenario& after, Edit& edit)
{
    if (!step)
        return step.error();
    if (auto applied = step->apply(after); !applied)
        return applied.error();
    edit.append(std::move(*step));
    return {};
}

// The layer of that name and kind, added when the character has none: an Override layer, so that
// where its actions cover the face (or the body part) they replace what the layers below do,
// and where they fade out the layers below show again.
Result<LayerPath> layerNamed(Scenario& after, Edit& edit, int character, const std::string& name, LayerKind kind)
{
    const auto& layers = after.characters[std::size_t(character)].layers;
    const auto it = std::find_if(layers.begin(), layers.end(),
                                 [&](const scenario::Layer& l) { return l.name == name && l.kind == kind; });
    if (it != layers.end()) {
        if (it->lock)
            return invalid("The layer " + inQuotes(name) + " is locked: unlock it to insert speech.");
        return LayerPath{character, int(it - layers.begin())};
    }
    scenario::Layer layer;
    layer.name = name;
    layer.kind = kind;
    layer.mode = anim::BlendMode::Override;
    const LayerPath path{character, int(layers.size())};
    if (auto added = take(Edit(LayerChange{path, std::nullopt, std::move(layer)}), after, edit); !added)
        return added.error();
    return path;
}

std::string visemeClipName(const std::string& viseme) { return "viseme " + viseme; }

// One face channel at 1, held for a second: stretched, it lasts as long as its cue.
ClipAsset visemeClip(const speech::VisemeCue& cue)
{
    ClipAsset clip;
    clip.name = visemeClipName(cue.name);
    clip.frameRate = 1;
    clip.scalars = {"viseme" + std::to_string(cue.viseme)};
    clip.frames = {1.0f, 1.0f};
    return clip;
}

scenario::ModifierSpec stretchTo(double seconds, double clipSeconds)
{
    return {.kind = scenario::ModifierKind::TimeStretch, .factor = seconds / clipSeconds};
}

std::string gesturesOf(const scenario::Character& character)
{
    std::string names;
    for (const scenario::Gesture& g : character.gestures)
        names += (names.empty() ? "" : ", ") + g.name;
    return names.empty() ? "none" : names;
}

} // namespace

Result<SpeechInsertion> insertSpeech(const Scenario& scenario, int character, Tick at,
                                     const std::vector<speech::VisemeCue>& visemes,
                                     const std::vector<speech::GestureCue>& gestures)
{
    if (character < 0 || character >= int(scenario.characters.size()))
        return invalid("There is no character " + std::to_string(character) + " to speak.");
    if (at < 0)
        return invalid("Speech cannot start before the timeline does.");
    for (const speech::VisemeCue& cue : visemes)
        if (cue.viseme < 1 || cue.viseme > scene::kVisemeCount || !(cue.duration > 0))
            return invalid("The viseme " + inQuotes(cue.name) + " is not one of MPEG-4's 14 the face shows.");
    const scenario::Character& speaker = scenario.characters[std::size_t(character)];
    for (const speech::GestureCue& cue : gestures)
        if (!speaker.findGesture(cue.animation))
            return makeError(ErrorCode::NotFound, "line " + std::to_string(cue.line) + ", column "
                                                      + std::to_string(cue.column) + ": the gesture "
                                                      + inQuotes(cue.animation) + " is not in " + speaker.name
                                                      + "'s gesticon (it has: " + gesturesOf(speaker) + ").");

    SpeechInsertion result;
    Edit& edit = result.edit;
    Scenario after = scenario;
    auto& who = after.characters[std::size_t(character)];
    if (!after.findMask(kSpeechMask))
        if (auto added = take(addMask(after, kSpeechMask, scene::faceMaskPreset(scene::FaceMaskPreset::Speech)), after, edit);
            !added)
            return added.error();
    std::vector<ClipAsset> missing;
    for (const speech::VisemeCue& cue : visemes)
        if (!who.findClip(visemeClipName(cue.name))
            && std::none_of(missing.begin(), missing.end(), [&](const ClipAsset& c) { return c.name == visemeClipName(cue.name); }))
            missing.push_back(visemeClip(cue));
    if (!missing.empty())
        if (auto added = take(addClips(after, character, std::move(missing)), after, edit); !added)
            return added.error();

    std::vector<ActionSpec> face, body;
    for (const speech::VisemeCue& cue : visemes) {
        ActionSpec action;
        action.name = cue.phoneme;
        action.clip = visemeClipName(cue.name);
        action.start = at + secondsToTicks(cue.start);
        action.modifiers.push_back(stretchTo(cue.duration, 1.0));
        action.weight = cue.weight;
        action.mask = kSpeechMask;
        face.push_back(std::move(action));
    }
    for (const speech::GestureCue& cue : gestures) {
        const scenario::Gesture& gesture = *who.findGesture(cue.animation);
        const ClipAsset* clip = who.findClip(gesture.clip);
        const bool isFace = clip && clip->joints.empty() && !clip->scalars.empty();
        ActionSpec action = scenario::gestureAction(after, gesture, at + secondsToTicks(cue.start));
        action.name = cue.id + " " + cue.animation;
        const double clipSeconds = clip && clip->frames.size() >= 2 * clip->valuesPerFrame()
                                       ? double(clip->frames.size() / clip->valuesPerFrame() - 1) / clip->frameRate
                                       : 0.0;
        // A keyframed face gesture lasts as long as its words; a recorded one plays as recorded
        // (how body gestures fit their words is the gesture planner's).
        if (isFace && clipSeconds > 0 && cue.end > cue.start)
            action.modifiers.insert(action.modifiers.begin(), stretchTo(cue.end - cue.start, clipSeconds));
        (isFace ? face : body).push_back(std::move(action));
    }
    // gestureAction() may have added a widened mask to `after`: the edit must add it too.
    for (std::size_t m = scenario.masks.size() + (scenario.findMask(kSpeechMask) ? 0 : 1); m < after.masks.size(); ++m)
        edit.add(MaskChange{int(m), std::nullopt, after.masks[m]});

    if (!face.empty()) {
        auto layer = layerNamed(after, edit, character, kSpeechLayer, LayerKind::Face);
        if (!layer)
            return layer.error();
        result.visemeActions = int(visemes.size());
        result.faceGestures = int(face.size() - visemes.size());
        if (auto added = take(insertActions(after, *layer, std::move(face)), after, edit); !added)
            return added.error();
    }
    if (!body.empty()) {
        auto layer = layerNamed(after, edit, character, kGestureLayer, LayerKind::Body);
        if (!layer)
            return layer.error();
        result.bodyGestures = int(body.size());
        if (auto added = take(insertActions(after, *layer, std::move(body)), after, edit); !added)
            return added.error();
    }
    if (edit.empty())
        return invalid("There is nothing to insert: the speech has no phonemes.");
    return result;
}

} // namespace thespis::core::edit
