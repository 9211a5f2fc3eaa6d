#pragma once
// The script `run` and `play` are given: a Python file, or else a script the scenario keeps
// under that name (naming it on the command line is the user's trust, packages included).

#include <filesystem>
#include <optional>
#include <string>

#include "scenario/scenario.h"

namespace thespis::cli {

struct ScriptSource {
    std::string text;
    std::string fileName; ///< names it in tracebacks
};

/// Prints what is wrong (an unreadable file; no file and no kept script of that name, with the
/// names the scenario keeps) and returns nothing.
std::optional<ScriptSource> readScriptReporting(const std::string& command, const std::filesystem::path& script,
                                                const core::scenario::Scenario& scenario);

} // namespace thespis::cli
