#include "commands.h"

#include <cmath>
#include <cstdio>

#include "exit_codes.h"
#include "scenario/scenario_io.h"

namespace thespis::cli {

const std::vector<Command>& commands()
{
    static const std::vector<Command> all = {
        {validateSpec(), &runValidate},
        {bakeMotionSpec(), &runBakeMotion},
        {bakeSpec(), &runBake},
        {renderSpec(), &runRender},
        {trainPcaSpec(), &runTrainPca},
        {buildIdleSpec(), &runBuildIdle},
        {calibrateSpec(), &runCalibrate},
        {trackSpec(), &runTrack},
        {playSpec(), &runPlay},
        {exportSpec(), &runExport},
        {importSpec(), &runImport},
#ifdef THESPIS_WITH_PYTHON
        {runSpec(), &runRun},
#endif
        {infoSpec(), &runInfo},
        {faceMappingSpec(), &runFaceMapping},
        {speakSpec(), &runSpeak},
        {lipsyncSpec(), &runLipsync},
        {chatSpec(), &runChat},
    };
    return all;
}

void printError(const std::string& command, const std::string& what)
{
    std::fprintf(stderr, "thespis-cli %s: error: %s\n", command.c_str(), what.c_str());
}

void printError(const std::string& command, const core::Error& error)
{
    printError(command, core::describe(error));
}

int usageError(const CommandSpec& spec, const std::string& problem)
{
    std::fprintf(stderr, "thespis-cli %s: %s\n%s\nRun 'thespis-cli %s --help' for more.\n", spec.name.c_str(),
                 problem.c_str(), usageLine(spec).c_str(), spec.name.c_str());
    return ExitUsage;
}

std::optional<core::scenario::Scenario> loadScenarioReporting(const std::string& command,
                                                              const std::filesystem::path& path)
{
    auto scenario = core::scenario::loadScenario(path);
    if (!scenario) {
        printError(command, scenario.error());
        return std::nullopt;
    }
    return std::move(scenario).value();
}

std::optional<core::scenario::OpenedScenario> openScenarioReporting(const std::string& command,
                                                                    const std::filesystem::path& path)
{
    auto opened = core::scenario::openScenario(path);
    if (!opened) {
        printError(command, opened.error());
        return std::nullopt;
    }
    return std::move(opened).value();
}

std::optional<long> integerOption(const CommandSpec& spec, const ParsedArguments& arguments, const std::string& name,
                                  long min, long max, int& exitCode)
{
    const auto text = arguments.value(name);
    if (!text)
        return std::nullopt;
    const auto value = parseNumber(*text);
    if (!value || *value != std::floor(*value) || *value < double(min) || *value > double(max)) {
        exitCode = usageError(spec, "--" + name + " must be a whole number from " + std::to_string(min) + " to "
                                        + std::to_string(max) + ", not '" + *text + "'");
        return std::nullopt;
    }
    return long(*value);
}

std::optional<double> secondsOption(const CommandSpec& spec, const ParsedArguments& arguments, const std::string& name,
                                    int& exitCode)
{
    const auto text = arguments.value(name);
    if (!text)
        return std::nullopt;
    const auto value = parseNumber(*text);
    if (!value || *value < 0) {
        exitCode = usageError(spec, "--" + name + " must be zero or more seconds, not '" + *text + "'");
        return std::nullopt;
    }
    return *value;
}

std::string joinNames(const std::vector<std::string>& names)
{
    if (names.empty())
        return "none";
    std::string text;
    for (const std::string& name : names)
        text += (text.empty() ? "" : ", ") + name;
    return text;
}

std::optional<std::vector<core::scenario::PostureSource>> postureSources(const CommandSpec& spec,
                                                                       const std::vector<std::string>& arguments,
                                                                       double defaultSkip, int& exitCode)
{
    std::vector<core::scenario::PostureSource> sources;
    for (const std::string& text : arguments) {
        const auto clip = parseClipArgument(text);
        if (!clip) {
            exitCode = usageError(spec, "'" + text + "': after '@' a frame rate (> 0) and after '+' seconds to skip (>= 0)");
            return std::nullopt;
        }
        core::scenario::PostureSource source;
        source.clip.file = clip->file;
        source.clip.name = std::filesystem::path(clip->file).stem().string();
        source.clip.frameRateOverride = clip->frameRate;
        source.skip = clip->skip.value_or(defaultSkip);
        sources.push_back(std::move(source));
    }
    return sources;
}

} // namespace thespis::cli
