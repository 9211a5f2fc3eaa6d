// Reading scenario JSON into the document model: one reader per object, each naming the field
// path of anything wrong (scenario_io.h).
#include <algorithm>
#include <limits>
#include <map>
#include <set>

#include "lighting/probe.h"
#include "scenario/scenario_json.h"
#include "scenario/scenario_object_reader.h"
#include "util/text.h"

namespace thespis::core::scenario::detail {

namespace {

// What a curve drives decides which values are allowed.
enum class CurveUse { Weight, Scale, Warp };

anim::Curve readCurve(const json& value, const std::string& path, CurveUse use, json& extra)
{
    ObjectReader r(value, path, "Curve.1");
    const anim::CurveKind kind = r.enumeration("kind", kCurveKinds, true, anim::CurveKind::Constant);
    // A weight must not go below 0 (the blend divides by the sum of weights).
    const Range level = use == CurveUse::Weight ? Range::NonNegative : Range::Any;
    anim::Curve curve;
    json keyExtras = json::array();
    bool anyKeyExtra = false;
    switch (kind) {
    case anim::CurveKind::Constant:
        curve = anim::Curve::constant(r.number("value", true, 1, level));
        break;
    case anim::CurveKind::LinearFade:
    case anim::CurveKind::CubicFade: {
        const double fadeIn = r.number("fadeIn", true, 0, Range::NonNegative);
        const double fadeOut = r.number("fadeOut", true, 0, Range::NonNegative);
        const double peak = r.number("peak", false, 1, level);
        curve = kind == anim::CurveKind::LinearFade ? anim::Curve::linearFade(fadeIn, fadeOut, peak)
                                                    : anim::Curve::cubicFade(fadeIn, fadeOut, peak);
        break;
    }
    case anim::CurveKind::LinearAdsr:
    case anim::CurveKind::CubicAdsr: {
        const double attack = r.number("attack", true, 0, Range::NonNegative);
        const double decay = r.number("decay", true, 0, Range::NonNegative);
        const double sustain = r.number("sustain", true, 1, Range::UnitInterval);
        const double release = r.number("release", true, 0, Range::NonNegative);
        const double peak = r.number("peak", false, 1, level);
        curve = kind == anim::CurveKind::LinearAdsr ? anim::Curve::linearAdsr(attack, decay, sustain, release, peak)
                                                    : anim::Curve::cubicAdsr(attack, decay, sustain, release, peak);
        break;
    }
    case anim::CurveKind::Dominance: {
        const double alpha = r.number("alpha", true, 1, Range::Positive);
        curve = anim::Curve::dominance(alpha, r.number("peak", false, 1, level));
        break;
    }
    case anim::CurveKind::Keyframed: {
        const json& list = r.array("keys", true);
        if (list.empty())
            fail(r.fieldPath("keys"), "a keyframed curve needs at least one key");
        std::vector<anim::CurveKey> keys;
        for (std::size_t i = 0; i < list.size(); ++i) {
            ObjectReader k(list[i], indexed(r.fieldPath("keys"), i), {});
            anim::CurveKey key;
            key.time = k.number("time", true, 0, Range::Any);
            key.value = k.number("value", true, 0, level);
            key.mode = k.enumeration("tangent", kTangentModes, false, anim::TangentMode::AutoClamped);
            key.inSlope = k.number("inSlope", false, 0, Range::Any);
            key.outSlope = k.number("outSlope", false, 0, Range::Any);
            if (i > 0 && !(key.time > keys.back().time))
                fail(k.fieldPath("time"), "keys must be in increasing time order (the previous key is at "
                                              + json(keys.back().time).dump() + " s)");
            keys.push_back(key);
            keyExtras.push_back(k.extra());
            anyKeyExtra = anyKeyExtra || !keyExtras.back().empty();
        }
        auto made = anim::Curve::keyframed(std::move(keys));
        if (!made)
            fail(r.fieldPath("keys"), made.error().message);
        curve = std::move(made).value();
        break;
    }
    }
    extra = r.extra();
    // Unknown members of keys travel with the curve's own, as a list aligned with the keys.
    if (anyKeyExtra)
        extra["keys"] = std::move(keyExtras);
    return curve;
}

ModifierSpec readModifier(const json& value, const std::string& path)
{
    ObjectReader r(value, path, "Modifier.2");
    ModifierSpec m;
    m.kind = r.enumeration("kind", kModifierKinds, true, ModifierKind::Loop);
    switch (m.kind) {
    case ModifierKind::TimeStretch:
        m.factor = r.number("factor", true, 1, Range::Positive);
        break;
    case ModifierKind::TimeWarp:
        m.warp = readCurve(r.require("warp"), r.fieldPath("warp"), CurveUse::Warp, m.warpExtra);
        m.duration = r.number("duration", true, 0, Range::Positive);
        break;
    case ModifierKind::Loop:
        m.count = int(r.integer("count", true, 0, 0, std::numeric_limits<int>::max()));
        m.rootMotion = r.boolean("rootMotion", false);
        break;
    case ModifierKind::Mirror:
        m.axis = int(r.integer("axis", false, 0, 0, 2));
        break;
    case ModifierKind::GlobalTransform: {
        if (const json* rotation = r.find("rotation")) {
            const std::string at = r.fieldPath("rotation");
            if (!rotation->is_array() || rotation->size() != 4)
                fail(at, "expected a quaternion [x, y, z, w], found " + describeValue(*rotation));
            float q[4];
            for (std::size_t i = 0; i < 4; ++i)
                q[i] = ObjectReader::checkedFloat((*rotation)[i], indexed(at, i), Range::Any);
            m.rotation = {q[0], q[1], q[2], q[3]};
            const double length = std::sqrt(double(anim::dot(m.rotation, m.rotation)));
            if (std::abs(length - 1.0) > 1e-3)
                fail(at, "expected a unit quaternion, found one of length " + json(length).dump());
        }
        if (const json* translation = r.find("translation")) {
            const std::string at = r.fieldPath("translation");
            if (!translation->is_array() || translation->size() != 3)
                fail(at, "expected a vector [x, y, z], found " + describeValue(*translation));
            m.translation = {ObjectReader::checkedFloat((*translation)[0], indexed(at, 0), Range::Any),
                             ObjectReader::checkedFloat((*translation)[1], indexed(at, 1), Range::Any),
                             ObjectReader::checkedFloat((*translation)[2], indexed(at, 2), Range::Any)};
        }
        break;
    }
    case ModifierKind::TimeOffset:
        m.offset = r.number("offset", true, 0, Range::Any);
        break;
    case ModifierKind::Trim:
        m.start = r.number("start", true, 0, Range::NonNegative);
        m.end = r.number("end", true, 0, Range::NonNegative);
        if (!(m.end > m.start))
            fail(r.fieldPath("end"), "must be after start (" + json(m.start).dump() + " s), found "
                                         + json(m.end).dump() + " s");
        break;
    case ModifierKind::DependentJointFilter:
        m.fadeFrom = int(r.integer("fadeFrom", false, 20, 1, 78));
        m.muteAbove = int(r.integer("muteAbove", false, 30, 1, 78));
        if (m.muteAbove < m.fadeFrom)
            fail(r.fieldPath("muteAbove"), "must not be below fadeFrom (" + std::to_string(m.fadeFrom) + "), found "
                                               + std::to_string(m.muteAbove));
        break;
    }
    m.extra = r.extra();
    return m;
}

// {"target": "Creon", "influence": "HEAD", "offsetAngle": 10, "offsetDirection": "LEFT"}: all
// but the target optional. Whether they read as gaze is the runtime's to check (it names the action).
GazeSpec readGaze(const json& value, const std::string& path)
{
    ObjectReader r(value, path, "");
    GazeSpec gaze;
    gaze.target = r.name("target");
    gaze.influence = r.string("influence", false, gaze.influence);
    gaze.offsetAngle = r.number("offsetAngle", false, 0, Range::Any);
    gaze.offsetDirection = r.string("offsetDirection", false);
    if (!r.extra().empty())
        fail(path + "." + r.extra().begin().key(),
             "unknown member of a gaze (known: target, influence, offsetAngle, offsetDirection)");
    return gaze;
}

// {"target": "Antigone", "hand": "LEFT_HAND"}: the hand optional. Whether they read is the
// runtime's to check, as for a gaze.
PointingSpec readPointing(const json& value, const std::string& path)
{
    ObjectReader r(value, path, "");
    PointingSpec pointing;
    pointing.target = r.name("target");
    pointing.hand = r.string("hand", false, pointing.hand);
    if (!r.extra().empty())
        fail(path + "." + r.extra().begin().key(), "unknown member of a pointing (known: target, hand)");
    return pointing;
}

ActionSpec readAction(const json& value, const std::string& path)
{
    ObjectReader r(value, path, "Action.4");
    ActionSpec a;
    a.name = r.name();
    if (const json* gaze = r.find("gaze"))
        a.gaze = readGaze(*gaze, r.fieldPath("gaze"));
    a.clip = a.gaze ? r.string("clip", false) : r.name("clip"); // a gaze action plays no clip
    if (const json* pointing = r.find("pointing"))
        a.pointing = readPointing(*pointing, r.fieldPath("pointing"));
    a.start = r.ticks("start", true);
    const json& modifiers = r.array("modifiers", false);
    for (std::size_t i = 0; i < modifiers.size(); ++i)
        a.modifiers.push_back(readModifier(modifiers[i], indexed(r.fieldPath("modifiers"), i)));
    if (const json* weight = r.find("weight"))
        a.weight = readCurve(*weight, r.fieldPath("weight"), CurveUse::Weight, a.weightExtra);
    if (const json* scale = r.find("scale"))
        a.scale = readCurve(*scale, r.fieldPath("scale"), CurveUse::Scale, a.scaleExtra);
    a.mask = r.string("mask", false);
    a.mode = r.enumeration("mode", kBlendModes, false, anim::BlendMode::Normalized);
    a.renderOutsideDomain = r.boolean("renderOutsideDomain", false);
    a.placement = r.enumeration("placement", kPlacements, false, Placement::World);
    a.extra = r.extra();
    return a;
}

Layer readLayer(const json& value, const std::string& path)
{
    ObjectReader r(value, path, "Layer.3");
    Layer layer;
    layer.name = r.name();
    layer.kind = r.enumeration("kind", kLayerKinds, false, LayerKind::Body);
    layer.mode = r.enumeration("mode", kBlendModes, false, anim::BlendMode::Normalized);
    layer.mute = r.boolean("mute", false);
    layer.solo = r.boolean("solo", false);
    layer.lock = r.boolean("lock", false);
    const json& actions = r.array("actions", false);
    for (std::size_t i = 0; i < actions.size(); ++i)
        layer.actions.push_back(readAction(actions[i], indexed(r.fieldPath("actions"), i)));
    layer.extra = r.extra();
    return layer;
}

ClipAsset readClip(const json& value, const std::string& path)
{
    ObjectReader r(value, path, "Clip.4");
    ClipAsset clip;
    clip.name = r.name();
    if (const json* blinks = r.find("blinks")) {
        for (const char* other : {"idle", "file", "frameRate", "animation", "unit", "fitGround", "keepCalibrationFrame",
                                  "mapping", "joints", "rootTranslation", "scalars", "frames"})
            if (r.find(other))
                fail(r.fieldPath(other), "a blink clip is synthesized: it has no file and no keyframes");
        ObjectReader s(*blinks, r.fieldPath("blinks"), "");
        BlinkClip b;
        b.rate = s.number("rate", false, 17, Range::Positive);
        b.seed = std::uint64_t(s.integer("seed", false, 1, 0, std::int64_t(1) << 53));
        b.closeSeconds = s.number("closeSeconds", false, 0.10, Range::Positive);
        b.shutSeconds = s.number("shutSeconds", false, 0.03, Range::NonNegative);
        b.openSeconds = s.number("openSeconds", false, 0.25, Range::Positive);
        if (const auto wrong = b.problem())
            fail(s.fieldPath(wrong->field), wrong->message);
        b.extra = s.extra();
        clip.blinks = std::move(b);
    } else if (const json* idle = r.find("idle")) {
        for (const char* other : {"file", "frameRate", "animation", "unit", "fitGround", "keepCalibrationFrame", "mapping",
                                  "joints", "rootTranslation", "scalars", "frames"})
            if (r.find(other))
                fail(r.fieldPath(other), "an idle motion clip is synthesized: it has no file and no keyframes");
        ObjectReader s(*idle, r.fieldPath("idle"), "");
        IdleSynthesizer synthesizer;
        synthesizer.database = s.string("database", true);
        if (synthesizer.database.empty())
            fail(s.fieldPath("database"), "must name an idle motion database file (.idle)");
        synthesizer.seed = std::uint64_t(s.integer("seed", false, 1, 0, std::int64_t(1) << 53));
        synthesizer.amplitude = s.number("amplitude", false, 1, Range::NonNegative);
        if (synthesizer.amplitude > 10)
            fail(s.fieldPath("amplitude"), "must be at most 10, found " + std::to_string(synthesizer.amplitude));
        synthesizer.extra = s.extra();
        clip.idle = std::move(synthesizer);
    } else if (r.find("file")) {
        clip.file = r.string("file", true);
        if (clip.file.empty())
            fail(r.fieldPath("file"), "must not be empty (leave the field out for a clip stored inline)");
        clip.frameRateOverride = r.number("frameRate", false, 0, Range::Positive);
        for (const char* inlineField : {"joints", "rootTranslation", "scalars", "frames"})
            if (r.find(inlineField))
                fail(r.fieldPath(inlineField), "a clip read from a file cannot also hold inline keyframes");
        clip.animation = r.string("animation", false);
        clip.unit = r.number("unit", false, 0, Range::NonNegative);
        clip.fitGround = r.boolean("fitGround", true);
        clip.keepCalibrationFrame = r.boolean("keepCalibrationFrame", false);
        if (const json* mapping = r.find("mapping")) {
            if (!mapping->is_object())
                fail(r.fieldPath("mapping"), "expected an object of file joint names and H-Anim names, found "
                                                 + describeValue(*mapping));
            for (const auto& [joint, name] : mapping->items()) {
                const std::string at = r.fieldPath("mapping") + "." + joint;
                if (joint.empty())
                    fail(r.fieldPath("mapping"), "a file joint name must not be empty");
                if (!name.is_string())
                    fail(at, "expected a joint name, found " + describeValue(name));
                clip.mapping[joint] = name.get<std::string>();
            }
        }
    } else {
        for (const char* fileField : {"animation", "unit", "fitGround", "keepCalibrationFrame", "mapping"})
            if (r.find(fileField))
                fail(r.fieldPath(fileField), "only a clip read from a file has this");
        clip.frameRate = r.number("frameRate", true, 30, Range::Positive);
        clip.joints = r.names("joints");
        clip.rootTranslation = r.boolean("rootTranslation", false);
        clip.scalars = r.names("scalars");
        if (clip.rootTranslation && clip.joints.empty())
            fail(r.fieldPath("rootTranslation"), "a root translation needs a root joint (the first of joints)");
        if (clip.joints.empty() && clip.scalars.empty())
            fail(r.fieldPath("joints"), "an inline clip needs at least one joint or scalar");
        const std::size_t width = clip.valuesPerFrame();
        const json& frames = r.array("frames", true);
        if (frames.empty())
            fail(r.fieldPath("frames"), "an inline clip needs at least one frame");
        clip.frames.reserve(frames.size() * width);
        for (std::size_t f = 0; f < frames.size(); ++f) {
            const std::string at = indexed(r.fieldPath("frames"), f);
            const json& row = frames[f];
            if (!row.is_array() || row.size() != width)
                fail(at, "expected a list of " + std::to_string(width) + " numbers ("
                             + std::to_string(clip.joints.size()) + " rotations x y z w"
                             + (clip.rootTranslation ? ", a root translation x y z" : "")
                             + (clip.scalars.empty() ? "" : ", " + std::to_string(clip.scalars.size()) + " scalars")
                             + "), found " + (row.is_array() ? std::to_string(row.size()) + " values" : describeValue(row)));
            for (std::size_t k = 0; k < width; ++k)
                clip.frames.push_back(ObjectReader::checkedFloat(row[k], indexed(at, k), Range::Any));
        }
    }
    clip.extra = r.extra();
    return clip;
}

bool isSkeletonSpec(const std::string& spec)
{
    return spec == "hanim-loa1" || spec == "hanim-loa2" || spec == "hanim-25" || spec == "model"
           || (spec.starts_with("clip:") && spec.size() > 5);
}

// {"name": "hair", "role": "receiver"}; the role is optional.
scene::SegmentTag readSegmentTag(const json& value, const std::string& path)
{
    ObjectReader r(value, path, "");
    scene::SegmentTag tag;
    tag.segment = r.name();
    if (const std::string role = r.string("role", false); !role.empty()) {
        auto parsed = scene::parseSegmentRole(role);
        if (!parsed)
            fail(r.fieldPath("role"), parsed.error().message);
        tag.role = *parsed;
    }
    // Unknown members of a tag are not kept: a tag is a small closed record.
    if (!r.extra().empty())
        fail(path + "." + r.extra().begin().key(), "unknown member of a segment tag (known: name, role)");
    return tag;
}

LightingSpec readLighting(const json& value, const std::string& path)
{
    ObjectReader r(value, path, "Lighting.2");
    LightingSpec lighting;
    lighting.probe = r.string("probe", false);
    lighting.layout = r.string("layout", false, lighting.layout);
    if (auto layout = lighting::parseProbeLayout(lighting.layout); !layout)
        fail(r.fieldPath("layout"), layout.error().message);
    lighting.rotation = r.number("rotation", false, 0, Range::Any);
    lighting.intensity = r.number("intensity", false, 1, Range::NonNegative);
    lighting.extra = r.extra();
    return lighting;
}

Gesture readGesture(const json& value, const std::string& path)
{
    ObjectReader r(value, path, "Gesture.2");
    Gesture gesture;
    gesture.name = r.name();
    gesture.clip = r.name("clip");
    gesture.mask = r.string("mask", false);
    gesture.fadeIn = r.ticks("fadeIn", false);
    gesture.fadeOut = r.ticks("fadeOut", false);
    gesture.dependentJointFilter = r.boolean("dependentJointFilter", false);
    gesture.filterFadeFrom = int(r.integer("filterFadeFrom", false, 20, 1, 78));
    gesture.filterMuteAbove = int(r.integer("filterMuteAbove", false, 30, 1, 78));
    if (gesture.filterMuteAbove < gesture.filterFadeFrom)
        fail(r.fieldPath("filterMuteAbove"), "must not be below filterFadeFrom (" + std::to_string(gesture.filterFadeFrom) +
                                                 "), found " + std::to_string(gesture.filterMuteAbove));
    const std::string fit = r.string("fit", false, "stretch");
    if (fit != "stretch" && fit != "hold")
        fail(r.fieldPath("fit"), "expected \"stretch\" or \"hold\", found " + describeValue(json(fit)));
    gesture.hold = fit == "hold";
    gesture.stroke = r.number("stroke", false, -1, Range::NonNegative);
    gesture.extra = r.extra();
    return gesture;
}

Marker readMarker(const json& value, const std::string& path)
{
    ObjectReader r(value, path, "Marker.1");
    Marker marker;
    marker.name = r.string("name", false);
    marker.time = r.ticks("time", true);
    marker.extra = r.extra();
    return marker;
}

ScriptSpec readScript(const json& value, const std::string& path)
{
    ObjectReader r(value, path, "Script.1");
    ScriptSpec script;
    script.name = r.name();
    script.source = r.string("source", true);
    script.extra = r.extra();
    return script;
}

SpeechLine readSpeechLine(const json& value, const std::string& path)
{
    ObjectReader r(value, path, "SpeechLine.1");
    SpeechLine line;
    line.name = r.name();
    if (r.find("start"))
        line.start = r.ticks("start", true);
    else
        line.start.reset(); // not on the timeline: said by scripts
    line.text = r.string("text", true);
    line.voice = r.string("voice", false, line.voice);
    line.rate = int(r.integer("rate", false, line.rate, 80, 450));
    line.pitch = int(r.integer("pitch", false, line.pitch, 0, 100));
    line.audio = r.string("audio", false);
    const json& words = r.array("words", false);
    for (std::size_t i = 0; i < words.size(); ++i) {
        ObjectReader w(words[i], indexed(r.fieldPath("words"), i), {});
        line.words.push_back({w.string("text", true), w.number("start", true, 0, Range::NonNegative),
                              w.number("end", true, 0, Range::NonNegative)});
        w.refuseUnknown("a word");
    }
    const json& phonemes = r.array("phonemes", false);
    for (std::size_t i = 0; i < phonemes.size(); ++i) {
        ObjectReader p(phonemes[i], indexed(r.fieldPath("phonemes"), i), {});
        line.phonemes.push_back({p.string("phoneme", true), p.number("start", true, 0, Range::NonNegative),
                                 p.number("end", true, 0, Range::NonNegative)});
        p.refuseUnknown("a phoneme");
    }
    line.extra = r.extra();
    return line;
}

// {"BEAT": "agree", "POINT": "point"}: BML lexemes and the gestures that play them. A lexeme is
// the same in any case, so two rows may not differ only by it; whether a gesture of that name
// exists is the runtime's to check (a warning), as a row only matters once BML names its lexeme.
std::map<std::string, std::string> readBmlLexicon(const json& value, const std::string& path)
{
    if (!value.is_object())
        fail(path, "expected an object of BML lexemes and gesture names, found " + describeValue(value));
    std::map<std::string, std::string> rows;
    std::map<std::string, std::string> byUpperCase;
    for (const auto& [lexeme, entry] : value.items()) {
        const std::string at = path + "." + lexeme;
        if (lexeme.empty())
            fail(path, "a lexeme must not be empty");
        if (!entry.is_string() || entry.get_ref<const std::string&>().empty())
            fail(at, "expected the name of a gesture of the character, found " + describeValue(entry));
        if (const auto [other, added] = byUpperCase.emplace(uppercase(lexeme), lexeme); !added)
            fail(at, "the lexeme " + quote(other->second) + " is the same in another case");
        rows[lexeme] = entry.get<std::string>();
    }
    return rows;
}

Character readCharacter(const json& value, const std::string& path)
{
    ObjectReader r(value, path, "Character.7");
    Character character;
    character.name = r.name();
    character.skeleton = r.string("skeleton", false, "hanim-loa1");
    if (!isSkeletonSpec(character.skeleton))
        fail(r.fieldPath("skeleton"), "expected \"hanim-loa1\", \"hanim-loa2\", \"hanim-25\", \"model\" or \"clip:NAME\", found "
                                          + quote(character.skeleton));
    character.model = r.string("model", false);
    if (character.skeleton == "model" && character.model.empty())
        fail(r.fieldPath("skeleton"), "\"model\" plays on the model's own rig, and the character has no model");
    if (const json* position = r.find("position")) {
        const std::string at = r.fieldPath("position");
        if (!position->is_array() || position->size() != 3)
            fail(at, "expected a position [x, y, z] in metres, found " + describeValue(*position));
        character.position = {ObjectReader::checkedFloat((*position)[0], indexed(at, 0), Range::Any),
                              ObjectReader::checkedFloat((*position)[1], indexed(at, 1), Range::Any),
                              ObjectReader::checkedFloat((*position)[2], indexed(at, 2), Range::Any)};
    }
    character.heading = r.number("heading", false, 0, Range::Any);
    character.bake = r.string("bake", false);
    character.faceMapping = r.string("faceMapping", false);
    std::set<std::string> names;
    const json& segments = r.array("segments", false);
    for (std::size_t i = 0; i < segments.size(); ++i) {
        character.segmentTags.push_back(readSegmentTag(segments[i], indexed(r.fieldPath("segments"), i)));
        if (!names.insert(character.segmentTags.back().segment).second)
            fail(indexed(r.fieldPath("segments"), i) + ".name",
                 "segment " + quote(character.segmentTags.back().segment) + " is tagged twice");
    }
    names.clear();
    const json& clips = r.array("clips", false);
    for (std::size_t i = 0; i < clips.size(); ++i) {
        character.clips.push_back(readClip(clips[i], indexed(r.fieldPath("clips"), i)));
        if (!names.insert(character.clips.back().name).second)
            fail(indexed(r.fieldPath("clips"), i) + ".name",
                 "another clip of this character is already named " + quote(character.clips.back().name));
    }
    names.clear();
    const json& layers = r.array("layers", false);
    for (std::size_t i = 0; i < layers.size(); ++i) {
        character.layers.push_back(readLayer(layers[i], indexed(r.fieldPath("layers"), i)));
        if (!names.insert(character.layers.back().name).second)
            fail(indexed(r.fieldPath("layers"), i) + ".name",
                 "another layer of this character is already named " + quote(character.layers.back().name));
    }
    names.clear();
    const json& gestures = r.array("gestures", false);
    for (std::size_t i = 0; i < gestures.size(); ++i) {
        character.gestures.push_back(readGesture(gestures[i], indexed(r.fieldPath("gestures"), i)));
        if (!names.insert(character.gestures.back().name).second)
            fail(indexed(r.fieldPath("gestures"), i) + ".name",
                 "another gesture of this character is already named " + quote(character.gestures.back().name));
    }
    if (const json* lexicon = r.find("bmlLexicon"))
        character.bmlLexicon = readBmlLexicon(*lexicon, r.fieldPath("bmlLexicon"));
    names.clear();
    const json& speech = r.array("speech", false);
    for (std::size_t i = 0; i < speech.size(); ++i) {
        character.speech.push_back(readSpeechLine(speech[i], indexed(r.fieldPath("speech"), i)));
        if (!names.insert(character.speech.back().name).second)
            fail(indexed(r.fieldPath("speech"), i) + ".name",
                 "another speech line of this character is already named " + quote(character.speech.back().name));
    }
    character.extra = r.extra();
    return character;
}

NamedMask readMask(const json& value, const std::string& path)
{
    ObjectReader r(value, path, "Mask.1");
    NamedMask mask;
    mask.name = r.name();
    const float defaultWeight = r.floatNumber("defaultWeight", false, 0.0f, Range::UnitInterval);
    std::map<std::string, float> weights;
    if (const json* list = r.find("weights")) {
        if (!list->is_object())
            fail(r.fieldPath("weights"), "expected an object of joint names and weights, found " + describeValue(*list));
        for (const auto& [joint, weight] : list->items()) {
            const std::string at = r.fieldPath("weights") + "." + joint;
            if (joint.empty())
                fail(r.fieldPath("weights"), "a joint name must not be empty");
            weights[joint] = ObjectReader::checkedFloat(weight, at, Range::UnitInterval);
        }
    }
    mask.mask = anim::JointMask(std::move(weights), defaultWeight);
    mask.extra = r.extra();
    return mask;
}

} // namespace

Scenario readScenario(const json& document)
{
    ObjectReader r(document, "", "Scenario.12");
    r.find("format");  // checked before
    r.find("version");
    Scenario scenario;
    scenario.name = r.string("name", false);
    scenario.duration = r.ticks("duration", false);
    std::set<std::string> names;
    const json& masks = r.array("masks", false);
    for (std::size_t i = 0; i < masks.size(); ++i) {
        scenario.masks.push_back(readMask(masks[i], indexed("masks", i)));
        if (!names.insert(scenario.masks.back().name).second)
            fail(indexed("masks", i) + ".name", "another mask is already named " + quote(scenario.masks.back().name));
    }
    names.clear();
    const json& characters = r.array("characters", false);
    for (std::size_t i = 0; i < characters.size(); ++i) {
        scenario.characters.push_back(readCharacter(characters[i], indexed("characters", i)));
        if (!names.insert(scenario.characters.back().name).second)
            fail(indexed("characters", i) + ".name",
                 "another character is already named " + quote(scenario.characters.back().name));
    }
    if (const json* lighting = r.find("lighting"))
        scenario.lighting = readLighting(*lighting, "lighting");
    scenario.postureBases = r.string("postureBases", false);
    if (const json* ar = r.find("ar"))
        scenario.ar = readArSpec(*ar, "ar");
    const json& markers = r.array("markers", false);
    for (std::size_t i = 0; i < markers.size(); ++i)
        scenario.markers.push_back(readMarker(markers[i], indexed("markers", i)));
    names.clear();
    const json& scripts = r.array("scripts", false);
    for (std::size_t i = 0; i < scripts.size(); ++i) {
        scenario.scripts.push_back(readScript(scripts[i], indexed("scripts", i)));
        if (!names.insert(scenario.scripts.back().name).second)
            fail(indexed("scripts", i) + ".name", "another script is already named " + quote(scenario.scripts.back().name));
    }
    scenario.extra = r.extra();
    return scenario;
}

} // namespace thespis::core::scenario::detail
