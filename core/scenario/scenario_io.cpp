#include "scenario/scenario_io.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "lighting/probe.h"
#include "scenario/scenario_upgrade.h"
#include "util/file_io.h"

namespace thespis::core::scenario {

// ---------------------------------------------------------------------------------------------
// Upgrade steps

namespace detail {

// 1 → 2: layers gained mute / solo / lock, characters a gesticon, the scenario markers. All are
// optional, so a version 1 document only needs the new schema names of the objects that changed.
static Result<void> upgradeV1toV2(nlohmann::json& document)
{
    auto renameSchema = [](nlohmann::json& object, std::string_view from, std::string_view to) {
        if (!object.is_object())
            return; // the reader names the field that is not an object
        const auto schema = object.find("schema");
        if (schema != object.end() && schema->is_string() && schema->get_ref<const std::string&>() == from)
            *schema = to;
    };
    renameSchema(document, "Scenario.1", "Scenario.2");
    const auto characters = document.find("characters");
    if (characters == document.end() || !characters->is_array())
        return {};
    for (nlohmann::json& character : *characters) {
        renameSchema(character, "Character.1", "Character.2");
        if (!character.is_object())
            continue;
        const auto layers = character.find("layers");
        if (layers != character.end() && layers->is_array())
            for (nlohmann::json& layer : *layers)
                renameSchema(layer, "Layer.1", "Layer.2");
    }
    return {};
}

std::span<const UpgradeStep> upgradeSteps()
{
    static constexpr UpgradeStep steps[] = {
        {format::Initial, "timeline state and gesticon", &upgradeV1toV2},
    };
    return steps;
}

Result<void> runUpgradeSteps(nlohmann::json& document, int fromVersion, int toVersion,
                             std::span<const UpgradeStep> steps)
{
    for (int version = fromVersion; version < toVersion; ++version) {
        const auto step = std::find_if(steps.begin(), steps.end(),
                                       [&](const UpgradeStep& s) { return s.from == version; });
        if (step == steps.end() || !step->apply)
            return makeError(ErrorCode::Internal,
                             "This Thespis cannot upgrade a scenario from format " + std::to_string(version)
                                 + " to " + std::to_string(version + 1) + ".",
                             "no upgrade step registered for version " + std::to_string(version));
        const std::string what = "Upgrading the scenario from format " + std::to_string(version) + " to "
                                 + std::to_string(version + 1) + " (" + step->name + ") failed";
        try {
            if (auto ok = step->apply(document); !ok)
                return makeError(ErrorCode::CorruptData, what + ": " + ok.error().message, ok.error().detail);
        } catch (const std::exception& e) {
            return makeError(ErrorCode::CorruptData, what + ".", e.what());
        }
        if (document.is_object())
            document["version"] = version + 1;
    }
    return {};
}

} // namespace detail

namespace {

using json = nlohmann::json;
using ojson = nlohmann::ordered_json;

// Documents nest a handful of levels; unknown fields could nest deeper, but a limit keeps the
// recursive parts (comparison, writing, destruction of foreign code's copies) safe from
// hostile files.
constexpr int kMaxDepth = 64;

// Thrown inside the reader only, caught in parseScenario: a field path and what is wrong.
struct FieldError {
    std::string path;
    std::string message;
};

[[noreturn]] void fail(const std::string& path, std::string message)
{
    throw FieldError{path, std::move(message)};
}

std::string join(const std::string& path, std::string_view key)
{
    return path.empty() ? std::string(key) : path + "." + std::string(key);
}

std::string indexed(const std::string& path, std::size_t index)
{
    return path + "[" + std::to_string(index) + "]";
}

std::string quote(std::string_view text)
{
    return json(std::string(text)).dump(-1, ' ', false, json::error_handler_t::replace);
}

// What a JSON value is, for "expected X, found Y" messages: short, with the value if small.
std::string describeValue(const json& value)
{
    switch (value.type()) {
    case json::value_t::null: return "null";
    case json::value_t::boolean: return value.get<bool>() ? "true" : "false";
    case json::value_t::string: {
        const auto& s = value.get_ref<const std::string&>();
        return s.size() <= 40 ? "the text " + quote(s) : "a text";
    }
    case json::value_t::number_integer:
    case json::value_t::number_unsigned:
    case json::value_t::number_float: return value.dump();
    case json::value_t::object: return "an object";
    case json::value_t::array: return "a list";
    default: return "an unsupported value";
    }
}

// The float nearest to `value`, as the double with the same shortest decimal form, so that
// files show "0.1" rather than "0.10000000149011612" and read back to the same float.
double floatForJson(float value)
{
    char buffer[32];
    const auto written = std::to_chars(buffer, buffer + sizeof buffer, value);
    double shortest = value;
    std::from_chars(buffer, written.ptr, shortest);
    // Read back through double, the decimal form must give the same float; if a double rounding
    // ever crossed a boundary, the exact value is written instead.
    return float(shortest) == value ? shortest : double(value);
}

// ---------------------------------------------------------------------------------------------
// Enumerations by name

template <class E>
struct NamedValue {
    E value;
    std::string_view name;
};

constexpr NamedValue<anim::CurveKind> kCurveKinds[] = {
    {anim::CurveKind::Constant, "constant"},     {anim::CurveKind::LinearFade, "linearFade"},
    {anim::CurveKind::CubicFade, "cubicFade"},   {anim::CurveKind::LinearAdsr, "linearAdsr"},
    {anim::CurveKind::CubicAdsr, "cubicAdsr"},   {anim::CurveKind::Keyframed, "keyframed"},
};
constexpr NamedValue<anim::TangentMode> kTangentModes[] = {
    {anim::TangentMode::AutoClamped, "autoClamped"}, {anim::TangentMode::Linear, "linear"},
    {anim::TangentMode::Constant, "constant"},       {anim::TangentMode::Free, "free"},
    {anim::TangentMode::Broken, "broken"},
};
constexpr NamedValue<anim::BlendMode> kBlendModes[] = {
    {anim::BlendMode::Normalized, "normalized"},
    {anim::BlendMode::Additive, "additive"},
    {anim::BlendMode::Override, "override"},
};
constexpr NamedValue<ModifierKind> kModifierKinds[] = {
    {ModifierKind::TimeStretch, "timeStretch"}, {ModifierKind::TimeWarp, "timeWarp"},
    {ModifierKind::Loop, "loop"},               {ModifierKind::Mirror, "mirror"},
    {ModifierKind::GlobalTransform, "globalTransform"}, {ModifierKind::TimeOffset, "timeOffset"},
    {ModifierKind::Trim, "trim"},
};
constexpr NamedValue<LayerKind> kLayerKinds[] = {
    {LayerKind::Body, "body"},
    {LayerKind::Face, "face"},
};

template <class E, std::size_t N>
std::string_view nameOf(const NamedValue<E> (&table)[N], E value)
{
    for (const auto& entry : table)
        if (entry.value == value)
            return entry.name;
    return table[0].name;
}

template <class E, std::size_t N>
std::string namesOf(const NamedValue<E> (&table)[N])
{
    std::string names;
    for (std::size_t i = 0; i < N; ++i)
        names += (i == 0 ? "" : i + 1 == N ? " or " : ", ") + quote(table[i].name);
    return names;
}

// ---------------------------------------------------------------------------------------------
// Reading

enum class Range { Any, NonNegative, Positive, UnitInterval };

// Reads one JSON object: typed fields by name, each read marking the name as known, so that
// the remaining members can be kept as `extra`. Every error names the field's path.
class ObjectReader {
public:
    ObjectReader(const json& value, std::string path, std::string_view schema)
        : m_value(value), m_path(std::move(path))
    {
        if (!value.is_object())
            fail(m_path, "expected an object, found " + describeValue(value));
        if (!schema.empty()) {
            // "schema" names the object's type and version (OpenTimelineIO style); files written
            // by hand may leave it out, but a wrong one means this is not the object we expect.
            if (const json* s = find("schema")) {
                if (!s->is_string() || s->get_ref<const std::string&>() != schema)
                    fail(join(m_path, "schema"), "expected " + quote(schema) + ", found " + describeValue(*s));
            }
        }
    }

