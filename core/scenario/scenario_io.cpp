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
#include "scenario/scenario_json.h"
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

// 2 → 3: clips gained retarget options and glTF animations, actions their placement, loops root
// motion, characters a placement and the "model" skeleton, the light a rotation and intensity.
// All are optional: only the schema names of the objects that changed are new.
static Result<void> upgradeV2toV3(nlohmann::json& document)
{
    const auto renameSchema = [](nlohmann::json& object, std::string_view from, std::string_view to) {
        if (!object.is_object())
            return;
        const auto schema = object.find("schema");
        if (schema != object.end() && schema->is_string() && schema->get_ref<const std::string&>() == from)
            *schema = to;
    };
    const auto each = [](nlohmann::json& object, const char* member, const auto& visit) {
        if (!object.is_object())
            return;
        const auto list = object.find(member);
        if (list != object.end() && list->is_array())
            for (nlohmann::json& item : *list)
                visit(item);
    };
    renameSchema(document, "Scenario.2", "Scenario.3");
    if (document.is_object())
        if (const auto lighting = document.find("lighting"); lighting != document.end())
            renameSchema(*lighting, "Lighting.1", "Lighting.2");
    each(document, "characters", [&](nlohmann::json& character) {
        renameSchema(character, "Character.2", "Character.3");
        each(character, "clips", [&](nlohmann::json& clip) { renameSchema(clip, "Clip.1", "Clip.2"); });
        each(character, "layers", [&](nlohmann::json& layer) {
            each(layer, "actions", [&](nlohmann::json& action) {
                renameSchema(action, "Action.1", "Action.2");
                each(action, "modifiers", [&](nlohmann::json& m) { renameSchema(m, "Modifier.1", "Modifier.2"); });
            });
        });
    });
    return {};
}

// 3 → 4: scenarios may hold scripts (an optional list); only the scenario's schema is new.
static Result<void> upgradeV3toV4(nlohmann::json& document)
{
    if (document.is_object())
        if (const auto schema = document.find("schema");
            schema != document.end() && schema->is_string() && schema->get_ref<const std::string&>() == "Scenario.3")
            *schema = "Scenario.4";
    return {};
}

std::span<const UpgradeStep> upgradeSteps()
{
    static constexpr UpgradeStep steps[] = {
        {format::Initial, "timeline state and gesticon", &upgradeV1toV2},
        {format::TimelineAndGesticon, "clip import options and placement", &upgradeV2toV3},
        {format::ImportAndPlacement, "scripts", &upgradeV3toV4},
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

using detail::describeValue;
using detail::json;
using detail::kMaxDepth;

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
        return detail::readScenario(document);
    } catch (const detail::FieldError& e) {
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