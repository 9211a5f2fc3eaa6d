// CurveView's gestures: the press / move / release state machine (select, move keys, box select,
// drag a tangent handle, pan), double-click to add a key, and the keys that cancel a gesture.

#include "widgets/curve_view.h"

#include <QKeyEvent>
#include <QMouseEvent>

namespace thespis::widgets {

namespace {

constexpr qreal kDragThreshold = 3; // pixels before a press becomes a drag

} // namespace

QPointF CurveView::moveDelta(QPointF pixel, Qt::KeyboardModifiers modifiers) const
{
    return keyMoveDelta(mapping(), m_pressPos, pixel, modifiers & Qt::ShiftModifier);
}

void CurveView::emitTangent(QPointF pixel, bool finished)
{
    const CurveViewKey* key = keyAt(m_pressKey);
    if (!key)
        return;
    const double slope = tangentSlopeTowards(mapping(), *key, pixel, m_tangentOutSide);
    double in = slope, out = slope;
    if (key->mode == CurveTangent::Broken) {
        in = m_tangentOutSide ? m_tangentIn : slope;
        out = m_tangentOutSide ? slope : m_tangentOut;
    }
    emit tangentRequested(m_pressKey, in, out, finished);
}

void CurveView::mousePressEvent(QMouseEvent* event)
{
    if (m_drag != Drag::None) // a second button during a gesture: the first one rules
        return;
    const QPointF pos = event->position();
    m_pressPos = pos;
    m_dragPos = pos;
    m_pressModifiers = event->modifiers();
    m_dragModifiers = event->modifiers();
    m_dragButton = event->button();
    if (event->button() == Qt::MiddleButton
        || (event->button() == Qt::LeftButton && (event->modifiers() & Qt::AltModifier))) {
        m_drag = Drag::Pan;
        m_panRange = m_range;
        setCursor(Qt::ClosedHandCursor);
        return;
    }
    if (event->button() != Qt::LeftButton) {
        QWidget::mousePressEvent(event);
        return;
    }
    const bool toggle = event->modifiers() & (Qt::ShiftModifier | Qt::ControlModifier);

    bool outSide = false;
    if (const CurveKeyRef handle = handleUnder(pos, &outSide); handle.curve >= 0) {
        const CurveViewKey* key = keyAt(handle);
        m_drag = Drag::Tangent;
        m_pressKey = handle;
        m_tangentOutSide = outSide;
        m_tangentMoved = false;
        m_tangentIn = key->inSlope;
        m_tangentOut = key->outSlope;
        return;
    }

    if (const CurveKeyRef key = keyUnder(pos); key.curve >= 0) {
        m_pressKey = key;
        m_collapseOnRelease = false;
        if (toggle) {
            QList<CurveKeyRef> keys = m_selection;
            if (isSelected(key))
                keys.removeOne(key);
            else
                keys.append(key);
            changeSelection(keys);
        } else if (!isSelected(key)) {
            changeSelection({key});
        } else {
            m_collapseOnRelease = m_selection.size() > 1;
        }
        m_drag = isSelected(key) ? Drag::PendingKey : Drag::None;
        return;
    }

    m_drag = Drag::PendingBox;
    m_selectionAtPress = m_selection;
}

void CurveView::mouseMoveEvent(QMouseEvent* event)
{
    const QPointF pos = event->position();
    const bool pastThreshold = (pos - m_pressPos).manhattanLength() >= kDragThreshold;
    switch (m_drag) {
    case Drag::None: {
        // Hover feedback.
        bool outSide = false;
        const CurveKeyRef handle = handleUnder(pos, &outSide);
        const CurveKeyRef key = handle.curve >= 0 ? CurveKeyRef{} : keyUnder(pos);
        if (!(handle == m_hoverHandle) || outSide != m_hoverHandleOut || !(key == m_hoverKey)) {
            m_hoverHandle = handle;
            m_hoverHandleOut = outSide;
            m_hoverKey = key;
            update();
        }
        break;
    }
    case Drag::PendingKey:
        if (!pastThreshold)
            break;
        m_drag = Drag::MovingKeys;
        m_dragKeys = m_selection;
        m_autoFrame = false;
        setCursor(Qt::SizeAllCursor);
        [[fallthrough]];
    case Drag::MovingKeys:
        m_dragPos = pos;
        m_dragModifiers = event->modifiers();
        update(); // the readout
        emit keysMoveRequested(m_dragKeys, moveDelta(pos, event->modifiers()), false);
        break;
    case Drag::PendingBox:
        if (!pastThreshold)
            break;
        m_drag = Drag::Box;
        [[fallthrough]];
    case Drag::Box: {
        m_dragPos = pos;
        QList<CurveKeyRef> keys = curveKeysIn(mapping(), m_curves, QRectF(m_pressPos, pos));
        if (m_pressModifiers & (Qt::ShiftModifier | Qt::ControlModifier))
            keys += m_selectionAtPress;
        // Shown live; selectionChanged is emitted once, on release.
        normalizeSelection(keys);
        if (keys != m_selection) {
            m_selection = std::move(keys);
            updateMenuActions();
        }
        update();
        break;
    }
    case Drag::Tangent:
        if (!m_tangentMoved && !pastThreshold)
            break;
        m_tangentMoved = true;
        m_autoFrame = false;
        m_dragPos = pos;
        emitTangent(pos, false);
        break;
    case Drag::Pan: {
        const CurveMapping m = mapping();
        const QPointF d = pos - m_pressPos;
        const double dt = d.x() / m.sx, dv = d.y() / m.sy;
        m_autoFrame = false;
        setVisibleRange({m_panRange.t0 - dt, m_panRange.t1 - dt, m_panRange.v0 + dv, m_panRange.v1 + dv});
        break;
    }
    }
}

void CurveView::mouseReleaseEvent(QMouseEvent* event)
{
    if (event->button() != m_dragButton)
        return;
    const QPointF pos = event->position();
    const Drag drag = m_drag;
    m_drag = Drag::None;
    unsetCursor();
    switch (drag) {
    case Drag::None:
        break;
    case Drag::PendingKey:
        if (m_collapseOnRelease)
            changeSelection({m_pressKey});
        break;
    case Drag::MovingKeys:
        emit keysMoveRequested(m_dragKeys, moveDelta(pos, event->modifiers()), true);
        m_dragKeys.clear();
        break;
    case Drag::PendingBox:
        if (m_pressModifiers & Qt::ControlModifier) {
            if (const int curve = editableCurveNear(mapping(), m_curves, pos); curve >= 0) {
                m_autoFrame = false;
                emit keyAddRequested(curve, fromWidget(pos));
            }
        } else if (!(m_pressModifiers & Qt::ShiftModifier)) {
            changeSelection({});
        }
        break;
    case Drag::Box:
        update();
        if (m_selection != m_selectionAtPress)
            emit selectionChanged();
        break;
    case Drag::Tangent:
        if (m_tangentMoved)
            emitTangent(pos, true);
        break;
    case Drag::Pan:
        break;
    }
}

void CurveView::mouseDoubleClickEvent(QMouseEvent* event)
{
    if (event->button() != Qt::LeftButton) {
        QWidget::mouseDoubleClickEvent(event);
        return;
    }
    // Not QWidget's default (a second press): a double-click only ever adds a key.
    m_drag = Drag::None;
    const QPointF pos = event->position();
    bool outSide = false;
    if (keyUnder(pos).curve >= 0 || handleUnder(pos, &outSide).curve >= 0)
        return;
    if (const int curve = editableCurveNear(mapping(), m_curves, pos); curve >= 0) {
        m_autoFrame = false;
        emit keyAddRequested(curve, fromWidget(pos));
    }
}

void CurveView::cancelDrag()
{
    if (m_drag == Drag::MovingKeys)
        emit keysMoveRequested(m_dragKeys, QPointF(0, 0), true);
    else if (m_drag == Drag::Tangent && m_tangentMoved)
        emit tangentRequested(m_pressKey, m_tangentIn, m_tangentOut, true);
    else if (m_drag == Drag::Box) {
        m_selection = m_selectionAtPress;
        updateMenuActions();
    }
    m_drag = Drag::None;
    m_dragKeys.clear();
    unsetCursor();
    update();
}

void CurveView::keyPressEvent(QKeyEvent* event)
{
    if (m_drag != Drag::None) {
        if (event->key() == Qt::Key_Escape || event->matches(QKeySequence::Undo)) {
            cancelDrag();
            return;
        }
        if (event->matches(QKeySequence::Redo))
            return; // nothing to redo while the drag's own edit is open
    }
    if (event->key() == Qt::Key_Delete || event->key() == Qt::Key_Backspace) {
        if (m_selection.isEmpty() || m_drag != Drag::None)
            event->ignore();
        else
            requestDelete();
        return;
    }
    if (event->key() == Qt::Key_F && !(event->modifiers() & ~Qt::KeypadModifier)) {
        frameAll();
        return;
    }
    if (event->matches(QKeySequence::SelectAll)) {
        QList<CurveKeyRef> all;
        for (int c = 0; c < m_curves.size(); ++c)
            for (int k = 0; k < m_curves[c].keys.size(); ++k)
                all.append({c, k});
        changeSelection(all);
        return;
    }
    QWidget::keyPressEvent(event);
}

} // namespace thespis::widgets