    const std::string& path() const { return m_path; }
    std::string fieldPath(std::string_view key) const { return join(m_path, key); }

    const json* find(std::string_view key)
    {
        m_known.emplace_back(key);
        const auto it = m_value.find(key);
        return it == m_value.end() ? nullptr : &*it;
    }

    const json& require(std::string_view key)
    {
        const json* value = find(key);
        if (!value)
            fail(fieldPath(key), "this field is required but missing");
        return *value;
    }

    std::string string(std::string_view key, bool required, std::string fallback = {})
    {
        const json* value = required ? &require(key) : find(key);
        if (!value)
            return fallback;
        if (!value->is_string())
            fail(fieldPath(key), "expected a text, found " + describeValue(*value));
        return value->get<std::string>();
    }

    std::string name(std::string_view key = "name")
    {
        std::string text = string(key, true);
        if (text.empty())
            fail(fieldPath(key), "must not be empty");
        return text;
    }

    bool boolean(std::string_view key, bool fallback)
    {
        const json* value = find(key);
        if (!value)
            return fallback;
        if (!value->is_boolean())
            fail(fieldPath(key), "expected true or false, found " + describeValue(*value));
        return value->get<bool>();
    }

    double number(std::string_view key, bool required, double fallback, Range range)
    {
        const json* value = required ? &require(key) : find(key);
        if (!value)
            return fallback;
        return checkedNumber(*value, fieldPath(key), range);
    }

