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

#include <QAbstractScrollArea>
#include <QBrush>
#include <QColor>
#include <QFont>
#include <QFontMetrics>
#include <QHash>
#include <QList>
#include <QLine>
#include <QMetaType>
#include <QPen>
#include <QPointF>
#include <QRect>
#include <QStaticText>
#include <QString>
#include <QVector>

#include <limits>
#include <vector>

class QMimeData;
class QPainter;

namespace thespis::widgets {

enum class TimelineEdge { Start, End };
enum class TimelineTrackFlag { Mute, Solo, Lock };

/// One row of the timeline.
struct TimelineTrack {
    QString name;  ///< "Body", "Face", …
    QString group; ///< the character's name; consecutive tracks of one group share a group header row
    bool muted = false, solo = false, locked = false;
    /// Clips are dragged only between tracks of the same group and the same kind ("body", "face").
    QString kind;
};

/// One action on a track, in ticks.
struct TimelineClip {
    int id = 0;      ///< stable id chosen by the caller
    int track = 0;   ///< index into the tracks; clips on a track that does not exist are not drawn
    QString name;
    qint64 start = 0, end = 0;      ///< end == TimelineView::OpenEnd for open-ended actions
    qint64 fadeIn = 0, fadeOut = 0; ///< lengths in ticks
    QVector<float> weight;          ///< weight samples evenly over [start, end] (thumbnail), 0..1+, may be empty
};

struct TimelineMarker {
    QString name;
    qint64 time = 0;
};

class TimelineView : public QAbstractScrollArea {
    Q_OBJECT
public:
    static constexpr qint64 OpenEnd = std::numeric_limits<qint64>::max();
    /// Mime type of a clip dragged in from a library; the data is the clip name in UTF-8.
    static constexpr const char* ClipMimeType = "application/x-thespis-clip";

    // Layout, in pixels (public so that tests and the editor can reason about it).
    static constexpr int HeaderWidth = 170; ///< the track header column on the left
    static constexpr int RulerHeight = 26;  ///< the time ruler on top
    static constexpr int TrackHeight = 40;  ///< one track's lane
    static constexpr int GroupHeight = 20;  ///< a character's header row above its tracks
    static constexpr int EdgeGrip = 5;      ///< a press this close to a clip's edge trims it
    static constexpr int SnapDistance = 8;  ///< snap targets this close (on screen) attract

    explicit TimelineView(QWidget* parent = nullptr);
    ~TimelineView() override;

    /// Ticks per second (default 705,600,000); values below 1 are ignored.
    void setTicksPerSecond(qint64 ticks);
    qint64 ticksPerSecond() const { return m_ticksPerSecond; }
    /// Frames per second for snapping, frame ticks and time labels (default 30); below 1 is ignored.
    void setFrameRate(int framesPerSecond);
    int frameRate() const { return m_frameRate; }

    void setTracks(QVector<TimelineTrack> tracks);
    const QVector<TimelineTrack>& tracks() const { return m_tracks; }
    /// Replaces every clip; the selection keeps the ids that are still present.
    void setClips(QVector<TimelineClip> clips);
    int clipCount() const { return int(m_clips.size()); }
    const TimelineClip* clip(int id) const;
    void setMarkers(QVector<TimelineMarker> markers);
    const QVector<TimelineMarker>& markers() const { return m_markers; }
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
    struct ClipItem {
        TimelineClip clip;
        bool selected = false;
        mutable QStaticText label;   // the name elided to labelWidth, laid out once, kept between paints
        mutable int labelWidth = -1;
    };
    struct Row {
        int top = 0;    // content y (0 = just below the ruler when not scrolled)
        int track = -1; // -1: a group header row
        int group = 0;  // index of the group's first track
        QString label;  // a group row's name, elided to the header
    };
    enum class HitKind { None, Corner, Ruler, Marker, Header, Flag, Lane, Body, StartEdge, EndEdge, FadeIn, FadeOut };
    struct Hit {
        HitKind kind = HitKind::None;
        int track = -1;
        int clip = -1; // index into m_clips
        int marker = -1;
        TimelineTrackFlag flag = TimelineTrackFlag::Mute;
    };
    enum class DragMode { None, Clip, TrimStart, TrimEnd, FadeIn, FadeOut, Scrub, Marker, RubberBand };
    struct Drag {
        DragMode mode = DragMode::None;
        QPoint pressPos;
        bool active = false;  // moved past the threshold
        bool emitted = false; // something was requested during this drag
        bool locked = false;  // started on a locked track: the gesture only selects
        bool toggleOnRelease = false;     // Shift/Ctrl+press on a selected clip: deselect unless dragged
        bool selectOnlyOnRelease = false; // press on a selected clip: select only it unless dragged
        int clip = -1;                    // index into m_clips
        int clipId = 0;
        int marker = -1;
        qint64 origStart = 0, origEnd = 0, origValue = 0; // origValue: fade length or marker time
        qint64 last = 0;                                   // last value requested
        QList<int> ids;                                    // moving clips
        QVector<TimelineClip> moving;                      // them as they were at the press
        int origTrack = -1;                                // the grabbed clip's track at the press
        int trackDelta = 0;                                // last track offset requested
        std::vector<qint64> edges;                         // their edges at the press
        qint64 minStart = 0;
        std::vector<char> baseSelection;                   // rubber band: selection kept (Shift/Ctrl)
        std::vector<char> pressSelection;                  // rubber band: selection before the press
        QRect band;
    };
    struct Colors {
        QColor lane, laneAlt, group, header, headerText, headerDim, separator, ruler, rulerText, rulerTick,
            gridMajor, gridMinor, outside, clip, clipBorder, clipSelected, clipSelectedBorder, clipText,
            clipSelectedText, fadeShade, fadeLine, weightLine, weightFill, handle, playhead, marker,
            markerText, snap, band, bandBorder, flagOff, flagOffText, mute, solo, lock, flagOnText;
        QBrush lockedHatch;
        bool dark = true;
    };

