#include "widgets/timeline_view.h"

#include <QApplication>
#include <QContextMenuEvent>
#include <QDragEnterEvent>
#include <QDragLeaveEvent>
#include <QDragMoveEvent>
#include <QDropEvent>
#include <QHelpEvent>
#include <QKeyEvent>
#include <QLinearGradient>
#include <QFileInfo>
#include <QMenu>
#include <QMimeData>
#include <QMouseEvent>
#include <QPainter>
#include <QScrollBar>
#include <QSet>
#include <QStaticText>
#include <QToolTip>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

#include "widgets/dropped_files.h"

namespace thespis::widgets {

namespace {

constexpr int kTimePad = 12;         // lane pixels left of time 0
constexpr int kClipInset = 3;        // clip bar inset from the lane's top and bottom
constexpr int kDragThreshold = 3;    // Manhattan pixels before a press becomes a drag
constexpr int kFadeHandleRadius = 4; // the fade handle's grab square is 2·r + 1 wide
constexpr int kMinClipDetail = 24;   // narrower clips are drawn as plain bars: no name, handles
constexpr int kMinSmoothClipWidth = 80; // narrower clips: fade ramps unshaded, lines aliased
constexpr int kOpenFadeWidth = 90;   // an open-ended clip fades out over this many pixels
constexpr int kFlagWidth = 20, kFlagHeight = 16, kFlagGap = 3, kFlagRight = 8;
constexpr double kMinPixelsPerSecond = 0.05;
constexpr double kMaxPixelsPerSecond = 50000.0;
constexpr qint64 kSecondSteps[] = {1, 2, 5, 10, 15, 30, 60, 120, 300, 600, 900, 1800, 3600, 7200};

qint64 floorDiv(qint64 a, qint64 b)
{
    qint64 q = a / b;
    if ((a % b != 0) && ((a < 0) != (b < 0)))
        --q;
    return q;
}

QColor mix(const QColor& a, const QColor& b, double t)
{
    return QColor::fromRgbF(float(a.redF() + (b.redF() - a.redF()) * t), float(a.greenF() + (b.greenF() - a.greenF()) * t),
                            float(a.blueF() + (b.blueF() - a.blueF()) * t), float(a.alphaF() + (b.alphaF() - a.alphaF()) * t));
}

QColor withAlpha(QColor color, int alpha)
{
    color.setAlpha(alpha);
    return color;
}

const char* flagLetter(TimelineTrackFlag flag)
{
    switch (flag) {
    case TimelineTrackFlag::Mute: return "M";
    case TimelineTrackFlag::Solo: return "S";
    case TimelineTrackFlag::Lock: return "L";
    }
    return "";
}

bool flagValue(const TimelineTrack& track, TimelineTrackFlag flag)
{
    switch (flag) {
    case TimelineTrackFlag::Mute: return track.muted;
    case TimelineTrackFlag::Solo: return track.solo;
    case TimelineTrackFlag::Lock: return track.locked;
    }
    return false;
}

// A bar with 1-pixel chamfered corners from solid fills only (no overlap, so that translucent
// brushes blend once): reads like a small corner radius at a fraction of a path's cost.
void fillBar(QPainter& painter, const QRect& r, const QBrush& fill, const QBrush& border, int b)
{
    const int x = r.left(), y = r.top(), w = r.width(), h = r.height();
    if (w <= 2 * b + 1 || h <= 2 * b + 1) {
        painter.fillRect(r, border);
        return;
    }
    painter.fillRect(QRect(x + 1, y, w - 2, b), border);         // top
    painter.fillRect(QRect(x + 1, y + h - b, w - 2, b), border); // bottom
    painter.fillRect(QRect(x, y + 1, b, h - 2), border);         // left (overlaps the top by one pixel at b = 2)
    painter.fillRect(QRect(x + w - b, y + 1, b, h - 2), border); // right
    painter.fillRect(QRect(x + b, y + b, w - 2 * b, h - 2 * b), fill);
}

constexpr TimelineTrackFlag kFlags[] = {TimelineTrackFlag::Mute, TimelineTrackFlag::Solo, TimelineTrackFlag::Lock};

} // namespace

TimelineView::TimelineView(QWidget* parent)
    : QAbstractScrollArea(parent), m_clipMetrics(font()), m_smallMetrics(font())
{
    setFocusPolicy(Qt::StrongFocus);
    setAcceptDrops(true);
    viewport()->setAcceptDrops(true);
    viewport()->setMouseTracking(true);
    viewport()->setAttribute(Qt::WA_OpaquePaintEvent);
    setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOn);
    setVerticalScrollBarPolicy(Qt::ScrollBarAsNeeded);
    horizontalScrollBar()->setSingleStep(20);
    verticalScrollBar()->setSingleStep(TrackHeight / 2);
    m_lines.reserve(512);
    m_points.reserve(1024);
    setFrameRate(30);
    updateColors();
    updateFonts();
    updateScrollRanges();
}

TimelineView::~TimelineView() = default;

// --- setters ------------------------------------------------------------------------------------

void TimelineView::setTicksPerSecond(qint64 ticks)
{
    if (ticks < 1 || ticks == m_ticksPerSecond)
        return;
    m_ticksPerSecond = ticks;
    updateScrollRanges();
    viewport()->update();
}

void TimelineView::setFrameRate(int framesPerSecond)
{
    if (framesPerSecond < 1)
        return;
    m_frameRate = framesPerSecond;
    m_frameRateLabel = tr("%1 fps").arg(framesPerSecond);
    // Sub-second ruler steps divide the second so that labels stay on whole seconds.
    m_stepCandidates.clear();
    for (int d = 1; d < framesPerSecond; ++d)
        if (framesPerSecond % d == 0)
            m_stepCandidates.push_back(d);
    for (qint64 seconds : kSecondSteps)
        m_stepCandidates.push_back(seconds * framesPerSecond);
    viewport()->update();
}

void TimelineView::setTracks(QVector<TimelineTrack> tracks)
{
    m_tracks = std::move(tracks);
    m_anySolo = std::any_of(m_tracks.cbegin(), m_tracks.cend(), [](const TimelineTrack& t) { return t.solo; });
    rebuildRows();
    updateScrollRanges();
    viewport()->update();
}

void TimelineView::setClips(QVector<TimelineClip> clips)
{
    QSet<int> selected;
    for (const ClipItem& item : std::as_const(m_clips))
        if (item.selected)
            selected.insert(item.clip.id);
    m_clips.clear();
    m_clips.reserve(clips.size());
    m_idToIndex.clear();
    m_idToIndex.reserve(clips.size());
    m_clipsEnd = 0;
    qsizetype mostSamples = 0;
    for (TimelineClip& clip : clips) {
        ClipItem item;
        item.selected = selected.contains(clip.id);
        m_clipsEnd = std::max(m_clipsEnd, clip.end == OpenEnd ? clip.start : clip.end);
        mostSamples = std::max(mostSamples, clip.weight.size());
        item.clip = std::move(clip);
        m_idToIndex.insert(item.clip.id, int(m_clips.size()));
        m_clips.push_back(std::move(item));
    }
    // The weight polyline needs at most one point per sample or per two pixels (plus the ends).
    m_points.reserve(std::size_t(std::max<qsizetype>(mostSamples + 2, 2048)));
    updateScrollRanges();
    viewport()->update();
}

const TimelineClip* TimelineView::clip(int id) const
{
    const int index = clipIndex(id);
    return index < 0 ? nullptr : &m_clips[index].clip;
}

void TimelineView::setMarkers(QVector<TimelineMarker> markers)
{
    m_markers = std::move(markers);
    m_markerWidths.resize(std::size_t(m_markers.size()));
    for (qsizetype i = 0; i < m_markers.size(); ++i)
        m_markerWidths[std::size_t(i)] = m_smallMetrics.horizontalAdvance(m_markers[i].name);
    updateScrollRanges();
    viewport()->update();
}

void TimelineView::setDuration(qint64 ticks)
{
    m_duration = std::max<qint64>(0, ticks);
    updateScrollRanges();
    viewport()->update();
}

void TimelineView::setPlayhead(qint64 ticks)
{
    if (ticks == m_playhead)
        return;
    m_playhead = ticks;
    if (ticks > m_duration && ticks > m_clipsEnd)
        updateScrollRanges();
    viewport()->update();
}

void TimelineView::setSnapping(bool on)
{
    m_snapping = on;
}

QList<int> TimelineView::selectedClips() const
{
    QList<int> ids;
    for (const ClipItem& item : m_clips)
        if (item.selected)
            ids.push_back(item.clip.id);
    std::sort(ids.begin(), ids.end());
    return ids;
}

void TimelineView::setSelectedClips(const QList<int>& ids)
{
    for (ClipItem& item : m_clips)
        item.selected = false;
    for (int id : ids)
        if (const int index = clipIndex(id); index >= 0)
            m_clips[index].selected = true;
    viewport()->update();
}

void TimelineView::setPixelsPerSecond(double zoom)
{
    if (!std::isfinite(zoom))
        return;
    zoom = std::clamp(zoom, kMinPixelsPerSecond, kMaxPixelsPerSecond);
    const double leftSeconds = horizontalScrollBar()->value() / m_pixelsPerSecond;
    m_pixelsPerSecond = zoom;
    updateScrollRanges();
    horizontalScrollBar()->setValue(int(std::lround(leftSeconds * zoom)));
    viewport()->update();
}

void TimelineView::frameAll()
{
    const int available = viewport()->width() - HeaderWidth - 2 * kTimePad - 16;
    if (available < 40) {
        m_frameAllPending = true; // no size yet: framed at the first resize
        return;
    }
    m_frameAllPending = false;
    qint64 end = std::max(m_duration, m_clipsEnd);
    for (const TimelineMarker& marker : std::as_const(m_markers))
        end = std::max(end, marker.time);
    if (end <= 0)
        end = 10 * m_ticksPerSecond;
    const double seconds = double(end) / double(m_ticksPerSecond);
    m_pixelsPerSecond = std::clamp(available / seconds, kMinPixelsPerSecond, kMaxPixelsPerSecond);
    updateScrollRanges();
    horizontalScrollBar()->setValue(0);
    viewport()->update();
}

