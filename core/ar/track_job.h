#pragma once
// Tracking a whole video (or a sequence of pictures) as a job (util/job.h): every frame through a
// TrackingSession, the poses written as CSV, one row per frame:
//     frame,tracked,rx,ry,rz,tx,ty,tz
// the Rodrigues vector and the translation (metres) of target → camera in the target's own frame
// (for an ArUco grid, the frame OpenCV 4.6's aruco::GridBoard uses), so that other tools can be
// compared with it. A frame where the target is not found has tracked 0 and no pose.
// `thespis-cli track` runs it; so do Python and the studio.

#include <filesystem>
#include <string>
#include <vector>

#include "ar/tracking_session.h"
#include "ar/tracking_target.h"
#include "util/job.h"

namespace thespis::core::ar {

struct TrackJob final : Job {
    static constexpr const char* Stage = "Tracking";

    std::filesystem::path video;                ///< a video file; or
    std::vector<std::filesystem::path> pictures; ///< pictures, one per frame,
    double picturesFps = 30;                    ///< at this rate
    std::filesystem::path cameraFile;           ///< OpenCV YAML (camera_file.h)
    TrackingTarget target;
    bool filter = true;                         ///< the temporal filter; off: each frame's own pose
    std::filesystem::path output;               ///< the CSV; empty: none

    // After run():
    std::vector<TrackedFrame> frames;
    TrackingSession::Statistics statistics;
    std::string trackerDescription;

    std::string title() const override;
    Result<void> validate() const override;
    Result<void> run(JobContext& context) override;
    void discardOutput() override;
};

/// The CSV of TrackJob for these frames (header line first): frame, tracked, the filtered pose
/// (rx ry rz Rodrigues, tx ty tz metres), and the frame's own blur (length px, direction degrees)
/// and IPPE ambiguity (TrackerEstimate); the pose and those are empty where the target was not found.
std::string formatPosesCsv(const std::vector<TrackedFrame>& frames);

} // namespace thespis::core::ar
