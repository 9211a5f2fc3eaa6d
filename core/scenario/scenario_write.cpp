// Writing the document model as scenario JSON (scenario_io.h): known fields in a fixed order,
// unknown ones kept, pretty printed for diffs.
#include <algorithm>

#include "scenario/scenario_io.h"
#include "scenario/scenario_json.h"

namespace thespis::core::scenario {
namespace detail {

ojson toOrdered(const json& value)
{
    switch (value.type()) {
    case json::value_t::object: {
        ojson result = ojson::object();
        for (const auto& [key, item] : value.items())
            result[key] = toOrdered(item);
        return result;
    }
    case json::value_t::array: {
        ojson result = ojson::array();
        for (const json& item : value)
            result.push_back(toOrdered(item));
        return result;
    }
    case json::value_t::string: return value.get<std::string>();
    case json::value_t::boolean: return value.get<bool>();
    case json::value_t::number_integer: return value.get<std::int64_t>();
    case json::value_t::number_unsigned: return value.get<std::uint64_t>();
    case json::value_t::number_float: return value.get<double>();
    default: return nullptr;
    }
}

// Known fields first, in the writer's order; unknown ones after, never replacing a known one.
// `skip` names a member written separately (empty: none; an unknown member may itself be
// named "", so the empty name must not mean "skip").
void appendExtra(ojson& out, const json& extra, std::string_view skip)
{
    if (!extra.is_object())
        return;
    for (const auto& [key, value] : extra.items())
        if ((skip.empty() || key != skip) && !out.contains(key))
            out[key] = toOrdered(value);
}

namespace {

ojson writeCurve(const anim::Curve& curve, const json& extra)
{
    ojson out = ojson::object();
    out["schema"] = "Curve.1";
    out["kind"] = nameOf(kCurveKinds, curve.kind());
    const anim::EnvelopeParams& e = curve.envelope();
    switch (curve.kind()) {
    case anim::CurveKind::Constant:
        out["value"] = curve.constantValue();
        break;
    case anim::CurveKind::LinearFade:
    case anim::CurveKind::CubicFade:
        out["fadeIn"] = e.attack;
        out["fadeOut"] = e.release;
        out["peak"] = e.peak;
        break;
    case anim::CurveKind::LinearAdsr:
    case anim::CurveKind::CubicAdsr:
        out["attack"] = e.attack;
        out["decay"] = e.decay;
        out["sustain"] = e.sustain;
        out["release"] = e.release;
        out["peak"] = e.peak;
        break;
    case anim::CurveKind::Dominance:
        out["alpha"] = e.alpha;
        out["peak"] = e.peak;
        break;
    case anim::CurveKind::Keyframed: {
        const json* keyExtras = nullptr;
        if (extra.is_object()) {
            const auto it = extra.find("keys");
            if (it != extra.end() && it->is_array() && it->size() == curve.keys().size())
                keyExtras = &*it;
        }
        ojson keys = ojson::array();
        for (std::size_t i = 0; i < curve.keys().size(); ++i) {
            const anim::CurveKey& k = curve.keys()[i];
            ojson key = ojson::object();
            key["time"] = k.time;
            key["value"] = k.value;
            key["tangent"] = nameOf(kTangentModes, k.mode);
            // Slopes only matter for free and broken keys, but are kept whenever set so that
            // switching a key's mode back and forth in the editor loses nothing.
            if (k.inSlope != 0)
                key["inSlope"] = k.inSlope;
            if (k.outSlope != 0)
                key["outSlope"] = k.outSlope;
            if (keyExtras)
                appendExtra(key, (*keyExtras)[i]);
            keys.push_back(std::move(key));
        }
        out["keys"] = std::move(keys);
        appendExtra(out, extra, "keys");
        return out;
    }
    }
    appendExtra(out, extra);
    return out;
}

ojson writeModifier(const ModifierSpec& m)
{
    ojson out = ojson::object();
    out["schema"] = "Modifier.2";
    out["kind"] = nameOf(kModifierKinds, m.kind);
    switch (m.kind) {
    case ModifierKind::TimeStretch: out["factor"] = m.factor; break;
    case ModifierKind::TimeWarp:
        out["warp"] = writeCurve(m.warp, m.warpExtra);
        out["duration"] = m.duration;
        break;
    case ModifierKind::Loop:
        out["count"] = m.count;
        if (m.rootMotion)
            out["rootMotion"] = true;
        break;
    case ModifierKind::Mirror: out["axis"] = m.axis; break;
    case ModifierKind::GlobalTransform:
        out["rotation"] = {floatForJson(m.rotation.x), floatForJson(m.rotation.y), floatForJson(m.rotation.z),
                           floatForJson(m.rotation.w)};
        out["translation"] = {floatForJson(m.translation.x), floatForJson(m.translation.y),
                              floatForJson(m.translation.z)};
        break;
    case ModifierKind::TimeOffset: out["offset"] = m.offset; break;
    case ModifierKind::Trim:
        out["start"] = m.start;
        out["end"] = m.end;
        break;
    case ModifierKind::DependentJointFilter:
        out["fadeFrom"] = m.fadeFrom;
        out["muteAbove"] = m.muteAbove;
        break;
    }
    appendExtra(out, m.extra);
    return out;
}

ojson writeAction(const ActionSpec& a)
{
    ojson out = ojson::object();
    out["schema"] = "Action.4";
    out["name"] = a.name;
    if (!a.clip.empty() || !a.gaze)
        out["clip"] = a.clip;
    if (a.gaze) {
        ojson gaze = ojson::object();
        gaze["target"] = a.gaze->target;
        gaze["influence"] = a.gaze->influence;
        if (a.gaze->offsetAngle != 0)
            gaze["offsetAngle"] = a.gaze->offsetAngle;
        if (!a.gaze->offsetDirection.empty())
            gaze["offsetDirection"] = a.gaze->offsetDirection;
        out["gaze"] = std::move(gaze);
    }
    if (a.pointing)
        out["pointing"] = ojson{{"target", a.pointing->target}, {"hand", a.pointing->hand}};
    out["start"] = a.start;
    if (!a.modifiers.empty()) {
        ojson modifiers = ojson::array();
        for (const ModifierSpec& m : a.modifiers)
            modifiers.push_back(writeModifier(m));
        out["modifiers"] = std::move(modifiers);
    }
    out["weight"] = writeCurve(a.weight, a.weightExtra);
    out["scale"] = writeCurve(a.scale, a.scaleExtra);
    if (!a.mask.empty())
        out["mask"] = a.mask;
    out["mode"] = nameOf(kBlendModes, a.mode);
    out["renderOutsideDomain"] = a.renderOutsideDomain;
    if (a.placement != Placement::World)
        out["placement"] = nameOf(kPlacements, a.placement);
    appendExtra(out, a.extra);
    return out;
}

ojson writeLayer(const Layer& layer)
{
    ojson out = ojson::object();
    out["schema"] = "Layer.3";
    out["name"] = layer.name;
    out["kind"] = nameOf(kLayerKinds, layer.kind);
    out["mode"] = nameOf(kBlendModes, layer.mode);
    // Written only when set, so that untouched layers read as before.
    if (layer.mute)
        out["mute"] = true;
    if (layer.solo)
        out["solo"] = true;
    if (layer.lock)
        out["lock"] = true;
    ojson actions = ojson::array();
    for (const ActionSpec& a : layer.actions)
        actions.push_back(writeAction(a));
    out["actions"] = std::move(actions);
    appendExtra(out, layer.extra);
    return out;
}

ojson writeClip(const ClipAsset& clip)
{
    ojson out = ojson::object();
    out["schema"] = "Clip.4";
    out["name"] = clip.name;
    if (clip.blinks) {
        ojson blinks = ojson::object();
        blinks["rate"] = clip.blinks->rate;
        blinks["seed"] = clip.blinks->seed;
        blinks["closeSeconds"] = clip.blinks->closeSeconds;
        blinks["shutSeconds"] = clip.blinks->shutSeconds;
        blinks["openSeconds"] = clip.blinks->openSeconds;
        appendExtra(blinks, clip.blinks->extra);
        out["blinks"] = std::move(blinks);
    } else if (clip.idle) {
        ojson idle = ojson::object();
        idle["database"] = clip.idle->database;
        idle["seed"] = clip.idle->seed;
        idle["amplitude"] = clip.idle->amplitude;
        appendExtra(idle, clip.idle->extra);
        out["idle"] = std::move(idle);
    } else if (!clip.file.empty()) {
        out["file"] = clip.file;
        if (clip.frameRateOverride > 0)
            out["frameRate"] = clip.frameRateOverride;
        // Import options only when they differ from the defaults.
        if (!clip.animation.empty())
            out["animation"] = clip.animation;
        if (clip.unit > 0)
            out["unit"] = clip.unit;
        if (!clip.fitGround)
            out["fitGround"] = false;
        if (clip.keepCalibrationFrame)
            out["keepCalibrationFrame"] = true;
        if (!clip.mapping.empty()) {
            ojson mapping = ojson::object();
            for (const auto& [joint, name] : clip.mapping)
                mapping[joint] = name;
            out["mapping"] = std::move(mapping);
        }
    } else {
        out["frameRate"] = clip.frameRate;
        out["joints"] = clip.joints;
        out["rootTranslation"] = clip.rootTranslation;
        if (!clip.scalars.empty())
            out["scalars"] = clip.scalars;
        const std::size_t width = clip.valuesPerFrame();
        ojson frames = ojson::array();
        if (width > 0) {
            for (std::size_t start = 0; start + width <= clip.frames.size(); start += width) {
                ojson row = ojson::array();
                for (std::size_t k = 0; k < width; ++k)
                    row.push_back(floatForJson(clip.frames[start + k]));
                frames.push_back(std::move(row));
            }
        }
        out["frames"] = std::move(frames);
    }
    appendExtra(out, clip.extra);
    return out;
}

ojson writeCharacter(const Character& character)
{
    ojson out = ojson::object();
    out["schema"] = "Character.7";
    out["name"] = character.name;
    out["skeleton"] = character.skeleton;
    // Written only when set, so that scenarios without models stay as they were.
    if (!character.model.empty())
        out["model"] = character.model;
    if (character.position != anim::Vec3{})
        out["position"] = {floatForJson(character.position.x), floatForJson(character.position.y),
                           floatForJson(character.position.z)};
    if (character.heading != 0)
        out["heading"] = character.heading;
    if (!character.segmentTags.empty()) {
        ojson segments = ojson::array();
        for (const scene::SegmentTag& tag : character.segmentTags) {
            ojson entry = ojson::object();
            entry["name"] = tag.segment;
            entry["role"] = scene::segmentRoleName(tag.role);
            segments.push_back(std::move(entry));
        }
        out["segments"] = std::move(segments);
    }
    if (!character.bake.empty())
        out["bake"] = character.bake;
    if (!character.faceMapping.empty())
        out["faceMapping"] = character.faceMapping;
    ojson clips = ojson::array();
    for (const ClipAsset& clip : character.clips)
        clips.push_back(writeClip(clip));
    out["clips"] = std::move(clips);
    ojson layers = ojson::array();
    for (const Layer& layer : character.layers)
        layers.push_back(writeLayer(layer));
    out["layers"] = std::move(layers);
    if (!character.gestures.empty()) {
        ojson gestures = ojson::array();
        for (const Gesture& gesture : character.gestures) {
            ojson entry = ojson::object();
            entry["schema"] = "Gesture.2";
            entry["name"] = gesture.name;
            entry["clip"] = gesture.clip;
            if (!gesture.mask.empty())
                entry["mask"] = gesture.mask;
            entry["fadeIn"] = gesture.fadeIn;
            entry["fadeOut"] = gesture.fadeOut;
            entry["dependentJointFilter"] = gesture.dependentJointFilter;
            if (gesture.filterFadeFrom != Gesture{}.filterFadeFrom || gesture.filterMuteAbove != Gesture{}.filterMuteAbove) {
                entry["filterFadeFrom"] = gesture.filterFadeFrom;
                entry["filterMuteAbove"] = gesture.filterMuteAbove;
            }
            if (gesture.hold)
                entry["fit"] = "hold";
            if (gesture.stroke >= 0)
                entry["stroke"] = gesture.stroke;
            appendExtra(entry, gesture.extra);
            gestures.push_back(std::move(entry));
        }
        out["gestures"] = std::move(gestures);
    }
    if (character.bmlLexicon) {
        ojson lexicon = ojson::object();
        for (const auto& [lexeme, entry] : *character.bmlLexicon)
            lexicon[lexeme] = entry;
        out["bmlLexicon"] = std::move(lexicon);
    }
    if (!character.speech.empty()) {
        ojson speech = ojson::array();
        for (const SpeechLine& line : character.speech) {
            ojson entry = ojson::object();
            entry["schema"] = "SpeechLine.1";
            entry["name"] = line.name;
            if (line.start)
                entry["start"] = *line.start;
            entry["text"] = line.text;
            entry["voice"] = line.voice;
            entry["rate"] = line.rate;
            entry["pitch"] = line.pitch;
            if (!line.audio.empty())
                entry["audio"] = line.audio;
            ojson words = ojson::array();
            for (const SpeechLine::Word& w : line.words)
                words.push_back(ojson{{"text", w.text}, {"start", w.start}, {"end", w.end}});
            entry["words"] = std::move(words);
            ojson phonemes = ojson::array();
            for (const SpeechLine::Phoneme& p : line.phonemes)
                phonemes.push_back(ojson{{"phoneme", p.phoneme}, {"start", p.start}, {"end", p.end}});
            entry["phonemes"] = std::move(phonemes);
            appendExtra(entry, line.extra);
            speech.push_back(std::move(entry));
        }
        out["speech"] = std::move(speech);
    }
    appendExtra(out, character.extra);
    return out;
}

ojson writeMask(const NamedMask& mask)
{
    ojson out = ojson::object();
    out["schema"] = "Mask.1";
    out["name"] = mask.name;
    out["defaultWeight"] = floatForJson(mask.mask.defaultWeight());
    ojson weights = ojson::object();
    for (const auto& [joint, weight] : mask.mask.weights())
        weights[joint] = floatForJson(weight);
    out["weights"] = std::move(weights);
    appendExtra(out, mask.extra);
    return out;
}

std::string dumpScalar(const ojson& value)
{
    return value.dump(-1, ' ', false, ojson::error_handler_t::replace);
}

// Pretty printing that keeps files readable and diffable: objects one member per line, lists
// of plain values (a frame, a quaternion, joint names) on one line.
void print(const ojson& value, int indent, std::string& out)
{
    const std::string inner(std::size_t(indent + 2), ' ');
    if (value.is_object()) {
        if (value.empty()) {
            out += "{}";
            return;
        }
        out += "{\n";
        bool first = true;
        for (const auto& [key, item] : value.items()) {
            if (!first)
                out += ",\n";
            first = false;
            out += inner;
            out += dumpScalar(ojson(key));
            out += ": ";
            print(item, indent + 2, out);
        }
        out += '\n';
        out.append(std::size_t(indent), ' ');
        out += '}';
    } else if (value.is_array()) {
        if (value.empty()) {
            out += "[]";
            return;
        }
        const bool flat = std::none_of(value.begin(), value.end(), [](const ojson& v) { return v.is_structured(); });
        if (flat) {
            out += "[";
            for (std::size_t i = 0; i < value.size(); ++i) {
                if (i > 0)
                    out += ", ";
                out += dumpScalar(value[i]);
            }
            out += "]";
            return;
        }
        out += "[\n";
        for (std::size_t i = 0; i < value.size(); ++i) {
            if (i > 0)
                out += ",\n";
            out += inner;
            print(value[i], indent + 2, out);
        }
        out += '\n';
        out.append(std::size_t(indent), ' ');
        out += ']';
    } else {
        out += dumpScalar(value);
    }
}

} // namespace

ojson writeScenario(const Scenario& scenario)
{
    ojson out = ojson::object();
    out["format"] = FormatName;
    out["version"] = int(format::Current);
    out["schema"] = "Scenario.12";
    out["name"] = scenario.name;
    out["duration"] = scenario.duration;
    ojson masks = ojson::array();
    for (const NamedMask& mask : scenario.masks)
        masks.push_back(writeMask(mask));
    out["masks"] = std::move(masks);
    ojson characters = ojson::array();
    for (const Character& character : scenario.characters)
        characters.push_back(writeCharacter(character));
    out["characters"] = std::move(characters);
    if (scenario.lighting != LightingSpec{}) {
        ojson lighting = ojson::object();
        lighting["schema"] = "Lighting.2";
        lighting["probe"] = scenario.lighting.probe;
        lighting["layout"] = scenario.lighting.layout;
        if (scenario.lighting.rotation != 0)
            lighting["rotation"] = scenario.lighting.rotation;
        if (scenario.lighting.intensity != 1)
            lighting["intensity"] = scenario.lighting.intensity;
        appendExtra(lighting, scenario.lighting.extra);
        out["lighting"] = std::move(lighting);
    }
    if (!scenario.postureBases.empty())
        out["postureBases"] = scenario.postureBases;
    if (scenario.ar != ArSpec{})
        out["ar"] = writeArSpec(scenario.ar);
    if (!scenario.markers.empty()) {
        ojson markers = ojson::array();
        for (const Marker& marker : scenario.markers) {
            ojson entry = ojson::object();
            entry["schema"] = "Marker.1";
            entry["name"] = marker.name;
            entry["time"] = marker.time;
            appendExtra(entry, marker.extra);
            markers.push_back(std::move(entry));
        }
        out["markers"] = std::move(markers);
    }
    if (!scenario.scripts.empty()) {
        ojson scripts = ojson::array();
        for (const ScriptSpec& script : scenario.scripts) {
            ojson entry = ojson::object();
            entry["schema"] = "Script.1";
            entry["name"] = script.name;
            entry["source"] = script.source;
            appendExtra(entry, script.extra);
            scripts.push_back(std::move(entry));
        }
        out["scripts"] = std::move(scripts);
    }
    appendExtra(out, scenario.extra);
    return out;
}

} // namespace detail

std::string serializeScenario(const Scenario& scenario)
{
    std::string text;
    detail::print(detail::writeScenario(scenario), 0, text);
    text += "\n";
    return text;
}

} // namespace thespis::core::scenario
