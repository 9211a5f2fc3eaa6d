#pragma once
// A BoardSpec as OpenCV 4.6's cv::aruco objects (the "old" aruco API of opencv_contrib), and the
// board's own picture. Private to core/ar: only its .cpp files include this.

#include <opencv2/aruco.hpp>
#include <opencv2/aruco/charuco.hpp>

#include "ar/board.h"

namespace thespis::core::ar {

/// The board's dictionary; parseBoard() has checked the name.
cv::Ptr<cv::aruco::Dictionary> arucoDictionary(const BoardSpec& board);
/// An aruco-grid as cv::aruco::GridBoard, a ChArUco board as cv::aruco::CharucoBoard. Not for
/// chessboards.
cv::Ptr<cv::aruco::Board> arucoBoard(const BoardSpec& board);
/// A ChArUco board (whose `chessboardCorners` are the inner corners). cv::aruco::Board is not
/// polymorphic in 4.6, so a ChArUco board is kept as what it is.
cv::Ptr<cv::aruco::CharucoBoard> charucoBoard(const BoardSpec& board);

/// The board as printed, `pixelsPerMetre` pixels per metre, grey, with a white margin of one
/// square (or marker) around it; `canvasToBoard` maps a canvas pixel (x, y, 1) to the board's
/// plane (metres, in OpenCV's board frame). Chessboards, grids and ChArUco boards alike.
cv::Mat drawBoard(const BoardSpec& board, double pixelsPerMetre, cv::Matx33d& canvasToBoard);

} // namespace thespis::core::ar
