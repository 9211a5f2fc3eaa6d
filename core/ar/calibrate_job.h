#pragma once
// Camera calibration as a job (util/job.h), the way OpenCV's own sample calibrates: the board's
// inner corners found in every view (refined to a tenth of a pixel), then the intrinsics and
// distortion that map the board onto them (cv::calibrateCamera), written atomically as an OpenCV
// YAML camera file (camera_file.h). `thespis-cli calibrate` runs it.

#include <filesystem>
#include <string>
#include <vector>

#include "ar/board.h"
#include "ar/camera_file.h"
#include "util/job.h"

namespace thespis::core::ar {

struct CalibrateJob final : Job {
    static constexpr const char* FindingStage = "Finding the board";
    static constexpr const char* SolvingStage = "Calibrating";
    static constexpr int MinimumViews = 3;

    std::vector<std::filesystem::path> images;
    BoardSpec board;             ///< a chessboard (ChArUco comes with the tracking)
    bool fixAspectRatio = false; ///< fx = fy (square pixels)
    std::filesystem::path output; ///< the camera file (.yml, .yaml, .xml or .json); empty: none

    struct View {
        std::filesystem::path image;
        bool found = false;
        double error = -1; ///< RMS reprojection error of this view, pixels
    };
    CameraIntrinsics camera; ///< after run()
    std::vector<View> views;

    std::string title() const override;
    Result<void> validate() const override;
    Result<void> run(JobContext& context) override;
    void discardOutput() override;
};

} // namespace thespis::core::ar
