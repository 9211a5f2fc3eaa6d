#pragma once
// JointMaskPicture: the body picture beside JointMaskView's tree. Keeps the figure's layout for its
// size, turns presses and drags into paint strokes with the view's brush, shows the brush and the
// joint under it, and paints the figure (joint_mask_picture_paint.cpp). Reads the joints and brush
// settings from its view and emits through it. Internal to widgets/: only the view creates one.

#include <QColor>
#include <QPointF>
#include <QRectF>
#include <QString>
#include <QVector>
#include <QWidget>

#include <utility>

#include "widgets/joint_mask_layout.h"
#include "widgets/joint_mask_view.h"

namespace thespis::widgets {

namespace joint_mask {
/// a → b by t, opaque (the alpha is dropped).
QColor mix(const QColor& a, const QColor& b, qreal t);
bool isDark(const QColor& color);
} // namespace joint_mask

class JointMaskPicture : public QWidget {
public:
    explicit JointMaskPicture(JointMaskView* view);

    void jointsChanged(bool structure, bool positions);
    QPointF screen(int joint) const;
    int jointAt(QPointF pos) const;
    void dropStroke();
    void brushChanged();

    QSize sizeHint() const override { return {440, 480}; }
    QSize minimumSizeHint() const override { return {180, 220}; }

protected:
    void paintEvent(QPaintEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void leaveEvent(QEvent* event) override;
    void hideEvent(QHideEvent* event) override;

private:
    void ensureLayout() const;
    bool touch(QPointF from, QPointF to);
    void emitStroke(bool finished);
    void setHover(QPointF pos, bool hovering);
    QRectF hoverRect() const;
    QRectF labelRect(const QFontMetrics& metrics) const;
    QString hoverText() const;

    JointMaskView* m_view;

    // Layout, computed lazily for the current size and joint positions.
    mutable bool m_layoutDirty = true;
    mutable JointMaskLayout m_layout;
    QVector<qreal> m_metresWidth; // per joint, body width in metres (from its name)

    // The stroke in progress.
    Qt::MouseButton m_strokeButton = Qt::NoButton;
    float m_strokeWeight = 1;
    QPointF m_last;
    QVector<int> m_stroke;
    QVector<char> m_touched;                 // per joint
    QVector<std::pair<qreal, int>> m_found;  // scratch: joints found by one touch, with their order

    // Hover.
    QPointF m_hover;
    bool m_hovering = false;
    int m_hoverJoint = -1;
};

} // namespace thespis::widgets
