#pragma once
// CurveView: the curve editor's plot. Shows an action's curves (weight, scale, …) over the
// action's local time in seconds, with a grid, axis labels, a legend, the playhead and the
// action's domain (outside it is shaded), and lets the user select and edit keyframes.
// A pure view: it never evaluates a curve. The caller supplies each curve's evaluated samples
// (drawn as a polyline) and its keys; gestures only emit intents (keysMoveRequested, …) that the
// editor turns into undoable commands, then it feeds the result back through setCurves().
// Setters emit nothing. Owns a copy of the curves, the key selection and the visible range.
// Files: pure mapping and hit testing in curve_geometry.h, gestures in curve_view_drag.cpp,
// painting in curve_view_paint.cpp.

#include <QList>
#include <QPointF>
#include <QRectF>
#include <QString>
#include <QVector>
#include <QWidget>

#include <array>

#include "widgets/curve_geometry.h"
#include "widgets/curve_types.h"

class QAction;
class QMenu;
class QPainter;

namespace thespis::widgets {

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
    QRectF visibleRange() const { return QRectF(m_range.t0, m_range.v0, m_range.t1 - m_range.t0, m_range.v1 - m_range.v0); }

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
    enum class Drag { None, PendingKey, MovingKeys, PendingBox, Box, Tangent, Pan };
    struct Colors; // derived from the palette at paint time (curve_view_paint.cpp)

    // Mapping and framing (curve_view.cpp)
    CurveMapping mapping() const; // for the current size and visible range
    void updateGutters();
    /// The visible range fills the plot rect; its spans are clamped.
    void setVisibleRange(CurveRange range);
    void autoFrame(); // while m_autoFrame: the domain, [0, 1] and everything
    double domainViewEnd() const;

    // Keys and selection (curve_view.cpp)
    const CurveViewKey* keyAt(CurveKeyRef ref) const { return curveKeyAt(m_curves, ref); }
    CurveKeyRef keyUnder(QPointF pixel) const { return curveKeyUnder(mapping(), m_curves, pixel); }
    CurveKeyRef handleUnder(QPointF pixel, bool* outSide) const
    {
        return curveHandleUnder(mapping(), m_curves, m_selection, pixel, outSide);
    }
    bool isSelected(CurveKeyRef ref) const;
    void normalizeSelection(QList<CurveKeyRef>& keys) const;
    void changeSelection(QList<CurveKeyRef> keys); // by the user: emits selectionChanged if it changed
    void requestDelete();
    void requestTangentMode(CurveTangent mode);
    void updateMenuActions();

    // Gestures (curve_view_drag.cpp)
    /// Ends the gesture in progress and puts everything back as it was.
    void cancelDrag();
    QPointF moveDelta(QPointF pixel, Qt::KeyboardModifiers modifiers) const;
    void emitTangent(QPointF pixel, bool finished);

    // Painting (curve_view_paint.cpp)
    void paintGrid(QPainter& painter, const Colors& colors, const CurveMapping& m);
    void paintCurves(QPainter& painter, const CurveMapping& m);
    void paintKeys(QPainter& painter, const Colors& colors, const CurveMapping& m);
    void paintOverlays(QPainter& painter, const Colors& colors, const CurveMapping& m);
    void paintPlayhead(QPainter& painter, const Colors& colors, const CurveMapping& m);

    QVector<CurveViewCurve> m_curves;
    QList<CurveKeyRef> m_selection;
    double m_domainStart = 0;
    double m_domainEnd = 1;
    double m_playhead = 0;
    CurveRange m_range{-0.1, 1.1, -0.1, 1.1};
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
    CurveRange m_panRange; // the visible range when the pan began

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
