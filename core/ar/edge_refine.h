#pragma once
// A marker's corners to a fraction of a pixel from its four edges, and the motion blur those
// edges show (issue 29). Private to core/ar.
//
// Each side's edge is found at many points along it, a line fitted through them, and the corners
// are where the lines cross. At each point the grey level is profiled across the side, from the
// white paper outside to the black border inside, and the edge is the centroid of the drop
// between the two plateaus. For any blur symmetric about the edge (a smear, defocus, the sensor
// pixel's own area) that centroid is the edge itself, however wide the ramp, and it does not
// depend on where the detector's thresholded contour started (which a smear pushes outward).
// (A marker's corner is an L, not the saddle cv::cornerSubPix is made for, which places it a few
// tenths of a pixel off, the same way every frame.)

#include <vector>

#include <opencv2/core.hpp>

#include "ar/tracker.h"

namespace thespis::core::ar {

/// What one side's profiles showed: the direction across it and how wide its ramp is.
struct EdgeRamp {
    cv::Point2f normal; ///< unit, across the side
    float width = 0;    ///< mean 10–90 % ramp width, pixels
    int profiles = 0;   ///< how many profiles measured it
};

/// Moves `corners` (4, clockwise in the picture, black square on white) onto the crossings of the
/// fitted edges; `cells` is the marker's width in cells (its bits and both borders), which sizes
/// the profiles to its black border. False (corners unchanged) when an edge cannot be found, or a
/// corner would move more than half the border. Each side's ramp is appended to `ramps`.
bool refineMarkerEdges(const cv::Mat& grey, std::vector<cv::Point2f>& corners, int cells,
                       std::vector<EdgeRamp>* ramps = nullptr);

/// The frame's motion blur from its edges' ramps: a smear of length L along d widens an edge of
/// normal n by L·|n·d|. Fitted as one smear (a rank-1 blur tensor) over the edges' directions.
MotionBlur estimateMotionBlur(const std::vector<EdgeRamp>& ramps);

} // namespace thespis::core::ar
