#pragma once
// Tracking over time: a tracker (tracker.h) per frame, the temporal filter (pose_filter.h) over
// its poses, the events people see (found, lost, recovered), and how long a frame took from
// capture to pose. The CLI's `track`, Python and the studio's AR preview all run one.

#include <cstdint>
#include <memory>

#include "ar/pose_filter.h"
#include "ar/tracker.h"

namespace thespis::core::ar {

enum class TrackingEvent { None, Found, Lost, Recovered };
const char* trackingEventName(TrackingEvent event); ///< "found", "lost", "recovered", ""

struct TrackedFrame {
    std::int64_t frame = -1;
    double time = 0;
    bool tracked = false;      ///< the target was found in this frame
    TargetPose pose;           ///< filtered; when not tracked, predicted while the filter remembers
    bool hasPose = false;      ///< false when lost for longer than the filter remembers
    TrackerEstimate measured;  ///< the frame's own estimate, before filtering
    TrackingEvent event = TrackingEvent::None;
    double latency = 0;        ///< seconds from the frame's capture to its pose
};

class TrackingSession {
public:
    /// `filter` false gives each frame's own estimate (to compare, or for a still picture).
    explicit TrackingSession(std::unique_ptr<Tracker> tracker, PoseFilterSettings settings = {}, bool filter = true);

    TrackedFrame process(const VideoFrame& frame);
    /// Starts over (a new video): the tracker and the filter forget.
    void reset();

    Tracker& tracker() { return *m_tracker; }
    bool tracking() const { return m_tracking; }

    struct Statistics {
        std::int64_t frames = 0, tracked = 0, lost = 0; ///< lost: how many times it was lost
        double meanLatency = 0, maxLatency = 0;          ///< seconds
    };
    const Statistics& statistics() const { return m_statistics; }

private:
    std::unique_ptr<Tracker> m_tracker;
    PoseFilter m_filter;
    bool m_filtering;
    bool m_tracking = false, m_everFound = false;
    Statistics m_statistics;
};

} // namespace thespis::core::ar
