#pragma once
// A smeared marker's corners by analysis by synthesis (issue 29). Private to core/ar.
//
// Edge profiles (edge_refine.h) place a marker's sides well while its black border is wider than
// the smear; a longer smear runs the border's outer ramp into the ramps of the bits inside, and
// the sides come out a few tenths of a pixel outward along the smear. Here the marker's whole
// pattern, known from its id, is drawn through a homography as the sensor sees it (each pixel's
// area, then the smear), and the homography, the smear and the two grey levels are fitted to the
// picture by Gauss–Newton, so the bits' ramps are part of the model instead of a bias on it.

#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

#include "ar/tracker.h"

namespace thespis::core::ar {

/// A marker as printed: `cells` × `cells` cells (its bits and its black border), row by row from
/// its top-left corner, 1 white and 0 black.
struct MarkerPattern {
    int cells = 0;
    std::vector<std::uint8_t> white;
};

enum class SmearDirection {
    Search, ///< `blur`'s direction is a guess: the best of every 15° is fitted from
    Known   ///< `blur` is close (another marker's fit in the same frame)
};

enum class CornerStart {
    Detected, ///< `corners` are the marker's as the detector (and its edges) saw it
    Predicted ///< `corners` are where a predicted pose puts it: the fit counts only if it moved them
};

/// Moves `corners` (4, the pattern's top-left first, clockwise) to where the pattern, smeared by
/// `blur`, best matches `grey`. `margin` is how many cells of white paper are known to surround
/// the marker (the pixels seen farther out are left out of the fit). The fitted smear is written
/// to `fitted`. False (corners unchanged) when the marker is too near the picture's border, the
/// fit does not converge, or it would move a corner farther than half the border or half the
/// smear, whichever is longer; from a predicted start, also when no step lowers the residual.
bool alignMarkerPattern(const cv::Mat& grey, std::vector<cv::Point2f>& corners, const MarkerPattern& pattern,
                        float margin, const MotionBlur& blur, SmearDirection direction,
                        MotionBlur* fitted = nullptr, CornerStart start = CornerStart::Detected);

} // namespace thespis::core::ar
