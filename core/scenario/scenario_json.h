#pragma once
// Private to core/scenario's reader and writer (scenario_read.cpp, scenario_write.cpp) and the
// entry points (scenario_io.cpp): JSON aliases, the enumerations by name, and messages (the
// document helpers come from util/json_document.h).

#include <charconv>
#include <cmath>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "scenario/scenario.h"
#include "util/json_document.h"

namespace thespis::core::scenario::detail {

using json = nlohmann::json;
using ojson = nlohmann::ordered_json;
using json_document::describeValue;
using json_document::fail;
using json_document::FieldError;
using json_document::indexed;
using json_document::join;
using json_document::kMaxDepth;
using json_document::quote;

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
    {anim::CurveKind::Dominance, "dominance"},
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
    {ModifierKind::Trim, "trim"},              {ModifierKind::DependentJointFilter, "dependentJointFilter"},
};
constexpr NamedValue<Placement> kPlacements[] = {
    {Placement::World, "world"},
    {Placement::Character, "character"},
    {Placement::Continue, "continue"},
};
constexpr NamedValue<LayerKind> kLayerKinds[] = {
    {LayerKind::Body, "body"},
    {LayerKind::Face, "face"},
    {LayerKind::Gaze, "gaze"},
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


/// Known fields first, in the writer's order; unknown ones (`extra`) after, never replacing a
/// known one. `skip` names a member written separately (empty: none).
void appendExtra(ojson& out, const json& extra, std::string_view skip = {});

/// The scenario's AR section (scenario_ar_io.cpp); throws FieldError naming the field.
ArSpec readArSpec(const json& value, const std::string& path);
ojson writeArSpec(const ArSpec& ar);

/// The document (already upgraded to the current version) as a Scenario; throws FieldError.
Scenario readScenario(const json& document);
/// The scenario as the current version's JSON, members in the writer's order.
ojson writeScenario(const Scenario& scenario);

} // namespace thespis::core::scenario::detail