void TimelineView::ensureTimeVisible(qint64 ticks)
{
    if (ticks == OpenEnd)
        return;
    const int lanesLeft = HeaderWidth + kTimePad;
    const int lanesWidth = viewport()->width() - lanesLeft - kTimePad;
    if (lanesWidth <= 0)
        return;
    const int x = xForTime(ticks);
    if (x >= lanesLeft && x <= lanesLeft + lanesWidth)
        return;
    const double seconds = double(ticks) / double(m_ticksPerSecond);
    horizontalScrollBar()->setValue(int(std::lround(seconds * m_pixelsPerSecond)) - lanesWidth / 10);
    viewport()->update();
}

// --- geometry -----------------------------------------------------------------------------------

qint64 TimelineView::frameTime(qint64 frame) const
{
    // Nearest tick to frame · tps / fps (exact when the frame rate divides the tick rate).
    return floorDiv(2 * frame * m_ticksPerSecond + m_frameRate, 2 * qint64(m_frameRate));
}

qint64 TimelineView::roundToFrame(qint64 ticks) const
{
    constexpr qint64 limit = std::numeric_limits<qint64>::max() / 2048;
    if (ticks == OpenEnd || ticks > limit || ticks < -limit)
        return ticks;
    const qint64 frame = floorDiv(2 * ticks * m_frameRate + m_ticksPerSecond, 2 * m_ticksPerSecond);
    return frameTime(frame);
}

int TimelineView::timeOriginX() const
{
    return HeaderWidth + kTimePad - horizontalScrollBar()->value();
}

int TimelineView::xForTime(qint64 ticks) const
{
    if (ticks == OpenEnd)
        return viewport()->width();
    const double x = timeOriginX() + double(ticks) / ticksPerPixel();
    return int(std::lround(std::clamp(x, -1e9, 1e9)));
}

qint64 TimelineView::timeForX(int x) const
{
    return std::llround(double(x - timeOriginX()) * ticksPerPixel());
}

qint64 TimelineView::rawDelta(const QPoint& pos) const
{
    return std::llround(double(pos.x() - m_drag.pressPos.x()) * ticksPerPixel());
}

int TimelineView::clipTrackDelta(int y) const
{
    if (m_drag.origTrack < 0 || m_drag.origTrack >= int(m_tracks.size()))
        return 0;
    // The track whose lane centre is nearest to the mouse (also over group rows, above and below
    // the tracks), then the offset nearest to it (the nearer to 0 on a tie) at which every clip fits.
    int under = m_drag.origTrack, nearest = std::numeric_limits<int>::max();
    for (int i = 0; i < int(m_tracks.size()); ++i)
        if (const int d = std::abs(y - (trackY(i) + TrackHeight / 2)); d < nearest) {
            nearest = d;
            under = i;
        }
    const int wanted = under - m_drag.origTrack;
    int best = 0;
    for (int offset = -int(m_tracks.size()); offset <= int(m_tracks.size()); ++offset) {
        const int distance = std::abs(offset - wanted), bestDistance = std::abs(best - wanted);
        if ((distance < bestDistance || (distance == bestDistance && std::abs(offset) < std::abs(best)))
            && trackOffsetFits(offset))
            best = offset;
    }
    return best;
}

bool TimelineView::trackOffsetFits(int offset) const
{
    if (offset == 0)
        return true;
    for (const TimelineClip& c : m_drag.moving) {
        const int to = c.track + offset;
        if (c.track < 0 || c.track >= int(m_tracks.size()) || to < 0 || to >= int(m_tracks.size()))
            return false;
        const TimelineTrack& from = m_tracks[c.track];
        const TimelineTrack& target = m_tracks[to];
        if (target.locked || target.group != from.group || target.kind != from.kind)
            return false;
    }
    return true;
}

void TimelineView::rebuildRows()
{
    m_rows.clear();
    m_trackRow.assign(std::size_t(m_tracks.size()), -1);
    int y = 0;
    int groupStart = -1;
    for (int i = 0; i < int(m_tracks.size()); ++i) {
        const QString& group = m_tracks[i].group;
        if (group.isEmpty()) {
            groupStart = -1;
        } else if (i == 0 || group != m_tracks[i - 1].group) {
            groupStart = i;
            m_rows.push_back(Row{y, -1, i, QFontMetrics(m_boldFont).elidedText(group, Qt::ElideRight, HeaderWidth - 16)});
            y += GroupHeight;
        }
        m_trackRow[std::size_t(i)] = int(m_rows.size());
        m_rows.push_back(Row{y, i, groupStart, {}});
        y += TrackHeight;
    }
    // Track names elided to the room left of the flags; recomputed only when tracks or fonts change.
    m_trackElided.resize(std::size_t(m_tracks.size()));
    const int flagsLeft = HeaderWidth - kFlagRight - 3 * kFlagWidth - 2 * kFlagGap;
    for (int i = 0; i < int(m_tracks.size()); ++i) {
        const int nameX = m_tracks[i].group.isEmpty() ? 10 : 22;
        m_trackElided[std::size_t(i)] = fontMetrics().elidedText(m_tracks[i].name, Qt::ElideRight, flagsLeft - 8 - nameX);
    }
}

int TimelineView::contentHeight() const
{
    return m_rows.empty() ? 0 : m_rows.back().top + (m_rows.back().track < 0 ? GroupHeight : TrackHeight);
}

int TimelineView::rowY(const Row& row) const
{
    return RulerHeight + row.top - verticalScrollBar()->value();
}

int TimelineView::trackY(int track) const
{
    return rowY(m_rows[std::size_t(m_trackRow[std::size_t(track)])]);
}

int TimelineView::trackAtY(int y) const
{
    if (y < RulerHeight)
        return -1;
    for (int i = 0; i < int(m_tracks.size()); ++i) {
        const int top = trackY(i);
        if (y >= top && y < top + TrackHeight)
            return i;
    }
    return -1;
}

bool TimelineView::trackLocked(int track) const
{
    return track >= 0 && track < int(m_tracks.size()) && m_tracks[track].locked;
}

bool TimelineView::trackDimmed(int track) const
{
    const TimelineTrack& t = m_tracks[track];
    return t.muted || (m_anySolo && !t.solo);
}

qint64 TimelineView::contentEndTime() const
{
    qint64 end = std::max({m_duration, m_clipsEnd, m_playhead, qint64(0)});
    for (const TimelineMarker& marker : m_markers)
        end = std::max(end, marker.time);
    return end;
}

void TimelineView::updateScrollRanges()
{
    const int laneWidth = std::max(0, viewport()->width() - HeaderWidth);
    // Half a view of room after the end, so that clips can be dragged past it.
    const double contentWidth = kTimePad + double(contentEndTime()) / ticksPerPixel() + laneWidth / 2.0;
    QScrollBar* h = horizontalScrollBar();
    h->setRange(0, int(std::clamp(std::ceil(contentWidth) - laneWidth, 0.0, 1e9)));
    h->setPageStep(std::max(1, laneWidth));
    const int laneHeight = std::max(0, viewport()->height() - RulerHeight);
    QScrollBar* v = verticalScrollBar();
    v->setRange(0, std::max(0, contentHeight() - laneHeight));
    v->setPageStep(std::max(1, laneHeight));
}

QRect TimelineView::rulerRect() const
{
    return QRect(HeaderWidth, 0, std::max(0, viewport()->width() - HeaderWidth), RulerHeight);
}

QRect TimelineView::trackRect(int track) const
{
    if (track < 0 || track >= int(m_tracks.size()))
        return {};
    return QRect(HeaderWidth, trackY(track), std::max(0, viewport()->width() - HeaderWidth), TrackHeight);
}

QRect TimelineView::trackFlagRect(int track, TimelineTrackFlag flag) const
{
    if (track < 0 || track >= int(m_tracks.size()))
        return {};
    const int slot = flag == TimelineTrackFlag::Mute ? 0 : flag == TimelineTrackFlag::Solo ? 1 : 2;
    const int left = HeaderWidth - kFlagRight - 3 * kFlagWidth - 2 * kFlagGap + slot * (kFlagWidth + kFlagGap);
    return QRect(left, trackY(track) + (TrackHeight - kFlagHeight) / 2, kFlagWidth, kFlagHeight);
}

QRect TimelineView::clipRectAt(int index) const
{
    const TimelineClip& c = m_clips[index].clip;
    if (c.track < 0 || c.track >= int(m_tracks.size()))
        return {};
    const int x0 = xForTime(c.start);
    const int x1 = std::max(x0 + 1, xForTime(c.end)); // OpenEnd: the viewport's right edge
    return QRect(x0, trackY(c.track) + kClipInset, x1 - x0, TrackHeight - 2 * kClipInset);
}

QRect TimelineView::clipRect(int id) const
{
    const int index = clipIndex(id);
    return index < 0 ? QRect() : clipRectAt(index);
}

QRect TimelineView::fadeHandleRectAt(int index, TimelineEdge edge) const
{
    const TimelineClip& c = m_clips[index].clip;
    const QRect r = clipRectAt(index);
    if (r.isNull() || (edge == TimelineEdge::End && c.end == OpenEnd))
        return {};
    const qint64 t = edge == TimelineEdge::Start ? c.start + c.fadeIn : c.end - c.fadeOut;
    // Kept inside the bar, so that a zero-length fade can be grabbed at the corner.
    const int inside = kFadeHandleRadius;
    int x = xForTime(t);
    x = std::clamp(x, r.left() + inside, std::max(r.left() + inside, r.left() + r.width() - inside));
    // Centred on the bar's top border, clear of the name below it.
    return QRect(x - kFadeHandleRadius, r.top() + 1 - kFadeHandleRadius, 2 * kFadeHandleRadius + 1,
                 2 * kFadeHandleRadius + 1);
}

