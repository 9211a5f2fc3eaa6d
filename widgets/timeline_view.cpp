#include "widgets/timeline_view.h"

#include <QContextMenuEvent>
#include <QHelpEvent>
#include <QMenu>
#include <QScrollBar>
#include <QSet>
#include <QToolTip>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

namespace thespis::widgets {

namespace {

using M = TimelineMetrics;

constexpr double kMinPixelsPerSecond = 0.05;
constexpr double kMaxPixelsPerSecond = 50000.0;
constexpr qint64 kSecondSteps[] = {1, 2, 5, 10, 15, 30, 60, 120, 300, 600, 900, 1800, 3600, 7200};

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
    if (ticks < 1 || ticks == m_time.ticksPerSecond)
        return;
    m_time.ticksPerSecond = ticks;
    updateScrollRanges();
    viewport()->update();
}

void TimelineView::setFrameRate(int framesPerSecond)
{
    if (framesPerSecond < 1)
        return;
    m_time.frameRate = framesPerSecond;
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
    for (int i = 0; i < int(m_clips.size()); ++i)
        if (m_selected[std::size_t(i)])
            selected.insert(m_clips[i].id);
    m_clips = std::move(clips);
    m_selected.assign(std::size_t(m_clips.size()), 0);
    m_clipLabels.assign(std::size_t(m_clips.size()), ClipLabel{});
    m_idToIndex.clear();
    m_idToIndex.reserve(m_clips.size());
    m_clipsEnd = 0;
    qsizetype mostSamples = 0;
    for (int i = 0; i < int(m_clips.size()); ++i) {
        const TimelineClip& clip = m_clips[i];
        m_selected[std::size_t(i)] = selected.contains(clip.id);
        m_clipsEnd = std::max(m_clipsEnd, clip.end == OpenEnd ? clip.start : clip.end);
        mostSamples = std::max(mostSamples, clip.weight.size());
        m_idToIndex.insert(clip.id, i);
    }
    // The weight polyline needs at most one point per sample or per two pixels (plus the ends).
    m_points.reserve(std::size_t(std::max<qsizetype>(mostSamples + 2, 2048)));
    updateScrollRanges();
    viewport()->update();
}

const TimelineClip* TimelineView::clip(int id) const
{
    const int index = clipIndex(id);
    return index < 0 ? nullptr : &m_clips[index];
}

void TimelineView::setCaptions(QVector<TimelineCaption> captions)
{
    m_captions = std::move(captions);
    viewport()->update();
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
    for (int i = 0; i < int(m_clips.size()); ++i)
        if (m_selected[std::size_t(i)])
            ids.push_back(m_clips[i].id);
    std::sort(ids.begin(), ids.end());
    return ids;
}

void TimelineView::setSelectedClips(const QList<int>& ids)
{
    std::fill(m_selected.begin(), m_selected.end(), 0);
    for (int id : ids)
        if (const int index = clipIndex(id); index >= 0)
            m_selected[std::size_t(index)] = 1;
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
    const int available = viewport()->width() - HeaderWidth - 2 * M::TimePad - 16;
    if (available < 40) {
        m_frameAllPending = true; // no size yet: framed at the first resize
        return;
    }
    m_frameAllPending = false;
    qint64 end = std::max(m_duration, m_clipsEnd);
    for (const TimelineMarker& marker : std::as_const(m_markers))
        end = std::max(end, marker.time);
    if (end <= 0)
        end = 10 * m_time.ticksPerSecond;
    const double seconds = double(end) / double(m_time.ticksPerSecond);
    m_pixelsPerSecond = std::clamp(available / seconds, kMinPixelsPerSecond, kMaxPixelsPerSecond);
    updateScrollRanges();
    horizontalScrollBar()->setValue(0);
    viewport()->update();
}

void TimelineView::ensureTimeVisible(qint64 ticks)
{
    if (ticks == OpenEnd)
        return;
    const int lanesLeft = HeaderWidth + M::TimePad;
    const int lanesWidth = viewport()->width() - lanesLeft - M::TimePad;
    if (lanesWidth <= 0)
        return;
    const int x = xForTime(ticks);
    if (x >= lanesLeft && x <= lanesLeft + lanesWidth)
        return;
    const double seconds = double(ticks) / double(m_time.ticksPerSecond);
    horizontalScrollBar()->setValue(int(std::lround(seconds * m_pixelsPerSecond)) - lanesWidth / 10);
    viewport()->update();
}

// --- geometry -----------------------------------------------------------------------------------

TimelineGeometry TimelineView::geometry() const
{
    TimelineGeometry g;
    g.time = m_time;
    g.pixelsPerSecond = m_pixelsPerSecond;
    g.scroll = QPoint(horizontalScrollBar()->value(), verticalScrollBar()->value());
    g.viewport = viewport()->size();
    g.rows = &m_rows;
    g.tracks = std::span(m_tracks.constData(), std::size_t(m_tracks.size()));
    g.clips = std::span(m_clips.constData(), std::size_t(m_clips.size()));
    g.selected = m_selected;
    g.markers = std::span(m_markers.constData(), std::size_t(m_markers.size()));
    g.markerWidths = m_markerWidths;
    return g;
}

qint64 TimelineView::frameTime(qint64 frame) const
{
    return m_time.frameTime(frame);
}

qint64 TimelineView::roundToFrame(qint64 ticks) const
{
    return m_time.roundToFrame(ticks);
}

int TimelineView::xForTime(qint64 ticks) const
{
    return geometry().xForTime(ticks);
}

qint64 TimelineView::timeForX(int x) const
{
    return geometry().timeForX(x);
}

QRect TimelineView::rulerRect() const
{
    return geometry().rulerRect();
}

QRect TimelineView::trackRect(int track) const
{
    return geometry().trackRect(track);
}

QRect TimelineView::trackFlagRect(int track, TimelineTrackFlag flag) const
{
    return geometry().trackFlagRect(track, flag);
}

QRect TimelineView::clipRect(int id) const
{
    const int index = clipIndex(id);
    return index < 0 ? QRect() : geometry().clipRect(index);
}

QRect TimelineView::fadeHandleRect(int id, TimelineEdge edge) const
{
    const int index = clipIndex(id);
    return index < 0 ? QRect() : geometry().fadeHandleRect(index, edge);
}

QRect TimelineView::markerRect(int index) const
{
    return geometry().markerRect(index);
}

QSize TimelineView::sizeHint() const
{
    return {900, RulerHeight + 4 * TrackHeight + 2 * GroupHeight + 20};
}

QSize TimelineView::minimumSizeHint() const
{
    return {HeaderWidth + 120, RulerHeight + TrackHeight + 20};
}

void TimelineView::rebuildRows()
{
    m_rows = TimelineRows::layout(std::span(m_tracks.constData(), std::size_t(m_tracks.size())));
    m_rowLabels.assign(m_rows.rows.size(), QString());
    const QFontMetrics bold(m_boldFont);
    for (std::size_t i = 0; i < m_rows.rows.size(); ++i)
        if (const TimelineRow& row = m_rows.rows[i]; row.track < 0)
            m_rowLabels[i] = bold.elidedText(m_tracks[row.group].group, Qt::ElideRight, HeaderWidth - 16);
    // Track names elided to the room left of the flags; recomputed only when tracks or fonts change.
    m_trackElided.resize(std::size_t(m_tracks.size()));
    const int flagsLeft = HeaderWidth - M::FlagRight - 3 * M::FlagWidth - 2 * M::FlagGap;
    for (int i = 0; i < int(m_tracks.size()); ++i) {
        const int nameX = m_tracks[i].group.isEmpty() ? 10 : 22;
        m_trackElided[std::size_t(i)] = fontMetrics().elidedText(m_tracks[i].name, Qt::ElideRight, flagsLeft - 8 - nameX);
    }
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
    const double ticksPerPixel = double(m_time.ticksPerSecond) / m_pixelsPerSecond;
    const double contentWidth = M::TimePad + double(contentEndTime()) / ticksPerPixel + laneWidth / 2.0;
    QScrollBar* h = horizontalScrollBar();
    h->setRange(0, int(std::clamp(std::ceil(contentWidth) - laneWidth, 0.0, 1e9)));
    h->setPageStep(std::max(1, laneWidth));
    const int laneHeight = std::max(0, viewport()->height() - RulerHeight);
    QScrollBar* v = verticalScrollBar();
    v->setRange(0, std::max(0, m_rows.contentHeight() - laneHeight));
    v->setPageStep(std::max(1, laneHeight));
}

qint64 TimelineView::clampSeek(qint64 ticks) const
{
    ticks = std::max<qint64>(0, ticks);
    return m_duration > 0 ? std::min(ticks, m_duration) : ticks;
}

TimelineView::Steps TimelineView::rulerSteps() const
{
    const double pixelsPerFrame = m_pixelsPerSecond / m_time.frameRate;
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

void TimelineView::buildSnapTargets(std::span<const char> excludeClips, int excludeMarker, bool includePlayhead)
{
    const TimelineGeometry g = geometry();
    m_snapTargets.collect(g.clips, excludeClips, g.markers, excludeMarker, m_duration,
                          includePlayhead ? std::optional<qint64>(m_playhead) : std::nullopt);
}

qint64 TimelineView::snapTime(qint64 ticks, bool bypass)
{
    m_snapLine = -1;
    if (!m_snapping || bypass)
        return ticks;
    const TimelineSnap snap = m_snapTargets.snapTime(ticks, timelineSnapThreshold(geometry().ticksPerPixel()), m_time);
    m_snapLine = snap.target;
    return snap.value;
}

qint64 TimelineView::snapDelta(qint64 delta, qint64 anchor, bool bypass)
{
    m_snapLine = -1;
    if (!m_snapping || bypass)
        return delta;
    const TimelineSnap snap = m_snapTargets.snapDelta(delta, m_drag.edges, anchor,
                                                      timelineSnapThreshold(geometry().ticksPerPixel()), m_time);
    m_snapLine = snap.target;
    return snap.value;
}

// --- selection ----------------------------------------------------------------------------------

void TimelineView::setSelectionFlags(const std::vector<char>& flags)
{
    for (std::size_t i = 0; i < m_selected.size() && i < flags.size(); ++i)
        m_selected[i] = flags[i];
}

void TimelineView::emitSelectionIfChanged(const std::vector<char>& before)
{
    if (before != m_selected)
        emit selectionChanged(selectedClips());
    viewport()->update();
}

void TimelineView::selectOnly(int index)
{
    for (int i = 0; i < int(m_selected.size()); ++i)
        m_selected[std::size_t(i)] = i == index;
}

// --- wheel, menus, tooltips ---------------------------------------------------------------------

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
        const double anchorSeconds = (x - geometry().originX()) / m_pixelsPerSecond;
        m_pixelsPerSecond = std::clamp(m_pixelsPerSecond * std::pow(2.0, delta / 480.0), kMinPixelsPerSecond,
                                       kMaxPixelsPerSecond);
        updateScrollRanges();
        horizontalScrollBar()->setValue(int(std::lround(anchorSeconds * m_pixelsPerSecond - (x - HeaderWidth - M::TimePad))));
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

void TimelineView::contextMenuEvent(QContextMenuEvent* event)
{
    const QPoint pos = event->pos();
    const TimelineHit hit = geometry().hitTest(pos);
    if (hit.kind != TimelineHitKind::Marker && hit.kind != TimelineHitKind::Ruler) {
        event->ignore();
        return;
    }
    QMenu menu(this);
    if (hit.kind == TimelineHitKind::Marker) {
        const int marker = hit.marker;
        connect(menu.addAction(tr("Remove Marker “%1”").arg(m_markers[marker].name)), &QAction::triggered, this,
                [this, marker] { emit markerRemoveRequested(marker); });
    }
    buildSnapTargets({}, -1, true);
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
        const TimelineGeometry g = geometry();
        const TimelineHit hit = g.hitTest(help->pos());
        QString text;
        if (hit.clip >= 0 && hit.kind != TimelineHitKind::Lane) {
            const TimelineClip& c = m_clips[hit.clip];
            text = c.end == OpenEnd ? tr("%1\n%2 – open end").arg(c.name, m_time.format(c.start))
                                    : tr("%1\n%2 – %3 (%4)").arg(c.name, m_time.format(c.start), m_time.format(c.end),
                                                                 m_time.format(c.end - c.start));
            if (g.trackLocked(c.track))
                text += QLatin1Char('\n') + tr("The track is locked");
        } else if (hit.kind == TimelineHitKind::Flag) {
            switch (hit.flag) {
            case TimelineTrackFlag::Mute: text = tr("Mute: leave this track out of playback"); break;
            case TimelineTrackFlag::Solo: text = tr("Solo: play only the soloed tracks"); break;
            case TimelineTrackFlag::Lock: text = tr("Lock: protect this track's clips from edits"); break;
            }
        } else if (hit.kind == TimelineHitKind::Marker) {
            text = tr("%1 at %2").arg(m_markers[hit.marker].name, m_time.format(m_markers[hit.marker].time));
        }
        if (text.isEmpty())
            QToolTip::hideText();
        else
            QToolTip::showText(help->globalPos(), text, viewport());
        return true;
    }
    if (event->type() == QEvent::Leave && m_drag.mode == TimelineDragMode::None)
        viewport()->unsetCursor();
    return QAbstractScrollArea::viewportEvent(event);
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
    for (ClipLabel& label : m_clipLabels)
        label.width = -1;
    for (qsizetype i = 0; i < m_markers.size(); ++i)
        m_markerWidths[std::size_t(i)] = m_smallMetrics.horizontalAdvance(m_markers[i].name);
    rebuildRows();
    viewport()->update();
}

} // namespace thespis::widgets
