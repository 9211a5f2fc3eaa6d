#include "ar/tracking_target.h"

#include <sstream>

#include "ar/marker_tracker.h"
#include "ar/planar_tracker.h"

namespace thespis::core::ar {

Result<std::unique_ptr<Tracker>> makeTracker(const TrackingTarget& target, const CameraIntrinsics& camera)
{
    const bool picture = !target.picture.empty();
    if (target.board.has_value() == picture)
        return makeError(ErrorCode::InvalidArgument, "Track either a board or a picture (one of the two)");
    if (target.board) {
        auto tracker = MarkerTracker::create(*target.board, camera);
        if (!tracker)
            return tracker.error();
        return std::unique_ptr<Tracker>(std::move(*tracker));
    }
    auto tracker = PlanarTracker::create(target.picture, target.pictureWidth, camera);
    if (!tracker)
        return tracker.error();
    return std::unique_ptr<Tracker>(std::move(*tracker));
}

std::string describeTarget(const TrackingTarget& target)
{
    if (target.board)
        return formatBoard(*target.board);
    std::ostringstream text;
    text << target.picture.filename().string() << ", " << target.pictureWidth << " m wide";
    return text.str();
}

} // namespace thespis::core::ar