QRect TimelineView::fadeHandleRect(int id, TimelineEdge edge) const
{
    const int index = clipIndex(id);
    return index < 0 ? QRect() : fadeHandleRectAt(index, edge);
}

QRect TimelineView::markerRect(int index) const
{
    if (index < 0 || index >= int(m_markers.size()))
        return {};
    const int x = xForTime(m_markers[index].time);
    // The flag hangs from the bottom of the ruler; the name sits right of it.
    return QRect(x - 5, RulerHeight - 13, 5 + 4 + m_markerWidths[std::size_t(index)] + 8, 13);
}

QSize TimelineView::sizeHint() const
{
    return {900, RulerHeight + 4 * TrackHeight + 2 * GroupHeight + 20};
}

QSize TimelineView::minimumSizeHint() const
{
    return {HeaderWidth + 120, RulerHeight + TrackHeight + 20};
}

QString TimelineView::formatTime(qint64 ticks) const
{
    const bool negative = ticks < 0;
    const qint64 frame = floorDiv(std::abs(ticks) * m_frameRate + m_ticksPerSecond / 1000, m_ticksPerSecond);
    const qint64 seconds = frame / m_frameRate;
    return QStringLiteral("%1%2:%3+%4")
        .arg(negative ? QStringLiteral("-") : QString())
        .arg(seconds / 60)
        .arg(seconds % 60, 2, 10, QLatin1Char('0'))
        .arg(frame % m_frameRate, 2, 10, QLatin1Char('0'));
}

qint64 TimelineView::clampSeek(qint64 ticks) const
{
    ticks = std::max<qint64>(0, ticks);
    return m_duration > 0 ? std::min(ticks, m_duration) : ticks;
}

TimelineView::Steps TimelineView::rulerSteps() const
{
    const double pixelsPerFrame = m_pixelsPerSecond / m_frameRate;
    const int labelRoom = m_smallMetrics.horizontalAdvance(QStringLiteral("00:00+00")) + 18;
    Steps steps;
    steps.major = m_stepCandidates.back();
    for (qint64 candidate : m_stepCandidates)
        if (candidate * pixelsPerFrame >= labelRoom) {
            steps.major = candidate;
            break;
        }
    for (qint64 candidate : m_stepCandidates) {
        if (candidate >= steps.major)
            break;
        if (steps.major % candidate == 0 && candidate * pixelsPerFrame >= 7) {
            steps.minor = candidate;
            break;
        }
    }
    return steps;
}

// --- snapping -----------------------------------------------------------------------------------

void TimelineView::buildSnapTargets(const std::vector<char>* excludeClips, int excludeMarker, bool includePlayhead)
{
    m_snapTargets.clear();
    m_snapTargets.reserve(std::size_t(2 * m_clips.size() + m_markers.size() + 3));
    m_snapTargets.push_back(0);
    if (m_duration > 0)
        m_snapTargets.push_back(m_duration);
    for (int i = 0; i < int(m_clips.size()); ++i) {
        if (excludeClips && (*excludeClips)[std::size_t(i)])
            continue;
        const TimelineClip& c = m_clips[i].clip;
        m_snapTargets.push_back(c.start);
        if (c.end != OpenEnd)
            m_snapTargets.push_back(c.end);
    }
    for (int i = 0; i < int(m_markers.size()); ++i)
        if (i != excludeMarker)
            m_snapTargets.push_back(m_markers[i].time);
    if (includePlayhead)
        m_snapTargets.push_back(m_playhead);
    std::sort(m_snapTargets.begin(), m_snapTargets.end());
    m_snapTargets.erase(std::unique(m_snapTargets.begin(), m_snapTargets.end()), m_snapTargets.end());
}

qint64 TimelineView::snapThreshold() const
{
    return std::llround(SnapDistance * ticksPerPixel());
}

bool TimelineView::nearestTarget(qint64 ticks, qint64& target) const
{
    if (m_snapTargets.empty())
        return false;
    auto it = std::lower_bound(m_snapTargets.begin(), m_snapTargets.end(), ticks);
    if (it == m_snapTargets.end()) {
        target = m_snapTargets.back();
    } else {
        target = *it;
        if (it != m_snapTargets.begin() && ticks - *(it - 1) < *it - ticks)
            target = *(it - 1);
    }
    return true;
}

qint64 TimelineView::snapTime(qint64 ticks, bool bypass)
{
    m_snapLine = -1;
    if (!m_snapping || bypass)
        return ticks;
    qint64 target = 0;
    if (nearestTarget(ticks, target) && std::abs(target - ticks) <= snapThreshold()) {
        m_snapLine = target;
        return target;
    }
    return roundToFrame(ticks);
}

qint64 TimelineView::snapDelta(qint64 delta, qint64 anchor, bool bypass)
{
    m_snapLine = -1;
    if (!m_snapping || bypass)
        return delta;
    const qint64 threshold = snapThreshold();
    qint64 best = 0, bestDistance = std::numeric_limits<qint64>::max();
    for (qint64 edge : m_drag.edges) {
        qint64 target = 0;
        if (!nearestTarget(edge + delta, target))
            break;
        const qint64 distance = std::abs(target - (edge + delta));
        if (distance <= threshold && distance < bestDistance) {
            bestDistance = distance;
            best = target - (edge + delta);
            m_snapLine = target;
        }
    }
    if (m_snapLine >= 0)
        return delta + best;
    // Nothing near: the grabbed clip's start lands on a whole frame.
    return roundToFrame(anchor + delta) - anchor;
}

// --- selection ----------------------------------------------------------------------------------

std::vector<char> TimelineView::selectionFlags() const
{
    std::vector<char> flags(std::size_t(m_clips.size()));
    for (int i = 0; i < int(m_clips.size()); ++i)
        flags[std::size_t(i)] = m_clips[i].selected;
    return flags;
}

void TimelineView::setSelectionFlags(const std::vector<char>& flags)
{
    for (int i = 0; i < int(m_clips.size()) && i < int(flags.size()); ++i)
        m_clips[i].selected = flags[std::size_t(i)];
}

void TimelineView::emitSelectionIfChanged(const std::vector<char>& before)
{
    if (before != selectionFlags())
        emit selectionChanged(selectedClips());
    viewport()->update();
}

void TimelineView::selectOnly(int index)
{
    for (int i = 0; i < int(m_clips.size()); ++i)
        m_clips[i].selected = i == index;
}

// --- hit testing --------------------------------------------------------------------------------

TimelineView::Hit TimelineView::hitTest(const QPoint& pos) const
{
    Hit hit;
    if (pos.y() < RulerHeight) {
        if (pos.x() < HeaderWidth) {
            hit.kind = HitKind::Corner;
            return hit;
        }
        for (int i = int(m_markers.size()) - 1; i >= 0; --i)
            if (markerRect(i).contains(pos)) {
                hit.kind = HitKind::Marker;
                hit.marker = i;
                return hit;
            }
        hit.kind = HitKind::Ruler;
        return hit;
    }
    hit.track = trackAtY(pos.y());
    if (pos.x() < HeaderWidth) {
        hit.kind = HitKind::Header;
        for (TimelineTrackFlag flag : kFlags)
            if (trackFlagRect(hit.track, flag).contains(pos)) {
                hit.kind = HitKind::Flag;
                hit.flag = flag;
            }
        return hit;
    }
    hit.kind = HitKind::Lane;
    if (hit.track < 0)
        return hit;
    // Selected clips are painted on top, so they are hit first; later clips before earlier ones.
    const bool locked = trackLocked(hit.track);
    for (int pass = 0; pass < 2; ++pass) {
        for (int i = int(m_clips.size()) - 1; i >= 0; --i) {
            const ClipItem& item = m_clips[i];
            if (item.clip.track != hit.track || item.selected != (pass == 0))
                continue;
            const QRect r = clipRectAt(i);
            if (pos.x() < r.left() - EdgeGrip || pos.x() > r.right() + EdgeGrip)
                continue;
            hit.clip = i;
            if (!locked && r.width() >= kMinClipDetail) {
                if (fadeHandleRectAt(i, TimelineEdge::Start).adjusted(-2, -2, 2, 2).contains(pos)) {
                    hit.kind = HitKind::FadeIn;
                    return hit;
                }
                if (fadeHandleRectAt(i, TimelineEdge::End).adjusted(-2, -2, 2, 2).contains(pos)) {
                    hit.kind = HitKind::FadeOut;
                    return hit;
                }
            }
            if (r.contains(pos)) {
                // Narrow clips keep a body to grab: the edge zones shrink to a quarter each.
                const int grip = std::min(EdgeGrip, r.width() / 4);
                const bool open = item.clip.end == OpenEnd;
                if (pos.x() < r.left() + grip)
                    hit.kind = HitKind::StartEdge;
                else if (!open && pos.x() > r.right() - grip)
                    hit.kind = HitKind::EndEdge;
                else
                    hit.kind = HitKind::Body;
                return hit;
            }
        }
    }
    // Just outside a clip: its edge, if one is within the grip.
    for (int i = int(m_clips.size()) - 1; i >= 0; --i) {
        const ClipItem& item = m_clips[i];
        if (item.clip.track != hit.track)
            continue;
        const QRect r = clipRectAt(i);
        if (std::abs(pos.x() - r.left()) <= EdgeGrip) {
            hit.kind = HitKind::StartEdge;
            hit.clip = i;
            return hit;
        }
        if (item.clip.end != OpenEnd && std::abs(pos.x() - (r.left() + r.width())) <= EdgeGrip) {
            hit.kind = HitKind::EndEdge;
            hit.clip = i;
            return hit;
        }
    }
    hit.clip = -1;
    return hit;
}

void TimelineView::updateHoverCursor(const QPoint& pos)
{
    const Hit hit = hitTest(pos);
    Qt::CursorShape shape = Qt::ArrowCursor;
    switch (hit.kind) {
    case HitKind::StartEdge:
    case HitKind::EndEdge:
    case HitKind::FadeIn:
    case HitKind::FadeOut:
        if (!trackLocked(hit.track))
            shape = Qt::SizeHorCursor;
        break;
    case HitKind::Marker: shape = Qt::SizeHorCursor; break;
    case HitKind::Flag: shape = Qt::PointingHandCursor; break;
    default: break;
    }
    if (viewport()->cursor().shape() != shape)
        viewport()->setCursor(shape);
}

