#pragma once
// CurveView: the curve editor's plot. Shows an action's curves (weight, scale, …) over the
// action's local time in seconds, with a grid, axis labels, a legend, the playhead and the
// action's domain (outside it is shaded), and lets the user select and edit keyframes.
// A pure view: it never evaluates a curve. The caller supplies each curve's evaluated samples
// (drawn as a polyline) and its keys; gestures only emit intents (keysMoveRequested, …) that the
// editor turns into undoable commands, then it feeds the result back through setCurves().
// Setters emit nothing. Owns a copy of the curves, the key selection and the visible range.

#include <QColor>
#include <QList>
#include <QMetaType>
#include <QPointF>
#include <QRectF>
#include <QString>
#include <QVector>
#include <QWidget>

#include <array>

class QAction;
class QMenu;
class QPainter;

namespace thespis::widgets {

/// How a key's tangents are chosen. Auto clamped, Linear and Constant are computed by the curve;
/// Free and Broken use the key's own slopes (Free: in = out; Broken: each side on its own), and
/// only those two show draggable tangent handles.
enum class CurveTangent { AutoClamped, Linear, Constant, Free, Broken };

/// One key of a keyframed curve, in the curve's units: time in seconds, slopes in value / second.
struct CurveViewKey {
    double time = 0, value = 0;
    CurveTangent mode = CurveTangent::AutoClamped;
    double inSlope = 0, outSlope = 0;
};

/// One curve as the view shows it.
struct CurveViewCurve {
    QString name;               ///< "Weight", "Scale": shown in the legend
    QColor color;
    QVector<QPointF> samples;   ///< the evaluated curve (x = seconds, ascending; y = value): a polyline
    QVector<CurveViewKey> keys; ///< empty for parametric curves (fades / ADSR): drawn, not key-editable
    /// Accepts new keys (double-click, Ctrl+click) even while `keys` is empty, e.g. a keyframed
    /// curve whose last key was deleted. Curves with keys are always editable.
    bool keyable = false;
};

/// A key by position: index of the curve in setCurves() and of the key in that curve.
struct CurveKeyRef {
    int curve = -1;
    int key = -1;
    bool operator==(const CurveKeyRef&) const = default;
};

class CurveView : public QWidget {
    Q_OBJECT
public:
    explicit CurveView(QWidget* parent = nullptr);
    ~CurveView() override;

    /// Replaces every curve. Emits nothing; keeps the selected keys whose indices still exist.
    /// Until the user zooms, pans or edits, the view frames the domain and the curves by itself.
    void setCurves(QVector<CurveViewCurve> curves);
    const QVector<CurveViewCurve>& curves() const { return m_curves; }

    /// The action's domain in local seconds; outside it is shaded. `end` may be +inf (an
    /// open-ended action): the view then frames start .. start + 10 s. A different domain re-arms
    /// the automatic framing (a new action is shown).
    void setTimeRange(double start, double end);
    double timeRangeStart() const { return m_domainStart; }
    double timeRangeEnd() const { return m_domainEnd; }

    /// The playhead in local seconds: a vertical line.
    void setPlayhead(double seconds);
    double playhead() const { return m_playhead; }

    /// Shown in the middle of the plot while there is no curve (e.g. "Select an action").
    void setPlaceholderText(const QString& text);
    QString placeholderText() const { return m_placeholder; }

    /// Fits every sample and key (of every curve) into the plot with a margin ('F' key and the
    /// context menu's "Frame All").
    void frameAll();

    /// Selected keys, sorted by curve then key.
    QList<CurveKeyRef> selectedKeys() const { return m_selection; }
    /// Emits nothing; refs to curves without that key (or to parametric curves) are dropped.
    void setSelectedKeys(const QList<CurveKeyRef>& keys);

