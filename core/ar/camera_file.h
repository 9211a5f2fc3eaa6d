#pragma once
// A camera's intrinsics as OpenCV writes them (YAML, cv::FileStorage): `image_width`,
// `image_height`, `camera_matrix` (3 × 3), `distortion_coefficients` (4, 5, 8, 12 or 14), and,
// when known, `avg_reprojection_error`. Other tools' calibration files read as they are; ours
// read in OpenCV's. The reader names the file and the field of what is missing or malformed.

#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "util/error.h"

namespace thespis::core::ar {

struct CameraIntrinsics {
    int width = 0, height = 0;          ///< pixels of the images it was calibrated on
    std::array<double, 9> matrix{};     ///< fx 0 cx / 0 fy cy / 0 0 1, row by row
    std::vector<double> distortion;     ///< k1 k2 p1 p2 [k3 …], OpenCV's order
    double reprojectionError = -1;      ///< RMS in pixels; −1 when the file does not say

    double fx() const { return matrix[0]; }
    double fy() const { return matrix[4]; }
    double cx() const { return matrix[2]; }
    double cy() const { return matrix[5]; }
    bool operator==(const CameraIntrinsics&) const = default;
};

/// Errors: the file is missing or not YAML/XML/JSON that OpenCV reads, a field is missing, a matrix
/// has the wrong size, sizes or focal lengths are not positive.
Result<CameraIntrinsics> readCameraFile(const std::filesystem::path& path);
/// The same from text (`name` in messages).
Result<CameraIntrinsics> parseCameraFile(const std::string& text, const std::string& name);
/// OpenCV's YAML, written atomically.
Result<void> writeCameraFile(const std::filesystem::path& path, const CameraIntrinsics& camera);
std::string encodeCameraFile(const CameraIntrinsics& camera);

} // namespace thespis::core::ar
