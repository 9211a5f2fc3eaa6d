// The timeline's pure geometry: frame arithmetic, time ↔ x, rows, rectangles and the hit test.

#include "widgets/timeline_geometry.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace thespis::widgets {

using M = TimelineMetrics;

bool trackFlagValue(const TimelineTrack& track, TimelineTrackFlag flag)
{
    switch (flag) {
    case TimelineTrackFlag::Mute: return track.muted;
    case TimelineTrackFlag::Solo: return track.solo;
    case TimelineTrackFlag::Lock: return track.locked;
    }
    return false;
}

qint64 floorDiv(qint64 a, qint64 b)
{
    qint64 q = a / b;
    if ((a % b != 0) && ((a < 0) != (b < 0)))
        --q;
    return q;
}

// --- time -----------------------------------------------------------------------------------------

qint64 TimelineTimebase::frameTime(qint64 frame) const
{
    // Exact when the frame rate divides the tick rate.
    return floorDiv(2 * frame * ticksPerSecond + frameRate, 2 * qint64(frameRate));
}

qint64 TimelineTimebase::roundToFrame(qint64 ticks) const
{
    constexpr qint64 limit = std::numeric_limits<qint64>::max() / 2048;
    if (ticks == TimelineOpenEnd || ticks > limit || ticks < -limit)
        return ticks;
    const qint64 frame = floorDiv(2 * ticks * frameRate + ticksPerSecond, 2 * ticksPerSecond);
    return frameTime(frame);
}

qint64 TimelineTimebase::frameAt(qint64 ticks) const
{
    return floorDiv(ticks * frameRate, ticksPerSecond);
}

QString TimelineTimebase::format(qint64 ticks) const
{
    const bool negative = ticks < 0;
    const qint64 frame = floorDiv(std::abs(ticks) * frameRate + ticksPerSecond / 1000, ticksPerSecond);
    const qint64 seconds = frame / frameRate;
    return QStringLiteral("%1%2:%3+%4")
        .arg(negative ? QStringLiteral("-") : QString())
        .arg(seconds / 60)
        .arg(seconds % 60, 2, 10, QLatin1Char('0'))
        .arg(frame % frameRate, 2, 10, QLatin1Char('0'));
}

// --- rows -----------------------------------------------------------------------------------------

TimelineRows TimelineRows::layout(std::span<const TimelineTrack> tracks)
{
    TimelineRows layout;
    layout.trackRow.assign(tracks.size(), -1);
    int y = 0;
    int groupStart = -1;
    for (int i = 0; i < int(tracks.size()); ++i) {
        const QString& group = tracks[std::size_t(i)].group;
        if (group.isEmpty()) {
            groupStart = -1;
        } else if (i == 0 || group != tracks[std::size_t(i) - 1].group) {
            groupStart = i;
            layout.rows.push_back(TimelineRow{y, -1, i});
            y += M::GroupHeight;
        }
        layout.trackRow[std::size_t(i)] = int(layout.rows.size());
        layout.rows.push_back(TimelineRow{y, i, groupStart});
        y += M::TrackHeight;
    }
    return layout;
}

int TimelineRows::contentHeight() const
{
    return rows.empty() ? 0 : rows.back().top + rows.back().height();
}

// --- geometry -------------------------------------------------------------------------------------

int TimelineGeometry::xForTime(qint64 ticks) const
{
    if (ticks == TimelineOpenEnd)
        return viewport.width();
    const double x = originX() + double(ticks) / ticksPerPixel();
    return int(std::lround(std::clamp(x, -1e9, 1e9)));
}

qint64 TimelineGeometry::timeForX(int x) const
{
    return ticksForPixels(x - originX());
}

qint64 TimelineGeometry::ticksForPixels(int pixels) const
{
    return std::llround(double(pixels) * ticksPerPixel());
}

int TimelineGeometry::rowY(const TimelineRow& row) const
{
    return M::RulerHeight + row.top - scroll.y();
}

int TimelineGeometry::trackY(int track) const
{
    return rowY(rows->rows[std::size_t(rows->trackRow[std::size_t(track)])]);
}

int TimelineGeometry::trackAtY(int y) const
{
    if (y < M::RulerHeight)
        return -1;
    for (int i = 0; i < int(tracks.size()); ++i) {
        const int top = trackY(i);
        if (y >= top && y < top + M::TrackHeight)
            return i;
    }
    return -1;
}

bool TimelineGeometry::trackLocked(int track) const
{
    return track >= 0 && track < int(tracks.size()) && tracks[std::size_t(track)].locked;
}

QRect TimelineGeometry::lanesRect() const
{
    return QRect(M::HeaderWidth, M::RulerHeight, std::max(0, viewport.width() - M::HeaderWidth),
                 std::max(0, viewport.height() - M::RulerHeight));
}

QRect TimelineGeometry::rulerRect() const
{
    return QRect(M::HeaderWidth, 0, std::max(0, viewport.width() - M::HeaderWidth), M::RulerHeight);
}

QRect TimelineGeometry::trackRect(int track) const
{
    if (track < 0 || track >= int(tracks.size()))
        return {};
    return QRect(M::HeaderWidth, trackY(track), std::max(0, viewport.width() - M::HeaderWidth), M::TrackHeight);
}

QRect TimelineGeometry::trackFlagRect(int track, TimelineTrackFlag flag) const
{
    if (track < 0 || track >= int(tracks.size()))
        return {};
    const int slot = flag == TimelineTrackFlag::Mute ? 0 : flag == TimelineTrackFlag::Solo ? 1 : 2;
    const int left = M::HeaderWidth - M::FlagRight - 3 * M::FlagWidth - 2 * M::FlagGap + slot * (M::FlagWidth + M::FlagGap);
    return QRect(left, trackY(track) + (M::TrackHeight - M::FlagHeight) / 2, M::FlagWidth, M::FlagHeight);
}

