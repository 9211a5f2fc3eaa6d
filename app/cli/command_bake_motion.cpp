// thespis-cli bake-motion: evaluates a character's body schedule at a fixed frame rate over the
// scenario (or a part of it) and writes the frames as a BVH clip on the character's skeleton.
// Frames are baked into memory first and written atomically at the end, so an interrupted or
// failed bake never leaves a partial file behind.

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <thread>

#include "anim/bvh.h"
#include "anim/keyframe_clip.h"
#include "cancel.h"
#include "commands.h"
#include "exit_codes.h"
#include "progress.h"
#include "scenario/scenario_runtime.h"

namespace thespis::cli {
namespace {

namespace anim = core::anim;
namespace scenario = core::scenario;

// Refuse bakes whose frames would not fit comfortably in memory (1 GiB of floats).
constexpr double MaxBakeFloats = double(1u << 28);

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
    spec.summary = "Evaluate a character's body animation and write it as a BVH clip.";
    spec.positionals = {"SCENARIO"};
    spec.options = {
        {"character", "NAME", "the character whose body schedule is baked", true},
        {"out", "FILE.bvh", "the BVH file to write; an existing file is replaced atomically", true},
        {"fps", "N", "frames per second (default 30)"},
        {"start", "SECONDS", "first frame's time (default 0)"},
        {"end", "SECONDS", "last frame's time (default: the scenario's duration)"},
        {"quiet", "", "no progress and no summary"},
    };
    spec.description =
        "Frames are taken at start, start + 1/fps, ... up to end, so a bake has (end - start) * fps + 1\n"
        "frames. The BVH uses the character's skeleton and joint names and opens in Blender and other\n"
        "tools. Progress is a bar on a terminal and plain lines otherwise; Ctrl-C stops the bake\n"
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
    if (outPath.extension() != ".bvh")
        return usageError(spec, "--out must name a .bvh file (only BVH output is supported), not '"
                                    + outPath.string() + "'");
    const std::filesystem::path outDir = outPath.parent_path().empty() ? "." : outPath.parent_path();
    if (std::error_code ec; !std::filesystem::is_directory(outDir, ec)) {
        printError(spec.name, "cannot write " + outPath.string() + ": the folder " + outDir.string()
                                  + " does not exist.");
        return ExitInvalidInput;
    }

    const auto document = loadScenarioReporting(spec.name, scenarioPath);
    if (!document)
        return ExitInvalidInput;
    if (!document->findCharacter(characterName)) {
        std::vector<std::string> names;
        for (const auto& character : document->characters)
            names.push_back(character.name);
        printError(spec.name, "the scenario " + scenarioPath.string() + " has no character named '" + characterName
                                  + "' (its characters: " + joinNames(names) + ").");
        return ExitInvalidInput;
    }
    const std::filesystem::path baseDir = scenarioPath.parent_path().empty() ? "." : scenarioPath.parent_path();
    auto runtime = scenario::buildRuntime(*document, baseDir);
    if (!runtime) {
        printError(spec.name, runtime.error());
        return ExitInvalidInput;
    }
    const scenario::CharacterRuntime* character = runtime->findCharacter(characterName);
    if (!character || !character->body) {
        printError(spec.name, "character '" + characterName + "' has no body animation to bake.");
        return ExitInvalidInput;
    }

    const double start = startOption.value_or(0.0);
    const double end = endOption.value_or(runtime->duration);
    if (start < 0)
        return usageError(spec, "--start must not be negative");
    if (end < start)
        return usageError(spec, "--end (" + std::to_string(end) + " s) is before --start (" + std::to_string(start)
                                    + " s)");
    if (!endOption && runtime->duration <= 0) {
        printError(spec.name, "the scenario has no duration and no finite action; give the bake's length with --end.");
        return ExitInvalidInput;
    }

    const anim::BlendingSchedule& body = *character->body;
    const anim::FrameLayoutPtr& layout = body.layout();
    const std::size_t floats = layout->floatCount();
    // A small tolerance so that e.g. 8.4 s × 30 fps gives 253 frames despite rounding.
    const double intervals = std::floor((end - start) * fps + 1e-6);
    if ((intervals + 1) * double(floats) > MaxBakeFloats) {
        printError(spec.name, "the bake would hold " + std::to_string(long(intervals + 1)) + " frames of "
                                  + std::to_string(floats) + " values; lower --fps or bake a shorter range.");
        return ExitInvalidInput;
    }
    const long frameCount = long(intervals) + 1;

    // Bake. The frame buffer is allocated once; evaluation itself allocates nothing.
    const auto delay = debugFrameDelay();
    const auto began = std::chrono::steady_clock::now();
    std::vector<float> frames(std::size_t(frameCount) * floats);
    ProgressReporter progress(stderr, "bake-motion", "frames", frameCount, quiet);
    for (long i = 0; i < frameCount; ++i) {
        if (interrupted()) {
            progress.abandon();
            std::fprintf(stderr, "thespis-cli bake-motion: cancelled after %ld of %ld frames; %s was not written.\n",
                         i, frameCount, outPath.string().c_str());
            return ExitCancelled;
        }
        const double t = start + double(i) / fps;
        body.evaluate(t, std::span<float>(frames.data() + std::size_t(i) * floats, floats));
        progress.update(i + 1);
        if (delay.count() > 0)
            std::this_thread::sleep_for(delay);
    }
    progress.finish();

    auto clip = anim::KeyframeClip::create(layout, fps, std::move(frames), characterName);
    if (!clip) {
        printError(spec.name, clip.error());
        return ExitFailure;
    }
    std::shared_ptr<anim::KeyframeClip> onSkeleton = clip.value();
    const anim::Skeleton& skeleton = character->skeleton;
    if (!(*layout == *skeleton.frameLayout())) {
        // The body schedule is built on the skeleton's layout; this keeps the writer safe if a
        // future runtime ever differs.
        auto remapped = anim::remapClip(*onSkeleton, skeleton.frameLayout(), skeleton.restFrame());
        if (!remapped) {
            printError(spec.name, remapped.error());
            return ExitFailure;
        }
        onSkeleton = remapped.value();
    }
    if (interrupted()) {
        std::fprintf(stderr, "thespis-cli bake-motion: cancelled; %s was not written.\n", outPath.string().c_str());
        return ExitCancelled;
    }
    if (auto saved = anim::bvh::save(outPath, skeleton, *onSkeleton); !saved) {
        printError(spec.name, saved.error());
        return ExitFailure;
    }

    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
    if (!quiet)
        std::printf("Baked %ld frames (%.3f s to %.3f s at %g fps) of '%s' to %s in %.2f s.\n", frameCount, start,
                    start + double(frameCount - 1) / fps, fps, characterName.c_str(), outPath.string().c_str(),
                    seconds);
    return ExitOk;
}

} // namespace thespis::cli
