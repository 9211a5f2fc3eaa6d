// thespis-cli run: plays a scenario with a Python script (the paper's §4.5 scripts) headless.
// The script runs on a manual clock (core::runtime::playScript, as `play`'s does): each of its
// waits jumps the clock forward, and every frame of --frames that falls in the jump is rendered
// first, so the pictures show the scenario and the script's live actions exactly as a player at
// those times would.

#include <chrono>
#include <cstdio>
#include <thread>

#include "cancel.h"
#include "commands.h"
#include "exit_codes.h"
#include "progress.h"
#include "runtime/scripted_play.h"
#include "scenario/scenario_runtime.h"
#include "scene_render.h"
#include "script_play.h"

namespace thespis::cli {

CommandSpec runSpec()
{
    CommandSpec spec;
    spec.name = "run";
    spec.summary = "Play a scenario with a Python script (animService, as in the paper), rendering frames headless.";
    spec.positionals = {"SCENARIO|PACKAGE"};
    spec.options = {
        {"script", "S.py|NAME", "the script to run (a file, or a script kept in the scenario): it sees `animService` (also `anim`) and `thespis`", true},
        {"frames", "A:B", "render frames A to B (inclusive) at --fps into --out while the script plays"},
        {"out", "DIR/", "the folder of the frames (frame_NNNNN.png)"},
        {"fps", "N", "frame rate of --frames (default 30)"},
        {"audio", "OUT.wav", "write the sounds the script played (voiceService, sndService) as a 16-bit WAV: over the frames, or from 0 to the script's end"},
    };
    addPictureOptions(spec);
    spec.description =
        "Time is simulated: a wait in the script (waitUntilActionFinished_body, wait) moves the clock at once,\n"
        "after the frames up to that time are rendered; frames after the script's end show what it left playing.\n"
        "Without --frames the script just runs (its prints go to the terminal).\n"
        "Exit status: 0 done, 2 bad command line, 3 unreadable scenario or script, or the script raised\n"
        "(its traceback is printed), 4 a frame could not be written, 130 cancelled.";
    return spec;
}

int runRun(const CommandSpec& spec, const ParsedArguments& arguments)
{
    const std::filesystem::path scenarioPath = arguments.positionals[0];
    const std::filesystem::path scriptPath = *arguments.value("script");
    const bool quiet = arguments.has("quiet");
    int exitCode = ExitOk;
    const std::optional<FrameRange> frames = frameRangeOption(spec, arguments, exitCode);
    if (exitCode != ExitOk)
        return exitCode;
    if (frames) {
        if (!arguments.has("out"))
            return usageError(spec, "--frames needs --out DIR/");
    } else if (arguments.has("out") || arguments.has("fps")) {
        return usageError(spec, "--out and --fps need --frames");
    }
    const auto fps = frameRateOption(spec, arguments, exitCode);
    if (exitCode != ExitOk)
        return exitCode;

    auto document = openScenarioReporting(spec.name, scenarioPath);
    if (!document)
        return ExitInvalidInput;
    const auto script = readScriptReporting(spec.name, scriptPath, document->scenario);
    if (!script)
        return ExitInvalidInput;

    // The stage: the rendered scene's, or one of its own when nothing is rendered.
    std::unique_ptr<core::render::ScenarioPicture> picture;
    std::shared_ptr<core::runtime::Stage> stage;
    std::filesystem::path outDir;
    if (frames) {
        outDir = *arguments.value("out");
        if (const int status = makeFrameFolder(spec.name, outDir); status != ExitOk)
            return status;
        if (const int status = makePicture(spec, arguments, scenarioPath, *document, quiet, picture); status != ExitOk)
            return status;
        stage = picture->scene().sharedStage();
    } else {
        auto runtime = core::scenario::buildRuntime(document->scenario, document->assets);
        if (!runtime) {
            printError(spec.name, runtime.error());
            return ExitInvalidInput;
        }
        stage = std::make_shared<core::runtime::Stage>(std::move(runtime).value());
    }

    installInterruptHandlers();
    script::ScriptRunner runner;
    const long count = frames ? frames->last - frames->first + 1 : 0;
    ProgressReporter progress(stderr, "run", "frames", count, quiet || !frames);
    long next = frames ? frames->first : 0;
    int renderStatus = ExitOk;
    // Renders every frame before `until` (all that are left when until is max).
    const auto renderUntil = [&](core::Tick until) -> core::Result<void> {
        for (; frames && next <= frames->last; ++next) {
            const double seconds = double(next) / *fps;
            if (core::secondsToTicks(seconds) >= until)
                break;
            if (interrupted())
                return core::makeError(core::ErrorCode::Cancelled, "stopped");
            picture->playAt(core::secondsToTicks(seconds));
            renderStatus = writePicture(spec.name, *picture, outDir / core::render::frameFileName(next));
            if (renderStatus != ExitOk)
                return core::makeError(core::ErrorCode::IoError, "a frame could not be written");
            progress.update(next - frames->first + 1);
        }
        return {};
    };
    // Ctrl-C stops the script, also one that computes without waiting.
    std::stop_source stop;
    std::jthread watcher([&](std::stop_token done) {
        while (!done.stop_requested() && !interrupted())
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
        if (interrupted())
            stop.request_stop();
    });
    auto played = core::runtime::playScript(playAlong(runner, *script), stage, document->assets, renderUntil,
                                            stop.get_token());
    watcher.request_stop();
    watcher.join();
    if (played && !interrupted())
        (void)renderUntil(std::numeric_limits<core::Tick>::max());
    if (renderStatus != ExitOk) {
        progress.abandon();
        return renderStatus;
    }
    if (interrupted() || (!played && played.error().code == core::ErrorCode::Cancelled)) {
        progress.abandon();
        std::fprintf(stderr, "thespis-cli run: cancelled%s.\n",
                     frames ? (" after " + std::to_string(next - frames->first) + " of " + std::to_string(count) + " frames").c_str() : "");
        return ExitCancelled;
    }
    if (!played) {
        progress.abandon();
        printError(spec.name, played.error().message);
        return ExitInvalidInput;
    }
    const std::shared_ptr<core::runtime::SoundService>& sound = played->sound;
    const std::shared_ptr<core::runtime::ManualClock>& clock = played->clock;
    progress.finish();
    if (const auto audio = arguments.value("audio")) {
        const core::Tick from = frames ? core::secondsToTicks(double(frames->first) / *fps) : 0;
        const core::Tick to = frames ? core::secondsToTicks(double(frames->last + 1) / *fps) : clock->now();
        if (auto written = sound->writeWav(*audio, from, to); !written) {
            printError(spec.name, written.error());
            return ExitFailure;
        }
        if (!quiet)
            std::printf("Wrote %zu sound%s into %s (%.3f s).\n", sound->activations().size(),
                        sound->activations().size() == 1 ? "" : "s", audio->c_str(), core::ticksToSeconds(to - from));
    }
    if (!quiet)
        std::printf("Ran %s on %s: the script ended at %.3f s%s.\n", script->fileName.c_str(),
                    scenarioPath.filename().string().c_str(), core::ticksToSeconds(clock->now()),
                    frames ? (", " + std::to_string(count) + " frames rendered into " + outDir.string()).c_str() : "");
    return ExitOk;
}

} // namespace thespis::cli