    // Layout
    void rebuildRows();
    void updateScrollRanges();
    void updateColors();
    void updateFonts();
    int contentHeight() const;
    int lanesTop() const { return RulerHeight; }
    int rowY(const Row& row) const;
    int trackY(int track) const; // viewport y of the track's lane top
    int trackAtY(int y) const;   // -1 if none
    int timeOriginX() const;     // viewport x of time 0
    double ticksPerPixel() const { return double(m_ticksPerSecond) / m_pixelsPerSecond; }
    qint64 contentEndTime() const;
    bool trackLocked(int track) const;
    bool trackDimmed(int track) const;
    int clipIndex(int id) const { return m_idToIndex.value(id, -1); }
    QRect clipRectAt(int index) const;
    QRect fadeHandleRectAt(int index, TimelineEdge edge) const;
    QString formatTime(qint64 ticks) const;
    qint64 clampSeek(qint64 ticks) const;
    struct Steps {
        qint64 major = 0, minor = 0; // in frames; minor 0: none
    };
    Steps rulerSteps() const;

    // Hit testing and gestures
    Hit hitTest(const QPoint& pos) const;
    void updateHoverCursor(const QPoint& pos);
    void beginClipPress(const Hit& hit, const QPoint& pos, Qt::KeyboardModifiers modifiers);
    void updateDrag(const QPoint& pos, Qt::KeyboardModifiers modifiers, bool finished);
    void updateRubberBand(const QPoint& pos);
    void cancelDrag();
    void selectOnly(int index);
    void setSelectionFlags(const std::vector<char>& flags);
    void emitSelectionIfChanged(const std::vector<char>& before);
    std::vector<char> selectionFlags() const;
    qint64 rawDelta(const QPoint& pos) const;
    int clipTrackDelta(int y) const; // the track offset of a clip drag with the mouse at y
    bool trackOffsetFits(int offset) const;

    // Snapping
    void buildSnapTargets(const std::vector<char>* excludeClips, int excludeMarker, bool includePlayhead);
    qint64 snapTime(qint64 ticks, bool bypass);
    qint64 snapDelta(qint64 delta, qint64 anchor, bool bypass);
    qint64 snapThreshold() const;
    bool nearestTarget(qint64 ticks, qint64& target) const;

    // Drop
    bool updateDrop(const QPoint& pos, const QMimeData* mime, Qt::KeyboardModifiers modifiers);

    // Painting
    void paintLanes(QPainter& painter, const QRect& lanes);
    void paintClips(QPainter& painter, const QRect& lanes);
    void paintClip(QPainter& painter, const ClipItem& item, const QRect& rect, bool dimmed, bool locked,
                   int laneRight);
    void paintOverlays(QPainter& painter, const QRect& lanes);
    void paintMoveGhosts(QPainter& painter);
    void paintGhost(QPainter& painter, const QRect& rect, const QString& name);
    void paintHeader(QPainter& painter);
    void paintRuler(QPainter& painter);
    void paintFlag(QPainter& painter, const QRect& rect, TimelineTrackFlag flag, bool on);

    QVector<TimelineTrack> m_tracks;
    QVector<ClipItem> m_clips;
    QHash<int, int> m_idToIndex;
    QVector<TimelineMarker> m_markers;
    std::vector<int> m_markerWidths; // name widths in the ruler font
    std::vector<Row> m_rows;
    std::vector<int> m_trackRow;     // track → index into m_rows
    std::vector<QString> m_trackElided;

    qint64 m_ticksPerSecond = 705'600'000;
    int m_frameRate = 30;
    QString m_frameRateLabel;
    qint64 m_duration = 0;
    qint64 m_playhead = 0;
    double m_pixelsPerSecond = 100.0;
    bool m_snapping = true;
    bool m_anySolo = false;
    qint64 m_clipsEnd = 0; // latest clip end (or open-ended start), for the scroll range
    bool m_frameAllPending = false;

    Drag m_drag;
    std::vector<qint64> m_snapTargets; // sorted, built when a gesture starts
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

Q_DECLARE_METATYPE(thespis::widgets::TimelineEdge)
Q_DECLARE_METATYPE(thespis::widgets::TimelineTrackFlag)
Q_DECLARE_METATYPE(thespis::widgets::TimelineTrack)
Q_DECLARE_METATYPE(thespis::widgets::TimelineClip)
Q_DECLARE_METATYPE(thespis::widgets::TimelineMarker)
