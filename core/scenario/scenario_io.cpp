// The scenario format's entry points: text → Scenario (checked, upgraded, read) and back.

#include "scenario/scenario_io.h"

#include <string>

#include "scenario/scenario_json.h"
#include "scenario/scenario_upgrade.h"
#include "util/file_io.h"

namespace thespis::core::scenario {

Result<Scenario> parseScenario(std::string_view text)
{
    static constexpr json_document::Kind kScenario{"scenario", FormatName, format::Initial, format::Current};
    auto parsed = json_document::parseVersioned(text, kScenario);
    if (!parsed)
        return parsed.error();
    nlohmann::json& document = parsed->document;
    if (auto upgraded = detail::runUpgradeSteps(document, parsed->version, format::Current, detail::upgradeSteps());
        !upgraded)
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