    float floatNumber(std::string_view key, bool required, float fallback, Range range)
    {
        const json* value = required ? &require(key) : find(key);
        if (!value)
            return fallback;
        return checkedFloat(*value, fieldPath(key), range);
    }

    std::int64_t integer(std::string_view key, bool required, std::int64_t fallback, std::int64_t min,
                         std::int64_t max)
    {
        const json* value = required ? &require(key) : find(key);
        if (!value)
            return fallback;
        if (!value->is_number_integer())
            fail(fieldPath(key), "expected a whole number, found " + describeValue(*value));
        const bool tooLarge = value->is_number_unsigned() && value->get<std::uint64_t>() > std::uint64_t(max);
        const auto n = tooLarge ? max : value->get<std::int64_t>();
        if (tooLarge || n < min || n > max)
            fail(fieldPath(key), "must be between " + std::to_string(min) + " and " + std::to_string(max)
                                     + ", found " + value->dump());
        return n;
    }

    Tick ticks(std::string_view key, bool required)
    {
        const json* value = required ? &require(key) : find(key);
        if (!value)
            return 0;
        if (!value->is_number_integer() || (value->is_number_unsigned()
                                            && value->get<std::uint64_t>() > std::uint64_t(std::numeric_limits<Tick>::max())))
            fail(fieldPath(key), "expected an integer number of ticks (" + std::to_string(TicksPerSecond)
                                     + " per second), found " + describeValue(*value));
        const Tick n = value->get<Tick>();
        if (n < 0)
            fail(fieldPath(key), "must not be negative, found " + std::to_string(n) + " ticks");
        return n;
    }

    template <class E, std::size_t N>
    E enumeration(std::string_view key, const NamedValue<E> (&table)[N], bool required, E fallback)
    {
        const json* value = required ? &require(key) : find(key);
        if (!value)
            return fallback;
        if (value->is_string())
            for (const auto& entry : table)
                if (entry.name == value->get_ref<const std::string&>())
                    return entry.value;
        fail(fieldPath(key), "expected " + namesOf(table) + ", found " + describeValue(*value));
    }

