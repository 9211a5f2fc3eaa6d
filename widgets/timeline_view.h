#pragma once
// TimelineView: the scenario's timeline — a header column with one row per track (grouped under
// their character, with Mute / Solo / Lock toggles), a ruler with seconds, frames, markers and the
// playhead, and the clips of every track as rounded bars with fade ramps and a weight thumbnail.
// A pure view: it knows nothing of core. The editor feeds tracks, clips and markers through the
// setters (which emit nothing) and turns the intent signals (…Requested) into undoable commands;
// the view never moves a clip itself. Drags report the total change since the press, after
// snapping, with finished = false while the mouse moves and one finished = true on release.
// Time is integer ticks (qint64) so that snapping to frames, clip edges and markers is exact.
// Owns a copy of what it shows plus small caches (elided names) so that painting does not
// allocate.
//
// It is a QAbstractScrollArea: the scroll bars are the area's own, every geometry (clipRect(),
// xForTime(), …) is in viewport() coordinates, and the mouse, wheel and drop events are those of
// the viewport. The header column and the ruler stay put while the lanes scroll.
//
// Gestures: drag a clip's body to move the selection in time and, up or down, to other tracks of
// each clip's own group and kind (clips on locked tracks stay; a ghost shows where they land until
// the editor has moved them there), within
// EdgeGrip px of an edge to trim, a handle on the top border to change a fade; click selects,
// Shift/Ctrl+click toggles, a drag on empty lane space is a rubber band; the ruler scrubs; M adds
// a marker at the playhead; Ctrl+wheel zooms about the mouse, Shift+wheel pans, the wheel scrolls
// the tracks; Escape or Undo's keys (Ctrl+Z) during a drag ask back what it requested, and Redo's
// do nothing until the drag ends, so no window action edits under the drag. Clips on locked tracks can be
// selected (to inspect them) but emit no move, trim or fade.
//
// Files: pure geometry and hit testing in timeline_geometry.h, snapping in timeline_snapping.h,
// gestures and drops in timeline_drag.cpp, painting in timeline_view_paint.cpp.

#include <QAbstractScrollArea>
#include <QBrush>
#include <QColor>
#include <QFont>
#include <QFontMetrics>
#include <QHash>
#include <QLine>
#include <QList>
#include <QPen>
#include <QPointF>
#include <QRect>
#include <QStaticText>
#include <QString>
#include <QVector>

#include <vector>

#include "widgets/timeline_drag.h"
#include "widgets/timeline_geometry.h"
#include "widgets/timeline_snapping.h"
#include "widgets/timeline_types.h"

class QMimeData;
class QPainter;

namespace thespis::widgets {

class TimelineView : public QAbstractScrollArea {
    Q_OBJECT
public:
    static constexpr qint64 OpenEnd = TimelineOpenEnd;
    /// Mime type of a clip dragged in from a library; the data is the clip name in UTF-8.
    static constexpr const char* ClipMimeType = "application/x-thespis-clip";
    /// Mime type of a motion synthesizer dragged in from a library ("idle"): it makes its clip
    /// when dropped; the data is the synthesizer's kind in UTF-8.
    static constexpr const char* SynthesizerMimeType = "application/x-thespis-synthesizer";

    // Layout, in pixels (public so that tests and the editor can reason about it).
    static constexpr int HeaderWidth = TimelineMetrics::HeaderWidth;   ///< the track header column on the left
    static constexpr int RulerHeight = TimelineMetrics::RulerHeight;   ///< the time ruler on top
    static constexpr int TrackHeight = TimelineMetrics::TrackHeight;   ///< one track's lane
    static constexpr int GroupHeight = TimelineMetrics::GroupHeight;   ///< a character's header row above its tracks
    static constexpr int EdgeGrip = TimelineMetrics::EdgeGrip;         ///< a press this close to a clip's edge trims it
    static constexpr int SnapDistance = TimelineMetrics::SnapDistance; ///< snap targets this close (on screen) attract

