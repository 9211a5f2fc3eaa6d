#include "ar/charuco_corners.h"

#include <algorithm>
#include <cmath>

#include <opencv2/imgproc.hpp>

namespace thespis::core::ar {

namespace {

// The half side of the search window for markers seen `markerSide` pixels wide.
int refineWindow(double markerSide, const BoardSpec& board)
{
    const double squarePixels = board.second > 0 ? markerSide * board.square / board.second : markerSide;
    return std::clamp(int(squarePixels / 4), 2, 8);
}

} // namespace

void refineCharucoCorners(const cv::Mat& grey, std::vector<cv::Point2f>& corners,
                          const std::vector<std::vector<cv::Point2f>>& markerCorners, const BoardSpec& board)
{
    if (corners.empty() || markerCorners.empty())
        return;
    // The median marker, so one marker seen at a slant or half-detected does not set the window.
    std::vector<double> sides;
    sides.reserve(markerCorners.size());
    for (const std::vector<cv::Point2f>& marker : markerCorners)
        if (marker.size() == 4)
            sides.push_back(std::sqrt(std::abs(cv::contourArea(marker))));
    if (sides.empty())
        return;
    const auto middle = sides.begin() + std::ptrdiff_t(sides.size() / 2);
    std::nth_element(sides.begin(), middle, sides.end());
    const int window = refineWindow(*middle, board);
    cv::cornerSubPix(grey, corners, cv::Size(window, window), cv::Size(-1, -1),
                     cv::TermCriteria(cv::TermCriteria::EPS + cv::TermCriteria::COUNT, 30, 0.01));
}

} // namespace thespis::core::ar