// --- mouse --------------------------------------------------------------------------------------

void TimelineView::mousePressEvent(QMouseEvent* event)
{
    if (event->button() != Qt::LeftButton) {
        event->ignore();
        return;
    }
    setFocus(Qt::MouseFocusReason);
    const QPoint pos = event->position().toPoint();
    const Qt::KeyboardModifiers modifiers = event->modifiers();
    const bool bypass = modifiers & Qt::ControlModifier;
    const Hit hit = hitTest(pos);
    m_drag = Drag{};
    m_drag.pressPos = pos;
    switch (hit.kind) {
    case HitKind::Ruler: {
        m_drag.mode = DragMode::Scrub;
        m_drag.active = true; // a scrub follows the mouse from the first pixel
        buildSnapTargets(nullptr, -1, false);
        m_drag.last = clampSeek(snapTime(timeForX(pos.x()), bypass));
        emit seekRequested(m_drag.last);
        break;
    }
    case HitKind::Marker:
        m_drag.mode = DragMode::Marker;
        m_drag.marker = hit.marker;
        m_drag.origValue = m_drag.last = m_markers[hit.marker].time;
        buildSnapTargets(nullptr, hit.marker, true);
        break;
    case HitKind::Flag:
        emit trackFlagRequested(hit.track, hit.flag, !flagValue(m_tracks[hit.track], hit.flag));
        break;
    case HitKind::Lane: {
        m_drag.mode = DragMode::RubberBand;
        m_drag.pressSelection = selectionFlags();
        if (modifiers & (Qt::ShiftModifier | Qt::ControlModifier))
            m_drag.baseSelection = m_drag.pressSelection;
        else
            m_drag.baseSelection.assign(m_drag.pressSelection.size(), 0); // a click on empty space clears
        setSelectionFlags(m_drag.baseSelection);
        break;
    }
    case HitKind::Body:
    case HitKind::StartEdge:
    case HitKind::EndEdge:
    case HitKind::FadeIn:
    case HitKind::FadeOut: beginClipPress(hit, pos, modifiers); break;
    case HitKind::None:
    case HitKind::Corner:
    case HitKind::Header: break;
    }
    viewport()->update();
}

void TimelineView::beginClipPress(const Hit& hit, const QPoint& pos, Qt::KeyboardModifiers modifiers)
{
    ClipItem& item = m_clips[hit.clip];
    m_drag.pressPos = pos;
    m_drag.clip = hit.clip;
    m_drag.clipId = item.clip.id;
    m_drag.origStart = item.clip.start;
    m_drag.origEnd = item.clip.end;
    m_drag.locked = trackLocked(item.clip.track);

    // Selection: a press on an unselected clip selects it (alone, or added with Shift/Ctrl); a
    // press on a selected clip keeps the selection for a drag and decides on release.
    const std::vector<char> before = selectionFlags();
    if (modifiers & (Qt::ShiftModifier | Qt::ControlModifier)) {
        if (item.selected)
            m_drag.toggleOnRelease = true;
        else
            item.selected = true;
    } else if (!item.selected) {
        selectOnly(hit.clip);
    } else {
        m_drag.selectOnlyOnRelease = true;
    }
    emitSelectionIfChanged(before);

    switch (hit.kind) {
    case HitKind::Body: {
        m_drag.mode = DragMode::Clip;
        std::vector<char> moving(std::size_t(m_clips.size()), 0);
        m_drag.minStart = std::numeric_limits<qint64>::max();
        for (int i = 0; i < int(m_clips.size()); ++i) {
            const TimelineClip& c = m_clips[i].clip;
            if (!m_clips[i].selected || trackLocked(c.track))
                continue;
            moving[std::size_t(i)] = 1;
            m_drag.ids.push_back(c.id);
            m_drag.moving.push_back(c);
            m_drag.edges.push_back(c.start);
            if (c.end != OpenEnd)
                m_drag.edges.push_back(c.end);
            m_drag.minStart = std::min(m_drag.minStart, c.start);
        }
        std::sort(m_drag.ids.begin(), m_drag.ids.end());
        m_drag.origTrack = item.clip.track;
        buildSnapTargets(&moving, -1, true);
        break;
    }
    case HitKind::StartEdge:
    case HitKind::EndEdge: {
        m_drag.mode = hit.kind == HitKind::StartEdge ? DragMode::TrimStart : DragMode::TrimEnd;
        m_drag.origValue = m_drag.last = hit.kind == HitKind::StartEdge ? item.clip.start : item.clip.end;
        std::vector<char> self(std::size_t(m_clips.size()), 0);
        self[std::size_t(hit.clip)] = 1;
        buildSnapTargets(&self, -1, true);
        break;
    }
    default: {
        m_drag.mode = hit.kind == HitKind::FadeIn ? DragMode::FadeIn : DragMode::FadeOut;
        m_drag.origValue = m_drag.last = hit.kind == HitKind::FadeIn ? item.clip.fadeIn : item.clip.fadeOut;
        buildSnapTargets(nullptr, -1, true); // the clip's own edges attract: fades snap back to 0
        break;
    }
    }
}

void TimelineView::updateDrag(const QPoint& pos, Qt::KeyboardModifiers modifiers, bool finished)
{
    const bool bypass = modifiers & Qt::ControlModifier;
    const qint64 raw = rawDelta(pos);
    const qint64 frame = std::max<qint64>(1, frameTime(1));
    const bool openEnd = m_drag.origEnd == OpenEnd;
    const qint64 length = openEnd ? std::numeric_limits<qint64>::max() : m_drag.origEnd - m_drag.origStart;

    // Emits `value` for this drag: while moving when it changed, on release if anything was asked.
    auto request = [&](qint64 value, auto&& emitter) {
        if (finished) {
            if (m_drag.emitted || value != m_drag.origValue)
                emitter(value, true);
        } else if (value != m_drag.last) {
            m_drag.last = value;
            m_drag.emitted = true;
            emitter(value, false);
        }
    };

    switch (m_drag.mode) {
    case DragMode::Scrub: {
        const qint64 t = clampSeek(snapTime(timeForX(pos.x()), bypass));
        if (t != m_drag.last) {
            m_drag.last = t;
            emit seekRequested(t);
        }
        break;
    }
    case DragMode::Marker: {
        const qint64 t = std::max<qint64>(0, snapTime(m_drag.origValue + raw, bypass));
        request(t, [&](qint64 v, bool done) { emit markerMoveRequested(m_drag.marker, v, done); });
        break;
    }
    case DragMode::Clip: {
        if (m_drag.locked || m_drag.ids.isEmpty())
            break;
        qint64 delta = snapDelta(raw, m_drag.origStart, bypass);
        if (delta < -m_drag.minStart) { // no clip goes before 0
            delta = -m_drag.minStart;
            m_snapLine = -1;
        }
        const int tracks = clipTrackDelta(pos.y());
        if (finished) {
            if (m_drag.emitted || delta != 0 || tracks != 0)
                emit clipsMoveRequested(m_drag.ids, delta, tracks, true);
        } else if (delta != m_drag.last || tracks != m_drag.trackDelta) {
            m_drag.last = delta;
            m_drag.trackDelta = tracks;
            m_drag.emitted = true;
            emit clipsMoveRequested(m_drag.ids, delta, tracks, false);
        }
        break;
    }
    case DragMode::TrimStart: {
        if (m_drag.locked)
            break;
        qint64 t = std::max<qint64>(0, snapTime(m_drag.origStart + raw, bypass));
        if (!openEnd)
            t = std::min(t, m_drag.origEnd - frame);
        request(t, [&](qint64 v, bool done) { emit clipTrimRequested(m_drag.clipId, TimelineEdge::Start, v, done); });
        break;
    }
    case DragMode::TrimEnd: {
        if (m_drag.locked)
            break;
        const qint64 t = std::max(snapTime(m_drag.origEnd + raw, bypass), m_drag.origStart + frame);
        request(t, [&](qint64 v, bool done) { emit clipTrimRequested(m_drag.clipId, TimelineEdge::End, v, done); });
        break;
    }
    case DragMode::FadeIn: {
        if (m_drag.locked)
            break;
        const qint64 handle = snapTime(m_drag.origStart + m_drag.origValue + raw, bypass);
        const qint64 fade = std::clamp<qint64>(handle - m_drag.origStart, 0, length);
        request(fade, [&](qint64 v, bool done) { emit clipFadeRequested(m_drag.clipId, TimelineEdge::Start, v, done); });
        break;
    }
    case DragMode::FadeOut: {
        if (m_drag.locked || openEnd)
            break;
        const qint64 handle = snapTime(m_drag.origEnd - m_drag.origValue + raw, bypass);
        const qint64 fade = std::clamp<qint64>(m_drag.origEnd - handle, 0, length);
        request(fade, [&](qint64 v, bool done) { emit clipFadeRequested(m_drag.clipId, TimelineEdge::End, v, done); });
        break;
    }
    case DragMode::None:
    case DragMode::RubberBand: break;
    }
}

void TimelineView::updateRubberBand(const QPoint& pos)
{
    const QRect lanes(HeaderWidth, RulerHeight, viewport()->width() - HeaderWidth, viewport()->height() - RulerHeight);
    m_drag.band = QRect(m_drag.pressPos, pos).normalized().intersected(lanes);
    m_drag.baseSelection.resize(std::size_t(m_clips.size()), 0); // the editor may have replaced the clips
    for (int i = 0; i < int(m_clips.size()); ++i) {
        const QRect r = clipRectAt(i);
        m_clips[i].selected = m_drag.baseSelection[std::size_t(i)] || (!r.isNull() && r.intersects(m_drag.band));
    }
}