    explicit TimelineView(QWidget* parent = nullptr);
    ~TimelineView() override;

    /// Ticks per second (default 705,600,000); values below 1 are ignored.
    void setTicksPerSecond(qint64 ticks);
    qint64 ticksPerSecond() const { return m_time.ticksPerSecond; }
    /// Frames per second for snapping, frame ticks and time labels (default 30); below 1 is ignored.
    void setFrameRate(int framesPerSecond);
    int frameRate() const { return m_time.frameRate; }

    void setTracks(QVector<TimelineTrack> tracks);
    const QVector<TimelineTrack>& tracks() const { return m_tracks; }
    /// Replaces every clip; the selection keeps the ids that are still present.
    void setClips(QVector<TimelineClip> clips);
    int clipCount() const { return int(m_clips.size()); }
    const TimelineClip* clip(int id) const;
    void setMarkers(QVector<TimelineMarker> markers);
    const QVector<TimelineMarker>& markers() const { return m_markers; }
    /// Words shown along the bottom of their tracks, over the clips (a speech line's words under
    /// its visemes).
    void setCaptions(QVector<TimelineCaption> captions);
    const QVector<TimelineCaption>& captions() const { return m_captions; }
    /// The scenario's length: drawn as the end of the active area, part of the scroll range.
    void setDuration(qint64 ticks);
    qint64 duration() const { return m_duration; }
    void setPlayhead(qint64 ticks);
    qint64 playhead() const { return m_playhead; }

    /// Snapping on (default): dragged edges, fades, markers, scrubs and drops land on whole frames
    /// and are attracted by clip edges, markers and the playhead within SnapDistance pixels.
    /// Holding Ctrl during a gesture bypasses it.
    void setSnapping(bool on);
    bool snapping() const { return m_snapping; }

    /// Ids of the selected clips, ascending.
    QList<int> selectedClips() const;
    /// Emits nothing; unknown ids are ignored.
    void setSelectedClips(const QList<int>& ids);

    /// Horizontal zoom; keeps the time at the left edge of the lanes in place.
    void setPixelsPerSecond(double zoom);
    double pixelsPerSecond() const { return m_pixelsPerSecond; }
    /// Zooms so that 0..duration (or the last clip end or marker, if later) fits the lanes, and
    /// scrolls to 0. Before the view has a size, this happens at its first resize.
    void frameAll();
    /// When `ticks` is outside the visible lanes, scrolls so that it sits a tenth of the lanes'
    /// width from the left (a playing playhead turns the page); otherwise does nothing.
    void ensureTimeVisible(qint64 ticks);

    // Geometry, in viewport() coordinates (tests drive the mouse with these).
    /// The clip's bar; an open-ended clip runs to the right edge of the viewport. Null if unknown.
    QRect clipRect(int id) const;
    /// The draggable fade handle at start + fadeIn (Start) or end − fadeOut (End). Null if the
    /// clip is unknown, or End for an open-ended clip.
    QRect fadeHandleRect(int id, TimelineEdge edge) const;
    int xForTime(qint64 ticks) const;
    qint64 timeForX(int x) const;
    QRect trackRect(int track) const;                             ///< the lane, right of the header
    QRect trackFlagRect(int track, TimelineTrackFlag flag) const; ///< the M/S/L toggle in the header
    QRect rulerRect() const;                                      ///< right of the top-left corner
    /// The marker's flag (and name) in the ruler; null if there is no such marker.
    QRect markerRect(int index) const;

