#include "ar/calibrate_job.h"

#include <opencv2/calib3d.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "ar/aruco_board.h"
#include "ar/charuco_corners.h"

namespace thespis::core::ar {

namespace {

// ChArUco corners are interpolated from the markers around them; fewer than this many markers
// give corners too loosely placed (as in the marker tracker).
constexpr int CharucoMinimumMarkers = 2;

// The board's points found in one view: where they are seen and, on a ChArUco board, which
// corners they are.
struct FoundPoints {
    std::vector<cv::Point2f> pixels;
    std::vector<int> ids;
};

// A chessboard is found whole or not at all; its corners refined to a tenth of a pixel.
bool findChessboard(const cv::Mat& grey, const BoardSpec& board, FoundPoints& found)
{
    if (!cv::findChessboardCorners(grey, cv::Size(board.columns, board.rows), found.pixels,
                                   cv::CALIB_CB_ADAPTIVE_THRESH | cv::CALIB_CB_NORMALIZE_IMAGE)) {
        found.pixels.clear();
        return false;
    }
    cv::cornerSubPix(grey, found.pixels, cv::Size(11, 11), cv::Size(-1, -1),
                     cv::TermCriteria(cv::TermCriteria::EPS + cv::TermCriteria::COUNT, 30, 0.01));
    return true;
}

// A ChArUco board's inner corners between the markers found, on the saddles. `grey` is inverted
// in place for a board printed white on black.
bool findCharuco(cv::Mat& grey, const BoardSpec& spec, const cv::Ptr<cv::aruco::CharucoBoard>& board,
                 FoundPoints& found)
{
    found = {};
    if (spec.inverted)
        cv::bitwise_not(grey, grey);
    cv::Ptr<cv::aruco::DetectorParameters> parameters = cv::aruco::DetectorParameters::create();
    parameters->cornerRefinementMethod = cv::aruco::CORNER_REFINE_SUBPIX;
    std::vector<std::vector<cv::Point2f>> markers, rejected;
    std::vector<int> markerIds;
    cv::aruco::detectMarkers(grey, board->dictionary, markers, markerIds, parameters, rejected);
    if (!markerIds.empty()) // markers missed at first, looked for again where the board puts them
        cv::aruco::refineDetectedMarkers(grey, cv::Ptr<cv::aruco::Board>(board), markers, markerIds, rejected,
                                         cv::noArray(), cv::noArray(), 10.f, 3.f, true, cv::noArray(), parameters);
    if (int(markerIds.size()) < CharucoMinimumMarkers)
        return false;
    cv::aruco::interpolateCornersCharuco(markers, markerIds, grey, board, found.pixels, found.ids, cv::noArray(),
                                         cv::noArray(), CharucoMinimumMarkers);
    refineCharucoCorners(grey, found.pixels, markers, spec);
    return int(found.ids.size()) >= CalibrateJob::MinimumCharucoCorners &&
           !cv::aruco::testCharucoCornersCollinear(board, found.ids);
}

std::string boardName(const BoardSpec& board)
{
    const std::string size = std::to_string(board.columns) + " × " + std::to_string(board.rows);
    if (board.kind == BoardKind::Charuco)
        return "ChArUco board " + size + " of " + board.dictionary + (board.inverted ? " (inverted)" : "");
    return size + " chessboard";
}

// What to check when the board was found in too few views.
std::string boardHint(const BoardSpec& board)
{
    if (board.kind == BoardKind::Charuco)
        return std::string(" Are the dictionary and the squares (not the corners) counted right") +
               (board.inverted ? ", and is the board printed white on black?"
                               : "? A board printed white on black needs :inverted.");
    return " Are the inner corners counted right?";
}

} // namespace

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
    switch (board.kind) {
    case BoardKind::Chessboard:
        if (board.columns < 2 || board.rows < 2 || !(board.square > 0))
            return makeError(ErrorCode::InvalidArgument,
                             "The chessboard needs at least 2 × 2 inner corners and a square side.");
        break;
    case BoardKind::Charuco:
        if (board.columns < 3 || board.rows < 3 || !(board.square > 0) || !(board.second > 0) ||
            board.second >= board.square)
            return makeError(ErrorCode::InvalidArgument,
                             "Calibration needs a ChArUco board of at least 3 × 3 squares, with markers smaller than "
                             "the squares.");
        if (arucoDictionaryId(board.dictionary) < 0)
            return makeError(ErrorCode::InvalidArgument, "\"" + board.dictionary +
                                                             "\" is not an ArUco dictionary (DICT_4X4_50, …).");
        break;
    case BoardKind::ArucoGrid:
        return makeError(ErrorCode::InvalidArgument,
                         "An ArUco grid is for tracking only; calibrate with a chessboard "
                         "(chessboard:COLUMNSxROWS:SQUARE) or a ChArUco board "
                         "(charuco:DICTIONARY:COLUMNSxROWS:SQUARE:MARKER).");
    }
    const std::string extension = output.extension().string();
    if (!output.empty() && extension != ".yml" && extension != ".yaml" && extension != ".xml" && extension != ".json")
        return makeError(ErrorCode::InvalidArgument, "The camera file must be .yml, .yaml, .xml or .json, not " +
                                                         output.string() + ".");
    return {};
}

