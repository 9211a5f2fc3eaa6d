#pragma once
// The timeline's geometry as pure values: exact frame arithmetic in ticks, time ↔ x at a zoom and
// scroll offset, the rows of track lanes and group headers, every rectangle the view draws, and the
// hit test. No widget here: TimelineView fills a TimelineGeometry from its state for each paint or
// event, and tests build one by hand.

#include <QPoint>
#include <QRect>
#include <QSize>
#include <QString>

#include <span>
#include <vector>

#include "widgets/timeline_types.h"

namespace thespis::widgets {

/// Sizes in pixels. TimelineView re-exports the public ones (TimelineView::HeaderWidth, …).
struct TimelineMetrics {
    static constexpr int HeaderWidth = 170; ///< the track header column on the left
    static constexpr int RulerHeight = 26;  ///< the time ruler on top
    static constexpr int TrackHeight = 40;  ///< one track's lane
    static constexpr int GroupHeight = 20;  ///< a character's header row above its tracks
    static constexpr int EdgeGrip = 5;      ///< a press this close to a clip's edge trims it
    static constexpr int SnapDistance = 8;  ///< snap targets this close (on screen) attract
    static constexpr int TimePad = 12;      ///< lane pixels left of time 0
    static constexpr int ClipInset = 3;     ///< clip bar inset from the lane's top and bottom
    static constexpr int FadeHandleRadius = 4; ///< the fade handle's grab square is 2·r + 1 wide
    static constexpr int MinClipDetail = 24;   ///< narrower clips have no name and no handles
    static constexpr int FlagWidth = 20, FlagHeight = 16, FlagGap = 3, FlagRight = 8;
};

inline constexpr TimelineTrackFlag TimelineTrackFlags[] = {TimelineTrackFlag::Mute, TimelineTrackFlag::Solo,
                                                           TimelineTrackFlag::Lock};

bool trackFlagValue(const TimelineTrack& track, TimelineTrackFlag flag);

/// a / b rounded towards minus infinity.
qint64 floorDiv(qint64 a, qint64 b);

/// Exact time arithmetic in integer ticks at a frame rate.
struct TimelineTimebase {
    qint64 ticksPerSecond = 705'600'000;
    int frameRate = 30;

    /// Frame `frame`'s start: the tick nearest to frame · ticksPerSecond / frameRate.
    qint64 frameTime(qint64 frame) const;
    /// The frame boundary nearest to `ticks`; OpenEnd and values too large to scale stay as they are.
    qint64 roundToFrame(qint64 ticks) const;
    /// The frame that holds `ticks` (rounded down).
    qint64 frameAt(qint64 ticks) const;
    /// "m:ss+ff" (minutes, seconds, frames), with a leading '-' for negative times.
    QString format(qint64 ticks) const;
};

/// One row below the ruler: a track's lane, or the header row above a group's tracks.
struct TimelineRow {
    int top = 0;    ///< content y (0 = just below the ruler when not scrolled)
    int track = -1; ///< -1: a group header row
    int group = 0;  ///< index of the group's first track; -1 for a track outside any group
    int height() const { return track < 0 ? TimelineMetrics::GroupHeight : TimelineMetrics::TrackHeight; }
};

/// The rows of a list of tracks, top to bottom.
struct TimelineRows {
    std::vector<TimelineRow> rows;
    std::vector<int> trackRow; ///< track → index into rows

    /// A group header row above each run of consecutive tracks of one (non-empty) group.
    static TimelineRows layout(std::span<const TimelineTrack> tracks);
    int contentHeight() const;
};

enum class TimelineHitKind { None, Corner, Ruler, Marker, Header, Flag, Lane, Body, StartEdge, EndEdge, FadeIn, FadeOut };

/// What is under a point of the viewport.
struct TimelineHit {
    TimelineHitKind kind = TimelineHitKind::None;
    int track = -1;
    int clip = -1; ///< index into the clips
    int marker = -1;
    TimelineTrackFlag flag = TimelineTrackFlag::Mute;
};

/// Where everything is in the viewport for one state of the view. Refers to the content (rows,
/// tracks, clips, markers); it does not own it.
struct TimelineGeometry {
    TimelineTimebase time;
    double pixelsPerSecond = 100.0;
    QPoint scroll;  ///< the scroll bars' values, in pixels
    QSize viewport; ///< an open-ended clip runs to the viewport's right edge
    const TimelineRows* rows = nullptr; ///< laid out from `tracks`
    std::span<const TimelineTrack> tracks;
    std::span<const TimelineClip> clips;
    std::span<const char> selected; ///< per clip: selected clips are on top, so they are hit first
    std::span<const TimelineMarker> markers;
    std::span<const int> markerWidths; ///< per marker: its name's width in the ruler font

    double ticksPerPixel() const { return double(time.ticksPerSecond) / pixelsPerSecond; }
    /// The viewport x of time 0.
    int originX() const { return TimelineMetrics::HeaderWidth + TimelineMetrics::TimePad - scroll.x(); }
    /// Rounded to the nearest pixel; OpenEnd maps to the viewport's right edge.
    int xForTime(qint64 ticks) const;
    qint64 timeForX(int x) const;
    /// A horizontal distance in pixels as ticks.
    qint64 ticksForPixels(int pixels) const;

    int rowY(const TimelineRow& row) const;
    int trackY(int track) const; ///< the viewport y of the track's lane top
    int trackAtY(int y) const;   ///< -1 over the ruler, a group row or below the tracks
    bool trackLocked(int track) const;

    QRect lanesRect() const; ///< right of the header, below the ruler
    QRect rulerRect() const;
    QRect trackRect(int track) const;
    QRect trackFlagRect(int track, TimelineTrackFlag flag) const;
    /// The clip's bar; null when its track does not exist.
    QRect clipRect(int clip) const;
    /// The fade handle on the bar's top border; null for End of an open-ended clip.
    QRect fadeHandleRect(int clip, TimelineEdge edge) const;
    /// The marker's flag and name in the ruler; null if there is no such marker.
    QRect markerRect(int marker) const;

    /// Edges within EdgeGrip pixels (inside or just outside the bar) trim, fade handles (not on
    /// locked tracks) come before the body, and the later of overlapping clips wins.
    TimelineHit hitTest(QPoint pos) const;
};

} // namespace thespis::widgets
