// thespis-cli track: runs core's TrackJob over a video or pictures (paper §7.2): a marker board or
// a printed picture followed frame by frame, filtered over time, one CSV row per frame
// (frame,tracked,rx,ry,rz,tx,ty,tz: target → camera, Rodrigues vector and metres; then the frame's
// motion blur and IPPE ambiguity).

#include <cstdio>

#include "ar/track_job.h"
#include "commands.h"
#include "exit_codes.h"
#include "job_progress.h"
#include "target_options.h"

namespace thespis::cli {

CommandSpec trackSpec()
{
    CommandSpec spec;
    spec.name = "track";
    spec.summary = "Track a marker board or a printed picture through a video; write the poses (CSV).";
    spec.positionals = {"VIDEO"};
    spec.repeatsLast = true;
    spec.options = {
        {"camera", "FILE.yml", "the camera's calibration (OpenCV YAML, e.g. from `calibrate`)", true},
        {"fps", "N", "frames per second when VIDEO is a list of pictures (default 30)"},
        {"no-filter", "", "each frame's own pose, without the temporal filter"},
        {"out", "FILE.csv", "the poses to write; replaced atomically", true},
        {"quiet", "", "no progress and no summary"},
    };
    addTargetOptions(spec);
    spec.description =
        "VIDEO is a video file, or several pictures played in order at --fps.\n"
        "Rows: frame,tracked,rx,ry,rz,tx,ty,tz,blur_px,blur_deg,ambiguity (target -> camera: Rodrigues\n"
        "vector, metres; for an ArUco grid in the board frame OpenCV 4.6's aruco::GridBoard uses; the\n"
        "motion blur the board's edges show, its length in pixels and direction in degrees; the ratio\n"
        "of IPPE's two poses' errors, below 3 when the tilt is unsure). A frame where the target\n"
        "is not found has tracked 0 and no pose. The summary gives the tracked share, how often the\n"
        "target was lost, and the time from a frame's capture to its pose.\n"
        "Example: thespis-cli track clip.mp4 --camera camera.yml --board aruco-grid:DICT_4X4_50:4x3:0.04:0.01 --out poses.csv\n"
        "Exit status: 0 written, 2 bad command line, 3 inputs that cannot be used,\n"
        "4 the file could not be written, 130 cancelled.";
    return spec;
}

int runTrack(const CommandSpec& spec, const ParsedArguments& arguments)
{
    core::ar::TrackJob job;
    if (arguments.positionals.size() == 1)
        job.video = arguments.positionals.front();
    else
        for (const std::string& picture : arguments.positionals)
            job.pictures.emplace_back(picture);
    job.cameraFile = *arguments.value("camera");
    if (const int status = readTargetOptions(spec, arguments, job.target); status != ExitOk)
        return status;
    if (const auto fps = arguments.value("fps")) {
        const auto rate = parseNumber(*fps);
        if (!rate || !(*rate > 0))
            return usageError(spec, "--fps must be a positive number, not '" + *fps + "'");
        job.picturesFps = *rate;
    }
    job.filter = !arguments.has("no-filter");
    job.output = *arguments.value("out");
    const bool quiet = arguments.has("quiet");
    if (auto valid = job.validate(); !valid)
        return usageError(spec, valid.error().message);

    const auto tracked = runJobWithProgress(spec.name, job, {core::ar::TrackJob::Stage, "frames"}, quiet,
                                            job.output.string() + " was not written");
    if (!tracked)
        return reportJobFailure(spec.name, tracked.error());
    if (!quiet) {
        const auto& s = job.statistics;
        std::printf("Tracked %s in %lld of %lld frames (%.1f %%); lost %lld times.\n", job.trackerDescription.c_str(),
                    static_cast<long long>(s.tracked), static_cast<long long>(s.frames),
                    100.0 * double(s.tracked) / double(s.frames), static_cast<long long>(s.lost));
        std::printf("Capture to pose: %.1f ms mean, %.1f ms at most.\n", s.meanLatency * 1000, s.maxLatency * 1000);
        std::printf("Wrote %s.\n", job.output.string().c_str());
    }
    return ExitOk;
}

} // namespace thespis::cli