Result<void> CalibrateJob::run(JobContext& context)
{
    if (auto valid = validate(); !valid)
        return valid;
    views.clear();
    context.beginStage(FindingStage, images.size());
    const bool charuco = board.kind == BoardKind::Charuco;
    const cv::Ptr<cv::aruco::CharucoBoard> charucoSpec = charuco ? charucoBoard(board) : nullptr;
    std::vector<std::vector<cv::Point2f>> imagePoints;
    std::vector<std::vector<int>> cornerIds; // ChArUco only
    cv::Size size;
    for (std::size_t i = 0; i < images.size(); ++i) {
        if (context.stopRequested())
            return cancelledError(title());
        const std::filesystem::path& path = images[i];
        cv::Mat grey = cv::imread(path.string(), cv::IMREAD_GRAYSCALE);
        if (grey.empty())
            return makeError(ErrorCode::NotFound, path.string() + ": not an image that can be read.");
        if (size.empty())
            size = grey.size();
        else if (grey.size() != size)
            return makeError(ErrorCode::InvalidArgument,
                             path.string() + ": " + std::to_string(grey.cols) + " × " + std::to_string(grey.rows) +
                                 " pixels, while the first view has " + std::to_string(size.width) + " × " +
                                 std::to_string(size.height) + ": calibrate one camera and resolution at a time.");
        FoundPoints found;
        View view{path};
        view.found = charuco ? findCharuco(grey, board, charucoSpec, found) : findChessboard(grey, board, found);
        view.corners = int(found.pixels.size());
        if (view.found) {
            imagePoints.push_back(std::move(found.pixels));
            cornerIds.push_back(std::move(found.ids));
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
                         "The " + boardName(board) + " was found in " + std::to_string(imagePoints.size()) + " of " +
                             std::to_string(images.size()) + " views (at least " + std::to_string(MinimumViews) +
                             " needed); not in " + missing + "." + boardHint(board));
    }

    context.beginStage(SolvingStage);
    if (context.stopRequested())
        return cancelledError(title());
    cv::Mat matrix = cv::Mat::eye(3, 3, CV_64F), distortion = cv::Mat::zeros(5, 1, CV_64F);
    std::vector<cv::Mat> rotations, translations;
    cv::Mat deviationsIntrinsic, deviationsExtrinsic, perView;
    const int flags = fixAspectRatio ? cv::CALIB_FIX_ASPECT_RATIO : 0;
    double rms = 0;
    if (charuco) {
        rms = cv::aruco::calibrateCameraCharuco(imagePoints, cornerIds, charucoSpec, size, matrix, distortion,
                                                rotations, translations, deviationsIntrinsic, deviationsExtrinsic,
                                                perView, flags);
    } else {
        std::vector<cv::Point3f> corners;
        for (const auto& c : chessboardCorners(board))
            corners.emplace_back(c[0], c[1], c[2]);
        const std::vector<std::vector<cv::Point3f>> objectPoints(imagePoints.size(), corners);
        rms = cv::calibrateCamera(objectPoints, imagePoints, size, matrix, distortion, rotations, translations,
                                  deviationsIntrinsic, deviationsExtrinsic, perView, flags);
    }
    camera.width = size.width;
    camera.height = size.height;
    for (int k = 0; k < 9; ++k)
        camera.matrix[std::size_t(k)] = matrix.at<double>(k / 3, k % 3);
    camera.distortion.assign(distortion.begin<double>(), distortion.end<double>());
    camera.reprojectionError = rms;
    for (int k = 0; k < 4; ++k)
        deviations[std::size_t(k)] = deviationsIntrinsic.at<double>(k);
    if (fixAspectRatio) // OpenCV solves for fy and derives fx, whose deviation it then gives as 0
        deviations[0] = deviations[1] * camera.fx() / camera.fy();
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