    /// The list under `key` (empty when absent).
    const json& array(std::string_view key, bool required)
    {
        static const json empty = json::array();
        const json* value = required ? &require(key) : find(key);
        if (!value)
            return empty;
        if (!value->is_array())
            fail(fieldPath(key), "expected a list, found " + describeValue(*value));
        return *value;
    }

    std::vector<std::string> names(std::string_view key)
    {
        std::vector<std::string> result;
        std::set<std::string> seen;
        const json& list = array(key, false);
        for (std::size_t i = 0; i < list.size(); ++i) {
            const std::string at = indexed(fieldPath(key), i);
            if (!list[i].is_string())
                fail(at, "expected a text, found " + describeValue(list[i]));
            const auto& text = list[i].get_ref<const std::string&>();
            if (text.empty())
                fail(at, "must not be empty");
            if (!seen.insert(text).second)
                fail(at, quote(text) + " is listed twice");
            result.push_back(text);
        }
        return result;
    }

    /// Members this reader has not asked for: kept so that they are written back unchanged.
    json extra() const
    {
        json result = json::object();
        for (const auto& [key, value] : m_value.items())
            if (std::find(m_known.begin(), m_known.end(), key) == m_known.end())
                result[key] = value;
        return result;
    }

    static double checkedNumber(const json& value, const std::string& path, Range range)
    {
        if (!value.is_number())
            fail(path, "expected a number, found " + describeValue(value));
        const double d = value.get<double>();
        if (!std::isfinite(d))
            fail(path, "expected a finite number, found " + value.dump());
        checkRange(d, path, range);
        return d;
    }

    static float checkedFloat(const json& value, const std::string& path, Range range)
    {
        const double d = checkedNumber(value, path, range);
        // Doubles below FLT_MAX + half its ulp still round to FLT_MAX (3.4028235e38 is written
        // for it); from there on the conversion would overflow.
        constexpr double kFloatLimit = double(std::numeric_limits<float>::max()) + 0x1p103;
        if (std::abs(d) >= kFloatLimit)
            fail(path, "the number " + value.dump() + " is too large");
        return float(d);
    }

private:
    static void checkRange(double d, const std::string& path, Range range)
    {
        switch (range) {
        case Range::Any: break;
        case Range::NonNegative:
            if (d < 0)
                fail(path, "must not be negative, found " + json(d).dump());
            break;
        case Range::Positive:
            if (!(d > 0))
                fail(path, "must be greater than 0, found " + json(d).dump());
            break;
        case Range::UnitInterval:
            if (d < 0 || d > 1)
                fail(path, "must be between 0 and 1, found " + json(d).dump());
            break;
        }
    }

    const json& m_value;
    std::string m_path;
    std::vector<std::string> m_known;
};

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
    ObjectReader r(value, path, "Modifier.1");
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
    }
    m.extra = r.extra();
    return m;
}

ActionSpec readAction(const json& value, const std::string& path)
{
    ObjectReader r(value, path, "Action.1");
    ActionSpec a;
    a.name = r.name();
    a.clip = r.name("clip");
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
    a.extra = r.extra();
    return a;
}

Layer readLayer(const json& value, const std::string& path)
{
    ObjectReader r(value, path, "Layer.2");
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
    ObjectReader r(value, path, "Clip.1");
    ClipAsset clip;
    clip.name = r.name();
    if (r.find("file")) {
        clip.file = r.string("file", true);
        if (clip.file.empty())
            fail(r.fieldPath("file"), "must not be empty (leave the field out for a clip stored inline)");
        clip.frameRateOverride = r.number("frameRate", false, 0, Range::Positive);
        for (const char* inlineField : {"joints", "rootTranslation", "scalars", "frames"})
            if (r.find(inlineField))
                fail(r.fieldPath(inlineField), "a clip read from a file cannot also hold inline keyframes");
    } else {
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
    return spec == "hanim-loa1" || spec == "hanim-loa2" || spec == "hanim-25"
           || (spec.starts_with("clip:") && spec.size() > 5);
}

// {"name": "hair", "role": "receiver", "posture": "pi"}; role and posture are optional.
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
    if (const std::string posture = r.string("posture", false); !posture.empty()) {
        auto parsed = scene::parsePosture(posture);
        if (!parsed)
            fail(r.fieldPath("posture"), parsed.error().message);
        tag.posture = *parsed;
    }
    // Unknown members of a tag are not kept: a tag is a small closed record.
    if (!r.extra().empty())
        fail(path + "." + r.extra().begin().key(), "unknown member of a segment tag (known: name, role, posture)");
    return tag;
}

