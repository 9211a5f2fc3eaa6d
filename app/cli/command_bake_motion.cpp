// thespis-cli bake-motion: runs core's MotionBakeJob (a character's poses as the Stage plays them, at a
// fixed frame rate, written as a BVH clip or a glTF animation) with a progress bar; Ctrl-C stops
// it and nothing is written.

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <thread>

#include <optional>

#include "commands.h"
#include "exit_codes.h"
#include "job_progress.h"
#include "runtime/motion_bake_job.h"

namespace thespis::cli {
namespace {

// THESPIS_CLI_FRAME_DELAY_MS slows each frame down by that many milliseconds. It exists for the
// tests, which need a bake long enough to interrupt and to watch its progress; 0 by default.
std::chrono::milliseconds debugFrameDelay()
{
    const char* text = std::getenv("THESPIS_CLI_FRAME_DELAY_MS");
    const auto value = text ? parseNumber(text) : std::nullopt;
    return std::chrono::milliseconds(value && *value > 0 ? long(*value) : 0L);
}

std::optional<double> numberOption(const CommandSpec& spec, const ParsedArguments& arguments, const std::string& name,
                                   int& exitCode)
{
    const auto text = arguments.value(name);
    if (!text)
        return std::nullopt;
    const auto value = parseNumber(*text);
    if (!value)
        exitCode = usageError(spec, "--" + name + " must be a number, not '" + *text + "'");
    return value;
}

} // namespace

CommandSpec bakeMotionSpec()
{
    CommandSpec spec;
    spec.name = "bake-motion";
    spec.summary = "Evaluate a character's animation and write it as a BVH clip or a glTF 2.0 animation (.glb).";
    spec.positionals = {"SCENARIO|PACKAGE"};
    spec.options = {
        {"character", "NAME", "the character whose body schedule is baked", true},
        {"out", "FILE.bvh|FILE.glb", "the file to write; an existing file is replaced atomically", true},
        {"animation-only", "", ".glb: only the nodes and the animation, without meshes and images"},
        {"fps", "N", "frames per second (default 30)"},
        {"start", "SECONDS", "first frame's time (default 0)"},
        {"end", "SECONDS", "last frame's time (default: the scenario's duration)"},
        {"quiet", "", "no progress and no summary"},
    };
    spec.description =
        "Frames are taken at start, start + 1/fps, ... up to end, so a bake has (end - start) * fps + 1\n"
        "frames. The BVH uses the character's skeleton and joint names and opens in Blender and other\n"
        "tools. A .glb holds the character's glTF model (meshes, skin, materials) with the motion as its\n"
        "animation, retargeted onto the model's rig as the studio shows it; face layers drive the morph\n"
        "targets named after their FAPs (\"fap19\" ...). The built-in humanoid is written whole as a glTF\n"
        "character: its joints, skinned mesh, materials and the motion. With --animation-only a .glb\n"
        "holds the nodes and the animation alone, which three.js or Blender play onto the model by node\n"
        "name.\n"
        "Example: thespis-cli bake-motion demo.thespis --character Creon --out creon.glb\n"
        "Progress is a bar on a terminal and plain lines otherwise; Ctrl-C stops the bake\n"
        "without writing anything.\n"
        "Exit status: 0 written, 2 bad command line, 3 invalid scenario or character,\n"
        "4 the file could not be written, 130 cancelled.";
    return spec;
}

int runBakeMotion(const CommandSpec& spec, const ParsedArguments& arguments)
{
    const std::filesystem::path scenarioPath = arguments.positionals[0];
    const std::string characterName = *arguments.value("character");
    const std::filesystem::path outPath = *arguments.value("out");
    const bool quiet = arguments.has("quiet");

    int exitCode = ExitOk;
    const double fps = numberOption(spec, arguments, "fps", exitCode).value_or(30.0);
    const auto startOption = numberOption(spec, arguments, "start", exitCode);
    const auto endOption = numberOption(spec, arguments, "end", exitCode);
    if (exitCode != ExitOk)
        return exitCode;
    if (!(fps > 0))
        return usageError(spec, "--fps must be a positive number");
    if (outPath.extension() != ".bvh" && outPath.extension() != ".glb")
        return usageError(spec, "--out must name a .bvh or .glb file, not '" + outPath.string() + "'");
    if (arguments.has("animation-only") && outPath.extension() != ".glb")
        return usageError(spec, "--animation-only goes with a .glb output");
    if (startOption && *startOption < 0)
        return usageError(spec, "--start must not be negative");
    if (endOption && *endOption < startOption.value_or(0.0))
        return usageError(spec, "--end (" + std::to_string(*endOption) + " s) is before --start ("
                                    + std::to_string(startOption.value_or(0.0)) + " s)");

    auto document = openScenarioReporting(spec.name, scenarioPath);
    if (!document)
        return ExitInvalidInput;
    core::runtime::MotionBakeJob job;
    job.scenario = std::move(document->scenario);
    job.assets = std::move(document->assets);
    job.character = characterName;
    job.output = outPath;
    job.fps = fps;
    job.start = startOption.value_or(0.0);
    job.end = endOption;
    job.animationOnly = arguments.has("animation-only");
    job.frameDelay = debugFrameDelay();

    const auto began = std::chrono::steady_clock::now();
    const auto baked = runJobWithProgress(spec.name, job, {core::runtime::MotionBakeJob::FramesStage, "frames"}, quiet,
                                          outPath.string() + " was not written");
    if (!baked) {
        if (baked.error().code == core::ErrorCode::Cancelled)
            return ExitCancelled;
        printError(spec.name, baked.error());
        return baked.error().code == core::ErrorCode::IoError ? ExitFailure : ExitInvalidInput;
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
    if (!quiet)
        std::printf("Baked %ld frames (%.3f s to %.3f s at %g fps) of '%s' to %s in %.2f s.\n", job.frameCount,
                    job.start, job.lastTime, fps, characterName.c_str(), outPath.string().c_str(), seconds);
    if (!quiet && !job.morphTargets.empty())
        std::printf("Face layers drive the morph targets %s.\n", joinNames(job.morphTargets).c_str());
    for (const std::string& warning : job.warnings)
        std::fprintf(stderr, "%s: warning: %s\n", spec.name.c_str(), warning.c_str());
    return ExitOk;
}

} // namespace thespis::cli
