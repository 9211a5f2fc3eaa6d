// The scenario format's upgrade steps (scenario_upgrade.h): each takes a document of version N to
// N + 1 before it is read.

#include "scenario/scenario_upgrade.h"

#include <algorithm>
#include <string>
#include <string_view>

#include "scenario/scenario_io.h"

namespace thespis::core::scenario {

namespace detail {

// Renames an object's "schema" from `from` to `to`; anything else is left for the reader, which
// names the field that is not an object.
static void renameSchema(nlohmann::json& object, std::string_view from, std::string_view to)
{
    if (!object.is_object())
        return;
    const auto schema = object.find("schema");
    if (schema != object.end() && schema->is_string() && schema->get_ref<const std::string&>() == from)
        *schema = to;
}

// Calls `visit` on each item of the array `object[member]`, when there is one (a document of the
// wrong shape is left as it is for the reader to name).
template <class Visit> void forEachIn(nlohmann::json& object, const char* member, const Visit& visit)
{
    if (!object.is_object())
        return;
    const auto list = object.find(member);
    if (list != object.end() && list->is_array())
        for (nlohmann::json& item : *list)
            visit(item);
}

// 1 → 2: layers gained mute / solo / lock, characters a gesticon, the scenario markers. All are
// optional, so a version 1 document only needs the new schema names of the objects that changed.
static Result<void> upgradeV1toV2(nlohmann::json& document)
{
    renameSchema(document, "Scenario.1", "Scenario.2");
    forEachIn(document, "characters", [](nlohmann::json& character) {
        renameSchema(character, "Character.1", "Character.2");
        forEachIn(character, "layers", [](nlohmann::json& layer) { renameSchema(layer, "Layer.1", "Layer.2"); });
    });
    return {};
}

// 2 → 3: clips gained retarget options and glTF animations, actions their placement, loops root
// motion, characters a placement and the "model" skeleton, the light a rotation and intensity.
// All are optional: only the schema names of the objects that changed are new.
static Result<void> upgradeV2toV3(nlohmann::json& document)
{
    renameSchema(document, "Scenario.2", "Scenario.3");
    if (document.is_object())
        if (const auto lighting = document.find("lighting"); lighting != document.end())
            renameSchema(*lighting, "Lighting.1", "Lighting.2");
    forEachIn(document, "characters", [](nlohmann::json& character) {
        renameSchema(character, "Character.2", "Character.3");
        forEachIn(character, "clips", [](nlohmann::json& clip) { renameSchema(clip, "Clip.1", "Clip.2"); });
        forEachIn(character, "layers", [](nlohmann::json& layer) {
            forEachIn(layer, "actions", [](nlohmann::json& action) {
                renameSchema(action, "Action.1", "Action.2");
                forEachIn(action, "modifiers", [](nlohmann::json& m) { renameSchema(m, "Modifier.1", "Modifier.2"); });
            });
        });
    });
    return {};
}

// 3 → 4: scenarios may hold scripts (an optional list); only the scenario's schema is new.
static Result<void> upgradeV3toV4(nlohmann::json& document)
{
    renameSchema(document, "Scenario.3", "Scenario.4");
    return {};
}

// 4 → 5: a clip may be an idle motion synthesizer (an optional member); the scenario's and the
// clips' schemas are new.
static Result<void> upgradeV4toV5(nlohmann::json& document)
{
    renameSchema(document, "Scenario.4", "Scenario.5");
    forEachIn(document, "characters", [](nlohmann::json& character) {
        forEachIn(character, "clips", [](nlohmann::json& clip) { renameSchema(clip, "Clip.2", "Clip.3"); });
    });
    return {};
}

// 5 → 6: segment tags lose "posture" ("pi" / "pd"): neither the bake nor the renderer ever read
// it, so dropping it changes no result. The scenario's and the characters' schemas are new.
static Result<void> upgradeV5toV6(nlohmann::json& document)
{
    renameSchema(document, "Scenario.5", "Scenario.6");
    forEachIn(document, "characters", [](nlohmann::json& character) {
        renameSchema(character, "Character.3", "Character.4");
        forEachIn(character, "segments", [](nlohmann::json& tag) {
            if (tag.is_object())
                tag.erase("posture");
        });
    });
    return {};
}

// 6 → 7: clips may be blink generators; nothing else changed, so the schemas are renamed.
static Result<void> upgradeV6toV7(nlohmann::json& document)
{
    renameSchema(document, "Scenario.6", "Scenario.7");
    forEachIn(document, "characters", [](nlohmann::json& character) {
        forEachIn(character, "clips", [](nlohmann::json& clip) { renameSchema(clip, "Clip.3", "Clip.4"); });
    });
    return {};
}

// 7 → 8: a character may name its own face mapping table ("faceMapping", optional); nothing else
// changed, so only the scenario's and the characters' schemas are new.
static Result<void> upgradeV7toV8(nlohmann::json& document)
{
    renameSchema(document, "Scenario.7", "Scenario.8");
    forEachIn(document, "characters", [](nlohmann::json& character) { renameSchema(character, "Character.4", "Character.5"); });
    return {};
}

// 8 → 9: characters may have speech lines ("speech", optional) and curves may be dominance
// curves; nothing else changed, so only the scenario's and the characters' schemas are new.
static Result<void> upgradeV8toV9(nlohmann::json& document)
{
    renameSchema(document, "Scenario.8", "Scenario.9");
    forEachIn(document, "characters", [](nlohmann::json& character) { renameSchema(character, "Character.5", "Character.6"); });
    return {};
}

// 9 → 10: layers may be gaze layers, whose actions name a target ("gaze") instead of a clip, and
// gestures may hold ("fit") and mark their stroke; nothing else changed, so only the scenario's,
// the layers', the actions' and the gestures' schemas are new.
static Result<void> upgradeV9toV10(nlohmann::json& document)
{
    renameSchema(document, "Scenario.9", "Scenario.10");
    forEachIn(document, "characters", [](nlohmann::json& character) {
        forEachIn(character, "gestures", [](nlohmann::json& gesture) { renameSchema(gesture, "Gesture.1", "Gesture.2"); });
        forEachIn(character, "layers", [](nlohmann::json& layer) {
            renameSchema(layer, "Layer.2", "Layer.3");
            forEachIn(layer, "actions", [](nlohmann::json& action) { renameSchema(action, "Action.2", "Action.3"); });
        });
    });
    return {};
}

// 10 → 11: body actions may point their gesture's arm at a target ("pointing"); nothing else
// changed, so only the scenario's and the actions' schemas are new.
static Result<void> upgradeV10toV11(nlohmann::json& document)
{
    renameSchema(document, "Scenario.10", "Scenario.11");
    forEachIn(document, "characters", [](nlohmann::json& character) {
        forEachIn(character, "layers", [](nlohmann::json& layer) {
            forEachIn(layer, "actions", [](nlohmann::json& action) { renameSchema(action, "Action.3", "Action.4"); });
        });
    });
    return {};
}

// 11 → 12: characters may keep their own BML lexicon ("bmlLexicon", optional: without one a
// character has the defaults, as every character had before); only the scenario's and the
// characters' schemas are new.
static Result<void> upgradeV11toV12(nlohmann::json& document)
{
    renameSchema(document, "Scenario.11", "Scenario.12");
    forEachIn(document, "characters", [](nlohmann::json& character) { renameSchema(character, "Character.6", "Character.7"); });
    return {};
}

std::span<const UpgradeStep> upgradeSteps()
{
    static constexpr UpgradeStep steps[] = {
        {format::Initial, "timeline state and gesticon", &upgradeV1toV2},
        {format::TimelineAndGesticon, "clip import options and placement", &upgradeV2toV3},
        {format::ImportAndPlacement, "scripts", &upgradeV3toV4},
        {format::Scripts, "idle motion clips", &upgradeV4toV5},
        {format::IdleMotion, "segment tags without posture", &upgradeV5toV6},
        {format::NoPostureTags, "blink clips", &upgradeV6toV7},
        {format::Blinks, "face mapping tables", &upgradeV7toV8},
        {format::FaceMappingTable, "speech lines", &upgradeV8toV9},
        {format::Speech, "gaze layers", &upgradeV9toV10},
        {format::Gaze, "pointing actions", &upgradeV10toV11},
        {format::Pointing, "BML lexicons", &upgradeV11toV12},
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

} // namespace thespis::core::scenario
