// thespis-cli calibrate: runs core's CalibrateJob (a camera's intrinsics from views of a
// chessboard, paper §7.2) with a progress bar, prints the RMS reprojection error and each view's,
// and writes OpenCV's YAML camera file that `track` and the studio's AR preview read.

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
    spec.summary = "Calibrate a camera from photos of a chessboard; write its intrinsics (OpenCV YAML).";
    spec.positionals = {"IMAGE"};
    spec.repeatsLast = true;
    spec.options = {
        {"board", "chessboard:COLSxROWS:SQUARE", "the board: inner corners along x and y, square side in metres", true},
        {"out", "FILE.yml", "the camera file to write (.yml, .yaml, .xml or .json); replaced atomically", true},
        {"fix-aspect", "", "square pixels: fx = fy"},
        {"quiet", "", "no progress and no summary"},
    };
    spec.description =
        "At least 3 IMAGEs of one camera at one resolution, the board seen from different angles.\n"
        "Corners are refined to a tenth of a pixel; the summary gives the RMS reprojection error of\n"
        "all views and of each (a view far above the rest is worth leaving out).\n"
        "Example: thespis-cli calibrate left*.jpg --board chessboard:9x6:0.025 --fix-aspect --out camera.yml\n"
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
    if (!solved) {
        if (solved.error().code == core::ErrorCode::Cancelled)
            return ExitCancelled;
        printError(spec.name, solved.error());
        return solved.error().code == core::ErrorCode::IoError ? ExitFailure : ExitInvalidInput;
    }
    if (!quiet) {
        const core::ar::CameraIntrinsics& c = job.camera;
        std::printf("Calibrated %d × %d: fx %.2f, fy %.2f, centre (%.2f, %.2f); RMS reprojection error %.3f px.\n",
                    c.width, c.height, c.fx(), c.fy(), c.cx(), c.cy(), c.reprojectionError);
        for (const core::ar::CalibrateJob::View& view : job.views)
            if (view.found)
                std::printf("  %s: %.3f px\n", view.image.filename().string().c_str(), view.error);
            else
                std::printf("  %s: board not found, left out\n", view.image.filename().string().c_str());
        std::printf("Wrote %s.\n", job.output.string().c_str());
    }
    return ExitOk;
}

} // namespace thespis::cli
