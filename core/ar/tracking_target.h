#pragma once
// What the user tracks, as the command line, Python and the studio let them say it: a marker
// board (board.h) or a printed picture of a known width (planar_tracker.h). makeTracker() is the
// one place that turns it into a Tracker.

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "ar/board.h"
#include "ar/camera_file.h"
#include "ar/tracker.h"
#include "util/error.h"

namespace thespis::core::ar {

struct TrackingTarget {
    std::optional<BoardSpec> board;  ///< an aruco-grid or a charuco board; or
    std::filesystem::path picture;   ///< a planar picture,
    double pictureWidth = 0;         ///< printed this wide (metres)
};

/// Errors: neither or both of a board and a picture, a chessboard, a picture that cannot be used
/// (each with the tracker's own message).
Result<std::unique_ptr<Tracker>> makeTracker(const TrackingTarget& target, const CameraIntrinsics& camera);

/// The board spec or "picture.png, 0.3 m wide", for messages.
std::string describeTarget(const TrackingTarget& target);

} // namespace thespis::core::ar