void TimelineView::mouseMoveEvent(QMouseEvent* event)
{
    const QPoint pos = event->position().toPoint();
    if (m_drag.mode == DragMode::None) {
        updateHoverCursor(pos);
        return;
    }
    if (!m_drag.active) {
        if ((pos - m_drag.pressPos).manhattanLength() < kDragThreshold)
            return;
        m_drag.active = true;
    }
    if (m_drag.mode == DragMode::RubberBand)
        updateRubberBand(pos);
    else
        updateDrag(pos, event->modifiers(), false);
    viewport()->update();
}

void TimelineView::mouseReleaseEvent(QMouseEvent* event)
{
    if (event->button() != Qt::LeftButton) {
        event->ignore();
        return;
    }
    const QPoint pos = event->position().toPoint();
    switch (m_drag.mode) {
    case DragMode::RubberBand:
        if (m_drag.active)
            updateRubberBand(pos);
        emitSelectionIfChanged(m_drag.pressSelection);
        break;
    case DragMode::Clip:
    case DragMode::TrimStart:
    case DragMode::TrimEnd:
    case DragMode::FadeIn:
    case DragMode::FadeOut:
        if (m_drag.active) {
            updateDrag(pos, event->modifiers(), true);
        } else if (const int index = clipIndex(m_drag.clipId); index >= 0) {
            // A click without a drag: Shift/Ctrl toggles a selected clip off, a plain click
            // narrows the selection to the clip.
            const std::vector<char> before = selectionFlags();
            if (m_drag.toggleOnRelease)
                m_clips[index].selected = false;
            else if (m_drag.selectOnlyOnRelease)
                selectOnly(index);
            emitSelectionIfChanged(before);
        }
        break;
    case DragMode::Scrub:
    case DragMode::Marker:
        if (m_drag.active)
            updateDrag(pos, event->modifiers(), true);
        break;
    case DragMode::None: break;
    }
    m_drag = Drag{};
    m_snapLine = -1;
    updateHoverCursor(pos);
    viewport()->update();
}

void TimelineView::mouseDoubleClickEvent(QMouseEvent* event)
{
    if (event->button() != Qt::LeftButton)
        return;
    const QPoint pos = event->position().toPoint();
    const Hit hit = hitTest(pos);
    if (hit.kind == HitKind::Ruler) {
        buildSnapTargets(nullptr, -1, true);
        emit markerAddRequested(std::max<qint64>(0, snapTime(timeForX(pos.x()), event->modifiers() & Qt::ControlModifier)));
        m_snapLine = -1;
    } else if (hit.clip >= 0 && hit.kind != HitKind::Lane) {
        emit clipActivated(m_clips[hit.clip].clip.id);
    }
}

void TimelineView::wheelEvent(QWheelEvent* event)
{
    const QPoint angle = event->angleDelta();
    const int delta = angle.y() != 0 ? angle.y() : angle.x();
    if (delta == 0) {
        event->ignore();
        return;
    }
    const Qt::KeyboardModifiers modifiers = event->modifiers();
    if (modifiers & Qt::ControlModifier) {
        // Zoom about the mouse: the time under it stays under it.
        const int x = std::max(int(event->position().x()), HeaderWidth);
        const double anchorSeconds = (x - timeOriginX()) / m_pixelsPerSecond;
        m_pixelsPerSecond = std::clamp(m_pixelsPerSecond * std::pow(2.0, delta / 480.0), kMinPixelsPerSecond,
                                       kMaxPixelsPerSecond);
        updateScrollRanges();
        horizontalScrollBar()->setValue(int(std::lround(anchorSeconds * m_pixelsPerSecond - (x - HeaderWidth - kTimePad))));
        viewport()->update();
    } else if ((modifiers & Qt::ShiftModifier) || (angle.y() == 0 && angle.x() != 0)) {
        QScrollBar* h = horizontalScrollBar();
        h->setValue(h->value() - delta * std::max(1, h->pageStep() / 6) / 120);
    } else {
        QScrollBar* v = verticalScrollBar();
        v->setValue(v->value() - delta * TrackHeight / 120);
    }
    event->accept();
}

// --- keys, menus, tooltips ----------------------------------------------------------------------

bool TimelineView::event(QEvent* event)
{
    // Keep Ctrl+A, M (and Escape, Undo and Redo during a drag) for the timeline while it has
    // focus, even if a window action uses them: an undo under a drag would pull the document
    // from under the drag's next steps.
    if (event->type() == QEvent::ShortcutOverride) {
        auto* key = static_cast<QKeyEvent*>(event);
        if (key->matches(QKeySequence::SelectAll)
            || (key->key() == Qt::Key_M && !(key->modifiers() & ~Qt::KeypadModifier))
            || (m_drag.mode != DragMode::None
                && (key->key() == Qt::Key_Escape || key->matches(QKeySequence::Undo) || key->matches(QKeySequence::Redo)))) {
            event->accept();
            return true;
        }
    }
    return QAbstractScrollArea::event(event);
}

void TimelineView::cancelDrag()
{
    // Whatever the drag asked for is asked back, as one finished request.
    if (m_drag.emitted) {
        switch (m_drag.mode) {
        case DragMode::Clip: emit clipsMoveRequested(m_drag.ids, 0, 0, true); break;
        case DragMode::TrimStart:
            emit clipTrimRequested(m_drag.clipId, TimelineEdge::Start, m_drag.origValue, true);
            break;
        case DragMode::TrimEnd: emit clipTrimRequested(m_drag.clipId, TimelineEdge::End, m_drag.origValue, true); break;
        case DragMode::FadeIn: emit clipFadeRequested(m_drag.clipId, TimelineEdge::Start, m_drag.origValue, true); break;
        case DragMode::FadeOut: emit clipFadeRequested(m_drag.clipId, TimelineEdge::End, m_drag.origValue, true); break;
        case DragMode::Marker: emit markerMoveRequested(m_drag.marker, m_drag.origValue, true); break;
        default: break;
        }
    }
    if (m_drag.mode == DragMode::RubberBand)
        setSelectionFlags(m_drag.pressSelection);
    m_drag = Drag{};
    m_snapLine = -1;
    viewport()->update();
}

void TimelineView::keyPressEvent(QKeyEvent* event)
{
    if (m_drag.mode != DragMode::None) {
        if (event->key() == Qt::Key_Escape || event->matches(QKeySequence::Undo)) {
            cancelDrag();
            return;
        }
        if (event->matches(QKeySequence::Redo))
            return; // nothing to redo while the drag's own edit is open
    }
    if (event->matches(QKeySequence::SelectAll)) {
        const std::vector<char> before = selectionFlags();
        for (ClipItem& item : m_clips)
            item.selected = true;
        emitSelectionIfChanged(before);
        return;
    }
    if (event->key() == Qt::Key_M && !(event->modifiers() & ~Qt::KeypadModifier)) {
        emit markerAddRequested(m_playhead);
        return;
    }
    QAbstractScrollArea::keyPressEvent(event);
}

void TimelineView::contextMenuEvent(QContextMenuEvent* event)
{
    const QPoint pos = event->pos();
    const Hit hit = hitTest(pos);
    if (hit.kind != HitKind::Marker && hit.kind != HitKind::Ruler) {
        event->ignore();
        return;
    }
    QMenu menu(this);
    if (hit.kind == HitKind::Marker) {
        const int marker = hit.marker;
        connect(menu.addAction(tr("Remove Marker “%1”").arg(m_markers[marker].name)), &QAction::triggered, this,
                [this, marker] { emit markerRemoveRequested(marker); });
    }
    buildSnapTargets(nullptr, -1, true);
    const qint64 time = std::max<qint64>(0, snapTime(timeForX(pos.x()), false));
    m_snapLine = -1;
    connect(menu.addAction(tr("Add Marker Here")), &QAction::triggered, this,
            [this, time] { emit markerAddRequested(time); });
    menu.exec(event->globalPos());
}

bool TimelineView::viewportEvent(QEvent* event)
{
    if (event->type() == QEvent::ToolTip) {
        auto* help = static_cast<QHelpEvent*>(event);
        const Hit hit = hitTest(help->pos());
        QString text;
        if (hit.clip >= 0 && hit.kind != HitKind::Lane) {
            const TimelineClip& c = m_clips[hit.clip].clip;
            text = c.end == OpenEnd ? tr("%1\n%2 – open end").arg(c.name, formatTime(c.start))
                                    : tr("%1\n%2 – %3 (%4)").arg(c.name, formatTime(c.start), formatTime(c.end),
                                                                 formatTime(c.end - c.start));
            if (trackLocked(c.track))
                text += QLatin1Char('\n') + tr("The track is locked");
        } else if (hit.kind == HitKind::Flag) {
            switch (hit.flag) {
            case TimelineTrackFlag::Mute: text = tr("Mute: leave this track out of playback"); break;
            case TimelineTrackFlag::Solo: text = tr("Solo: play only the soloed tracks"); break;
            case TimelineTrackFlag::Lock: text = tr("Lock: protect this track's clips from edits"); break;
            }
        } else if (hit.kind == HitKind::Marker) {
            text = tr("%1 at %2").arg(m_markers[hit.marker].name, formatTime(m_markers[hit.marker].time));
        }
        if (text.isEmpty())
            QToolTip::hideText();
        else
            QToolTip::showText(help->globalPos(), text, viewport());
        return true;
    }
    if (event->type() == QEvent::Leave && m_drag.mode == DragMode::None)
        viewport()->unsetCursor();
    return QAbstractScrollArea::viewportEvent(event);
}

// --- drop ---------------------------------------------------------------------------------------

bool TimelineView::updateDrop(const QPoint& pos, const QMimeData*, Qt::KeyboardModifiers modifiers)
{
    const int track = trackAtY(pos.y());
    const bool valid = pos.x() >= HeaderWidth && track >= 0 && !trackLocked(track);
    m_dropActive = valid;
    if (valid) {
        m_dropTrack = track;
        m_dropTime = std::max<qint64>(0, snapTime(timeForX(pos.x()), modifiers & Qt::ControlModifier));
    }
    viewport()->update();
    return valid;
}

