// thespis-cli play: runs core's PlayJob — a scenario played to a video file, over a tracked video
// (paper §7.2: the virtual human standing on the board or picture the camera films) or on its own.

#include <cstdio>

#include "commands.h"
#include "exit_codes.h"
#include "job_progress.h"
#include "render/play_job.h"
#include "scene_render.h"
#include "script_source.h"
#include "target_options.h"

#ifdef THESPIS_WITH_PYTHON
#include "script_play.h"
#endif

namespace thespis::cli {

CommandSpec playSpec()
{
    CommandSpec spec;
    spec.name = "play";
    spec.summary = "Play a scenario to a video file, over a tracked video or on its own.";
    spec.positionals = {"SCENARIO|PACKAGE"};
    spec.options = {
        {"out", "FILE.mp4", "the video to write (.mp4 or .avi); replaced when finished", true},
        {"video", "IN", "a video to play the scenario over, its characters standing on the tracked target"},
        {"camera", "FILE.yml", "the calibration of the camera that filmed --video"},
        {"fps", "N", "frames per second without --video (default 30)"},
        {"script", "S.py|NAME", "a Python script that plays along (a file, or a script kept in the scenario), as `run` runs it"},
        {"audio", "", "also write the sounds played (the characters' speech lines, the script's voiceService) as a WAV beside the video: OUT.wav"},
    };
    addTargetOptions(spec);
    addPictureOptions(spec);
    spec.description =
        "With --video, every frame is tracked (--board or --target with --width) and the scenario is\n"
        "drawn over it on the video's clock, placed, scaled and hidden by phantom occluders as its \"ar\"\n"
        "section says; frames where the target is lost stay as filmed. Without --video the scenario\n"
        "plays over its timeline as `render` draws it.\n"
        "With --script the script drives the clock: each of its waits writes the frames up to the wait's end,\n"
        "and the video lasts until the scenario's end or the script's, whichever is later; its prints go to\n"
        "the terminal. The video file holds no sound (OpenCV's writer has none): --audio writes it beside.\n"
        "Example: thespis-cli play demo.thespis --script wave.py --audio --out wave.mp4\n"
        "Example: thespis-cli play demo.thespis --video clip.mp4 --camera camera.yml --board aruco-grid:DICT_4X4_50:4x3:0.04:0.01 --out ar.mp4\n"
        "Exit status: 0 written, 2 bad command line, 3 inputs that cannot be used,\n"
        "4 the file could not be written, 130 cancelled; 3 also when the script raised (its traceback is printed).";
    return spec;
}

int runPlay(const CommandSpec& spec, const ParsedArguments& arguments)
{
    const std::filesystem::path scenarioPath = arguments.positionals.front();
    const bool quiet = arguments.has("quiet");
    core::render::PlayJob job;
    job.output = *arguments.value("out");
    int exitCode = ExitOk;
    if (const auto video = arguments.value("video")) {
        job.video = *video;
        const auto camera = arguments.value("camera");
        if (!camera)
            return usageError(spec, "--video needs --camera, the calibration of the camera that filmed it");
        job.cameraFile = *camera;
        if (const int status = readTargetOptions(spec, arguments, job.target); status != ExitOk)
            return status;
    } else if (arguments.has("camera") || arguments.has("board") || arguments.has("target")) {
        return usageError(spec, "--camera, --board and --target go with --video");
    }
    if (const auto fps = frameRateOption(spec, arguments, exitCode))
        job.fps = *fps;
    if (exitCode != ExitOk)
        return exitCode;
    auto document = openScenarioReporting(spec.name, scenarioPath);
    if (!document)
        return ExitInvalidInput;
    if (const int status = readPictureSettings(spec, arguments, document->scenario, job.picture); status != ExitOk)
        return status;
    job.compositor.samples = job.picture.samples;
    job.compositor.shading = job.picture.shading;
    job.compositor.skinning = job.picture.skinning;
    if (arguments.has("audio")) {
        job.audio = job.output;
        job.audio.replace_extension(".wav");
    }
#ifdef THESPIS_WITH_PYTHON
    script::ScriptRunner runner;
    std::optional<ScriptSource> source;
    if (const auto scriptName = arguments.value("script")) {
        source = readScriptReporting(spec.name, *scriptName, document->scenario);
        if (!source)
            return ExitInvalidInput;
        job.script = playAlong(runner, *source);
    }
#else
    if (arguments.has("script"))
        return usageError(spec, "--script needs Python, and this thespis-cli was built without it");
#endif
    job.scenario = std::move(document->scenario);
    job.assets = std::move(document->assets);
    if (auto valid = job.validate(); !valid)
        return usageError(spec, valid.error().message);

    JobBar bar{core::render::PlayJob::FramesStage, "frames", 0, [&] {
        if (!quiet)
            for (const std::string& warning : job.warnings)
                std::fprintf(stderr, "thespis-cli play: warning: %s\n", warning.c_str());
    }};
    const auto played = runJobWithProgress(spec.name, job, bar, quiet, job.output.string() + " was not written");
    if (!played)
        return reportJobFailure(spec.name, played.error());
    if (!quiet) {
        if (job.video.empty())
            std::printf("Played %s: %lld frames at %g fps into %s.\n", scenarioPath.filename().string().c_str(),
                        static_cast<long long>(job.frames), job.fps, job.output.string().c_str());
        else
            std::printf("Played %s over %s: the target tracked in %lld of %lld frames; wrote %s.\n",
                        scenarioPath.filename().string().c_str(), job.video.filename().string().c_str(),
                        static_cast<long long>(job.tracked), static_cast<long long>(job.frames),
                        job.output.string().c_str());
        if (job.script || job.sounds > 0)
            std::printf("%zu sound%s played (speech lines and the script's); the video lasts %.3f s.\n", job.sounds,
                        job.sounds == 1 ? "" : "s", job.seconds);
        if (!job.audio.empty())
            std::printf("Wrote the sound into %s.\n", job.audio.string().c_str());
    }
    return ExitOk;
}

} // namespace thespis::cli