QRect TimelineGeometry::clipRect(int clip) const
{
    const TimelineClip& c = clips[std::size_t(clip)];
    if (c.track < 0 || c.track >= int(tracks.size()))
        return {};
    const int x0 = xForTime(c.start);
    const int x1 = std::max(x0 + 1, xForTime(c.end)); // OpenEnd: the viewport's right edge
    return QRect(x0, trackY(c.track) + M::ClipInset, x1 - x0, M::TrackHeight - 2 * M::ClipInset);
}

QRect TimelineGeometry::fadeHandleRect(int clip, TimelineEdge edge) const
{
    const TimelineClip& c = clips[std::size_t(clip)];
    const QRect r = clipRect(clip);
    if (r.isNull() || (edge == TimelineEdge::End && c.end == TimelineOpenEnd))
        return {};
    const qint64 t = edge == TimelineEdge::Start ? c.start + c.fadeIn : c.end - c.fadeOut;
    // Kept inside the bar, so that a zero-length fade can be grabbed at the corner.
    const int inside = M::FadeHandleRadius;
    int x = xForTime(t);
    x = std::clamp(x, r.left() + inside, std::max(r.left() + inside, r.left() + r.width() - inside));
    // Centred on the bar's top border, clear of the name below it.
    return QRect(x - M::FadeHandleRadius, r.top() + 1 - M::FadeHandleRadius, 2 * M::FadeHandleRadius + 1,
                 2 * M::FadeHandleRadius + 1);
}

QRect TimelineGeometry::markerRect(int marker) const
{
    if (marker < 0 || marker >= int(markers.size()))
        return {};
    const int x = xForTime(markers[std::size_t(marker)].time);
    // The flag hangs from the bottom of the ruler; the name sits right of it.
    return QRect(x - 5, M::RulerHeight - 13, 5 + 4 + markerWidths[std::size_t(marker)] + 8, 13);
}

TimelineHit TimelineGeometry::hitTest(QPoint pos) const
{
    using Kind = TimelineHitKind;
    TimelineHit hit;
    if (pos.y() < M::RulerHeight) {
        if (pos.x() < M::HeaderWidth) {
            hit.kind = Kind::Corner;
            return hit;
        }
        for (int i = int(markers.size()) - 1; i >= 0; --i)
            if (markerRect(i).contains(pos)) {
                hit.kind = Kind::Marker;
                hit.marker = i;
                return hit;
            }
        hit.kind = Kind::Ruler;
        return hit;
    }
    hit.track = trackAtY(pos.y());
    if (pos.x() < M::HeaderWidth) {
        hit.kind = Kind::Header;
        for (TimelineTrackFlag flag : TimelineTrackFlags)
            if (trackFlagRect(hit.track, flag).contains(pos)) {
                hit.kind = Kind::Flag;
                hit.flag = flag;
            }
        return hit;
    }
    hit.kind = Kind::Lane;
    if (hit.track < 0)
        return hit;
    // Selected clips are painted on top, so they are hit first; later clips before earlier ones.
    const bool locked = trackLocked(hit.track);
    for (int pass = 0; pass < 2; ++pass) {
        for (int i = int(clips.size()) - 1; i >= 0; --i) {
            const TimelineClip& clip = clips[std::size_t(i)];
            if (clip.track != hit.track || bool(selected[std::size_t(i)]) != (pass == 0))
                continue;
            const QRect r = clipRect(i);
            if (pos.x() < r.left() - M::EdgeGrip || pos.x() > r.right() + M::EdgeGrip)
                continue;
            hit.clip = i;
            if (!locked && r.width() >= M::MinClipDetail) {
                if (fadeHandleRect(i, TimelineEdge::Start).adjusted(-2, -2, 2, 2).contains(pos)) {
                    hit.kind = Kind::FadeIn;
                    return hit;
                }
                if (fadeHandleRect(i, TimelineEdge::End).adjusted(-2, -2, 2, 2).contains(pos)) {
                    hit.kind = Kind::FadeOut;
                    return hit;
                }
            }
            if (r.contains(pos)) {
                // Narrow clips keep a body to grab: the edge zones shrink to a quarter each.
                const int grip = std::min(int(M::EdgeGrip), r.width() / 4);
                const bool open = clip.end == TimelineOpenEnd;
                if (pos.x() < r.left() + grip)
                    hit.kind = Kind::StartEdge;
                else if (!open && pos.x() > r.right() - grip)
                    hit.kind = Kind::EndEdge;
                else
                    hit.kind = Kind::Body;
                return hit;
            }
        }
    }
    // Just outside a clip: its edge, if one is within the grip.
    for (int i = int(clips.size()) - 1; i >= 0; --i) {
        const TimelineClip& clip = clips[std::size_t(i)];
        if (clip.track != hit.track)
            continue;
        const QRect r = clipRect(i);
        if (std::abs(pos.x() - r.left()) <= M::EdgeGrip) {
            hit.kind = Kind::StartEdge;
            hit.clip = i;
            return hit;
        }
        if (clip.end != TimelineOpenEnd && std::abs(pos.x() - (r.left() + r.width())) <= M::EdgeGrip) {
            hit.kind = Kind::EndEdge;
            hit.clip = i;
            return hit;
        }
    }
    hit.clip = -1;
    return hit;
}

} // namespace thespis::widgets