namespace {

bool acceptsDrop(const QMimeData* mime)
{
    return mime && (mime->hasFormat(QLatin1String(TimelineView::ClipMimeType)) || !droppedFiles(mime).isEmpty());
}

} // namespace

void TimelineView::dragEnterEvent(QDragEnterEvent* event)
{
    if (!acceptsDrop(event->mimeData())) {
        event->ignore();
        return;
    }
    const QStringList files = droppedFiles(event->mimeData());
    m_dropName = files.isEmpty() ? QString::fromUtf8(event->mimeData()->data(QLatin1String(ClipMimeType)))
                                 : QFileInfo(files.front()).completeBaseName();
    buildSnapTargets(nullptr, -1, true);
    updateDrop(event->position().toPoint(), event->mimeData(), event->modifiers());
    event->acceptProposedAction(); // accepted even over the header, so that moves keep coming
}

void TimelineView::dragMoveEvent(QDragMoveEvent* event)
{
    if (!acceptsDrop(event->mimeData())) {
        event->ignore();
        return;
    }
    if (updateDrop(event->position().toPoint(), event->mimeData(), event->modifiers()))
        event->acceptProposedAction();
    else
        event->ignore();
}

void TimelineView::dragLeaveEvent(QDragLeaveEvent* event)
{
    m_dropActive = false;
    m_snapLine = -1;
    viewport()->update();
    event->accept();
}

void TimelineView::dropEvent(QDropEvent* event)
{
    const bool ours = acceptsDrop(event->mimeData());
    if (ours && updateDrop(event->position().toPoint(), event->mimeData(), event->modifiers())) {
        event->acceptProposedAction();
        if (const QStringList files = droppedFiles(event->mimeData()); !files.isEmpty())
            emit filesDropRequested(m_dropTrack, m_dropTime, files);
        else
            emit clipDropRequested(m_dropTrack, m_dropTime,
                                   QString::fromUtf8(event->mimeData()->data(QLatin1String(ClipMimeType))));
    } else {
        event->ignore();
    }
    m_dropActive = false;
    m_snapLine = -1;
    viewport()->update();
}

// --- look ---------------------------------------------------------------------------------------

void TimelineView::resizeEvent(QResizeEvent* event)
{
    QAbstractScrollArea::resizeEvent(event);
    updateScrollRanges();
    if (m_frameAllPending)
        frameAll();
}

void TimelineView::scrollContentsBy(int, int)
{
    // The header and ruler stay put while the lanes scroll: repaint rather than blit.
    viewport()->update();
}

void TimelineView::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::PaletteChange || event->type() == QEvent::StyleChange)
        updateColors();
    if (event->type() == QEvent::FontChange)
        updateFonts();
    QAbstractScrollArea::changeEvent(event);
}

void TimelineView::updateFonts()
{
    m_clipFont = font();
    m_clipFont.setPointSizeF(font().pointSizeF() * 0.92);
    m_smallFont = font();
    m_smallFont.setPointSizeF(font().pointSizeF() * 0.82);
    m_boldFont = font();
    m_boldFont.setBold(true);
    m_clipMetrics = QFontMetrics(m_clipFont);
    m_smallMetrics = QFontMetrics(m_smallFont);
    for (ClipItem& item : m_clips)
        item.labelWidth = -1;
    for (qsizetype i = 0; i < m_markers.size(); ++i)
        m_markerWidths[std::size_t(i)] = m_smallMetrics.horizontalAdvance(m_markers[i].name);
    rebuildRows();
    viewport()->update();
}

void TimelineView::updateColors()
{
    const QPalette& pal = palette();
    const QColor window = pal.color(QPalette::Window);
    const QColor windowText = pal.color(QPalette::WindowText);
    const QColor base = pal.color(QPalette::Base);
    const QColor text = pal.color(QPalette::Text);
    const QColor highlight = pal.color(QPalette::Highlight);
    const QColor shadow = pal.color(QPalette::Shadow);
    Colors& c = m_colors;
    c.dark = window.lightnessF() < 0.5;
    c.lane = base;
    c.laneAlt = mix(base, text, 0.035);
    c.group = mix(window, windowText, c.dark ? 0.10 : 0.08);
    c.header = window;
    c.headerText = windowText;
    c.headerDim = mix(windowText, window, 0.55);
    c.separator = mix(window, shadow, c.dark ? 0.5 : 0.2);
    c.ruler = mix(window, windowText, 0.05);
    c.rulerText = mix(windowText, window, 0.2);
    c.rulerTick = mix(windowText, window, 0.55);
    c.gridMajor = mix(base, text, 0.10);
    c.gridMinor = mix(base, text, 0.05);
    c.outside = mix(base, shadow, c.dark ? 0.35 : 0.07);

    // Clips: the highlight's hue, calmed down; selected ones closer to the highlight itself.
    const float hue = std::max(0.0f, highlight.hslHueF());
    const float saturation = highlight.hslSaturationF();
    c.clip = QColor::fromHslF(hue, saturation * 0.32f, c.dark ? 0.35f : 0.80f);
    c.clipBorder = c.dark ? c.clip.darker(160) : c.clip.darker(130);
    c.clipSelected = QColor::fromHslF(hue, saturation * 0.70f, c.dark ? 0.45f : 0.68f);
    c.clipSelectedBorder = c.dark ? QColor::fromHslF(hue, 0.9f, 0.78f) : QColor::fromHslF(hue, 0.9f, 0.30f);
    c.clipText = text;
    c.clipSelectedText = c.dark ? QColor(0xff, 0xff, 0xff) : QColor(0x0b, 0x0d, 0x10);
    c.fadeShade = c.dark ? QColor(0, 0, 0, 90) : QColor(0, 0, 0, 40);
    c.fadeLine = withAlpha(text, 160);
    c.weightLine = withAlpha(text, 150);
    c.weightFill = withAlpha(text, 28);
    c.handle = c.dark ? QColor(0xf2, 0xf2, 0xf2) : QColor(0xff, 0xff, 0xff);
    c.playhead = QColor(0xe5, 0x48, 0x4d);
    c.marker = QColor(0xf0, 0xa8, 0x30);
    c.markerText = QColor(0x26, 0x1c, 0x08);
    c.snap = c.dark ? QColor(0xff, 0xd8, 0x4d) : QColor(0xc0, 0x7a, 0x00);
    c.band = withAlpha(highlight, 50);
    c.bandBorder = highlight;
    c.flagOff = mix(window, windowText, c.dark ? 0.10 : 0.07);
    c.flagOffText = mix(windowText, window, 0.45);
    c.mute = QColor(0xe0, 0x7b, 0x39);
    c.solo = QColor(0xe6, 0xc2, 0x29);
    c.lock = QColor(0x6f, 0xa0, 0xd8);
    c.flagOnText = QColor(0x1a, 0x1a, 0x1a);
    m_fadePen = QPen(c.fadeLine, 1.0);
    m_fadePen.setCosmetic(true);
    m_weightPen = QPen(c.weightLine, 1.0);
    m_weightPen.setCosmetic(true);
    c.lockedHatch = QBrush(mix(base, text, c.dark ? 0.13 : 0.12), Qt::BDiagPattern);
    viewport()->update();
}

void TimelineView::paintEvent(QPaintEvent*)
{
    QPainter painter(viewport());
    const QRect lanes(HeaderWidth, RulerHeight, std::max(0, viewport()->width() - HeaderWidth),
                      std::max(0, viewport()->height() - RulerHeight));
    painter.setClipRect(lanes);
    paintLanes(painter, lanes);
    paintClips(painter, lanes);
    paintOverlays(painter, lanes);
    painter.setClipping(false);
    paintHeader(painter);
    paintRuler(painter);
}

void TimelineView::paintLanes(QPainter& painter, const QRect& lanes)
{
    const Colors& c = m_colors;
    painter.fillRect(lanes, c.outside);
    const int right = lanes.right() + 1;
    for (const Row& row : m_rows) {
        const int y = rowY(row);
        if (y > lanes.bottom())
            break;
        const int height = row.track < 0 ? GroupHeight : TrackHeight;
        if (y + height <= lanes.top())
            continue;
        const QRect r(lanes.left(), y, lanes.width(), height);
        if (row.track < 0) {
            painter.fillRect(r, c.group);
        } else {
            painter.fillRect(r, row.track % 2 ? c.laneAlt : c.lane);
            if (m_tracks[row.track].locked)
                painter.fillRect(r, c.lockedHatch);
            if (trackDimmed(row.track))
                painter.fillRect(r, withAlpha(c.outside, 120));
        }
        painter.setPen(c.separator);
        painter.drawLine(lanes.left(), y + height - 1, right, y + height - 1);
    }

    // Time past the scenario's end is shaded.
    if (m_duration > 0) {
        const int endX = xForTime(m_duration);
        if (endX < right) {
            const int bottom = std::min(lanes.bottom(), RulerHeight + contentHeight() - verticalScrollBar()->value());
            const QRect after(std::max(endX, lanes.left()), lanes.top(), right - std::max(endX, lanes.left()),
                              bottom - lanes.top() + 1);
            painter.fillRect(after, withAlpha(c.outside, 150));
        }
    }

    // Vertical grid at the ruler's major steps.
    const Steps steps = rulerSteps();
    const qint64 firstFrame = std::max<qint64>(0, floorDiv(floorDiv(timeForX(lanes.left()) * m_frameRate, m_ticksPerSecond), steps.major));
    m_lines.clear();
    for (qint64 k = firstFrame;; ++k) {
        const int x = xForTime(frameTime(k * steps.major));
        if (x > right)
            break;
        m_lines.emplace_back(x, lanes.top(), x, lanes.bottom());
    }
    painter.setPen(c.gridMajor);
    painter.drawLines(m_lines.data(), int(m_lines.size()));

    // Markers: a thin line through the lanes.
    painter.setPen(QPen(withAlpha(c.marker, 110), 1, Qt::DashLine));
    for (const TimelineMarker& marker : m_markers) {
        const int x = xForTime(marker.time);
        if (x >= lanes.left() && x <= right)
            painter.drawLine(x, lanes.top(), x, lanes.bottom());
    }
}