LightingSpec readLighting(const json& value, const std::string& path)
{
    ObjectReader r(value, path, "Lighting.1");
    LightingSpec lighting;
    lighting.probe = r.string("probe", false);
    lighting.layout = r.string("layout", false, lighting.layout);
    if (auto layout = lighting::parseProbeLayout(lighting.layout); !layout)
        fail(r.fieldPath("layout"), layout.error().message);
    lighting.extra = r.extra();
    return lighting;
}

Gesture readGesture(const json& value, const std::string& path)
{
    ObjectReader r(value, path, "Gesture.1");
    Gesture gesture;
    gesture.name = r.name();
    gesture.clip = r.name("clip");
    gesture.mask = r.string("mask", false);
    gesture.fadeIn = r.ticks("fadeIn", false);
    gesture.fadeOut = r.ticks("fadeOut", false);
    gesture.dependentJointFilter = r.boolean("dependentJointFilter", false);
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

Character readCharacter(const json& value, const std::string& path)
{
    ObjectReader r(value, path, "Character.2");
    Character character;
    character.name = r.name();
    character.skeleton = r.string("skeleton", false, "hanim-loa1");
    if (!isSkeletonSpec(character.skeleton))
        fail(r.fieldPath("skeleton"), "expected \"hanim-loa1\", \"hanim-loa2\", \"hanim-25\" or \"clip:NAME\", found "
                                          + quote(character.skeleton));
    character.model = r.string("model", false);
    character.bake = r.string("bake", false);
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

Scenario readScenario(const json& document)
{
    ObjectReader r(document, "", "Scenario.2");
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
    const json& markers = r.array("markers", false);
    for (std::size_t i = 0; i < markers.size(); ++i)
        scenario.markers.push_back(readMarker(markers[i], indexed("markers", i)));
    scenario.extra = r.extra();
    return scenario;
}

// Scans the text once for nesting depth (outside strings), so that nothing recursive ever sees
// a hostile file nested thousands of levels deep. Returns the byte offset where the limit is
// crossed, or npos.
std::size_t findExcessiveNesting(std::string_view text)
{
    int depth = 0;
    bool inString = false, escaped = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (inString) {
            if (escaped)
                escaped = false;
            else if (c == '\\')
                escaped = true;
            else if (c == '"')
                inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '{' || c == '[') {
            if (++depth > kMaxDepth)
                return i;
        } else if (c == '}' || c == ']') {
            --depth;
        }
    }
    return std::string_view::npos;
}

std::string lineAndColumn(std::string_view text, std::size_t offset)
{
    offset = std::min(offset, text.size());
    std::size_t line = 1, column = 1;
    for (std::size_t i = 0; i < offset; ++i) {
        if (text[i] == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
    return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

// ---------------------------------------------------------------------------------------------
// Writing

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
void appendExtra(ojson& out, const json& extra, std::string_view skip = {})
{
    if (!extra.is_object())
        return;
    for (const auto& [key, value] : extra.items())
        if ((skip.empty() || key != skip) && !out.contains(key))
            out[key] = toOrdered(value);
}

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
    out["schema"] = "Modifier.1";
    out["kind"] = nameOf(kModifierKinds, m.kind);
    switch (m.kind) {
    case ModifierKind::TimeStretch: out["factor"] = m.factor; break;
    case ModifierKind::TimeWarp:
        out["warp"] = writeCurve(m.warp, m.warpExtra);
        out["duration"] = m.duration;
        break;
    case ModifierKind::Loop: out["count"] = m.count; break;
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
    }
    appendExtra(out, m.extra);
    return out;
}

ojson writeAction(const ActionSpec& a)
{
    ojson out = ojson::object();
    out["schema"] = "Action.1";
    out["name"] = a.name;
    out["clip"] = a.clip;
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
    appendExtra(out, a.extra);
    return out;
}

ojson writeLayer(const Layer& layer)
{
    ojson out = ojson::object();
    out["schema"] = "Layer.2";
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
    out["schema"] = "Clip.1";
    out["name"] = clip.name;
    if (!clip.file.empty()) {
        out["file"] = clip.file;
        if (clip.frameRateOverride > 0)
            out["frameRate"] = clip.frameRateOverride;
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
    out["schema"] = "Character.2";
    out["name"] = character.name;
    out["skeleton"] = character.skeleton;
    // Written only when set, so that scenarios without models stay as they were.
    if (!character.model.empty())
        out["model"] = character.model;
    if (!character.segmentTags.empty()) {
        ojson segments = ojson::array();
        for (const scene::SegmentTag& tag : character.segmentTags) {
            ojson entry = ojson::object();
            entry["name"] = tag.segment;
            entry["role"] = scene::segmentRoleName(tag.role);
            if (tag.posture)
                entry["posture"] = scene::postureName(*tag.posture);
            segments.push_back(std::move(entry));
        }
        out["segments"] = std::move(segments);
    }
    if (!character.bake.empty())
        out["bake"] = character.bake;
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
            entry["schema"] = "Gesture.1";
            entry["name"] = gesture.name;
            entry["clip"] = gesture.clip;
            if (!gesture.mask.empty())
                entry["mask"] = gesture.mask;
            entry["fadeIn"] = gesture.fadeIn;
            entry["fadeOut"] = gesture.fadeOut;
            entry["dependentJointFilter"] = gesture.dependentJointFilter;
            appendExtra(entry, gesture.extra);
            gestures.push_back(std::move(entry));
        }
        out["gestures"] = std::move(gestures);
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
        out += "\n" + std::string(std::size_t(indent), ' ') + "}";
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
        out += "\n" + std::string(std::size_t(indent), ' ') + "]";
    } else {
        out += dumpScalar(value);
    }
}

} // namespace

Result<Scenario> parseScenario(std::string_view text)
{
    // A UTF-8 byte order mark is harmless: some editors add one.
    if (text.starts_with("\xEF\xBB\xBF"))
        text.remove_prefix(3);
    const std::size_t first = text.find_first_not_of(" \t\r\n");
    if (first == std::string_view::npos || text[first] != '{')
        return makeError(ErrorCode::NotOurFormat, "This is not a Thespis scenario: it does not start with a JSON object.");
    if (const std::size_t at = findExcessiveNesting(text); at != std::string_view::npos)
        return makeError(ErrorCode::CorruptData,
                         lineAndColumn(text, at) + ": the scenario nests deeper than " + std::to_string(kMaxDepth)
                             + " levels.");
    json document;
    try {
        document = json::parse(text);
    } catch (const json::parse_error& e) {
        // nlohmann's text is "[json.exception.parse_error.101] parse error at line L, column C: why".
        std::string why = e.what();
        if (const std::size_t colon = why.find(": "); colon != std::string::npos)
            why = why.substr(colon + 2);
        const std::size_t offset = e.byte > 0 ? e.byte - 1 : 0;
        return makeError(ErrorCode::CorruptData,
                         lineAndColumn(text, offset) + ": the scenario is not valid JSON (" + why + ").", e.what());
    } catch (const json::out_of_range& e) {
        // "number overflow parsing '1e999'": point at the number when it can be found.
        const std::string why = e.what();
        const std::size_t open = why.find('\''), close = why.rfind('\'');
        std::string where;
        if (open != std::string::npos && close > open + 1)
            if (const std::size_t at = text.find(why.substr(open + 1, close - open - 1)); at != std::string_view::npos)
                where = lineAndColumn(text, at) + ": ";
        return makeError(ErrorCode::CorruptData, where + "the scenario holds a number too large to read.", why);
    } catch (const std::exception& e) {
        return makeError(ErrorCode::CorruptData, "The scenario could not be read as JSON.", e.what());
    }
    if (!document.is_object())
        return makeError(ErrorCode::NotOurFormat, "This is not a Thespis scenario: it is not a JSON object.");

    const auto format = document.find("format");
    if (format == document.end())
        return makeError(ErrorCode::NotOurFormat, "This is not a Thespis scenario: it has no \"format\" field.");
    if (!format->is_string() || format->get_ref<const std::string&>() != FormatName)
        return makeError(ErrorCode::NotOurFormat, "This is not a Thespis scenario: its format is "
                                                      + describeValue(*format) + ", not \"" + std::string(FormatName)
                                                      + "\".");
    const auto version = document.find("version");
    if (version == document.end())
        return makeError(ErrorCode::CorruptData, "version: this field is required but missing.");
    if (!version->is_number_integer())
        return makeError(ErrorCode::CorruptData, "version: expected a whole number, found " + describeValue(*version) + ".");
    if (version->is_number_unsigned() && version->get<std::uint64_t>() > std::uint64_t(std::numeric_limits<int>::max()))
        return makeError(ErrorCode::NewerVersion, "This scenario was saved by a newer Thespis (format " + version->dump()
                                                      + "). Update Thespis to open it.");
    const std::int64_t number = version->get<std::int64_t>();
    if (number < format::Initial)
        return makeError(ErrorCode::CorruptData, "version: " + std::to_string(number)
                                                     + " is not a scenario format version (the first is 1).");
    if (number > format::Current)
        return makeError(ErrorCode::NewerVersion, "This scenario was saved by a newer Thespis (format "
                                                      + std::to_string(number) + "). Update Thespis to open it.",
                         "this build reads formats 1 to " + std::to_string(int(format::Current)));
    if (auto upgraded = detail::runUpgradeSteps(document, int(number), format::Current, detail::upgradeSteps()); !upgraded)
        return upgraded.error();

    try {
        return readScenario(document);
    } catch (const FieldError& e) {
        return makeError(ErrorCode::CorruptData, (e.path.empty() ? "" : e.path + ": ") + e.message + ".");
    } catch (const std::exception& e) {
        return makeError(ErrorCode::Internal, "Reading the scenario failed unexpectedly.", e.what());
    }
}

Result<Scenario> loadScenario(const std::filesystem::path& path)
{
    auto text = readTextFile(path);
    if (!text)
        return text.error();
    auto scenario = parseScenario(*text);
    if (!scenario) {
        Error error = scenario.error();
        error.detail = "file " + path.string() + (error.detail.empty() ? "" : "; " + error.detail);
        return error;
    }
    return scenario;
}

std::string serializeScenario(const Scenario& scenario)
{
    ojson out = ojson::object();
    out["format"] = FormatName;
    out["version"] = int(format::Current);
    out["schema"] = "Scenario.2";
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
        lighting["schema"] = "Lighting.1";
        lighting["probe"] = scenario.lighting.probe;
        lighting["layout"] = scenario.lighting.layout;
        appendExtra(lighting, scenario.lighting.extra);
        out["lighting"] = std::move(lighting);
    }
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
    appendExtra(out, scenario.extra);
    std::string text;
    print(out, 0, text);
    text += "\n";
    return text;
}

Result<void> saveScenario(const std::filesystem::path& path, const Scenario& scenario)
{
    const std::string text = serializeScenario(scenario);
    // Never write a file this reader would refuse (a NaN weight becomes null, an empty name…):
    // the user would lose the document on the next open.
    if (auto check = parseScenario(text); !check)
        return makeError(ErrorCode::InvalidArgument,
                         "The scenario cannot be saved: " + check.error().message, check.error().detail);
    return writeFileAtomically(path, text);
}

} // namespace thespis::core::scenario
