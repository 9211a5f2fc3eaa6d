#pragma once
// Private to core/scenario's reader and writer (scenario_read.cpp, scenario_write.cpp) and the
// entry points (scenario_io.cpp): JSON aliases, the enumerations by name, and messages.

#include <charconv>
#include <cmath>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "scenario/scenario.h"

namespace thespis::core::scenario::detail {

using json = nlohmann::json;
using ojson = nlohmann::ordered_json;

// Documents nest a handful of levels; unknown fields could nest deeper, but a limit keeps the
// recursive parts (comparison, writing, destruction of foreign code's copies) safe from
// hostile files.
inline constexpr int kMaxDepth = 64;

// Thrown inside the reader only, caught in parseScenario: a field path and what is wrong.
struct FieldError {
    std::string path;
    std::string message;
};

[[noreturn]] inline void fail(const std::string& path, std::string message)
{
    throw FieldError{path, std::move(message)};
}

inline std::string join(const std::string& path, std::string_view key)
{
    return path.empty() ? std::string(key) : path + "." + std::string(key);
}

inline std::string indexed(const std::string& path, std::size_t index)
{
    return path + "[" + std::to_string(index) + "]";
}

inline std::string quote(std::string_view text)
{
    return json(std::string(text)).dump(-1, ' ', false, json::error_handler_t::replace);
}

// What a JSON value is, for "expected X, found Y" messages: short, with the value if small.
inline std::string describeValue(const json& value)
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
inline double floatForJson(float value)
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
constexpr NamedValue<Placement> kPlacements[] = {
    {Placement::World, "world"},
    {Placement::Character, "character"},
    {Placement::Continue, "continue"},
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


/// The document (already upgraded to the current version) as a Scenario; throws FieldError.
Scenario readScenario(const json& document);
/// The scenario as the current version's JSON, members in the writer's order.
ojson writeScenario(const Scenario& scenario);

} // namespace thespis::core::scenario::detail
