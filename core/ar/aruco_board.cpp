#include "ar/aruco_board.h"

#include <algorithm>

#include <opencv2/imgproc.hpp>

namespace thespis::core::ar {

cv::Ptr<cv::aruco::Dictionary> arucoDictionary(const BoardSpec& board)
{
    return cv::aruco::getPredefinedDictionary(arucoDictionaryId(board.dictionary));
}

cv::Ptr<cv::aruco::CharucoBoard> charucoBoard(const BoardSpec& board)
{
    return cv::aruco::CharucoBoard::create(board.columns, board.rows, float(board.square), float(board.second),
                                           arucoDictionary(board));
}

cv::Ptr<cv::aruco::Board> arucoBoard(const BoardSpec& board)
{
    if (board.kind == BoardKind::Charuco)
        return charucoBoard(board);
    return cv::aruco::GridBoard::create(board.columns, board.rows, float(board.square), float(board.second),
                                        arucoDictionary(board));
}

namespace {

// The board's extent in its plane: the markers' corners (grids) or the squares (the others).
cv::Rect2d boardExtent(const BoardSpec& board, const cv::aruco::Board* aruco)
{
    if (board.kind == BoardKind::Chessboard)
        return {-board.square, -board.square, (board.columns + 1) * board.square, (board.rows + 1) * board.square};
    if (board.kind == BoardKind::Charuco)
        return {0, 0, board.columns * board.square, board.rows * board.square};
    double minX = 1e9, minY = 1e9, maxX = -1e9, maxY = -1e9;
    for (const auto& marker : aruco->objPoints)
        for (const cv::Point3f& corner : marker) {
            minX = std::min(minX, double(corner.x)), maxX = std::max(maxX, double(corner.x));
            minY = std::min(minY, double(corner.y)), maxY = std::max(maxY, double(corner.y));
        }
    return {minX, minY, maxX - minX, maxY - minY};
}

} // namespace

cv::Mat drawBoard(const BoardSpec& board, double pixelsPerMetre, cv::Matx33d& canvasToBoard)
{
    const cv::Ptr<cv::aruco::Board> aruco = board.kind == BoardKind::Chessboard ? nullptr : arucoBoard(board);
    const cv::Rect2d extent = boardExtent(board, aruco.get());
    const double margin = board.square;
    const cv::Size size(int(std::lround((extent.width + 2 * margin) * pixelsPerMetre)),
                        int(std::lround((extent.height + 2 * margin) * pixelsPerMetre)));
    // Canvas rows run down the board's y axis; a board whose markers say otherwise (an ArUco grid
    // in 4.6 has y up) is still drawn right, since every marker is placed by its own corners.
    const cv::Matx33d boardToCanvas(pixelsPerMetre, 0, (margin - extent.x) * pixelsPerMetre,
                                    0, pixelsPerMetre, (margin - extent.y) * pixelsPerMetre,
                                    0, 0, 1);
    canvasToBoard = boardToCanvas.inv();
    cv::Mat canvas(size, CV_8UC1, cv::Scalar(255));
    const auto toCanvas = [&](double x, double y) {
        const cv::Vec3d p = boardToCanvas * cv::Vec3d(x, y, 1);
        return cv::Point2d(p[0], p[1]);
    };
    const auto fillSquare = [&](double x, double y, double side) {
        const cv::Point2d a = toCanvas(x, y), b = toCanvas(x + side, y + side);
        cv::rectangle(canvas, cv::Rect(cv::Point(int(std::lround(std::min(a.x, b.x))), int(std::lround(std::min(a.y, b.y)))),
                                       cv::Point(int(std::lround(std::max(a.x, b.x))), int(std::lround(std::max(a.y, b.y))))),
                      cv::Scalar(0), cv::FILLED);
    };
    if (board.kind == BoardKind::Chessboard) {
        // Inner corners at (i·square, j·square): squares from −square, the top-left one black.
        for (int j = -1; j < board.rows; ++j)
            for (int i = -1; i < board.columns; ++i)
                if ((i + j) % 2 == 0)
                    fillSquare(i * board.square, j * board.square, board.square);
        return canvas;
    }
    std::vector<cv::Rect2d> markerCells;
    const int markerPixels = std::max(16, int(std::lround(std::abs(aruco->objPoints[0][1].x - aruco->objPoints[0][0].x) *
                                                           pixelsPerMetre)));
    cv::Mat marker, warped;
    for (std::size_t m = 0; m < aruco->ids.size(); ++m) {
        cv::aruco::drawMarker(aruco->dictionary, aruco->ids[m], markerPixels, marker, 1);
        const std::vector<cv::Point3f>& corners = aruco->objPoints[m];
        const cv::Point2f from[4] = {{0, 0}, {float(markerPixels), 0}, {float(markerPixels), float(markerPixels)},
                                     {0, float(markerPixels)}};
        cv::Point2f to[4];
        for (int c = 0; c < 4; ++c)
            to[c] = cv::Point2f(toCanvas(corners[c].x, corners[c].y));
        const cv::Mat placement = cv::getPerspectiveTransform(from, to);
        cv::Mat mask(marker.size(), CV_8UC1, cv::Scalar(255)), warpedMask;
        cv::warpPerspective(marker, warped, placement, size, cv::INTER_NEAREST);
        cv::warpPerspective(mask, warpedMask, placement, size, cv::INTER_NEAREST);
        warped.copyTo(canvas, warpedMask);
        const auto [minX, maxX] = std::minmax({corners[0].x, corners[1].x, corners[2].x, corners[3].x});
        const auto [minY, maxY] = std::minmax({corners[0].y, corners[1].y, corners[2].y, corners[3].y});
        const cv::Rect2d bounds(minX, minY, maxX - minX, maxY - minY);
        markerCells.emplace_back(bounds);
    }
    if (board.kind == BoardKind::Charuco) {
        // The squares without a marker are the black ones.
        for (int j = 0; j < board.rows; ++j)
            for (int i = 0; i < board.columns; ++i) {
                const cv::Point2d centre((i + 0.5) * board.square, (j + 0.5) * board.square);
                const bool holdsMarker = std::any_of(markerCells.begin(), markerCells.end(), [&](const cv::Rect2d& cell) {
                    return centre.x > cell.x && centre.x < cell.x + cell.width && centre.y > cell.y &&
                           centre.y < cell.y + cell.height;
                });
                if (!holdsMarker)
                    fillSquare(i * board.square, j * board.square, board.square);
            }
        if (board.inverted)
            cv::bitwise_not(canvas, canvas);
    }
    return canvas;
}

} // namespace thespis::core::ar
