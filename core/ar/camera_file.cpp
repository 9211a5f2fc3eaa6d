#include "ar/camera_file.h"

#include <opencv2/core.hpp>

#include <cmath>

#include "util/file_io.h"

namespace thespis::core::ar {

namespace {

Error malformed(const std::string& name, const std::string& field, const std::string& what)
{
    return makeError(ErrorCode::CorruptData, name + ": " + field + ": " + what);
}

bool finite(const cv::Mat& m)
{
    return cv::checkRange(m);
}

} // namespace

Result<CameraIntrinsics> parseCameraFile(const std::string& text, const std::string& name)
{
    try {
        cv::FileStorage file(text, cv::FileStorage::READ | cv::FileStorage::MEMORY);
        if (!file.isOpened())
            return makeError(ErrorCode::CorruptData, name + ": not a camera file OpenCV can read.");
        CameraIntrinsics camera;
        for (const auto& [field, value] : {std::pair{"image_width", &camera.width}, std::pair{"image_height", &camera.height}}) {
            const cv::FileNode node = file[field];
            if (node.empty())
                return malformed(name, field, "this field is required but missing");
            if (!node.isInt() || int(node) <= 0)
                return malformed(name, field, "expected a positive whole number of pixels");
            *value = int(node);
        }
        cv::Mat matrix, distortion;
        if (file["camera_matrix"].empty())
            return malformed(name, "camera_matrix", "this field is required but missing");
        file["camera_matrix"] >> matrix;
        if (matrix.rows != 3 || matrix.cols != 3 || matrix.channels() != 1)
            return malformed(name, "camera_matrix", "expected a 3 × 3 matrix");
        matrix.convertTo(matrix, CV_64F);
        if (!finite(matrix) || !(matrix.at<double>(0, 0) > 0) || !(matrix.at<double>(1, 1) > 0))
            return malformed(name, "camera_matrix", "the focal lengths must be positive numbers");
        for (int i = 0; i < 9; ++i)
            camera.matrix[std::size_t(i)] = matrix.at<double>(i / 3, i % 3);
        if (file["distortion_coefficients"].empty())
            return malformed(name, "distortion_coefficients", "this field is required but missing");
        file["distortion_coefficients"] >> distortion;
        const int count = int(distortion.total());
        if (distortion.channels() != 1 || (distortion.rows != 1 && distortion.cols != 1)
            || (count != 4 && count != 5 && count != 8 && count != 12 && count != 14))
            return malformed(name, "distortion_coefficients", "expected 4, 5, 8, 12 or 14 numbers in a row or column");
        distortion.convertTo(distortion, CV_64F);
        if (!finite(distortion))
            return malformed(name, "distortion_coefficients", "expected finite numbers");
        camera.distortion.assign(distortion.begin<double>(), distortion.end<double>());
        if (const cv::FileNode error = file["avg_reprojection_error"]; !error.empty() && error.isReal())
            camera.reprojectionError = double(error);
        return camera;
    } catch (const cv::Exception& e) {
        return makeError(ErrorCode::CorruptData, name + ": not a camera file OpenCV can read (" + e.msg + ").");
    }
}

Result<CameraIntrinsics> readCameraFile(const std::filesystem::path& path)
{
    auto text = readTextFile(path);
    if (!text)
        return text.error();
    return parseCameraFile(*text, path.string());
}

std::string encodeCameraFile(const CameraIntrinsics& camera)
{
    cv::FileStorage file(".yml", cv::FileStorage::WRITE | cv::FileStorage::MEMORY);
    file << "image_width" << camera.width << "image_height" << camera.height;
    file << "camera_matrix" << cv::Mat(3, 3, CV_64F, const_cast<double*>(camera.matrix.data())).clone();
    // No distortion is written as OpenCV writes it: five zeros.
    file << "distortion_coefficients"
         << (camera.distortion.empty()
                 ? cv::Mat::zeros(5, 1, CV_64F)
                 : cv::Mat(int(camera.distortion.size()), 1, CV_64F, const_cast<double*>(camera.distortion.data())).clone());
    if (camera.reprojectionError >= 0)
        file << "avg_reprojection_error" << camera.reprojectionError;
    return file.releaseAndGetString();
}

Result<void> writeCameraFile(const std::filesystem::path& path, const CameraIntrinsics& camera)
{
    return writeFileAtomically(path, encodeCameraFile(camera));
}

} // namespace thespis::core::ar
