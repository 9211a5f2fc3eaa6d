#pragma once
// The subcommands of thespis-cli. Each one describes its arguments (CommandSpec) and runs on
// parsed arguments, returning an exit code (exit_codes.h). Messages go to stderr, results and
// reports to stdout.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "arguments.h"
#include "scenario/posture_clip.h"
#include "scenario/open_scenario.h"
#include "scenario/scenario.h"
#include "util/error.h"

namespace thespis::cli {

struct Command {
    CommandSpec spec;
    int (*run)(const CommandSpec& spec, const ParsedArguments& arguments);
};

/// Every subcommand, in the order `thespis-cli --help` lists them.
const std::vector<Command>& commands();

CommandSpec validateSpec();
int runValidate(const CommandSpec& spec, const ParsedArguments& arguments);
CommandSpec bakeMotionSpec();
int runBakeMotion(const CommandSpec& spec, const ParsedArguments& arguments);
CommandSpec bakeSpec();
int runBake(const CommandSpec& spec, const ParsedArguments& arguments);
CommandSpec renderSpec();
int runRender(const CommandSpec& spec, const ParsedArguments& arguments);
CommandSpec trainPcaSpec();
int runTrainPca(const CommandSpec& spec, const ParsedArguments& arguments);
CommandSpec buildIdleSpec();
int runBuildIdle(const CommandSpec& spec, const ParsedArguments& arguments);
CommandSpec calibrateSpec();
int runCalibrate(const CommandSpec& spec, const ParsedArguments& arguments);
CommandSpec exportSpec();
int runExport(const CommandSpec& spec, const ParsedArguments& arguments);
CommandSpec importSpec();
int runImport(const CommandSpec& spec, const ParsedArguments& arguments);
CommandSpec trackSpec();
int runTrack(const CommandSpec& spec, const ParsedArguments& arguments);
CommandSpec playSpec();
int runPlay(const CommandSpec& spec, const ParsedArguments& arguments);
CommandSpec infoSpec();
int runInfo(const CommandSpec& spec, const ParsedArguments& arguments);
CommandSpec faceMappingSpec();
int runFaceMapping(const CommandSpec& spec, const ParsedArguments& arguments);
CommandSpec speakSpec();
int runSpeak(const CommandSpec& spec, const ParsedArguments& arguments);
CommandSpec lipsyncSpec();
int runLipsync(const CommandSpec& spec, const ParsedArguments& arguments);
CommandSpec chatSpec();
int runChat(const CommandSpec& spec, const ParsedArguments& arguments);
#ifdef THESPIS_WITH_PYTHON
CommandSpec runSpec();
int runRun(const CommandSpec& spec, const ParsedArguments& arguments);
#endif

// Shared helpers.

/// Prints "thespis-cli COMMAND: error: <what>" on stderr.
void printError(const std::string& command, const std::string& what);
void printError(const std::string& command, const core::Error& error);
/// Prints the problem, the usage line and a hint to --help on stderr; returns ExitUsage.
int usageError(const CommandSpec& spec, const std::string& problem);
/// Loads a scenario file, printing the error when it cannot be read.
std::optional<core::scenario::Scenario> loadScenarioReporting(const std::string& command,
                                                              const std::filesystem::path& path);
/// A scenario file or a package, opened as everything opens them (core::scenario::openScenario).
/// Prints the error and returns nothing on failure.
std::optional<core::scenario::OpenedScenario> openScenarioReporting(const std::string& command,
                                                                    const std::filesystem::path& path);
/// Reads an option of zero or more seconds; on a bad value prints the usage error and sets
/// exitCode (to ExitUsage).
std::optional<double> secondsOption(const CommandSpec& spec, const ParsedArguments& arguments, const std::string& name,
                                    int& exitCode);
/// Reads an integer option within [min, max]; on a bad value prints the usage error and sets
/// exitCode (to ExitUsage).
std::optional<long> integerOption(const CommandSpec& spec, const ParsedArguments& arguments, const std::string& name,
                                  long min, long max, int& exitCode);
/// Parses an enumeration option with the core's parser, whose message lists the choices.
template <class T, class Parse>
std::optional<T> choiceOption(const CommandSpec& spec, const ParsedArguments& arguments, const std::string& name,
                              T fallback, Parse parse, int& exitCode)
{
    const auto text = arguments.value(name);
    if (!text)
        return fallback;
    auto parsed = parse(*text);
    if (!parsed) {
        exitCode = usageError(spec, "--" + name + ": " + parsed.error().message);
        return std::nullopt;
    }
    return *parsed;
}
/// The motion files of a command line ("FILE[@FPS][+SKIP]", arguments.h), each skipping
/// `defaultSkip` seconds unless it says otherwise. On a malformed one prints the usage error,
/// sets exitCode and returns nothing.
std::optional<std::vector<core::scenario::PostureSource>> postureSources(const CommandSpec& spec,
                                                                       const std::vector<std::string>& arguments,
                                                                       double defaultSkip, int& exitCode);
/// "a, b, c", or "none".
std::string joinNames(const std::vector<std::string>& names);

} // namespace thespis::cli
