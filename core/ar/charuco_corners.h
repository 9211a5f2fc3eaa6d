#pragma once
// ChArUco corners placed on the chessboard's saddles. cv::aruco::interpolateCornersCharuco (OpenCV
// 4.6) places each corner from the markers around it, then refines it with a window too small to
// reach the saddle: the corners stay about 0.4 px inside the black square. Refined again with a
// window scaled to the square's size in the picture, they land within about 0.1 px of it. Shared by
// the marker tracker and the calibration. Private to core/ar: only its .cpp files include this.

#include <vector>

#include <opencv2/core.hpp>

#include "ar/board.h"

namespace thespis::core::ar {

/// Moves `corners` (interpolateCornersCharuco's output, in `grey`) onto the saddles with
/// cv::cornerSubPix. The search window's half side is a quarter of a square in pixels, clamped to
/// 2…8; a square's size is taken from the markers found (`markerCorners`, as detectMarkers returns
/// them; their median side) and the board's square-to-marker ratio. Nothing moves when no marker is
/// given. `grey` is the picture the markers were found in (inverted already, for an inverted board).
void refineCharucoCorners(const cv::Mat& grey, std::vector<cv::Point2f>& corners,
                          const std::vector<std::vector<cv::Point2f>>& markerCorners, const BoardSpec& board);

} // namespace thespis::core::ar
