// thespis-cli render: pictures of a scenario without any X server (EGL offscreen, Mesa's software
// GL when there is no GPU): one frame at --time, or a numbered sequence with --frames (core's
// FrameSequenceJob, with a progress bar; Ctrl-C stops it and takes its frames back).

#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>

#include "commands.h"
#include "exit_codes.h"
#include "job_progress.h"
#include "render/frame_sequence_job.h"
#include "scene_render.h"

namespace thespis::cli {

CommandSpec renderSpec()
{
    CommandSpec spec;
    spec.name = "render";
    spec.summary = "Render frames of a scenario to PNG, headless (no X server needed).";
    spec.positionals = {"SCENARIO|PACKAGE"};
    spec.options = {
        {"out", "FILE.png|DIR/", "the picture to write, or the folder of a --frames sequence", true},
        {"time", "SECONDS", "the moment to render (default 0)"},
        {"frames", "A:B", "render frames A to B (inclusive) at --fps into DIR/frame_NNNNN.png"},
        {"fps", "N", "frame rate of --frames (default 30)"},
    };
    addPictureOptions(spec);
    spec.description =
        "The light comes from the scenario's probe, or a default sky. Rendering uses EGL on Mesa's\n"
        "surfaceless platform, so it runs on servers and in CI; GALLIUM_DRIVER=llvmpipe forces software GL.\n"
        "Exit status: 0 written, 2 bad command line, 3 unreadable scenario, bake or probe,\n"
        "4 no OpenGL or the picture could not be written, 130 cancelled (the frames written are taken back).";
    return spec;
}

int runRender(const CommandSpec& spec, const ParsedArguments& arguments)
{
    const std::filesystem::path scenarioPath = arguments.positionals[0];
    const std::filesystem::path outPath = *arguments.value("out");
    const bool quiet = arguments.has("quiet");
    int exitCode = ExitOk;

    const std::optional<FrameRange> frames = frameRangeOption(spec, arguments, exitCode);
    if (exitCode != ExitOk)
        return exitCode;
    if (frames) {
        if (arguments.has("time"))
            return usageError(spec, "give either --time or --frames, not both");
    } else if (arguments.has("fps")) {
        return usageError(spec, "--fps needs --frames");
    }
    const auto fps = frameRateOption(spec, arguments, exitCode);
    double time = 0;
    if (const auto text = arguments.value("time")) {
        const auto value = parseNumber(*text);
        if (!value || !std::isfinite(*value) || *value < 0)
            return usageError(spec, "--time must be a time in seconds (0 or more), not '" + *text + "'");
        time = *value;
    }
    if (exitCode != ExitOk)
        return exitCode;

    auto document = openScenarioReporting(spec.name, scenarioPath);
    if (!document)
        return ExitInvalidInput;
    if (!frames) {
        const std::filesystem::path outDir = outPath.parent_path().empty() ? "." : outPath.parent_path();
        if (std::error_code ec; !std::filesystem::is_directory(outDir, ec)) {
            printError(spec.name, "cannot write " + outPath.string() + ": the folder " + outDir.string() + " does not exist.");
            return ExitInvalidInput;
        }
        std::unique_ptr<core::render::ScenarioPicture> picture;
        if (const int status = makePicture(spec, arguments, scenarioPath, *document, quiet, picture); status != ExitOk)
            return status;
        picture->playAt(core::secondsToTicks(time));
        if (const int status = writePicture(spec.name, *picture, outPath); status != ExitOk)
            return status;
        if (!quiet)
            std::printf("Rendered %s at %.3f s (%dx%d, %s) to %s with %s.\n", scenarioPath.filename().string().c_str(),
                        time, picture->settings().width, picture->settings().height,
                        core::render::shadingName(picture->settings().shading), outPath.string().c_str(),
                        picture->glDescription().c_str());
        return ExitOk;
    }

    core::render::FrameSequenceJob job;
    if (const int status = readPictureSettings(spec, arguments, document->scenario, job.picture); status != ExitOk)
        return status;
    job.scenario = std::move(document->scenario);
    job.assets = std::move(document->assets);
    job.first = frames->first;
    job.last = frames->last;
    job.fps = *fps;
    job.folder = outPath;

    const long count = frames->last - frames->first + 1;
    JobBar bar{core::render::FrameSequenceJob::FramesStage, "frames", count, [&] { // once the scene is ready
        if (!quiet)
            for (const std::string& warning : job.warnings)
                std::fprintf(stderr, "thespis-cli render: warning: %s\n", warning.c_str());
    }};
    const auto rendered = runJobWithProgress(spec.name, job, bar, quiet, "no frame was kept");
    if (!rendered) {
        if (rendered.error().code == core::ErrorCode::Cancelled)
            return ExitCancelled;
        printSceneError(spec, arguments, scenarioPath, rendered.error());
        return rendered.error().code == core::ErrorCode::IoError ? ExitFailure : ExitInvalidInput;
    }
    if (!quiet)
        std::printf("Rendered %ld frames (%ld to %ld at %g fps, %dx%d, %s) into %s.\n", count, frames->first,
                    frames->last, *fps, job.picture.width, job.picture.height,
                    core::render::shadingName(job.picture.shading), outPath.string().c_str());
    return ExitOk;
}

} // namespace thespis::cli