void TimelineView::paintClips(QPainter& painter, const QRect& lanes)
{
    if (m_clips.isEmpty() || m_tracks.isEmpty())
        return;
    // Cull in ticks first (no pixel math for clips outside the visible time range).
    const qint64 visibleStart = timeForX(lanes.left() - 2);
    const qint64 visibleEnd = timeForX(lanes.right() + 2);
    const int laneRight = lanes.right() + 1;
    // Unselected clips first, so that selected outlines are never covered.
    for (int pass = 0; pass < 2; ++pass) {
        for (const ClipItem& item : m_clips) {
            const TimelineClip& c = item.clip;
            if (item.selected != (pass == 1) || c.track < 0 || c.track >= int(m_tracks.size()))
                continue;
            if (c.start > visibleEnd || (c.end != OpenEnd && c.end < visibleStart))
                continue;
            const int y = trackY(c.track);
            if (y + TrackHeight <= lanes.top() || y > lanes.bottom())
                continue;
            const int x0 = xForTime(c.start);
            const int x1 = c.end == OpenEnd ? laneRight : std::max(x0 + 1, xForTime(c.end));
            const QRect r(x0, y + kClipInset, x1 - x0, TrackHeight - 2 * kClipInset);
            paintClip(painter, item, r, trackDimmed(c.track), m_tracks[c.track].locked, laneRight);
        }
    }
}

void TimelineView::paintClip(QPainter& painter, const ClipItem& item, const QRect& r, bool dimmed, bool locked,
                             int laneRight)
{
    // Solid fills and aliased shapes wherever they look the same: antialiased paths cost ten
    // times as much, and a thousand clips must paint in a few milliseconds. Only the thin lines
    // (fade ramps, weight curve) are antialiased, with cosmetic pens (the rasterizer's fast path).
    const Colors& c = m_colors;
    const TimelineClip& clip = item.clip;
    const bool open = clip.end == OpenEnd;
    const QColor& fill = item.selected ? c.clipSelected : c.clip;
    if (dimmed)
        painter.setOpacity(0.45);
    if (r.width() < 5) {
        // Zoomed far out: a bar is all that can be seen.
        painter.fillRect(r, item.selected ? c.clipSelectedBorder : fill);
        if (dimmed)
            painter.setOpacity(1.0);
        return;
    }
    const int borderWidth = item.selected ? 2 : 1;
    const QColor& borderColor = item.selected ? c.clipSelectedBorder : c.clipBorder;
    if (open) {
        // Open-ended: no right border; fill and border fade out towards the view's edge.
        QLinearGradient fillFade(laneRight - kOpenFadeWidth, 0, laneRight, 0);
        fillFade.setColorAt(0, fill);
        fillFade.setColorAt(1, withAlpha(fill, 0));
        QLinearGradient borderFade(laneRight - kOpenFadeWidth, 0, laneRight, 0);
        borderFade.setColorAt(0, borderColor);
        borderFade.setColorAt(1, withAlpha(borderColor, 0));
        fillBar(painter, r.adjusted(0, 0, 4, 0), QBrush(fillFade), QBrush(borderFade), borderWidth);
    } else {
        fillBar(painter, r, fill, borderColor, borderWidth);
    }

    const int top = r.top() + borderWidth, bottom = r.bottom() - borderWidth + 1;
    const int left = r.left() + borderWidth, right = r.left() + r.width() - borderWidth;
    if (r.width() >= 10) {
        // Narrow clips (zoomed out, hundreds in view) keep the ramps but not their shading, and
        // draw their lines aliased: at that size neither is visible, and switching smoothing on
        // and off per clip costs more than the drawing itself.
        const bool smooth = r.width() >= kMinSmoothClipWidth;
        // Fades: the part above the ramp is shaded, the ramp itself a line.
        if (smooth && clip.fadeIn > 0) {
            const int xf = std::clamp(xForTime(clip.start + clip.fadeIn), left, right);
            const QPoint shade[] = {{left, top}, {xf, top}, {left, bottom}};
            painter.setPen(Qt::NoPen);
            painter.setBrush(c.fadeShade);
            painter.drawConvexPolygon(shade, 3);
        }
        if (smooth && !open && clip.fadeOut > 0) {
            const int xf = std::clamp(xForTime(clip.end - clip.fadeOut), left, right);
            const QPoint shade[] = {{right, top}, {xf, top}, {right, bottom}};
            painter.setPen(Qt::NoPen);
            painter.setBrush(c.fadeShade);
            painter.drawConvexPolygon(shade, 3);
        }
        if (smooth)
            painter.setRenderHint(QPainter::Antialiasing, true);
        if (clip.fadeIn > 0) {
            painter.setPen(m_fadePen);
            painter.drawLine(QPointF(left, bottom), QPointF(std::clamp(xForTime(clip.start + clip.fadeIn), left, right), top));
        }
        if (!open && clip.fadeOut > 0) {
            painter.setPen(m_fadePen);
            painter.drawLine(QPointF(right, bottom), QPointF(std::clamp(xForTime(clip.end - clip.fadeOut), left, right), top));
        }

        // Weight thumbnail in the lower part: one point per sample, or per two pixels (four on a
        // narrow clip) when the samples are denser than that (keeping each bucket's peak),
        // visible columns only.
        const QVector<float>& weight = clip.weight;
        const qsizetype n = weight.size();
        const double barLeft = r.left() + 0.5;
        const double barRight = open ? laneRight : r.left() + r.width() - 0.5;
        if (n >= 2 && r.width() >= 16) {
            const double span = barRight - barLeft;
            const double baseY = bottom - 2.5;
            const double amplitude = (r.height() - 4) * 0.45;
            const double visibleLeft = std::max<double>(barLeft, HeaderWidth - 2);
            const double visibleRight = std::min<double>(barRight, laneRight + 2);
            auto yFor = [&](float w) { return baseY - std::clamp(double(w), 0.0, 1.3) * amplitude; };
            m_points.clear();
            const double bucket = smooth ? 2.0 : 4.0; // pixels per point
            if (double(n - 1) <= span / bucket) {
                const double step = span / double(n - 1);
                const qsizetype first = std::max<qsizetype>(0, qsizetype(std::floor((visibleLeft - barLeft) / step)));
                const qsizetype last = std::min<qsizetype>(n - 1, qsizetype(std::ceil((visibleRight - barLeft) / step)));
                for (qsizetype i = first; i <= last; ++i)
                    m_points.emplace_back(barLeft + double(i) * step, yFor(weight[i]));
            } else {
                const double samplesPerPixel = double(n - 1) / span;
                for (double x = visibleLeft; x <= visibleRight; x += bucket) {
                    const qsizetype i0 = std::clamp<qsizetype>(qsizetype((x - barLeft) * samplesPerPixel), 0, n - 1);
                    const qsizetype i1 = std::clamp<qsizetype>(qsizetype((x + bucket - barLeft) * samplesPerPixel), i0, n - 1);
                    float peak = weight[i0];
                    for (qsizetype i = i0 + 1; i <= i1; ++i)
                        peak = std::max(peak, weight[i]);
                    m_points.emplace_back(x, yFor(peak));
                }
            }
            if (m_points.size() >= 2) {
                painter.setPen(m_weightPen);
                painter.drawPolyline(m_points.data(), int(m_points.size()));
            }
        }
        if (smooth)
            painter.setRenderHint(QPainter::Antialiasing, false);
    }

    if (r.width() >= kMinClipDetail) {
        // The name, kept in view when the clip starts left of the lanes.
        const int textLeft = std::max(r.left(), HeaderWidth) + 7;
        const int textRight = std::min(r.left() + r.width(), laneRight) - 5;
        const int room = textRight - textLeft;
        if (room >= 12) {
            if (item.labelWidth != room) {
                item.label.setText(m_clipMetrics.elidedText(clip.name, Qt::ElideRight, room));
                item.label.prepare(QTransform(), m_clipFont);
                item.labelWidth = room;
            }
            painter.setFont(m_clipFont);
            painter.setPen(item.selected ? c.clipSelectedText : c.clipText);
            painter.drawStaticText(textLeft, r.top() + 4, item.label);
        }
        // Fade handles: small squares on the top border (not on locked tracks: they cannot be dragged).
        if (!locked) {
            const int index = int(&item - m_clips.constData());
            for (TimelineEdge edge : {TimelineEdge::Start, TimelineEdge::End}) {
                if (edge == TimelineEdge::End && open)
                    break;
                const QPoint centre = fadeHandleRectAt(index, edge).center();
                painter.fillRect(QRect(centre.x() - 3, centre.y() - 3, 7, 7), borderColor);
                painter.fillRect(QRect(centre.x() - 2, centre.y() - 2, 5, 5), c.handle);
            }
        }
    }
    if (dimmed)
        painter.setOpacity(1.0);
}

void TimelineView::paintOverlays(QPainter& painter, const QRect& lanes)
{
    const Colors& c = m_colors;
    if (m_dropActive && m_dropTrack >= 0) {
        const int x = xForTime(m_dropTime);
        const int width = std::max(90, int(m_pixelsPerSecond));
        paintGhost(painter, QRect(x, trackY(m_dropTrack) + kClipInset, width, TrackHeight - 2 * kClipInset), m_dropName);
        painter.fillRect(QRect(x - 1, lanes.top(), 2, lanes.height()), c.snap);
    }
    paintMoveGhosts(painter);
    if (m_snapLine >= 0) {
        const int x = xForTime(m_snapLine);
        painter.fillRect(QRect(x, lanes.top(), 1, lanes.height()), c.snap);
    }
    if (m_drag.mode == DragMode::RubberBand && m_drag.active && !m_drag.band.isEmpty()) {
        painter.setPen(c.bandBorder);
        painter.setBrush(c.band);
        painter.drawRect(m_drag.band.adjusted(0, 0, -1, -1));
    }
    // The playhead over every track.
    const int x = xForTime(m_playhead);
    if (x >= lanes.left() - 1 && x <= lanes.right() + 1)
        painter.fillRect(QRect(x, lanes.top(), 1, lanes.height()), c.playhead);
}

