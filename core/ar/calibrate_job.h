#pragma once
// Camera calibration as a job (util/job.h), the way OpenCV's own samples calibrate: the board's
// points found in every view, then the intrinsics and distortion that map the board onto them,
// written atomically as an OpenCV YAML camera file (camera_file.h). `thespis-cli calibrate` runs it.
//   chessboard  every inner corner must be seen (cv::findChessboardCorners), refined to a tenth of
//               a pixel; cv::calibrateCamera.
//   ChArUco     the markers found (cv::aruco::detectMarkers) give the inner corners between them
//               (cv::aruco::interpolateCornersCharuco), so a board partly out of the picture or
//               covered still counts; the corners are moved onto the saddles (charuco_corners.h);
//               cv::aruco::calibrateCameraCharuco. A board printed white on black is found in
//               the inverted picture.
// An ArUco grid is refused: its points are the markers' own corners, where two edges meet in an
// L, which the detector places less surely than a chessboard's saddles.

#include <array>
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
    /// A ChArUco view counts with at least this many corners, not all on one line.
    static constexpr int MinimumCharucoCorners = 4;

    std::vector<std::filesystem::path> images;
    BoardSpec board;             ///< a chessboard or a ChArUco board
    bool fixAspectRatio = false; ///< fx = fy (square pixels)
    std::filesystem::path output; ///< the camera file (.yml, .yaml, .xml or .json); empty: none

    struct View {
        std::filesystem::path image;
        bool found = false; ///< the view took part in the calibration
        int corners = 0;    ///< the board's corners found in it (a chessboard: all or none)
        double error = -1;  ///< RMS reprojection error of this view, pixels
    };
    CameraIntrinsics camera; ///< after run()
    /// How surely the views pin the camera down, after run(): OpenCV's estimated standard
    /// deviations of fx, fy, cx and cy, in pixels. Few views, or views seen from alike angles,
    /// leave them large (then a tenth of a pixel on the corners moves the focal length by percents).
    std::array<double, 4> deviations{};
    std::vector<View> views;

    std::string title() const override;
    Result<void> validate() const override;
    Result<void> run(JobContext& context) override;
    void discardOutput() override;
};

} // namespace thespis::core::ar
