#pragma once
// Tracking an ArUco grid or a ChArUco board (board.h) with OpenCV 4.6's cv::aruco: markers found
// with sub-pixel corners, markers the first pass missed recovered against the board's layout,
// ChArUco corners interpolated between them, and the pose by IPPE with the mirror-image pose
// rejected (pose_fit.h). One frame at a time; TrackingSession filters the poses over time.

#include <array>
#include <memory>
#include <string_view>
#include <vector>

#include "ar/board.h"
#include "ar/camera_file.h"
#include "ar/tracker.h"
#include "util/error.h"

namespace thespis::core::ar {

struct DetectedMarker {
    int id = -1;
    std::array<std::array<float, 2>, 4> corners{}; ///< pixels: top-left, top-right, bottom-right, bottom-left
};

enum class MarkerCorners {
    SubPixel,   ///< each side's edge found along its length, the corners where the edges cross
    WholePixels ///< as OpenCV's detector gives them (its contour's corners, whole pixels)
};

/// The markers of a predefined dictionary (DICT_…) in a picture, in OpenCV's order. Errors: an
/// unknown dictionary name.
Result<std::vector<DetectedMarker>> detectMarkers(const VideoFrame& frame, std::string_view dictionary,
                                                  MarkerCorners corners = MarkerCorners::SubPixel);

class MarkerTracker final : public Tracker {
public:
    /// Errors: a chessboard (it is for calibration only: its pose flips with its symmetry), a
    /// camera without a positive focal length.
    static Result<std::unique_ptr<MarkerTracker>> create(const BoardSpec& board, const CameraIntrinsics& camera);
    ~MarkerTracker() override;

    std::string description() const override;
    TrackerEstimate estimate(const VideoFrame& frame) override;
    void reset() override;
    TargetGeometry geometry() const override;

    /// The last frame's markers of the board, for the overlay.
    const std::vector<DetectedMarker>& markers() const;
    /// The last frame's ChArUco corners (board corner ids and pixels); empty for a grid.
    const std::vector<std::pair<int, std::array<float, 2>>>& charucoCorners() const;

private:
    struct State;
    explicit MarkerTracker(std::unique_ptr<State> state);
    std::unique_ptr<State> m_state;
};

} // namespace thespis::core::ar
