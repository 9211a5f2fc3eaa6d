// CurveView's painting: grid, axis labels and the shaded outside of the domain, the curves'
// polylines, keys and tangent handles, the playhead, the box selection, the move readout and the
// legend; and the colours taken from the palette.

#include "widgets/curve_view.h"
#include "widgets/color_mix.h"

#include <QFontMetricsF>
#include <QPainter>

#include <algorithm>
#include <cmath>

namespace thespis::widgets {

namespace {

using M = CurveMetrics;

int decimalsFor(double step)
{
    return std::clamp(int(-std::floor(std::log10(step) + 1e-9)), 0, 9);
}

QString formatNumber(double value, double step)
{
    if (std::abs(value) < step * 1e-6)
        value = 0; // no "-0"
    return QString::number(value, 'f', decimalsFor(step));
}

} // namespace

// Everything is derived from the palette, but the plot stays dark-neutral in light themes too
// (as in Blender's and Maya's graph editors): coloured curves read best on a dark ground.
struct CurveView::Colors {
    QColor background, gutter, outside, gridMinor, gridMajor, gridEmphasis, domainEdge;
    QColor label, strongLabel, highlight, highlightText, keyOutline, selectedKey, handle;

    explicit Colors(const QPalette& palette)
    {
        const QColor base = palette.color(QPalette::Base);
        if (base.lightnessF() < 0.3) {
            background = base;
        } else {
            const QColor window = palette.color(QPalette::Window);
            const float hue = std::max(window.hslHueF(), 0.0f);
            background = QColor::fromHslF(hue, window.hslSaturationF() * 0.4f, 0.2f);
        }
        const QColor ink(235, 235, 235);
        gutter = background.darker(118);
        outside = withAlpha(QColor(0, 0, 0), 105);
        gridMinor = mix(background, ink, 0.045);
        gridMajor = mix(background, ink, 0.11);
        gridEmphasis = mix(background, ink, 0.32);
        domainEdge = mix(background, ink, 0.45);
        label = mix(background, ink, 0.62);
        strongLabel = mix(background, ink, 0.9);
        highlight = palette.color(QPalette::Highlight);
        if (highlight.lightnessF() < 0.5)
            highlight = highlight.lighter(130);
        highlightText = palette.color(QPalette::HighlightedText);
        keyOutline = background.darker(160);
        selectedKey = QColor(250, 250, 250);
        handle = mix(background, ink, 0.78);
    }
};

void CurveView::paintEvent(QPaintEvent*)
{
    QPainter painter(this);
    const Colors colors(palette());
    const CurveMapping m = mapping();
    const QRectF& plot = m.plot;
    paintGrid(painter, colors, m);

    painter.save();
    painter.setClipRect(plot);
    painter.setRenderHint(QPainter::Antialiasing);
    paintCurves(painter, m);
    paintPlayhead(painter, colors, m);
    paintKeys(painter, colors, m);
    if (m_drag == Drag::Box) {
        const QRectF band = QRectF(m_pressPos, m_dragPos).normalized();
        painter.setRenderHint(QPainter::Antialiasing, false);
        painter.setPen(QPen(colors.highlight, 1));
        painter.setBrush(withAlpha(colors.highlight, 45));
        painter.drawRect(band.adjusted(0.5, 0.5, -0.5, -0.5));
    }
    if (m_curves.isEmpty() && !m_placeholder.isEmpty()) {
        painter.setPen(colors.label);
        painter.drawText(plot.adjusted(16, 16, -16, -16), Qt::AlignCenter | Qt::TextWordWrap, m_placeholder);
    }
    painter.restore();

    painter.setRenderHint(QPainter::Antialiasing);
    paintOverlays(painter, colors, m);
}

void CurveView::paintGrid(QPainter& painter, const Colors& colors, const CurveMapping& m)
{
    const QRectF& plot = m.plot;
    painter.fillRect(rect(), colors.gutter);
    painter.fillRect(plot, colors.background);

    // Outside the action's domain: shaded, with its edges marked.
    const double domainLeft = m.map(m_domainStart, 0).x();
    const double domainRight = std::isfinite(m_domainEnd) ? m.map(m_domainEnd, 0).x() : plot.right() + 1;
    if (domainLeft > plot.left())
        painter.fillRect(QRectF(plot.left(), plot.top(), std::min(domainLeft, plot.right()) - plot.left(), plot.height()), colors.outside);
    if (domainRight < plot.right())
        painter.fillRect(QRectF(std::max(domainRight, plot.left()), plot.top(), plot.right() - std::max(domainRight, plot.left()), plot.height()),
                         colors.outside);

    const QFontMetricsF metrics(painter.font());
    const double textHeight = metrics.height();

    // Time: vertical lines, labels along the bottom. Steps wide enough for the widest label.
    int timeMinor = 5;
    const double labelWidth = metrics.horizontalAdvance(tr("%1 s").arg(QStringLiteral("-00.00")));
    const double timeStep = niceGridStep(m.sx, labelWidth + 24, &timeMinor);
    const double timeMinorStep = timeStep / timeMinor;
    const bool drawTimeMinor = timeMinorStep * m.sx >= 8;
    // Value: horizontal lines, labels at the left.
    int valueMinor = 5;
    const double valueStep = niceGridStep(m.sy, textHeight * 2.2, &valueMinor);
    const double valueMinorStep = valueStep / valueMinor;
    const bool drawValueMinor = valueMinorStep * m.sy >= 7;

    painter.setRenderHint(QPainter::Antialiasing, false);
    auto crisp = [](double coordinate) { return std::floor(coordinate) + 0.5; };

    {
        const double step = drawTimeMinor ? timeMinorStep : timeStep;
        const long long first = (long long)std::ceil(m_range.t0 / step), last = (long long)std::floor(m_range.t1 / step);
        for (long long i = first; i <= last && last - first < 4000; ++i) {
            const bool major = !drawTimeMinor || i % timeMinor == 0;
            const double x = crisp(m.map(double(i) * step, 0).x());
            painter.setPen(major ? colors.gridMajor : colors.gridMinor);
            painter.drawLine(QPointF(x, plot.top()), QPointF(x, plot.bottom()));
        }
    }
    {
        const double step = drawValueMinor ? valueMinorStep : valueStep;
        const long long first = (long long)std::ceil(m_range.v0 / step), last = (long long)std::floor(m_range.v1 / step);
        for (long long i = first; i <= last && last - first < 4000; ++i) {
            const bool major = !drawValueMinor || i % valueMinor == 0;
            const double y = crisp(m.map(0, double(i) * step).y());
            painter.setPen(major ? colors.gridMajor : colors.gridMinor);
            painter.drawLine(QPointF(plot.left(), y), QPointF(plot.right(), y));
        }
    }
    // Value 0 and 1 (a weight's off and full) stand out.
    painter.setPen(QPen(colors.gridEmphasis, 1));
    for (double v : {0.0, 1.0}) {
        const double y = crisp(m.map(0, v).y());
        if (y >= plot.top() && y <= plot.bottom())
            painter.drawLine(QPointF(plot.left(), y), QPointF(plot.right(), y));
    }
    painter.setPen(QPen(colors.domainEdge, 1, Qt::DashLine));
    if (domainLeft >= plot.left() && domainLeft <= plot.right())
        painter.drawLine(QPointF(crisp(domainLeft), plot.top()), QPointF(crisp(domainLeft), plot.bottom()));
    if (domainRight >= plot.left() && domainRight <= plot.right())
        painter.drawLine(QPointF(crisp(domainRight), plot.top()), QPointF(crisp(domainRight), plot.bottom()));

    // Labels.
    painter.setPen(colors.label);
    {
        const long long first = (long long)std::ceil(m_range.t0 / timeStep), last = (long long)std::floor(m_range.t1 / timeStep);
        for (long long i = first; i <= last && last - first < 1000; ++i) {
            const double t = double(i) * timeStep;
            const double x = m.map(t, 0).x();
            const QString text = tr("%1 s").arg(formatNumber(t, timeStep));
            const double w = metrics.horizontalAdvance(text);
            const double left = std::clamp(x - w / 2, plot.left() + 2, double(width()) - w - 2);
            painter.drawText(QRectF(left, plot.bottom() + 3, w + 1, m_bottomGutter - 3), Qt::AlignHCenter | Qt::AlignTop, text);
        }
        // Tick marks into the gutter.
        painter.setPen(colors.gridEmphasis);
        for (long long i = first; i <= last && last - first < 1000; ++i) {
            const double x = crisp(m.map(double(i) * timeStep, 0).x());
            painter.drawLine(QPointF(x, plot.bottom()), QPointF(x, plot.bottom() + 3));
        }
    }
    {
        painter.setPen(colors.label);
        const long long first = (long long)std::ceil(m_range.v0 / valueStep), last = (long long)std::floor(m_range.v1 / valueStep);
        for (long long i = first; i <= last && last - first < 1000; ++i) {
            const double v = double(i) * valueStep;
            const double y = m.map(0, v).y();
            const double top = std::clamp(y - textHeight / 2, plot.top(), plot.bottom() - textHeight);
            painter.setPen(v == 0.0 || v == 1.0 ? colors.strongLabel : colors.label);
            painter.drawText(QRectF(0, top, m_leftGutter - 7, textHeight), Qt::AlignRight | Qt::AlignVCenter,
                             formatNumber(v, valueStep));
        }
    }
}

void CurveView::paintCurves(QPainter& painter, const CurveMapping& m)
{
    const double margin = 2 / m.sx; // one sample beyond each edge is kept anyway
    for (const CurveViewCurve& curve : m_curves) {
        const QVector<QPointF>& s = curve.samples;
        if (s.isEmpty())
            continue;
        // Only the samples on screen (and one either side, so the line reaches the edges).
        auto first = std::lower_bound(s.begin(), s.end(), m_range.t0 - margin, [](const QPointF& p, double x) { return p.x() < x; });
        auto last = std::upper_bound(s.begin(), s.end(), m_range.t1 + margin, [](double x, const QPointF& p) { return x < p.x(); });
        if (first != s.begin())
            --first;
        if (last != s.end())
            ++last;
        m_polyline.clear();
        QPointF previous(-1e9, -1e9);
        for (auto it = first; it != last; ++it) {
            const QPointF p = m.map(*it);
            // Dense sampling: drop points that land on the same pixel column and row.
            if (std::abs(p.x() - previous.x()) < 0.5 && std::abs(p.y() - previous.y()) < 0.5)
                continue;
            m_polyline.append(p);
            previous = p;
        }
        const bool keyed = !curve.keys.isEmpty() || curve.keyable;
        QPen pen(curve.color, keyed ? 2.0 : 1.75);
        pen.setCapStyle(Qt::RoundCap);
        pen.setJoinStyle(Qt::RoundJoin);
        if (!keyed) // parametric: the shape is fixed, so it looks different from an editable curve
            pen.setDashPattern({5, 3});
        painter.setPen(pen);
        painter.setBrush(Qt::NoBrush);
        if (m_polyline.size() == 1)
            painter.drawPoint(m_polyline.front());
        else
            painter.drawPolyline(m_polyline.constData(), int(m_polyline.size()));
    }
}

void CurveView::paintKeys(QPainter& painter, const Colors& colors, const CurveMapping& m)
{
    const QRectF& plot = m.plot;
    const QRectF visible = plot.adjusted(-M::HandleLength - 8, -M::HandleLength - 8, M::HandleLength + 8, M::HandleLength + 8);

    // Tangent handles of selected Free / Broken keys, under the keys.
    for (const CurveKeyRef& ref : m_selection) {
        const CurveViewKey* key = keyAt(ref);
        if (!key || !hasTangentHandles(key->mode))
            continue;
        const QPointF centre = m.map(key->time, key->value);
        if (!visible.contains(centre))
            continue;
        for (bool out : {false, true}) {
            const QPointF end = tangentHandlePoint(m, *key, out);
            const bool hot = (m_drag == Drag::Tangent && m_pressKey == ref && m_tangentOutSide == out)
                             || (m_drag == Drag::None && m_hoverHandle == ref && m_hoverHandleOut == out);
            painter.setPen(QPen(colors.handle, 1.25));
            painter.drawLine(centre, end);
            painter.setPen(QPen(colors.keyOutline, 1));
            painter.setBrush(hot ? colors.highlight : colors.handle);
            painter.drawEllipse(end, hot ? M::HandleRadius + 1 : M::HandleRadius, hot ? M::HandleRadius + 1 : M::HandleRadius);
        }
    }

    for (int c = 0; c < m_curves.size(); ++c) {
        const CurveViewCurve& curve = m_curves[c];
        for (int k = 0; k < curve.keys.size(); ++k) {
            const CurveViewKey& key = curve.keys[k];
            const QPointF p = m.map(key.time, key.value);
            if (!plot.adjusted(-10, -10, 10, 10).contains(p))
                continue;
            const CurveKeyRef ref{c, k};
            const bool selected = isSelected(ref);
            const bool hover = m_drag == Drag::None && m_hoverKey == ref;
            const qreal r = M::KeyRadius + (selected ? 1 : 0) + (hover ? 0.5 : 0);
            if (selected) {
                painter.setPen(QPen(colors.highlight, 2));
                painter.setBrush(colors.selectedKey);
            } else {
                painter.setPen(QPen(hover ? colors.selectedKey : colors.keyOutline, 1.25));
                painter.setBrush(curve.color);
            }
            // Smooth keys are diamonds; Linear and Constant keys are squares.
            if (key.mode == CurveTangent::Linear || key.mode == CurveTangent::Constant) {
                const qreal half = r * 0.8;
                painter.drawRect(QRectF(p.x() - half, p.y() - half, 2 * half, 2 * half));
            } else {
                const QPointF diamond[4] = {{p.x(), p.y() - r}, {p.x() + r, p.y()}, {p.x(), p.y() + r}, {p.x() - r, p.y()}};
                painter.drawPolygon(diamond, 4);
            }
        }
    }
}

void CurveView::paintPlayhead(QPainter& painter, const Colors& colors, const CurveMapping& m)
{
    const QRectF& plot = m.plot;
    const double x = m.map(m_playhead, 0).x();
    if (!std::isfinite(x) || x < plot.left() - 1 || x > plot.right() + 1)
        return;
    painter.setPen(QPen(colors.highlight, 1.5));
    painter.drawLine(QPointF(x, plot.top()), QPointF(x, plot.bottom()));
    const QPointF marker[3] = {{x - 5, plot.top()}, {x + 5, plot.top()}, {x, plot.top() + 6}};
    painter.setPen(Qt::NoPen);
    painter.setBrush(colors.highlight);
    painter.drawPolygon(marker, 3);
}

void CurveView::paintOverlays(QPainter& painter, const Colors& colors, const CurveMapping& m)
{
    const QRectF& plot = m.plot;
    // The playhead's time sits on the time axis, over the labels.
    const QFontMetricsF metrics(painter.font());
    const double px = m.map(m_playhead, 0).x();
    if (std::isfinite(px) && px >= plot.left() - 1 && px <= plot.right() + 1) {
        const QString text = QString::number(m_playhead, 'f', 2);
        const double w = metrics.horizontalAdvance(text) + 10;
        const double left = std::clamp(px - w / 2, plot.left(), double(width()) - w);
        const QRectF box(left, plot.bottom() + 1, w, metrics.height() + 4);
        painter.setPen(Qt::NoPen);
        painter.setBrush(colors.highlight);
        painter.drawRoundedRect(box, 3, 3);
        painter.setPen(colors.highlightText);
        painter.drawText(box, Qt::AlignCenter, text);
    }

    // While keys move: how far, next to the cursor.
    if (m_drag == Drag::MovingKeys) {
        const QPointF delta = moveDelta(m_dragPos, m_dragModifiers);
        auto signedNumber = [](double value) {
            return (value >= 0 ? QStringLiteral("+") : QString()) + QString::number(value, 'f', 3);
        };
        const QString text = tr("Δt %1 s   Δv %2").arg(signedNumber(delta.x()), signedNumber(delta.y()));
        const QSizeF size(metrics.horizontalAdvance(text) + 12, metrics.height() + 6);
        QPointF corner = m_dragPos + QPointF(14, 14);
        corner.setX(std::min(corner.x(), plot.right() - size.width() - 2));
        corner.setY(std::min(corner.y(), plot.bottom() - size.height() - 2));
        const QRectF box(corner, size);
        painter.setPen(QPen(colors.gridEmphasis, 1));
        painter.setBrush(withAlpha(colors.gutter, 230));
        painter.drawRoundedRect(box.adjusted(0.5, 0.5, -0.5, -0.5), 3, 3);
        painter.setPen(colors.strongLabel);
        painter.drawText(box, Qt::AlignCenter, text);
    }

    if (m_curves.isEmpty())
        return;
    // Legend: top-right corner, one row per curve.
    const double swatch = 18, gap = 6, padding = 6, rowHeight = metrics.height() + 2;
    double textWidth = 0;
    for (const CurveViewCurve& curve : m_curves)
        textWidth = std::max(textWidth, metrics.horizontalAdvance(curve.name));
    const QSizeF size(padding * 2 + swatch + gap + textWidth, padding * 2 + rowHeight * double(m_curves.size()) - 2);
    const QRectF box(plot.right() - size.width() - 8, plot.top() + 8, size.width(), size.height());
    painter.setPen(QPen(colors.gridEmphasis, 1));
    painter.setBrush(withAlpha(colors.gutter, 215));
    painter.drawRoundedRect(box.adjusted(0.5, 0.5, -0.5, -0.5), 3, 3);
    double y = box.top() + padding;
    for (const CurveViewCurve& curve : m_curves) {
        const bool keyed = !curve.keys.isEmpty() || curve.keyable;
        QPen pen(curve.color, keyed ? 2.5 : 2.0);
        if (!keyed)
            pen.setDashPattern({3, 2});
        pen.setCapStyle(Qt::FlatCap);
        painter.setPen(pen);
        const double cy = y + rowHeight / 2 - 1;
        painter.drawLine(QPointF(box.left() + padding, cy), QPointF(box.left() + padding + swatch, cy));
        painter.setPen(colors.strongLabel);
        painter.drawText(QRectF(box.left() + padding + swatch + gap, y, textWidth + 1, rowHeight), Qt::AlignLeft | Qt::AlignVCenter,
                         curve.name);
        y += rowHeight;
    }
}

} // namespace thespis::widgets
