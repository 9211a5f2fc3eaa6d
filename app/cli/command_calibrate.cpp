// thespis-cli calibrate: runs core's CalibrateJob (a camera's intrinsics from views of a
// chessboard or a ChArUco board, paper §7.2) with a progress bar, prints the RMS reprojection
// error and each view's, and writes OpenCV's YAML camera file that `track` and the studio's AR
// preview read.

#include <cstdio>

#include "ar/calibrate_job.h"
#include "commands.h"
#include "exit_codes.h"
#include "job_progress.h"

namespace thespis::cli {

CommandSpec calibrateSpec()
{
    CommandSpec spec;
    spec.name = "calibrate";
    spec.summary = "Calibrate a camera from photos of a chessboard or a ChArUco board; write its intrinsics (OpenCV "
                   "YAML).";
    spec.positionals = {"IMAGE"};
    spec.repeatsLast = true;
    spec.options = {
        {"board", "BOARD",
         "chessboard:COLSxROWS:SQUARE (inner corners) or charuco:DICT:COLSxROWS:SQUARE:MARKER[:inverted] "
         "(squares); sides in metres",
         true},
        {"out", "FILE.yml", "the camera file to write (.yml, .yaml, .xml or .json); replaced atomically", true},
        {"fix-aspect", "", "square pixels: fx = fy"},
        {"quiet", "", "no progress and no summary"},
    };
    spec.description =
        "At least 3 IMAGEs of one camera at one resolution, the board seen from different angles.\n"
        "A chessboard must be seen whole. A ChArUco board (OpenCV 4.6's: DICT names the ArUco\n"
        "dictionary, e.g. DICT_6X6_250; :inverted for one printed white on black) may be partly\n"
        "hidden or cut off: the corners between the markers found count. An ArUco grid is for\n"
        "tracking only. Corners are refined to a tenth of a pixel; the summary gives the RMS\n"
        "reprojection error of all views and of each (a view far above the rest is worth leaving\n"
        "out) and how surely the views pin fx, fy and the centre down (standard deviations: more\n"
        "views, at more angles, make them smaller).\n"
        "Examples: thespis-cli calibrate left*.jpg --board chessboard:9x6:0.025 --fix-aspect --out camera.yml\n"
        "          thespis-cli calibrate view*.jpg --board charuco:DICT_6X6_250:5x7:0.04:0.02 --out camera.yml\n"
        "Exit status: 0 written, 2 bad command line, 3 images that cannot be used,\n"
        "4 the file could not be written, 130 cancelled.";
    return spec;
}

int runCalibrate(const CommandSpec& spec, const ParsedArguments& arguments)
{
    core::ar::CalibrateJob job;
    auto board = core::ar::parseBoard(*arguments.value("board"));
    if (!board)
        return usageError(spec, board.error().message);
    job.board = *board;
    for (const std::string& image : arguments.positionals)
        job.images.emplace_back(image);
    job.fixAspectRatio = arguments.has("fix-aspect");
    job.output = *arguments.value("out");
    const bool quiet = arguments.has("quiet");
    if (auto valid = job.validate(); !valid)
        return usageError(spec, valid.error().message);

    const auto solved = runJobWithProgress(spec.name, job, {core::ar::CalibrateJob::FindingStage, "views"}, quiet,
                                           job.output.string() + " was not written");
    if (!solved)
        return reportJobFailure(spec.name, solved.error());
    if (!quiet) {
        const core::ar::CameraIntrinsics& c = job.camera;
        std::printf("Calibrated %d × %d: fx %.2f, fy %.2f, centre (%.2f, %.2f); RMS reprojection error %.3f px.\n",
                    c.width, c.height, c.fx(), c.fy(), c.cx(), c.cy(), c.reprojectionError);
        const auto& d = job.deviations;
        std::printf("Standard deviations: fx %.2f, fy %.2f, cx %.2f, cy %.2f px.\n", d[0], d[1], d[2], d[3]);
        const bool charuco = job.board.kind == core::ar::BoardKind::Charuco;
        for (const core::ar::CalibrateJob::View& view : job.views) {
            const std::string name = view.image.filename().string();
            if (view.found && charuco)
                std::printf("  %s: %.3f px (%d corners)\n", name.c_str(), view.error, view.corners);
            else if (view.found)
                std::printf("  %s: %.3f px\n", name.c_str(), view.error);
            else if (charuco && view.corners > 0)
                std::printf("  %s: %d corners, too few or in one line, left out\n", name.c_str(), view.corners);
            else
                std::printf("  %s: board not found, left out\n", name.c_str());
        }
        std::printf("Wrote %s.\n", job.output.string().c_str());
    }
    return ExitOk;
}

} // namespace thespis::cli
