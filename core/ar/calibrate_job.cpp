#include "ar/calibrate_job.h"

#include <opencv2/calib3d.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

namespace thespis::core::ar {

std::string CalibrateJob::title() const
{
    return "The calibration from " + std::to_string(images.size()) + (images.size() == 1 ? " view" : " views");
}

Result<void> CalibrateJob::validate() const
{
    if (int(images.size()) < MinimumViews)
        return makeError(ErrorCode::InvalidArgument, "Calibration needs at least " + std::to_string(MinimumViews) +
                                                         " views of the board; " + std::to_string(images.size()) +
                                                         " given.");
    if (board.kind != BoardKind::Chessboard)
        return makeError(ErrorCode::InvalidArgument, "Calibration takes a chessboard (chessboard:COLUMNSxROWS:SQUARE).");
    if (board.columns < 2 || board.rows < 2 || !(board.square > 0))
        return makeError(ErrorCode::InvalidArgument, "The chessboard needs at least 2 × 2 inner corners and a square side.");
    const std::string extension = output.extension().string();
    if (!output.empty() && extension != ".yml" && extension != ".yaml" && extension != ".xml" && extension != ".json")
        return makeError(ErrorCode::InvalidArgument, "The camera file must be .yml, .yaml, .xml or .json, not " +
                                                         output.string() + ".");
    return {};
}

Result<void> CalibrateJob::run(JobContext& context)
{
    views.clear();
    context.beginStage(FindingStage, images.size());
    const cv::Size pattern(board.columns, board.rows);
    std::vector<cv::Point3f> corners;
    for (const auto& c : chessboardCorners(board))
        corners.emplace_back(c[0], c[1], c[2]);
    std::vector<std::vector<cv::Point3f>> objectPoints;
    std::vector<std::vector<cv::Point2f>> imagePoints;
    cv::Size size;
    for (std::size_t i = 0; i < images.size(); ++i) {
        if (context.stopRequested())
            return cancelledError(title());
        const std::filesystem::path& path = images[i];
        const cv::Mat gray = cv::imread(path.string(), cv::IMREAD_GRAYSCALE);
        if (gray.empty())
            return makeError(ErrorCode::NotFound, path.string() + ": not an image that can be read.");
        if (size.empty())
            size = gray.size();
        else if (gray.size() != size)
            return makeError(ErrorCode::InvalidArgument,
                             path.string() + ": " + std::to_string(gray.cols) + " × " + std::to_string(gray.rows) +
                                 " pixels, while the first view has " + std::to_string(size.width) + " × " +
                                 std::to_string(size.height) + ": calibrate one camera and resolution at a time.");
        std::vector<cv::Point2f> found;
        View view{path};
        view.found = cv::findChessboardCorners(gray, pattern, found,
                                               cv::CALIB_CB_ADAPTIVE_THRESH | cv::CALIB_CB_NORMALIZE_IMAGE);
        if (view.found) {
            cv::cornerSubPix(gray, found, cv::Size(11, 11), cv::Size(-1, -1),
                             cv::TermCriteria(cv::TermCriteria::EPS + cv::TermCriteria::COUNT, 30, 0.01));
            imagePoints.push_back(std::move(found));
            objectPoints.push_back(corners);
        }
        views.push_back(std::move(view));
        context.setDone(i + 1);
    }
    if (int(imagePoints.size()) < MinimumViews) {
        std::string missing;
        for (const View& view : views)
            if (!view.found)
                missing += (missing.empty() ? "" : ", ") + view.image.filename().string();
        return makeError(ErrorCode::InvalidArgument,
                         "The " + std::to_string(board.columns) + " × " + std::to_string(board.rows) +
                             " chessboard was found in " + std::to_string(imagePoints.size()) + " of " +
                             std::to_string(images.size()) + " views (at least " + std::to_string(MinimumViews) +
                             " needed); not in " + missing + ". Are the inner corners counted right?");
    }

    context.beginStage(SolvingStage);
    if (context.stopRequested())
        return cancelledError(title());
    cv::Mat matrix = cv::Mat::eye(3, 3, CV_64F), distortion = cv::Mat::zeros(5, 1, CV_64F);
    std::vector<cv::Mat> rotations, translations;
    cv::Mat deviationsIntrinsic, deviationsExtrinsic, perView;
    const int flags = fixAspectRatio ? cv::CALIB_FIX_ASPECT_RATIO : 0;
    const double rms = cv::calibrateCamera(objectPoints, imagePoints, size, matrix, distortion, rotations, translations,
                                           deviationsIntrinsic, deviationsExtrinsic, perView, flags);
    camera.width = size.width;
    camera.height = size.height;
    for (int k = 0; k < 9; ++k)
        camera.matrix[std::size_t(k)] = matrix.at<double>(k / 3, k % 3);
    camera.distortion.assign(distortion.begin<double>(), distortion.end<double>());
    camera.reprojectionError = rms;
    for (std::size_t v = 0, solved = 0; v < views.size(); ++v)
        if (views[v].found)
            views[v].error = perView.at<double>(int(solved++));
    if (context.stopRequested())
        return cancelledError(title());
    return output.empty() ? Result<void>() : writeCameraFile(output, camera);
}

void CalibrateJob::discardOutput()
{
    std::error_code ignored;
    if (!output.empty())
        std::filesystem::remove(output, ignored);
}

} // namespace thespis::core::ar