    /// (seconds, value) → widget pixels.
    QPointF toWidget(QPointF curvePoint) const;
    /// Widget pixels → (seconds, value).
    QPointF fromWidget(QPointF pixel) const;
    /// Pixel position of the end of a key's tangent handle (drawn for selected Free / Broken
    /// keys): a fixed pixel length from the key along its in (outSide = false) or out slope, as
    /// the slope looks at the current zoom. A null point for a key that does not exist.
    QPointF tangentHandle(CurveKeyRef key, bool outSide) const;
    /// The plotting area (the rest holds the axis labels).
    QRectF plotRect() const;
    /// The visible time range and value range.
    QRectF visibleRange() const { return QRectF(m_t0, m_v0, m_t1 - m_t0, m_v1 - m_v0); }

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

signals:
    /// The user changed the selection (click, Shift/Ctrl+click, box, Ctrl+A, Delete).
    void selectionChanged();
    /// Double-click near a keyed curve (or Ctrl+click): at = (clicked time, clicked value).
    void keyAddRequested(int curve, QPointF at);
    /// Dragging selected keys: delta (seconds, value) is the total since the drag began, applied
    /// to the keys as they were then. Unfinished while the mouse moves, finished = true once on
    /// release (Escape or Ctrl+Z: finished with a zero delta; Undo and Redo do nothing else
    /// during a drag). A click without movement emits nothing.
    void keysMoveRequested(const QList<thespis::widgets::CurveKeyRef>& keys, QPointF delta, bool finished);
    /// Delete / Backspace (or the context menu) with keys selected. The view then clears its
    /// selection, since the indices no longer name the same keys.
    void keysDeleteRequested(const QList<thespis::widgets::CurveKeyRef>& keys);
    /// Dragging a tangent handle: the key's new slopes (value / second). Free keys get equal slopes;
    /// Broken keys change only the dragged side. finished = true once on release.
    void tangentRequested(thespis::widgets::CurveKeyRef key, double inSlope, double outSlope, bool finished);
    /// Context menu on selected keys: Auto clamped / Linear / Constant / Free / Broken.
    void tangentModeRequested(const QList<thespis::widgets::CurveKeyRef>& keys, thespis::widgets::CurveTangent mode);

protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void mouseDoubleClickEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void contextMenuEvent(QContextMenuEvent* event) override;
    void leaveEvent(QEvent* event) override;
    bool event(QEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void changeEvent(QEvent* event) override;

private:
    /// Ends the gesture in progress and puts everything back as it was.
    void cancelDrag();
    enum class Drag { None, PendingKey, MovingKeys, PendingBox, Box, Tangent, Pan };
    struct Colors;  // derived from the palette at paint time
    struct Mapping; // (seconds, value) ↔ pixels for the current size and visible range
    Mapping mapping() const;
    void updateGutters();

    // The visible range [m_t0, m_t1] × [m_v0, m_v1] fills the plot rect.
    void setVisible(double t0, double t1, double v0, double v1);
    void fitBounds(double t0, double t1, double v0, double v1);
    void autoFrame(); // while m_autoFrame: the domain, [0, 1] and everything
    double domainViewEnd() const;
    void stopAutoFrame() { m_autoFrame = false; }

    bool isEditable(int curve) const;
    const CurveViewKey* keyAt(CurveKeyRef ref) const;
    bool isSelected(CurveKeyRef ref) const;
    void normalizeSelection(QList<CurveKeyRef>& keys) const;
    void changeSelection(QList<CurveKeyRef> keys); // by the user: emits selectionChanged if it changed
    CurveKeyRef keyUnder(QPointF pixel) const;
    /// A selected Free / Broken key's handle under `pixel`; outSide says which one.
    CurveKeyRef handleUnder(QPointF pixel, bool* outSide) const;
    /// The editable curve whose polyline passes nearest `pixel` (within a few pixels), or -1.
    int editableCurveNear(QPointF pixel) const;
    QList<CurveKeyRef> keysIn(const QRectF& pixelRect) const;
    QPointF moveDelta(QPointF pixel, Qt::KeyboardModifiers modifiers) const;
    void emitTangent(QPointF pixel, bool finished);
    void requestDelete();
    void requestTangentMode(CurveTangent mode);
    void updateMenuActions();

    void paintGrid(QPainter& painter, const Colors& colors, const QRectF& plot);
    void paintCurves(QPainter& painter, const Colors& colors, const QRectF& plot);
    void paintKeys(QPainter& painter, const Colors& colors, const QRectF& plot);
    void paintOverlays(QPainter& painter, const Colors& colors, const QRectF& plot);
    void paintPlayhead(QPainter& painter, const Colors& colors, const QRectF& plot);

    QVector<CurveViewCurve> m_curves;
    QList<CurveKeyRef> m_selection;
    double m_domainStart = 0;
    double m_domainEnd = 1;
    double m_playhead = 0;
    double m_t0 = -0.1, m_t1 = 1.1, m_v0 = -0.1, m_v1 = 1.1;
    bool m_autoFrame = true;
    QString m_placeholder;
    qreal m_leftGutter = 40;   // value labels
    qreal m_bottomGutter = 24; // time labels

    // The gesture in progress.
    Drag m_drag = Drag::None;
    QPointF m_pressPos;
    QPointF m_dragPos;
    Qt::KeyboardModifiers m_pressModifiers;
    Qt::KeyboardModifiers m_dragModifiers; // while moving keys (Shift constrains)
    Qt::MouseButton m_dragButton = Qt::NoButton;
    CurveKeyRef m_pressKey;            // the key pressed (PendingKey / MovingKeys / Tangent)
    bool m_collapseOnRelease = false;  // a plain click on one of several selected keys
    QList<CurveKeyRef> m_dragKeys;     // the keys being moved
    QList<CurveKeyRef> m_selectionAtPress;
    bool m_tangentOutSide = false;
    bool m_tangentMoved = false;
    double m_tangentIn = 0, m_tangentOut = 0; // slopes when the tangent drag began
    double m_panT0 = 0, m_panT1 = 0, m_panV0 = 0, m_panV1 = 0;

    CurveKeyRef m_hoverKey;
    CurveKeyRef m_hoverHandle;
    bool m_hoverHandleOut = false;

    QVector<QPointF> m_polyline; // scratch for painting, reused between paints

    QMenu* m_menu = nullptr;
    std::array<QAction*, 5> m_modeActions{}; // by CurveTangent
    QAction* m_deleteAction = nullptr;
    QAction* m_frameAllAction = nullptr;
};

} // namespace thespis::widgets

Q_DECLARE_METATYPE(thespis::widgets::CurveKeyRef)
Q_DECLARE_METATYPE(QList<thespis::widgets::CurveKeyRef>)
Q_DECLARE_METATYPE(thespis::widgets::CurveTangent)
