#include "ar/tracking_session.h"

#include <algorithm>
#include <chrono>

namespace thespis::core::ar {

const char* trackingEventName(TrackingEvent event)
{
    switch (event) {
    case TrackingEvent::None:
        return "";
    case TrackingEvent::Found:
        return "found";
    case TrackingEvent::Lost:
        return "lost";
    case TrackingEvent::Recovered:
        return "recovered";
    }
    return "";
}

TrackingSession::TrackingSession(std::unique_ptr<Tracker> tracker, PoseFilterSettings settings, bool filter)
    : m_tracker(std::move(tracker)), m_filter(settings), m_filtering(filter)
{
}

void TrackingSession::reset()
{
    m_tracker->reset();
    m_filter.reset();
    m_tracking = false;
    m_everFound = false;
    m_statistics = {};
}

TrackedFrame TrackingSession::process(const VideoFrame& frame)
{
    TrackedFrame out;
    out.frame = frame.index;
    out.time = frame.time;
    out.measured = m_tracker->estimate(frame);
    out.tracked = out.measured.found;
    if (out.tracked) {
        out.pose = m_filtering ? m_filter.update(frame.time, out.measured.pose, out.measured.information)
                               : out.measured.pose;
        out.hasPose = true;
        if (!m_tracking)
            out.event = m_everFound ? TrackingEvent::Recovered : TrackingEvent::Found;
        m_tracking = m_everFound = true;
    } else {
        if (m_filtering)
            if (const std::optional<TargetPose> predicted = m_filter.predict(frame.time)) {
                out.pose = *predicted;
                out.hasPose = true;
            }
        if (m_tracking) {
            out.event = TrackingEvent::Lost;
            ++m_statistics.lost;
        }
        m_tracking = false;
    }
    out.latency = std::chrono::duration<double>(std::chrono::steady_clock::now() - frame.captured).count();
    Statistics& s = m_statistics;
    s.meanLatency = (s.meanLatency * double(s.frames) + out.latency) / double(s.frames + 1);
    s.maxLatency = std::max(s.maxLatency, out.latency);
    ++s.frames;
    s.tracked += out.tracked ? 1 : 0;
    return out;
}

} // namespace thespis::core::ar