void TimelineView::paintGhost(QPainter& painter, const QRect& ghost, const QString& name)
{
    const Colors& c = m_colors;
    painter.setRenderHint(QPainter::Antialiasing, true);
    painter.setPen(QPen(c.clipSelectedBorder, 1.5, Qt::DashLine));
    painter.setBrush(withAlpha(c.clipSelected, 110));
    painter.drawRoundedRect(QRectF(ghost).adjusted(0.5, 0.5, -0.5, -0.5), 3, 3);
    painter.setRenderHint(QPainter::Antialiasing, false);
    painter.setFont(m_clipFont);
    painter.setPen(c.clipSelectedText);
    painter.drawText(ghost.adjusted(8, 3, -4, 0), Qt::AlignLeft | Qt::AlignTop,
                     m_clipMetrics.elidedText(name, Qt::ElideRight, ghost.width() - 12));
}

void TimelineView::paintMoveGhosts(QPainter& painter)
{
    // Where a clip drag puts the clips, for as long as the editor has not moved them there (it
    // may refuse, or apply the move only on release).
    if (m_drag.mode != DragMode::Clip || !m_drag.active || m_drag.locked || (m_drag.last == 0 && m_drag.trackDelta == 0))
        return;
    QSet<std::pair<int, qint64>> shown; // (track, start) of the clips as they are now
    for (const ClipItem& item : std::as_const(m_clips))
        shown.insert({item.clip.track, item.clip.start});
    const int laneRight = viewport()->width();
    for (const TimelineClip& c : std::as_const(m_drag.moving)) {
        const int track = c.track + m_drag.trackDelta;
        const qint64 start = c.start + m_drag.last;
        if (track < 0 || track >= int(m_tracks.size()) || shown.contains({track, start}))
            continue;
        const int x0 = xForTime(start);
        const int x1 = c.end == OpenEnd ? laneRight : std::max(x0 + 1, xForTime(c.end + m_drag.last));
        paintGhost(painter, QRect(x0, trackY(track) + kClipInset, x1 - x0, TrackHeight - 2 * kClipInset), c.name);
    }
}

void TimelineView::paintFlag(QPainter& painter, const QRect& rect, TimelineTrackFlag flag, bool on)
{
    const Colors& c = m_colors;
    const QColor& lit = flag == TimelineTrackFlag::Mute ? c.mute : flag == TimelineTrackFlag::Solo ? c.solo : c.lock;
    painter.setRenderHint(QPainter::Antialiasing, true);
    painter.setPen(on ? lit.darker(130) : c.separator);
    painter.setBrush(on ? lit : c.flagOff);
    painter.drawRoundedRect(QRectF(rect).adjusted(0.5, 0.5, -0.5, -0.5), 3, 3);
    painter.setRenderHint(QPainter::Antialiasing, false);
    painter.setPen(on ? c.flagOnText : c.flagOffText);
    painter.drawText(rect, Qt::AlignCenter, QLatin1String(flagLetter(flag)));
}

void TimelineView::paintHeader(QPainter& painter)
{
    const Colors& c = m_colors;
    const QRect column(0, RulerHeight, HeaderWidth, std::max(0, viewport()->height() - RulerHeight));
    painter.setClipRect(column);
    painter.fillRect(column, c.header);
    for (const Row& row : m_rows) {
        const int y = rowY(row);
        if (y > column.bottom())
            break;
        const int height = row.track < 0 ? GroupHeight : TrackHeight;
        if (y + height <= column.top())
            continue;
        if (row.track < 0) {
            // The character: a bold label on a band that spans the lanes too.
            painter.fillRect(QRect(0, y, HeaderWidth, height), c.group);
            painter.fillRect(QRect(0, y, 3, height), c.bandBorder);
            painter.setFont(m_boldFont);
            painter.setPen(c.headerText);
            painter.drawText(QRect(10, y, HeaderWidth - 16, height), Qt::AlignLeft | Qt::AlignVCenter, row.label);
        } else {
            const TimelineTrack& track = m_tracks[row.track];
            if (row.group >= 0)
                painter.fillRect(QRect(0, y, 3, height), withAlpha(c.bandBorder, 110));
            const int nameX = track.group.isEmpty() ? 10 : 22;
            painter.setFont(font());
            painter.setPen(trackDimmed(row.track) ? c.headerDim : c.headerText);
            painter.drawText(QRect(nameX, y, HeaderWidth - nameX, height), Qt::AlignLeft | Qt::AlignVCenter,
                             m_trackElided[std::size_t(row.track)]);
            painter.setFont(m_smallFont);
            for (TimelineTrackFlag flag : kFlags)
                paintFlag(painter, trackFlagRect(row.track, flag), flag, flagValue(track, flag));
        }
        painter.setPen(c.separator);
        painter.drawLine(0, y + height - 1, HeaderWidth, y + height - 1);
    }
    painter.setPen(c.separator);
    painter.drawLine(HeaderWidth - 1, column.top(), HeaderWidth - 1, column.bottom());
    painter.setClipping(false);
}

void TimelineView::paintRuler(QPainter& painter)
{
    const Colors& c = m_colors;
    const QRect ruler = rulerRect();
    const int right = ruler.right() + 1;

    // Top-left corner: the playhead's time.
    const QRect corner(0, 0, HeaderWidth, RulerHeight);
    painter.fillRect(corner, c.ruler);
    painter.setFont(m_boldFont);
    painter.setPen(c.headerText);
    painter.drawText(corner.adjusted(10, 0, -8, 0), Qt::AlignLeft | Qt::AlignVCenter, formatTime(m_playhead));
    painter.setFont(m_smallFont);
    painter.setPen(c.rulerText);
    painter.drawText(corner.adjusted(10, 0, -8, 0), Qt::AlignRight | Qt::AlignVCenter, m_frameRateLabel);
    painter.setPen(c.separator);
    painter.drawLine(HeaderWidth - 1, 0, HeaderWidth - 1, RulerHeight);

    painter.setClipRect(ruler);
    painter.fillRect(ruler, c.ruler);
    const Steps steps = rulerSteps();
    // Minor ticks (frames when zoomed in), then major ticks with labels.
    if (steps.minor > 0) {
        m_lines.clear();
        qint64 k = std::max<qint64>(0, floorDiv(floorDiv(timeForX(ruler.left()) * m_frameRate, m_ticksPerSecond), steps.minor));
        for (;; ++k) {
            const int x = xForTime(frameTime(k * steps.minor));
            if (x > right)
                break;
            m_lines.emplace_back(x, RulerHeight - 5, x, RulerHeight - 1);
        }
        painter.setPen(c.rulerTick);
        painter.drawLines(m_lines.data(), int(m_lines.size()));
    }
    painter.setFont(m_smallFont);
    const int labelY = 2 + m_smallMetrics.ascent();
    // Start one step early so that a label whose tick is just off the left still shows.
    qint64 k = std::max<qint64>(0, floorDiv(floorDiv(timeForX(ruler.left()) * m_frameRate, m_ticksPerSecond), steps.major) - 1);
    for (;; ++k) {
        const qint64 frame = k * steps.major;
        const int x = xForTime(frameTime(frame));
        if (x > right)
            break;
        painter.setPen(c.rulerText);
        painter.drawLine(x, 0, x, RulerHeight - 1);
        const qint64 seconds = frame / m_frameRate;
        const qint64 frames = frame % m_frameRate;
        const QString label = frames == 0
                                  ? QStringLiteral("%1:%2").arg(seconds / 60).arg(seconds % 60, 2, 10, QLatin1Char('0'))
                                  : QStringLiteral("%1:%2+%3")
                                        .arg(seconds / 60)
                                        .arg(seconds % 60, 2, 10, QLatin1Char('0'))
                                        .arg(frames, 2, 10, QLatin1Char('0'));
        painter.drawText(x + 4, labelY, label);
    }

    // Markers: a flag hanging from the bottom edge with the name beside it.
    painter.setRenderHint(QPainter::Antialiasing, true);
    for (int i = 0; i < int(m_markers.size()); ++i) {
        const QRect r = markerRect(i);
        if (r.right() < ruler.left() || r.left() > right)
            continue;
        const int x = xForTime(m_markers[i].time);
        const QRectF pill(x, r.top() + 0.5, r.width() - 5, r.height() - 1.5);
        painter.setPen(Qt::NoPen);
        painter.setBrush(c.marker);
        painter.drawRoundedRect(pill, 2, 2);
        const QPointF pole[] = {{x - 4.5, double(r.top()) + 0.5}, {x + 0.5, double(r.top()) + 0.5}, {x + 0.5, double(RulerHeight)}};
        painter.drawPolygon(pole, 3);
        painter.setPen(c.markerText);
        painter.drawText(QRectF(x + 4, r.top(), m_markerWidths[std::size_t(i)] + 2, r.height()),
                         Qt::AlignLeft | Qt::AlignVCenter, m_markers[i].name);
    }

    // The playhead's handle.
    const int x = xForTime(m_playhead);
    if (x >= ruler.left() - 6 && x <= right + 6) {
        const QPointF handle[] = {{x - 5.5, 1.0}, {x + 6.5, 1.0}, {x + 6.5, 13.0}, {x + 0.5, double(RulerHeight)},
                                  {x - 5.5, 13.0}};
        painter.setPen(QPen(c.playhead.darker(140), 1.0));
        painter.setBrush(c.playhead);
        painter.drawPolygon(handle, 5);
    }
    painter.setRenderHint(QPainter::Antialiasing, false);
    painter.setPen(c.separator);
    painter.drawLine(ruler.left(), RulerHeight - 1, right, RulerHeight - 1);
    painter.setClipping(false);
}

} // namespace thespis::widgets
