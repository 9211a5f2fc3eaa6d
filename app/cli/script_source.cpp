#include "script_source.h"

#include <fstream>
#include <sstream>

#include "commands.h"

namespace thespis::cli {

std::optional<ScriptSource> readScriptReporting(const std::string& command, const std::filesystem::path& script,
                                                const core::scenario::Scenario& scenario)
{
    if (std::error_code ec; std::filesystem::is_regular_file(script, ec)) {
        std::ifstream file(script, std::ios::binary);
        std::ostringstream text;
        text << file.rdbuf();
        if (!file) {
            printError(command, "cannot read the script " + script.string() + ".");
            return std::nullopt;
        }
        return ScriptSource{text.str(), script.filename().string()};
    }
    if (const core::scenario::ScriptSpec* kept = scenario.findScript(script.string()))
        return ScriptSource{kept->source, kept->name};
    std::vector<std::string> names;
    for (const core::scenario::ScriptSpec& kept : scenario.scripts)
        names.push_back(kept.name);
    printError(command, "there is no file " + script.string() + ", and the scenario keeps no script of that name (it has: " +
                            joinNames(names) + ").");
    return std::nullopt;
}

} // namespace thespis::cli