    /// Time arithmetic used for snapping, exact in ticks: frame `frame`'s start, and the frame
    /// boundary nearest to `ticks`.
    qint64 frameTime(qint64 frame) const;
    qint64 roundToFrame(qint64 ticks) const;

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

signals:
    /// The user changed the selection (click, Shift/Ctrl+click, rubber band, Ctrl+A).
    void selectionChanged(const QList<int>& ids);
    /// Drag of selected clip bodies: delta = total time since the press, after snapping (clamped so
    /// no clip starts before 0); trackDelta = how many tracks down (up when negative) the clips go,
    /// from the track under the mouse, the nearest offset at which every clip lands on an unlocked
    /// track of its own group and kind (0 when there is none). Clips on locked tracks are never among
    /// the ids, and the ids are those at the press for the whole drag. Emitted with finished = false
    /// whenever delta or trackDelta changes, then once with finished = true on release if anything
    /// was requested (a release without movement emits nothing). Escape (or Ctrl+Z) during a drag asks back:
    /// one finished request with delta 0 and trackDelta 0 (or the original time / length below).
    void clipsMoveRequested(const QList<int>& ids, qint64 delta, int trackDelta, bool finished);
    /// Drag of a clip's edge: the new start or end time (the clip keeps at least one frame).
    void clipTrimRequested(int id, thespis::widgets::TimelineEdge edge, qint64 time, bool finished);
    /// Drag of a fade handle: the new fadeIn / fadeOut length, clamped to [0, clip length].
    void clipFadeRequested(int id, thespis::widgets::TimelineEdge edge, qint64 length, bool finished);
    /// Press or drag in the ruler (scrub), continuous while dragging; within [0, duration].
    void seekRequested(qint64 ticks);
    void trackFlagRequested(int track, thespis::widgets::TimelineTrackFlag flag, bool on);
    /// 'M' (at the playhead) or a double-click in the ruler (at the snapped time).
    void markerAddRequested(qint64 time);
    void markerMoveRequested(int index, qint64 time, bool finished);
    /// "Remove Marker" in the marker's context menu.
    void markerRemoveRequested(int index);
    /// A drop of ClipMimeType data on a lane that is not locked, at the snapped time.
    void clipDropRequested(int track, qint64 time, const QString& clipName);
    /// A drop of SynthesizerMimeType data on a lane that is not locked, at the snapped time.
    void synthesizerDropRequested(int track, qint64 time, const QString& kind);
    /// Files dropped from the file manager on a lane that is not locked, at the snapped time.
    void filesDropRequested(int track, qint64 time, const QStringList& files);
    /// Double-click on a clip.
    void clipActivated(int id);

protected:
    void paintEvent(QPaintEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void scrollContentsBy(int dx, int dy) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void mouseDoubleClickEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void contextMenuEvent(QContextMenuEvent* event) override;
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dragMoveEvent(QDragMoveEvent* event) override;
    void dragLeaveEvent(QDragLeaveEvent* event) override;
    void dropEvent(QDropEvent* event) override;
    void changeEvent(QEvent* event) override;
    bool event(QEvent* event) override;
    bool viewportEvent(QEvent* event) override;

private:
    struct ClipLabel {
        QStaticText text; // the clip's name elided to width, laid out once, kept between paints
        int width = -1;
    };
    struct Colors {
        QColor lane, laneAlt, group, header, headerText, headerDim, separator, ruler, rulerText, rulerTick,
            gridMajor, gridMinor, outside, clip, clipBorder, clipSelected, clipSelectedBorder, clipText,
            clipSelectedText, fadeShade, fadeLine, weightLine, weightFill, handle, playhead, marker,
            markerText, snap, band, bandBorder, flagOff, flagOffText, mute, solo, lock, flagOnText;
        QBrush lockedHatch;
        bool dark = true;
    };
    struct Steps {
        qint64 major = 0, minor = 0; // in frames; minor 0: none
    };

    // Layout (timeline_view.cpp)
    /// Where everything is now: the view's content at its zoom, scroll and size.
    TimelineGeometry geometry() const;
    void rebuildRows();
    void updateScrollRanges();
    void updateFonts();
    qint64 contentEndTime() const;
    bool trackDimmed(int track) const;
    int clipIndex(int id) const { return m_idToIndex.value(id, -1); }
    qint64 clampSeek(qint64 ticks) const;
    Steps rulerSteps() const;

    // Selection (timeline_view.cpp)
    void selectOnly(int index);
    void setSelectionFlags(const std::vector<char>& flags);
    void emitSelectionIfChanged(const std::vector<char>& before);

    // Gestures and drops (timeline_drag.cpp)
    void updateHoverCursor(const QPoint& pos);
    void beginClipPress(const TimelineHit& hit, const QPoint& pos, Qt::KeyboardModifiers modifiers);
    void updateDrag(const QPoint& pos, Qt::KeyboardModifiers modifiers, bool finished);
    void updateRubberBand(const QPoint& pos);
    void cancelDrag();
    bool updateDrop(const QPoint& pos, Qt::KeyboardModifiers modifiers);

    // Snapping: collects the gesture's targets; snapTime() and snapDelta() set m_snapLine.
    void buildSnapTargets(std::span<const char> excludeClips, int excludeMarker, bool includePlayhead);
    qint64 snapTime(qint64 ticks, bool bypass);
    qint64 snapDelta(qint64 delta, qint64 anchor, bool bypass);

    // Painting (timeline_view_paint.cpp)
    void updateColors();
    void paintLanes(QPainter& painter, const TimelineGeometry& g);
    void paintClips(QPainter& painter, const TimelineGeometry& g);
    void paintCaptions(QPainter& painter, const TimelineGeometry& g);
    void paintClip(QPainter& painter, const TimelineGeometry& g, int index, const QRect& rect, bool dimmed,
                   bool locked, int laneRight);
    void paintOverlays(QPainter& painter, const TimelineGeometry& g);
    void paintMoveGhosts(QPainter& painter, const TimelineGeometry& g);
    void paintGhost(QPainter& painter, const QRect& rect, const QString& name);
    void paintHeader(QPainter& painter, const TimelineGeometry& g);
    void paintRuler(QPainter& painter, const TimelineGeometry& g);
    void paintFlag(QPainter& painter, const QRect& rect, TimelineTrackFlag flag, bool on);

    QVector<TimelineTrack> m_tracks;
    QVector<TimelineClip> m_clips;
    std::vector<char> m_selected;               // per clip
    std::vector<ClipLabel> m_clipLabels; // per clip
    QHash<int, int> m_idToIndex;
    QVector<TimelineMarker> m_markers;
    QVector<TimelineCaption> m_captions;
    std::vector<int> m_markerWidths; // name widths in the ruler font
    TimelineRows m_rows;
    std::vector<QString> m_rowLabels; // per row: a group's name elided to the header
    std::vector<QString> m_trackElided;

    TimelineTimebase m_time;
    QString m_frameRateLabel;
    qint64 m_duration = 0;
    qint64 m_playhead = 0;
    double m_pixelsPerSecond = 100.0;
    bool m_snapping = true;
    bool m_anySolo = false;
    qint64 m_clipsEnd = 0; // latest clip end (or open-ended start), for the scroll range
    bool m_frameAllPending = false;

    TimelineDrag m_drag;
    TimelineSnapTargets m_snapTargets; // built when a gesture starts
    qint64 m_snapLine = -1;            // the target snapped to, drawn while dragging; -1 none
    bool m_dropActive = false;
    int m_dropTrack = -1;
    qint64 m_dropTime = 0;
    QString m_dropName;

    Colors m_colors;
    QFont m_clipFont, m_smallFont, m_boldFont;
    QFontMetrics m_clipMetrics, m_smallMetrics;
    QPen m_fadePen, m_weightPen; // cosmetic, antialiased: the rasterizer's fast path
    mutable std::vector<QPointF> m_points; // scratch: weight polyline
    mutable std::vector<QLine> m_lines;    // scratch: ruler ticks and grid
    std::vector<qint64> m_stepCandidates;  // ruler steps in frames: divisors of the frame rate, then seconds
};

} // namespace thespis::widgets
