#pragma once
// Timeline snapping as pure values: the times that attract a gesture (0, the scenario's end, clip
// edges, markers, the playhead) and how a dragged time or a move snaps to them within a threshold,
// or else to the nearest whole frame. Exact in ticks.

#include <optional>
#include <span>
#include <vector>

#include "widgets/timeline_geometry.h"

namespace thespis::widgets {

struct TimelineSnap {
    qint64 value = 0;   ///< the snapped time or delta
    qint64 target = -1; ///< the target it snapped to (drawn as a line); -1 when it only went to a frame
};

/// The snap threshold in ticks: SnapDistance pixels at this zoom.
qint64 timelineSnapThreshold(double ticksPerPixel);

/// The sorted, distinct times one gesture snaps to, collected when it starts.
class TimelineSnapTargets {
public:
    /// 0, `duration` when above 0, the start and (unless open) end of every clip not flagged in
    /// `excludeClips` (empty: none excluded), every marker but `excludeMarker`, and `playhead`.
    void collect(std::span<const TimelineClip> clips, std::span<const char> excludeClips,
                 std::span<const TimelineMarker> markers, int excludeMarker, qint64 duration,
                 std::optional<qint64> playhead);
    const std::vector<qint64>& times() const { return m_times; }

    /// The target nearest to `ticks` (the later one on a tie); false when there are none.
    bool nearest(qint64 ticks, qint64& target) const;
    /// `ticks` moved onto the nearest target if it is within `threshold`, else onto the nearest frame.
    TimelineSnap snapTime(qint64 ticks, qint64 threshold, const TimelineTimebase& time) const;
    /// A move by `delta` of clips with these `edges`: corrected so that the edge nearest to a target
    /// (within `threshold`) lands on it, else so that `anchor` (the grabbed clip's start) lands on a frame.
    TimelineSnap snapDelta(qint64 delta, std::span<const qint64> edges, qint64 anchor, qint64 threshold,
                           const TimelineTimebase& time) const;

private:
    std::vector<qint64> m_times;
};

} // namespace thespis::widgets
