// JointMaskPicture's behaviour: following the joints and the brush, paint strokes from presses and
// drags, and the hover feedback (brush circle and the name of the joint under it).

#include "widgets/joint_mask_picture.h"

#include <QMouseEvent>

namespace thespis::widgets {

JointMaskPicture::JointMaskPicture(JointMaskView* view) : QWidget(view), m_view(view)
{
    setObjectName(QStringLiteral("jointPicture"));
    setAttribute(Qt::WA_OpaquePaintEvent);
    setMouseTracking(true);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
    setFocusPolicy(Qt::ClickFocus);
}

void JointMaskPicture::jointsChanged(bool structure, bool positions)
{
    const int count = int(m_view->m_joints.size());
    if (structure) {
        dropStroke();
        m_touched.fill(0, count);
        m_stroke.reserve(count);
        m_found.reserve(count);
        m_metresWidth.resize(count);
        for (int i = 0; i < count; ++i)
            m_metresWidth[i] = m_view->m_faceOutline.isEmpty() ? jointBodyWidth(m_view->m_joints[i].name.toLower()) : 0.0;
    }
    if (structure || positions)
        m_layoutDirty = true;
    if (m_hovering)
        m_hoverJoint = jointAt(m_hover);
    update();
}

void JointMaskPicture::dropStroke()
{
    m_strokeButton = Qt::NoButton;
    m_stroke.clear();
    m_touched.fill(0);
}

void JointMaskPicture::brushChanged()
{
    if (m_hovering)
        m_hoverJoint = jointAt(m_hover);
    update();
}

void JointMaskPicture::ensureLayout() const
{
    if (!m_layoutDirty)
        return;
    m_layoutDirty = false;
    // Margins for the L / R labels at the sides and the footer (hint and legend) below.
    const QFontMetrics metrics = fontMetrics();
    const qreal side = metrics.horizontalAdvance(QLatin1Char('M')) + 18;
    const QRectF fit = QRectF(rect()).adjusted(side, 14, -side, -(metrics.height() + 18));
    m_layout.fitInto(m_view->m_joints, m_metresWidth, fit, m_view->m_faceOutline);
}

QPointF JointMaskPicture::screen(int joint) const
{
    ensureLayout();
    if (joint < 0 || joint >= m_layout.screen.size())
        return {-1, -1};
    return m_layout.screen[joint];
}

int JointMaskPicture::jointAt(QPointF pos) const
{
    ensureLayout();
    return m_layout.jointAt(pos, m_view->m_brushRadius);
}

// Adds to the stroke every joint within the brush radius of the segment from → to, in the order
// the brush meets them. Returns whether any joint was new.
bool JointMaskPicture::touch(QPointF from, QPointF to)
{
    ensureLayout();
    // m_found keeps the capacity reserved in jointsChanged().
    m_layout.brushHits(from, to, m_view->m_brushRadius, m_touched, m_found);
    if (m_found.isEmpty())
        return false;
    for (const auto& [order, joint] : m_found) {
        m_touched[joint] = 1;
        m_stroke.append(joint);
    }
    return true;
}

void JointMaskPicture::emitStroke(bool finished)
{
    // A copy (shared, no allocation): a slot that calls setJoints() may drop the stroke.
    const QVector<int> joints = m_stroke;
    emit m_view->weightsPaintRequested(joints, m_strokeWeight, finished);
}

void JointMaskPicture::mousePressEvent(QMouseEvent* event)
{
    const Qt::MouseButton button = event->button();
    if (m_strokeButton != Qt::NoButton || (button != Qt::LeftButton && button != Qt::RightButton)) {
        event->ignore();
        return;
    }
    const QPointF pos = event->position();
    setHover(pos, true);
    m_strokeButton = button;
    m_strokeWeight = button == Qt::LeftButton ? m_view->m_brushWeight : 0.0f;
    m_stroke.clear();
    m_touched.fill(0, int(m_view->m_joints.size()));
    m_last = pos;
    if (const int joint = jointAt(pos); joint >= 0)
        m_view->selectFromPicture(joint);
    if (m_strokeButton != Qt::NoButton && touch(pos, pos))
        emitStroke(false);
    update();
}

void JointMaskPicture::mouseMoveEvent(QMouseEvent* event)
{
    const QPointF pos = event->position();
    setHover(pos, true);
    if (m_strokeButton == Qt::NoButton)
        return;
    const QPointF from = m_last;
    m_last = pos;
    if (touch(from, pos))
        emitStroke(false);
}

void JointMaskPicture::mouseReleaseEvent(QMouseEvent* event)
{
    if (event->button() != m_strokeButton || m_strokeButton == Qt::NoButton) {
        event->ignore();
        return;
    }
    const QPointF pos = event->position();
    if (pos != m_last)
        touch(m_last, pos);
    const bool any = !m_stroke.isEmpty();
    if (any)
        emitStroke(true);
    dropStroke();
    update();
}

void JointMaskPicture::leaveEvent(QEvent*)
{
    setHover({}, false);
}

void JointMaskPicture::hideEvent(QHideEvent*)
{
    // The release will not come: close the stroke so that the editor ends its merge.
    if (m_strokeButton != Qt::NoButton && !m_stroke.isEmpty())
        emitStroke(true);
    dropStroke();
    m_hovering = false;
}

void JointMaskPicture::resizeEvent(QResizeEvent*)
{
    m_layoutDirty = true;
    if (m_hovering)
        m_hoverJoint = jointAt(m_hover);
}

QString JointMaskPicture::hoverText() const
{
    if (m_hoverJoint < 0 || m_hoverJoint >= m_view->m_joints.size())
        return {};
    const MaskJoint& joint = m_view->m_joints[m_hoverJoint];
    return QStringLiteral("%1  %2").arg(joint.name, QString::number(double(joint.weight), 'f', 2));
}

QRectF JointMaskPicture::labelRect(const QFontMetrics& metrics) const
{
    const QString text = hoverText();
    if (text.isEmpty())
        return {};
    const qreal w = metrics.horizontalAdvance(text) + 12, h = metrics.height() + 4;
    const qreal r = m_view->m_brushRadius;
    QRectF label(m_hover.x() + r * 0.75 + 4, m_hover.y() - r * 0.75 - h, w, h);
    if (label.right() > width() - 2)
        label.moveRight(m_hover.x() - r * 0.75 - 4);
    if (label.top() < 2)
        label.moveTop(m_hover.y() + r * 0.75 + 4);
    return label;
}

QRectF JointMaskPicture::hoverRect() const
{
    if (!m_hovering)
        return {};
    const qreal r = m_view->m_brushRadius + 2 + m_layout.dotRadius + 4;
    return QRectF(m_hover.x() - r, m_hover.y() - r, 2 * r, 2 * r).united(labelRect(fontMetrics()).adjusted(-2, -2, 2, 2));
}

void JointMaskPicture::setHover(QPointF pos, bool hovering)
{
    const QRectF before = hoverRect();
    m_hover = pos;
    m_hovering = hovering;
    m_hoverJoint = hovering ? jointAt(pos) : -1;
    // Only the brush circle and the label move: repaint where they were and where they are, plus
    // the dots the brush covers (inside the circle's rectangle).
    update(before.toAlignedRect());
    update(hoverRect().toAlignedRect());
}

} // namespace thespis::widgets
