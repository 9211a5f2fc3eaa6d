// JointMaskPicture's painting: the body silhouette, the L / R labels, bones, joint dots coloured by
// weight, the current joint, the footer with the hint and the colour legend, and the brush.

#include "widgets/joint_mask_picture.h"

#include <QLinearGradient>
#include <QPaintEvent>
#include <QPainter>

#include <algorithm>
#include <cmath>

namespace thespis::widgets {

namespace joint_mask {

QColor mix(const QColor& a, const QColor& b, qreal t)
{
    return QColor::fromRgbF(float(a.redF() + (b.redF() - a.redF()) * t), float(a.greenF() + (b.greenF() - a.greenF()) * t),
                            float(a.blueF() + (b.blueF() - a.blueF()) * t));
}

bool isDark(const QColor& c)
{
    return c.lightnessF() < 0.5;
}

} // namespace joint_mask

using joint_mask::isDark;
using joint_mask::mix;

void JointMaskPicture::paintEvent(QPaintEvent* event)
{
    ensureLayout();
    const QRectF dirty = event->rect();
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    const QPalette& pal = palette();
    const QColor base = pal.color(QPalette::Base);
    const QColor text = pal.color(QPalette::Text);
    const bool dark = isDark(base);
    painter.fillRect(dirty, base);

    const QVector<MaskJoint>& joints = m_view->m_joints;
    const QFontMetrics metrics = fontMetrics();
    if (joints.isEmpty()) {
        painter.setPen(mix(text, base, 0.4));
        painter.drawText(rect().adjusted(16, 16, -16, -16), Qt::AlignCenter | Qt::TextWordWrap, JointMaskView::tr("No skeleton"));
        return;
    }
    const int count = int(joints.size());
    auto visible = [&](QPointF a, QPointF b, qreal pad) {
        return QRectF(a, b).normalized().adjusted(-pad, -pad, pad, pad).intersects(dirty);
    };

    // Silhouette: capsules along the bones and the head, first a little wider in the outline
    // colour, then in the fill colour, so that overlapping capsules merge into one outlined body.
    const QColor fill = mix(base, text, dark ? 0.09 : 0.06);
    const QColor outline = mix(base, text, dark ? 0.20 : 0.16);
    for (int pass = 0; pass < 2; ++pass) {
        const QColor color = pass == 0 ? outline : fill;
        const qreal extra = pass == 0 ? 2.5 : 0.0;
        painter.setBrush(color);
        painter.setPen(Qt::NoPen);
        if (!m_layout.head.isEmpty())
            painter.drawEllipse(m_layout.head.adjusted(-extra / 2, -extra / 2, extra / 2, extra / 2));
        for (int i = 0; i < count; ++i) {
            if (const qreal tw = m_layout.tipWidth[i]; tw > 0 && visible(m_layout.screen[i], m_layout.tip[i], tw)) {
                painter.setPen(QPen(color, tw + extra, Qt::SolidLine, Qt::RoundCap));
                painter.drawLine(m_layout.screen[i], m_layout.tip[i]);
            }
            const qreal w = m_layout.bodyWidth[i];
            if (w <= 0)
                continue;
            const int parent = joints[i].parent;
            const QPointF a = m_layout.screen[i];
            const QPointF b = parent >= 0 && parent < i ? m_layout.screen[parent] : a;
            if (!visible(a, b, w))
                continue;
            if (std::abs(a.x() - b.x()) + std::abs(a.y() - b.y()) < 0.5) {
                painter.setPen(Qt::NoPen);
                painter.drawEllipse(a, (w + extra) / 2, (w + extra) / 2);
            } else {
                painter.setPen(QPen(color, w + extra, Qt::SolidLine, Qt::RoundCap));
                painter.drawLine(a, b);
            }
        }
    }

    // L / R: the character faces the viewer, so its left is on the viewer's right.
    {
        QFont font = painter.font();
        font.setBold(true);
        painter.setFont(font);
        painter.setPen(mix(text, base, 0.45));
        // Beside the figure at about shoulder height, inside the margins kept for them.
        const qreal y = m_layout.figure.top() + 0.3 * m_layout.figure.height();
        const qreal w = metrics.horizontalAdvance(QLatin1Char('M')) + 8;
        const qreal leftX = std::max<qreal>(4, m_layout.figure.left() - w - 8);
        const qreal rightX = std::min<qreal>(width() - 4 - w, m_layout.figure.right() + 8);
        painter.drawText(QRectF(leftX, y - metrics.height(), w, 2 * metrics.height()), Qt::AlignCenter,
                         JointMaskView::tr("R", "the character's right side"));
        painter.drawText(QRectF(rightX, y - metrics.height(), w, 2 * metrics.height()), Qt::AlignCenter,
                         JointMaskView::tr("L", "the character's left side"));
        font.setBold(false);
        painter.setFont(font);
    }

    // Bones.
    painter.setPen(QPen(mix(base, text, 0.42), 1.5, Qt::SolidLine, Qt::RoundCap));
    for (int i = 0; i < count; ++i) {
        const int parent = joints[i].parent;
        if (parent >= 0 && parent < i && visible(m_layout.screen[i], m_layout.screen[parent], 2))
            painter.drawLine(m_layout.screen[parent], m_layout.screen[i]);
    }

    // Joints: full dots where the mask sets the weight, smaller ones where it is inherited.
    const qreal r = m_layout.dotRadius;
    const int current = m_view->currentJoint();
    const qreal brush = m_view->m_brushRadius;
    const QColor ring = isDark(base) ? QColor(0x10, 0x12, 0x14) : QColor(0x40, 0x44, 0x4a);
    for (int i = 0; i < count; ++i) {
        const QPointF p = m_layout.screen[i];
        if (!visible(p, p, r + 6))
            continue;
        const qreal radius = joints[i].named ? r : r * 0.72;
        painter.setPen(QPen(ring, 1.2));
        painter.setBrush(JointMaskView::weightColor(joints[i].weight, base));
        painter.drawEllipse(p, radius, radius);
        // Joints under the brush (what a click here would paint) get a thin ring.
        if (m_hovering && m_strokeButton == Qt::NoButton) {
            const QPointF d = p - m_hover;
            if (QPointF::dotProduct(d, d) <= brush * brush) {
                painter.setPen(QPen(text, 1));
                painter.setBrush(Qt::NoBrush);
                painter.drawEllipse(p, r + 2.5, r + 2.5);
            }
        }
    }
    if (current >= 0 && current < count) {
        painter.setPen(QPen(pal.color(QPalette::Highlight), 2.2));
        painter.setBrush(Qt::NoBrush);
        painter.drawEllipse(m_layout.screen[current], r + 3.5, r + 3.5);
    }

    // Footer: how to paint, and the colour legend.
    {
        const qreal y = height() - metrics.height() - 8;
        const QColor muted = mix(text, base, 0.4);
        const qreal legendW = std::min<qreal>(72, width() * 0.2);
        const qreal digit = metrics.horizontalAdvance(QLatin1Char('0')) + 4;
        const QRectF legend(width() - 10 - digit - legendW, y + metrics.height() / 2.0 - 4, legendW, 8);
        if (QRectF(0, y - 2, width(), metrics.height() + 8).intersects(dirty)) {
            QLinearGradient gradient(legend.topLeft(), legend.topRight());
            for (int step = 0; step <= 4; ++step)
                gradient.setColorAt(step / 4.0, JointMaskView::weightColor(float(step / 4.0), base));
            painter.setPen(QPen(ring, 0.8));
            painter.setBrush(gradient);
            painter.drawRoundedRect(legend, 3, 3);
            painter.setPen(muted);
            painter.drawText(QRectF(legend.left() - digit - 2, y, digit, metrics.height()), Qt::AlignRight | Qt::AlignVCenter,
                             QStringLiteral("0"));
            painter.drawText(QRectF(legend.right() + 2, y, digit, metrics.height()), Qt::AlignLeft | Qt::AlignVCenter,
                             QStringLiteral("1"));
            const qreal hintW = legend.left() - digit - 20;
            if (hintW > 40)
                painter.drawText(QRectF(10, y, hintW, metrics.height()), Qt::AlignLeft | Qt::AlignVCenter,
                                 metrics.elidedText(JointMaskView::tr("Drag to paint · right-drag paints 0"), Qt::ElideRight,
                                                    int(hintW)));
        }
    }

    // The brush and the name of the joint under it.
    if (m_hovering) {
        const float weight = m_strokeButton == Qt::NoButton ? m_view->m_brushWeight : m_strokeWeight;
        QColor brushFill = JointMaskView::weightColor(weight, base);
        brushFill.setAlphaF(m_strokeButton == Qt::NoButton ? 0.10f : 0.22f);
        QColor brushLine = text;
        brushLine.setAlphaF(0.65f);
        painter.setPen(QPen(brushLine, 1.2, m_strokeButton == Qt::NoButton ? Qt::DashLine : Qt::SolidLine));
        painter.setBrush(brushFill);
        painter.drawEllipse(m_hover, brush, brush);
        const QRectF label = labelRect(metrics);
        if (!label.isEmpty()) {
            painter.setPen(Qt::NoPen);
            QColor back = pal.color(QPalette::ToolTipBase);
            back.setAlphaF(0.92f);
            painter.setBrush(back);
            painter.drawRoundedRect(label, 4, 4);
            painter.setPen(pal.color(QPalette::ToolTipText));
            painter.drawText(label, Qt::AlignCenter, hoverText());
        }
    }
}

} // namespace thespis::widgets
