// TimelineView's gestures: the press / move / release state machine (clip moves, trims, fades,
// scrubs, marker moves, rubber band), the keys that cancel it, and drops from the clip library or
// the file manager. Also the pure rule for a clip drag's track offset.

#include "widgets/timeline_view.h"

#include <QApplication>
#include <QDragEnterEvent>
#include <QDragLeaveEvent>
#include <QDragMoveEvent>
#include <QDropEvent>
#include <QFileInfo>
#include <QKeyEvent>
#include <QMimeData>
#include <QMouseEvent>

#include <algorithm>
#include <cstdlib>
#include <limits>

#include "widgets/dropped_files.h"

namespace thespis::widgets {

namespace {

constexpr int kDragThreshold = 3; // Manhattan pixels before a press becomes a drag

bool acceptsDrop(const QMimeData* mime)
{
    return mime && (mime->hasFormat(QLatin1String(TimelineView::ClipMimeType)) ||
                    mime->hasFormat(QLatin1String(TimelineView::SynthesizerMimeType)) || !droppedFiles(mime).isEmpty());
}

// What a drop is called while it is dragged over the lanes.
QString dropName(const QMimeData* mime)
{
    if (const QStringList files = droppedFiles(mime); !files.isEmpty())
        return QFileInfo(files.front()).completeBaseName();
    if (mime->hasFormat(QLatin1String(TimelineView::SynthesizerMimeType)))
        return QString::fromUtf8(mime->data(QLatin1String(TimelineView::SynthesizerMimeType)));
    return QString::fromUtf8(mime->data(QLatin1String(TimelineView::ClipMimeType)));
}

} // namespace

bool trackOffsetFits(std::span<const TimelineTrack> tracks, std::span<const TimelineClip> moving, int offset)
{
    if (offset == 0)
        return true;
    const int count = int(tracks.size());
    for (const TimelineClip& c : moving) {
        const int to = c.track + offset;
        if (c.track < 0 || c.track >= count || to < 0 || to >= count)
            return false;
        const TimelineTrack& from = tracks[std::size_t(c.track)];
        const TimelineTrack& target = tracks[std::size_t(to)];
        if (target.locked || target.group != from.group || target.kind != from.kind)
            return false;
    }
    return true;
}

int clipDragTrackOffset(const TimelineGeometry& geometry, std::span<const TimelineClip> moving, int origTrack, int y)
{
    const int count = int(geometry.tracks.size());
    if (origTrack < 0 || origTrack >= count)
        return 0;
    // The track whose lane centre is nearest to the mouse (also over group rows, above and below
    // the tracks), then the offset nearest to it (the nearer to 0 on a tie) at which every clip fits.
    int under = origTrack, nearest = std::numeric_limits<int>::max();
    for (int i = 0; i < count; ++i)
        if (const int d = std::abs(y - (geometry.trackY(i) + TimelineMetrics::TrackHeight / 2)); d < nearest) {
            nearest = d;
            under = i;
        }
    const int wanted = under - origTrack;
    int best = 0;
    for (int offset = -count; offset <= count; ++offset) {
        const int distance = std::abs(offset - wanted), bestDistance = std::abs(best - wanted);
        if ((distance < bestDistance || (distance == bestDistance && std::abs(offset) < std::abs(best)))
            && trackOffsetFits(geometry.tracks, moving, offset))
            best = offset;
    }
    return best;
}

// --- hover --------------------------------------------------------------------------------------

void TimelineView::updateHoverCursor(const QPoint& pos)
{
    const TimelineGeometry g = geometry();
    const TimelineHit hit = g.hitTest(pos);
    Qt::CursorShape shape = Qt::ArrowCursor;
    switch (hit.kind) {
    case TimelineHitKind::StartEdge:
    case TimelineHitKind::EndEdge:
    case TimelineHitKind::FadeIn:
    case TimelineHitKind::FadeOut:
        if (!g.trackLocked(hit.track))
            shape = Qt::SizeHorCursor;
        break;
    case TimelineHitKind::Marker: shape = Qt::SizeHorCursor; break;
    case TimelineHitKind::Flag: shape = Qt::PointingHandCursor; break;
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
    const TimelineHit hit = geometry().hitTest(pos);
    m_drag = TimelineDrag{};
    m_drag.pressPos = pos;
    switch (hit.kind) {
    case TimelineHitKind::Ruler: {
        m_drag.mode = TimelineDragMode::Scrub;
        m_drag.active = true; // a scrub follows the mouse from the first pixel
        buildSnapTargets({}, -1, false);
        m_drag.last = clampSeek(snapTime(timeForX(pos.x()), bypass));
        emit seekRequested(m_drag.last);
        break;
    }
    case TimelineHitKind::Marker:
        m_drag.mode = TimelineDragMode::Marker;
        m_drag.marker = hit.marker;
        m_drag.origValue = m_drag.last = m_markers[hit.marker].time;
        buildSnapTargets({}, hit.marker, true);
        break;
    case TimelineHitKind::Flag:
        emit trackFlagRequested(hit.track, hit.flag, !trackFlagValue(m_tracks[hit.track], hit.flag));
        break;
    case TimelineHitKind::Lane: {
        m_drag.mode = TimelineDragMode::RubberBand;
        m_drag.pressSelection = m_selected;
        if (modifiers & (Qt::ShiftModifier | Qt::ControlModifier))
            m_drag.baseSelection = m_drag.pressSelection;
        else
            m_drag.baseSelection.assign(m_drag.pressSelection.size(), 0); // a click on empty space clears
        setSelectionFlags(m_drag.baseSelection);
        break;
    }
    case TimelineHitKind::Body:
    case TimelineHitKind::StartEdge:
    case TimelineHitKind::EndEdge:
    case TimelineHitKind::FadeIn:
    case TimelineHitKind::FadeOut: beginClipPress(hit, pos, modifiers); break;
    case TimelineHitKind::None:
    case TimelineHitKind::Corner:
    case TimelineHitKind::Header: break;
    }
    viewport()->update();
}

void TimelineView::beginClipPress(const TimelineHit& hit, const QPoint& pos, Qt::KeyboardModifiers modifiers)
{
    const TimelineClip& clip = m_clips[hit.clip];
    m_drag.pressPos = pos;
    m_drag.clip = hit.clip;
    m_drag.clipId = clip.id;
    m_drag.origStart = clip.start;
    m_drag.origEnd = clip.end;
    m_drag.locked = geometry().trackLocked(clip.track);

    // Selection: a press on an unselected clip selects it (alone, or added with Shift/Ctrl); a
    // press on a selected clip keeps the selection for a drag and decides on release.
    const std::vector<char> before = m_selected;
    char& selected = m_selected[std::size_t(hit.clip)];
    if (modifiers & (Qt::ShiftModifier | Qt::ControlModifier)) {
        if (selected)
            m_drag.toggleOnRelease = true;
        else
            selected = 1;
    } else if (!selected) {
        selectOnly(hit.clip);
    } else {
        m_drag.selectOnlyOnRelease = true;
    }
    emitSelectionIfChanged(before);

    const TimelineGeometry g = geometry(); // after the signal, which may have changed the content
    switch (hit.kind) {
    case TimelineHitKind::Body: {
        m_drag.mode = TimelineDragMode::Clip;
        std::vector<char> moving(std::size_t(m_clips.size()), 0);
        m_drag.minStart = std::numeric_limits<qint64>::max();
        for (int i = 0; i < int(m_clips.size()); ++i) {
            const TimelineClip& c = m_clips[i];
            if (!m_selected[std::size_t(i)] || g.trackLocked(c.track))
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
        m_drag.origTrack = clip.track;
        buildSnapTargets(moving, -1, true);
        break;
    }
    case TimelineHitKind::StartEdge:
    case TimelineHitKind::EndEdge: {
        const bool start = hit.kind == TimelineHitKind::StartEdge;
        m_drag.mode = start ? TimelineDragMode::TrimStart : TimelineDragMode::TrimEnd;
        m_drag.origValue = m_drag.last = start ? clip.start : clip.end;
        std::vector<char> self(std::size_t(m_clips.size()), 0);
        self[std::size_t(hit.clip)] = 1;
        buildSnapTargets(self, -1, true);
        break;
    }
    default: {
        const bool in = hit.kind == TimelineHitKind::FadeIn;
        m_drag.mode = in ? TimelineDragMode::FadeIn : TimelineDragMode::FadeOut;
        m_drag.origValue = m_drag.last = in ? clip.fadeIn : clip.fadeOut;
        buildSnapTargets({}, -1, true); // the clip's own edges attract: fades snap back to 0
        break;
    }
    }
}

void TimelineView::updateDrag(const QPoint& pos, Qt::KeyboardModifiers modifiers, bool finished)
{
    const bool bypass = modifiers & Qt::ControlModifier;
    const TimelineGeometry g = geometry();
    const qint64 raw = g.ticksForPixels(pos.x() - m_drag.pressPos.x());
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
    case TimelineDragMode::Scrub: {
        const qint64 t = clampSeek(snapTime(g.timeForX(pos.x()), bypass));
        if (t != m_drag.last) {
            m_drag.last = t;
            emit seekRequested(t);
        }
        break;
    }
    case TimelineDragMode::Marker: {
        const qint64 t = std::max<qint64>(0, snapTime(m_drag.origValue + raw, bypass));
        request(t, [&](qint64 v, bool done) { emit markerMoveRequested(m_drag.marker, v, done); });
        break;
    }
    case TimelineDragMode::Clip: {
        if (m_drag.locked || m_drag.ids.isEmpty())
            break;
        qint64 delta = snapDelta(raw, m_drag.origStart, bypass);
        if (delta < -m_drag.minStart) { // no clip goes before 0
            delta = -m_drag.minStart;
            m_snapLine = -1;
        }
        const int tracks = clipDragTrackOffset(g, m_drag.moving, m_drag.origTrack, pos.y());
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
    case TimelineDragMode::TrimStart: {
        if (m_drag.locked)
            break;
        qint64 t = std::max<qint64>(0, snapTime(m_drag.origStart + raw, bypass));
        if (!openEnd)
            t = std::min(t, m_drag.origEnd - frame);
        request(t, [&](qint64 v, bool done) { emit clipTrimRequested(m_drag.clipId, TimelineEdge::Start, v, done); });
        break;
    }
    case TimelineDragMode::TrimEnd: {
        if (m_drag.locked)
            break;
        const qint64 t = std::max(snapTime(m_drag.origEnd + raw, bypass), m_drag.origStart + frame);
        request(t, [&](qint64 v, bool done) { emit clipTrimRequested(m_drag.clipId, TimelineEdge::End, v, done); });
        break;
    }
    case TimelineDragMode::FadeIn: {
        if (m_drag.locked)
            break;
        const qint64 handle = snapTime(m_drag.origStart + m_drag.origValue + raw, bypass);
        const qint64 fade = std::clamp<qint64>(handle - m_drag.origStart, 0, length);
        request(fade, [&](qint64 v, bool done) { emit clipFadeRequested(m_drag.clipId, TimelineEdge::Start, v, done); });
        break;
    }
    case TimelineDragMode::FadeOut: {
        if (m_drag.locked || openEnd)
            break;
        const qint64 handle = snapTime(m_drag.origEnd - m_drag.origValue + raw, bypass);
        const qint64 fade = std::clamp<qint64>(m_drag.origEnd - handle, 0, length);
        request(fade, [&](qint64 v, bool done) { emit clipFadeRequested(m_drag.clipId, TimelineEdge::End, v, done); });
        break;
    }
    case TimelineDragMode::None:
    case TimelineDragMode::RubberBand: break;
    }
}

void TimelineView::updateRubberBand(const QPoint& pos)
{
    const TimelineGeometry g = geometry();
    const QRect lanes(HeaderWidth, RulerHeight, viewport()->width() - HeaderWidth, viewport()->height() - RulerHeight);
    m_drag.band = QRect(m_drag.pressPos, pos).normalized().intersected(lanes);
    m_drag.baseSelection.resize(m_selected.size(), 0); // the editor may have replaced the clips
    for (int i = 0; i < int(m_clips.size()); ++i) {
        const QRect r = g.clipRect(i);
        m_selected[std::size_t(i)] = m_drag.baseSelection[std::size_t(i)] || (!r.isNull() && r.intersects(m_drag.band));
    }
}

void TimelineView::mouseMoveEvent(QMouseEvent* event)
{
    const QPoint pos = event->position().toPoint();
    if (m_drag.mode == TimelineDragMode::None) {
        updateHoverCursor(pos);
        return;
    }
    if (!m_drag.active) {
        if ((pos - m_drag.pressPos).manhattanLength() < kDragThreshold)
            return;
        m_drag.active = true;
    }
    if (m_drag.mode == TimelineDragMode::RubberBand)
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
    case TimelineDragMode::RubberBand:
        if (m_drag.active)
            updateRubberBand(pos);
        emitSelectionIfChanged(m_drag.pressSelection);
        break;
    case TimelineDragMode::Clip:
    case TimelineDragMode::TrimStart:
    case TimelineDragMode::TrimEnd:
    case TimelineDragMode::FadeIn:
    case TimelineDragMode::FadeOut:
        if (m_drag.active) {
            updateDrag(pos, event->modifiers(), true);
        } else if (const int index = clipIndex(m_drag.clipId); index >= 0) {
            // A click without a drag: Shift/Ctrl toggles a selected clip off, a plain click
            // narrows the selection to the clip.
            const std::vector<char> before = m_selected;
            if (m_drag.toggleOnRelease)
                m_selected[std::size_t(index)] = 0;
            else if (m_drag.selectOnlyOnRelease)
                selectOnly(index);
            emitSelectionIfChanged(before);
        }
        break;
    case TimelineDragMode::Scrub:
    case TimelineDragMode::Marker:
        if (m_drag.active)
            updateDrag(pos, event->modifiers(), true);
        break;
    case TimelineDragMode::None: break;
    }
    m_drag = TimelineDrag{};
    m_snapLine = -1;
    updateHoverCursor(pos);
    viewport()->update();
}

void TimelineView::mouseDoubleClickEvent(QMouseEvent* event)
{
    if (event->button() != Qt::LeftButton)
        return;
    const QPoint pos = event->position().toPoint();
    const TimelineHit hit = geometry().hitTest(pos);
    if (hit.kind == TimelineHitKind::Ruler) {
        buildSnapTargets({}, -1, true);
        emit markerAddRequested(std::max<qint64>(0, snapTime(timeForX(pos.x()), event->modifiers() & Qt::ControlModifier)));
        m_snapLine = -1;
    } else if (hit.clip >= 0 && hit.kind != TimelineHitKind::Lane) {
        emit clipActivated(m_clips[hit.clip].id);
    }
}

// --- keys ---------------------------------------------------------------------------------------

bool TimelineView::event(QEvent* event)
{
    // Keep Ctrl+A, M (and Escape, Undo and Redo during a drag) for the timeline while it has
    // focus, even if a window action uses them: an undo under a drag would pull the document
    // from under the drag's next steps.
    if (event->type() == QEvent::ShortcutOverride) {
        auto* key = static_cast<QKeyEvent*>(event);
        if (key->matches(QKeySequence::SelectAll)
            || (key->key() == Qt::Key_M && !(key->modifiers() & ~Qt::KeypadModifier))
            || (m_drag.mode != TimelineDragMode::None
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
        case TimelineDragMode::Clip: emit clipsMoveRequested(m_drag.ids, 0, 0, true); break;
        case TimelineDragMode::TrimStart:
            emit clipTrimRequested(m_drag.clipId, TimelineEdge::Start, m_drag.origValue, true);
            break;
        case TimelineDragMode::TrimEnd: emit clipTrimRequested(m_drag.clipId, TimelineEdge::End, m_drag.origValue, true); break;
        case TimelineDragMode::FadeIn: emit clipFadeRequested(m_drag.clipId, TimelineEdge::Start, m_drag.origValue, true); break;
        case TimelineDragMode::FadeOut: emit clipFadeRequested(m_drag.clipId, TimelineEdge::End, m_drag.origValue, true); break;
        case TimelineDragMode::Marker: emit markerMoveRequested(m_drag.marker, m_drag.origValue, true); break;
        default: break;
        }
    }
    if (m_drag.mode == TimelineDragMode::RubberBand)
        setSelectionFlags(m_drag.pressSelection);
    m_drag = TimelineDrag{};
    m_snapLine = -1;
    viewport()->update();
}

void TimelineView::keyPressEvent(QKeyEvent* event)
{
    if (m_drag.mode != TimelineDragMode::None) {
        if (event->key() == Qt::Key_Escape || event->matches(QKeySequence::Undo)) {
            cancelDrag();
            return;
        }
        if (event->matches(QKeySequence::Redo))
            return; // nothing to redo while the drag's own edit is open
    }
    if (event->matches(QKeySequence::SelectAll)) {
        const std::vector<char> before = m_selected;
        std::fill(m_selected.begin(), m_selected.end(), 1);
        emitSelectionIfChanged(before);
        return;
    }
    if (event->key() == Qt::Key_M && !(event->modifiers() & ~Qt::KeypadModifier)) {
        emit markerAddRequested(m_playhead);
        return;
    }
    QAbstractScrollArea::keyPressEvent(event);
}

// --- drop ---------------------------------------------------------------------------------------

bool TimelineView::updateDrop(const QPoint& pos, Qt::KeyboardModifiers modifiers)
{
    const TimelineGeometry g = geometry();
    const int track = g.trackAtY(pos.y());
    const bool valid = pos.x() >= HeaderWidth && track >= 0 && !g.trackLocked(track);
    m_dropActive = valid;
    if (valid) {
        m_dropTrack = track;
        m_dropTime = std::max<qint64>(0, snapTime(g.timeForX(pos.x()), modifiers & Qt::ControlModifier));
    }
    viewport()->update();
    return valid;
}

void TimelineView::dragEnterEvent(QDragEnterEvent* event)
{
    if (!acceptsDrop(event->mimeData())) {
        event->ignore();
        return;
    }
    m_dropName = dropName(event->mimeData());
    buildSnapTargets({}, -1, true);
    updateDrop(event->position().toPoint(), event->modifiers());
    event->acceptProposedAction(); // accepted even over the header, so that moves keep coming
}

void TimelineView::dragMoveEvent(QDragMoveEvent* event)
{
    if (!acceptsDrop(event->mimeData())) {
        event->ignore();
        return;
    }
    if (updateDrop(event->position().toPoint(), event->modifiers()))
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
    if (ours && updateDrop(event->position().toPoint(), event->modifiers())) {
        event->acceptProposedAction();
        const QMimeData* mime = event->mimeData();
        if (const QStringList files = droppedFiles(mime); !files.isEmpty())
            emit filesDropRequested(m_dropTrack, m_dropTime, files);
        else if (mime->hasFormat(QLatin1String(SynthesizerMimeType)))
            emit synthesizerDropRequested(m_dropTrack, m_dropTime,
                                          QString::fromUtf8(mime->data(QLatin1String(SynthesizerMimeType))));
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

} // namespace thespis::widgets
