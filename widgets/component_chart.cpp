#include "widgets/component_chart.h"

#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace thespis::widgets {

namespace {

constexpr int kMargin = 8;
constexpr int kAxisLeft = 44;   // room for the value labels
constexpr int kAxisBottom = 22; // room for the index labels

// A round step for about `ticks` labels over [0, top].
double niceStep(double top, int ticks)
{
    const double raw = top / std::max(1, ticks);
    const double power = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 2.5, 5.0, 10.0})
        if (m * power >= raw)
            return m * power;
    return 10 * power;
}

} // namespace

ComponentChart::ComponentChart(QWidget* parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("componentChart"));
    setAutoFillBackground(true);
    setBackgroundRole(QPalette::Base);
}

void ComponentChart::setSeries(ChartSeries bars, QVector<ChartSeries> lines)
{
    m_bars = std::move(bars);
    m_lines = std::move(lines);
    update();
}

void ComponentChart::setBands(QVector<ChartBand> bands)
{
    m_bands = std::move(bands);
    update();
}

void ComponentChart::setMessage(const QString& message)
{
    m_message = message;
    update();
}

void ComponentChart::setCaption(const QString& caption)
{
    m_caption = caption;
    update();
}

void ComponentChart::paintEvent(QPaintEvent*)
{
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    const QPalette& pal = palette();
    const QFontMetrics fm = fontMetrics();
    if (m_bars.values.isEmpty()) {
        painter.setPen(pal.color(QPalette::PlaceholderText));
        painter.drawText(rect().adjusted(kMargin, kMargin, -kMargin, -kMargin), Qt::AlignCenter | Qt::TextWordWrap,
                         m_message);
        return;
    }
    // Legend and caption on top.
    int y = kMargin;
    int x = kAxisLeft;
    const int swatch = fm.height() - 4;
    auto legend = [&](const ChartSeries& series, bool bar) {
        painter.setPen(Qt::NoPen);
        painter.setBrush(series.color);
        if (bar)
            painter.drawRect(x, y + 2, swatch, swatch);
        else
            painter.drawRect(x, y + fm.height() / 2 - 1, swatch, 3);
        painter.setPen(pal.color(QPalette::Text));
        painter.drawText(x + swatch + 4, y + fm.ascent(), series.name);
        x += swatch + 4 + fm.horizontalAdvance(series.name) + 16;
    };
    legend(m_bars, true);
    for (const ChartSeries& line : m_lines)
        legend(line, false);
    y += fm.height() + 2;
    if (!m_caption.isEmpty()) {
        painter.setPen(pal.color(QPalette::Text));
        painter.drawText(kAxisLeft, y + fm.ascent(), m_caption);
        y += fm.height() + 2;
    }
    const QRectF plot(kAxisLeft, y + 4, width() - kAxisLeft - kMargin, height() - y - 4 - kAxisBottom);
    if (plot.width() < 20 || plot.height() < 20)
        return;

    const int count = int(m_bars.values.size());
    float top = 0;
    for (float v : m_bars.values)
        top = std::max(top, v);
    for (const ChartSeries& line : m_lines)
        for (int i = 0; i < std::min<int>(count, int(line.values.size())); ++i)
            top = std::max(top, line.values[i]);
    top = top > 0 ? top * 1.05f : 1.0f;
    const double slot = plot.width() / count;
    auto xOf = [&](double index) { return plot.left() + (index - 0.5) * slot; }; // centre of component `index`
    auto yOf = [&](double value) { return plot.bottom() - value / top * plot.height(); };

    // Bands behind everything.
    for (const ChartBand& band : m_bands) {
        const double left = xOf(std::max(1, band.first) - 0.5), right = xOf(std::min(count, band.last) + 0.5);
        if (right <= left)
            continue;
        QColor shade = pal.color(QPalette::Highlight);
        shade.setAlpha(28);
        painter.fillRect(QRectF(left, plot.top(), right - left, plot.height()), shade);
        painter.setPen(pal.color(QPalette::PlaceholderText));
        painter.drawText(QRectF(left + 3, plot.top() + 2, right - left - 6, fm.height() * 2), Qt::AlignLeft | Qt::TextWordWrap,
                         band.label);
    }
    // Axes, value grid and labels.
    const double step = niceStep(top, 4);
    painter.setFont(font());
    for (double v = 0; v <= top; v += step) {
        painter.setPen(QPen(pal.color(QPalette::Mid), 0, v == 0 ? Qt::SolidLine : Qt::DotLine));
        painter.drawLine(QPointF(plot.left(), yOf(v)), QPointF(plot.right(), yOf(v)));
        painter.setPen(pal.color(QPalette::Text));
        painter.drawText(QRectF(0, yOf(v) - fm.height() / 2.0, kAxisLeft - 4, fm.height()), Qt::AlignRight | Qt::AlignVCenter,
                         QString::number(v, 'g', 3));
    }
    const int labelEvery = count <= 20 ? 1 : count <= 50 ? 5 : 10;
    for (int i = 1; i <= count; ++i)
        if (i == 1 || i % labelEvery == 0)
            painter.drawText(QRectF(xOf(i) - 20, plot.bottom() + 2, 40, fm.height()), Qt::AlignHCenter | Qt::AlignTop,
                             QString::number(i));
    // The bars, then the lines over them.
    painter.setPen(Qt::NoPen);
    painter.setBrush(m_bars.color);
    const double barWidth = std::max(1.0, slot * 0.7);
    for (int i = 0; i < count; ++i)
        painter.drawRect(QRectF(xOf(i + 1) - barWidth / 2, yOf(m_bars.values[i]), barWidth, plot.bottom() - yOf(m_bars.values[i])));
    painter.setBrush(Qt::NoBrush);
    for (const ChartSeries& line : m_lines) {
        QPainterPath path;
        for (int i = 0; i < std::min<int>(count, int(line.values.size())); ++i) {
            const QPointF p(xOf(i + 1), yOf(line.values[i]));
            i == 0 ? path.moveTo(p) : path.lineTo(p);
        }
        painter.setPen(QPen(line.color, 2));
        painter.drawPath(path);
    }
}

} // namespace thespis::widgets
