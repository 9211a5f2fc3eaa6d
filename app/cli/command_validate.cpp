// thespis-cli validate SCENARIO|PACKAGE: reads the file, lists every problem validateScenario
// finds, then builds the runtime (loading every clip) to catch what only loading reveals. A
// package is opened first (every check of core/scenario/package.h), and its scenario checked
// as it plays: from the package (package_resolver.h).

#include <cstdio>

#include "cancel.h"
#include "commands.h"
#include "exit_codes.h"
#include "scenario/open_scenario.h"
#include "scenario/package_manifest.h"
#include "scenario/scenario_runtime.h"

namespace thespis::cli {

namespace {

/// `path` names the scenario in messages.
int validateScenario(const CommandSpec& spec, const core::scenario::Scenario& scenario, const core::scenario::Assets& assets,
                     const std::filesystem::path& path, bool quiet)
{
    const std::vector<core::Error> problems = core::scenario::validateScenario(scenario, assets);
    if (interrupted())
        return ExitCancelled;
    if (!problems.empty()) {
        std::printf("%s: %zu problem%s\n", path.string().c_str(), problems.size(), problems.size() == 1 ? "" : "s");
        for (const core::Error& problem : problems)
            std::printf("  - %s\n", core::describe(problem).c_str());
        printError(spec.name, path.string() + " is not valid (" + std::to_string(problems.size()) + " problem"
                                  + (problems.size() == 1 ? "" : "s") + ").");
        return ExitInvalidInput;
    }

    auto runtime = core::scenario::buildRuntime(scenario, assets);
    if (!runtime) {
        std::printf("%s: 1 problem\n  - %s\n", path.string().c_str(), core::describe(runtime.error()).c_str());
        printError(spec.name, path.string() + " is not valid.");
        return ExitInvalidInput;
    }
    for (const core::scenario::CharacterRuntime& character : runtime->characters)
        for (const std::string& warning : character.warnings)
            std::fprintf(stderr, "thespis-cli validate: warning: %s: %s\n", character.name.c_str(), warning.c_str());

    if (!quiet) {
        std::size_t actions = 0, clips = 0;
        for (const auto& character : scenario.characters) {
            clips += character.clips.size();
            for (const auto& layer : character.layers)
                actions += layer.actions.size();
        }
        std::printf("%s: valid. '%s': %zu character%s, %zu clip%s, %zu action%s, %.3f s.\n", path.string().c_str(),
                    scenario.name.c_str(), scenario.characters.size(), scenario.characters.size() == 1 ? "" : "s",
                    clips, clips == 1 ? "" : "s", actions, actions == 1 ? "" : "s", core::ticksToSeconds(runtime->duration));
    }
    return ExitOk;
}

} // namespace

CommandSpec validateSpec()
{
    CommandSpec spec;
    spec.name = "validate";
    spec.summary = "Check a scenario or a package: its format, every field, and that every clip loads.";
    spec.positionals = {"SCENARIO|PACKAGE"};
    spec.options = {{"quiet", "", "print only problems, not the summary"}};
    spec.description = "Each problem is printed with the character, action and field it concerns. A package\n"
                       "(.thespkg) is checked as `import` checks it, then its scenario as above.\n"
                       "Exit status: 0 valid, 3 invalid or unreadable, 2 bad command line.";
    return spec;
}

int runValidate(const CommandSpec& spec, const ParsedArguments& arguments)
{
    const std::filesystem::path path = arguments.positionals[0];
    const bool quiet = arguments.has("quiet");
    auto opened = core::scenario::openScenario(path);
    if (!opened) {
        if (!core::scenario::isPackagePath(path)) {
            printError(spec.name, opened.error());
            return ExitInvalidInput;
        }
        std::printf("%s: 1 problem\n  - %s\n", path.string().c_str(), core::describe(opened.error()).c_str());
        printError(spec.name, path.string() + " is not a valid package.");
        return ExitInvalidInput;
    }
    std::filesystem::path shown = path;
    if (opened->package) {
        const core::scenario::PackageManifest& manifest = opened->package->manifest();
        if (!quiet)
            std::printf("%s: a package by %s; %zu entries, each as its manifest says.\n", path.string().c_str(),
                        manifest.writer.c_str(), manifest.entries.size() + 1);
        shown = path / manifest.scenario;
    }
    return validateScenario(spec, opened->scenario, opened->assets, shown, quiet);
}

} // namespace thespis::cli
