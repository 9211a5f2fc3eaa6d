// Timeline snapping: collecting a gesture's targets and snapping times and moves to them.

#include "widgets/timeline_snapping.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace thespis::widgets {

qint64 timelineSnapThreshold(double ticksPerPixel)
{
    return std::llround(TimelineMetrics::SnapDistance * ticksPerPixel);
}

void TimelineSnapTargets::collect(std::span<const TimelineClip> clips, std::span<const char> excludeClips,
                                  std::span<const TimelineMarker> markers, int excludeMarker, qint64 duration,
                                  std::optional<qint64> playhead)
{
    m_times.clear();
    m_times.reserve(2 * clips.size() + markers.size() + 3);
    m_times.push_back(0);
    if (duration > 0)
        m_times.push_back(duration);
    for (std::size_t i = 0; i < clips.size(); ++i) {
        if (!excludeClips.empty() && excludeClips[i])
            continue;
        m_times.push_back(clips[i].start);
        if (clips[i].end != TimelineOpenEnd)
            m_times.push_back(clips[i].end);
    }
    for (int i = 0; i < int(markers.size()); ++i)
        if (i != excludeMarker)
            m_times.push_back(markers[std::size_t(i)].time);
    if (playhead)
        m_times.push_back(*playhead);
    std::sort(m_times.begin(), m_times.end());
    m_times.erase(std::unique(m_times.begin(), m_times.end()), m_times.end());
}

bool TimelineSnapTargets::nearest(qint64 ticks, qint64& target) const
{
    if (m_times.empty())
        return false;
    auto it = std::lower_bound(m_times.begin(), m_times.end(), ticks);
    if (it == m_times.end()) {
        target = m_times.back();
    } else {
        target = *it;
        if (it != m_times.begin() && ticks - *(it - 1) < *it - ticks)
            target = *(it - 1);
    }
    return true;
}

TimelineSnap TimelineSnapTargets::snapTime(qint64 ticks, qint64 threshold, const TimelineTimebase& time) const
{
    qint64 target = 0;
    if (nearest(ticks, target) && std::abs(target - ticks) <= threshold)
        return {target, target};
    return {time.roundToFrame(ticks), -1};
}

TimelineSnap TimelineSnapTargets::snapDelta(qint64 delta, std::span<const qint64> edges, qint64 anchor,
                                            qint64 threshold, const TimelineTimebase& time) const
{
    qint64 best = 0, bestDistance = std::numeric_limits<qint64>::max(), line = -1;
    for (qint64 edge : edges) {
        qint64 target = 0;
        if (!nearest(edge + delta, target))
            break;
        const qint64 distance = std::abs(target - (edge + delta));
        if (distance <= threshold && distance < bestDistance) {
            bestDistance = distance;
            best = target - (edge + delta);
            line = target;
        }
    }
    if (line >= 0)
        return {delta + best, line};
    // Nothing near: the grabbed clip's start lands on a whole frame.
    return {time.roundToFrame(anchor + delta) - anchor, -1};
}

} // namespace thespis::widgets
