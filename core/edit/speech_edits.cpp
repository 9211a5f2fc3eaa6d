#include "edit/speech_edits.h"

#include <algorithm>
#include <span>

#include "edit/content_edits.h"
#include "edit/document_edits.h"
#include "edit/gesture_insert.h"
#include "edit/layer_insert.h"
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

// Named after the MPEG-4 viseme the face shows: the visemes of any set that show alike share it.
std::string visemeClipName(const speech::VisemeCue& cue)
{
    return "viseme " + speech::mpeg4Visemes().find(cue.mpeg4)->name;
}

// One face channel at 1, held for a second: stretched, it lasts as long as its cue.
ClipAsset visemeClip(const speech::VisemeCue& cue)
{
    ClipAsset clip;
    clip.name = visemeClipName(cue);
    clip.frameRate = 1;
    clip.scalars = {"viseme" + std::to_string(cue.mpeg4)};
    clip.frames = {1.0f, 1.0f};
    return clip;
}

} // namespace

scenario::SpeechLine speechLine(const std::string& text, const speech::VoiceSettings& voice,
                                const speech::SpeechTiming& timing, std::string audio, Tick start)
{
    scenario::SpeechLine line;
    line.name = "line";
    line.start = start;
    line.text = text;
    line.voice = voice.voice;
    line.rate = voice.wordsPerMinute;
    line.pitch = voice.pitch;
    line.audio = std::move(audio);
    for (const speech::WordTiming& w : timing.words)
        line.words.push_back({w.text, w.start, w.end});
    for (const speech::PhonemeTiming& p : timing.phonemes)
        line.phonemes.push_back({p.phoneme, p.start, p.end});
    return line;
}

Result<SpeechInsertion> insertSpeech(const Scenario& scenario, int character, scenario::SpeechLine line,
                                     const std::vector<speech::VisemeCue>& visemes, const speech::TaggedBml& gestures,
                                     const scenario::ScenarioRuntime* runtime)
{
    if (!line.start)
        return invalid("A speech line inserted on the timeline needs a start.");
    const Tick at = *line.start;
    if (character < 0 || character >= int(scenario.characters.size()))
        return invalid("There is no character " + std::to_string(character) + " to speak.");
    if (at < 0)
        return invalid("Speech cannot start before the timeline does.");
    for (const speech::VisemeCue& cue : visemes)
        if (cue.mpeg4 < 0 || cue.mpeg4 > scene::kVisemeCount || !(cue.duration > 0))
            return invalid("The viseme " + inQuotes(cue.name) + " shows as none of MPEG-4's 14 the face has.");
    const scenario::Character& speaker = scenario.characters[std::size_t(character)];
    std::optional<speech::BmlPlan> plan;
    if (!gestures.empty()) {
        if (!runtime || character >= int(runtime->characters.size()))
            return invalid("Gestures are timed on the character's gesticon as built: no built scenario was given.");
        auto planned = speech::planBml(gestures.block, gestures.speech,
                                       timelineGesticon(speaker, runtime->characters[std::size_t(character)]),
                                       speech::BmlLexicon::of(speaker.bmlLexicon));
        if (!planned)
            return planned.error();
        plan = std::move(planned).value();
    }

    SpeechInsertion result;
    Scenario after = scenario;
    auto& who = after.characters[std::size_t(character)];
    if (!after.findMask(kSpeechMask))
        if (auto added = take(addMask(after, kSpeechMask, scene::faceMaskPreset(scene::FaceMaskPreset::Speech)), after);
            !added)
            return added.error();
    std::vector<ClipAsset> missing;
    for (const speech::VisemeCue& cue : visemes)
        if (cue.mpeg4 != 0 && !who.findClip(visemeClipName(cue))
            && std::none_of(missing.begin(), missing.end(), [&](const ClipAsset& c) { return c.name == visemeClipName(cue); }))
            missing.push_back(visemeClip(cue));
    if (!missing.empty())
        if (auto added = take(addClips(after, character, std::move(missing)), after); !added)
            return added.error();

    std::vector<ActionSpec> face, body;
    for (const speech::VisemeCue& cue : visemes) {
        if (cue.mpeg4 == 0)
            continue; // the mouth at rest
        ActionSpec action;
        action.name = cue.phoneme;
        action.clip = visemeClipName(cue);
        action.start = at + secondsToTicks(cue.start);
        action.modifiers.push_back(stretchTo(cue.duration, 1.0));
        action.weight = cue.weight;
        action.mask = kSpeechMask;
        face.push_back(std::move(action));
    }
    for (const speech::BmlPlanned& planned : plan ? plan->behaviors : std::span<const speech::BmlPlanned>{}) {
        if (planned.gesture.empty())
            continue; // the speech
        auto action = plannedGestureAction(after, *who.findGesture(planned.gesture),
                                           gestures.block.behaviors[planned.behavior].id, planned, at);
        if (!action)
            return action.error();
        (planned.entry.face ? face : body).push_back(std::move(action).value());
    }
    if (face.empty() && body.empty())
        return invalid("There is nothing to insert: the speech has no phonemes.");
    if (!face.empty()) {
        // Override: where its actions cover the face they replace what the layers below do.
        auto layer = layerNamed(after, character, kSpeechLayer, LayerKind::Face, anim::BlendMode::Override);
        if (!layer)
            return layer.error();
        result.visemeActions = int(visemes.size());
        result.faceGestures = int(face.size() - visemes.size());
        if (auto added = take(insertActions(after, *layer, std::move(face)), after); !added)
            return added.error();
    }
    if (!body.empty()) {
        auto layer = layerNamed(after, character, kGestureLayer, LayerKind::Body, anim::BlendMode::Override);
        if (!layer)
            return layer.error();
        result.bodyGestures = int(body.size());
        if (auto added = take(insertActions(after, *layer, std::move(body)), after); !added)
            return added.error();
    }
    // One change for the character (its clips, layers, actions and the line), after the masks it
    // uses (the Speech mask, gestures' widened ones): the steps above only built it.
    std::vector<std::string> taken;
    for (const scenario::SpeechLine& other : who.speech)
        taken.push_back(other.name);
    line.name = uniqueName(line.name.empty() ? "line" : line.name, taken);
    who.speech.push_back(std::move(line));
    result.edit = characterEdit(scenario, after, character);
    return result;
}

} // namespace thespis::core::edit
