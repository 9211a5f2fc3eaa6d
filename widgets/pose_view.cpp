#include "widgets/pose_view.h"

#include <QLoggingCategory>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>
#include <limits>

Q_LOGGING_CATEGORY(lcPoseView, "thespis.widgets.poseview")

namespace thespis::widgets {

namespace {

const QColor kBackground(0x26, 0x29, 0x2e);
const QColor kFloor(0x30, 0x34, 0x3a);
const QColor kGrid(0x3a, 0x3f, 0x46);
const QColor kFloorLine(0x6b, 0x73, 0x7f);
const QColor kLabel(0xb8, 0xc0, 0xcc);
const QColor kSeparator(0x16, 0x18, 0x1b);

// Projection of a world position onto a panel: horizontal axis, vertical axis (up) and depth
// (larger = nearer the viewer, drawn last).
struct Axes {
    float (*horizontal)(const QVector3D&);
    float (*depth)(const QVector3D&);
};

// Front: the viewer stands in front of the figure (which faces +Z), so its left (+X) is on
// the viewer's right and larger Z is nearer.
const Axes kFrontAxes{[](const QVector3D& p) { return p.x(); }, [](const QVector3D& p) { return p.z(); }};
// Side: the viewer stands at the figure's right (−X) looking towards +X, so the figure faces
// right on screen (+Z to the right) and smaller X is nearer.
const Axes kSideAxes{[](const QVector3D& p) { return p.z(); }, [](const QVector3D& p) { return -p.x(); }};

// A "nice" grid step (1, 2 or 5 × 10^k) giving lines at least `minPixels` apart.
double gridStep(double pixelsPerUnit, double minPixels)
{
    const double raw = minPixels / std::max(pixelsPerUnit, 1e-9);
    const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    for (double factor : {1.0, 2.0, 5.0, 10.0})
        if (factor * magnitude >= raw)
            return factor * magnitude;
    return 10.0 * magnitude;
}

QString formatLength(double value, const QString& unit)
{
    return QStringLiteral("%1 %2").arg(QString::number(value, 'g', 3), unit);
}

} // namespace

QColor figureColor(int index)
{
    // Hand-picked hues (Tableau-like), bright enough on the dark viewport and distinct from
    // each other; past eight, rotate the hue by the golden angle.
    static const QColor palette[] = {QColor(0x4e, 0xa8, 0xde), QColor(0xf2, 0x8e, 0x2b),
                                     QColor(0x59, 0xc1, 0x6b), QColor(0xe1, 0x57, 0x59),
                                     QColor(0xb0, 0x7a, 0xd9), QColor(0xed, 0xc9, 0x48),
                                     QColor(0x76, 0xd7, 0xc4), QColor(0xff, 0x9d, 0xa7)};
    constexpr int count = int(std::size(palette));
    if (index >= 0 && index < count)
        return palette[index];
    return QColor::fromHsvF(std::fmod(0.61803398875 * index, 1.0), 0.6, 0.9);
}

PoseView::PoseView(QWidget* parent) : QWidget(parent)
{
    setAttribute(Qt::WA_OpaquePaintEvent);
    setAutoFillBackground(false);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
}

void PoseView::setFigures(std::vector<PoseFigure> figures)
{
    m_figures.clear();
    m_figures.reserve(figures.size());
    for (PoseFigure& info : figures) {
        Figure figure;
        figure.positions.reserve(info.parents.size());
        for (std::size_t joint = 0; joint < info.parents.size(); ++joint)
            if (info.parents[joint] >= 0)
                figure.boneOrder.push_back(int(joint));
        if (!info.sides.empty() && info.sides.size() != info.parents.size()) {
            qCWarning(lcPoseView) << "figure" << info.name << "has" << info.sides.size()
                                  << "sides for" << info.parents.size() << "joints; ignoring sides";
            info.sides.clear();
        }
        // Dots mark where a limb bends or ends (root, branches, leaves, side joints); the
        // chain of spine joints reads better as one line.
        std::vector<int> children(info.parents.size(), 0);
        for (int parent : info.parents)
            if (parent >= 0 && std::size_t(parent) < children.size())
                ++children[std::size_t(parent)];
        figure.dots.resize(info.parents.size());
        for (std::size_t joint = 0; joint < info.parents.size(); ++joint) {
            const bool side = !info.sides.empty() && info.sides[joint] != BodySide::Centre;
            figure.dots[joint] = info.parents[joint] < 0 || children[joint] != 1 || side;
        }
        figure.info = std::move(info);
        m_figures.push_back(std::move(figure));
    }
    m_labelRects.reserve(m_figures.size());
    m_figureOrder.reserve(m_figures.size());
    m_seenBounds = {};
    update();
}

void PoseView::setFigurePositions(int figure, std::span<const QVector3D> positions)
{
    if (figure < 0 || figure >= figureCount()) {
        qCWarning(lcPoseView) << "no figure" << figure << "(there are" << figureCount() << ")";
        return;
    }
    Figure& target = m_figures[std::size_t(figure)];
    if (positions.size() != target.info.parents.size()) {
        qCWarning(lcPoseView) << "figure" << target.info.name << "has" << target.info.parents.size()
                              << "joints but got" << positions.size() << "positions";
        return;
    }
    // assign() reuses the capacity reserved in setFigures(): no allocation per frame.
    target.positions.assign(positions.begin(), positions.end());
    if (!m_sceneBounds.valid)
        growBounds(positions);
    update();
}

std::span<const QVector3D> PoseView::figurePositions(int figure) const
{
    if (figure < 0 || figure >= figureCount())
        return {};
    return m_figures[std::size_t(figure)].positions;
}

void PoseView::setSceneBounds(const QVector3D& min, const QVector3D& max)
{
    m_sceneBounds = {min, max, true};
    update();
}

void PoseView::clearSceneBounds()
{
    m_sceneBounds = {};
    m_seenBounds = {};
    for (const Figure& figure : m_figures)
        growBounds(figure.positions);
    update();
}

void PoseView::setProjection(Projection projection)
{
    if (projection == m_projection)
        return;
    m_projection = projection;
    update();
}

void PoseView::setLengthUnit(const QString& unit)
{
    m_unit = unit;
    update();
}

void PoseView::setPlaceholderText(const QString& text)
{
    m_placeholder = text;
    update();
}

QSize PoseView::sizeHint() const
{
    return {720, 480};
}

QSize PoseView::minimumSizeHint() const
{
    return {240, 180};
}

void PoseView::growBounds(std::span<const QVector3D> positions)
{
    for (const QVector3D& p : positions) {
        if (!m_seenBounds.valid) {
            m_seenBounds = {p, p, true};
            continue;
        }
        m_seenBounds.min = QVector3D(std::min(m_seenBounds.min.x(), p.x()), std::min(m_seenBounds.min.y(), p.y()),
                                     std::min(m_seenBounds.min.z(), p.z()));
        m_seenBounds.max = QVector3D(std::max(m_seenBounds.max.x(), p.x()), std::max(m_seenBounds.max.y(), p.y()),
                                     std::max(m_seenBounds.max.z(), p.z()));
    }
}

void PoseView::paintEvent(QPaintEvent*)
{
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.fillRect(rect(), kBackground);

    const bool anyPose = std::any_of(m_figures.begin(), m_figures.end(),
                                     [](const Figure& f) { return !f.positions.empty(); });
    if (!anyPose) {
        painter.setPen(kLabel);
        QFont font = painter.font();
        font.setPointSizeF(font.pointSizeF() * 1.2);
        painter.setFont(font);
        painter.drawText(rect().adjusted(20, 20, -20, -20), Qt::AlignCenter | Qt::TextWordWrap,
                         m_placeholder.isEmpty() ? tr("Nothing to show") : m_placeholder);
        return;
    }

    const QRectF area = rect();
    const QFontMetrics metrics = painter.fontMetrics();
    if (m_projection == Projection::FrontAndSide) {
        // One scale for both panels, so that a figure is as tall in the side view as in the
        // front view and one scale bar reads for both; each panel gets the width its content
        // needs at that scale (the front usually more: characters stand side by side).
        const Framing front = framing(Projection::Front);
        const Framing side = framing(Projection::Side);
        const qreal fraction = std::clamp(qreal(front.spanH() / (front.spanH() + side.spanH())), qreal(0.5), qreal(0.75));
        const qreal split = std::round(area.width() * fraction);
        const QRectF frontRect(area.left(), area.top(), split, area.height());
        const QRectF sideRect(area.left() + split + 1, area.top(), area.width() - split - 1, area.height());
        const qreal scale = std::min(fitScale(front, innerRect(frontRect, metrics)), fitScale(side, innerRect(sideRect, metrics)));
        paintPanel(painter, frontRect, Projection::Front, scale);
        paintPanel(painter, sideRect, Projection::Side, scale);
        painter.setPen(QPen(kSeparator, 2));
        painter.drawLine(QPointF(frontRect.right() + 0.5, area.top()), QPointF(frontRect.right() + 0.5, area.bottom()));
    } else {
        paintPanel(painter, area, m_projection, fitScale(framing(m_projection), innerRect(area, metrics)));
    }
}

PoseView::Framing PoseView::framing(Projection panel) const
{
    const Axes& axes = panel == Projection::Side ? kSideAxes : kFrontAxes;
    // The scene bounds (or what was seen), padded for heads.
    Bounds bounds = m_sceneBounds.valid ? m_sceneBounds : m_seenBounds;
    if (!bounds.valid)
        bounds = {QVector3D(-1, 0, -1), QVector3D(1, 2, 1), true};
    float headRoom = 0;
    for (const Figure& figure : m_figures)
        if (figure.info.headJoint >= 0)
            headRoom = std::max(headRoom, 2.2f * figure.info.headRadius);
    Framing frame;
    frame.h0 = std::min(axes.horizontal(bounds.min), axes.horizontal(bounds.max));
    frame.h1 = std::max(axes.horizontal(bounds.min), axes.horizontal(bounds.max));
    frame.v0 = bounds.min.y();
    frame.v1 = bounds.max.y() + headRoom;
    // A figure seen edge-on still gets some width, for its name and the grid around it.
    const float minWidth = 0.3f * frame.spanV();
    if (frame.h1 - frame.h0 < minWidth) {
        const float centre = 0.5f * (frame.h0 + frame.h1);
        frame.h0 = centre - 0.5f * minWidth;
        frame.h1 = centre + 0.5f * minWidth;
    }
    return frame;
}

QRectF PoseView::innerRect(const QRectF& panel, const QFontMetrics& metrics)
{
    // Room for the title above, the names over the heads and the scale bar below.
    const qreal titleHeight = metrics.height() + 12;
    return panel.adjusted(24, titleHeight + 2 * metrics.height() + 8, -24, -36);
}

qreal PoseView::fitScale(const Framing& frame, const QRectF& inner)
{
    return std::max(1e-6, std::min(inner.width() / (frame.spanH() * 1.1), inner.height() / (frame.spanV() * 1.02)));
}

void PoseView::paintPanel(QPainter& painter, const QRectF& rect, Projection panel, qreal scale)
{
    const Axes& axes = panel == Projection::Side ? kSideAxes : kFrontAxes;
    painter.save();
    painter.setClipRect(rect);

    const Framing frame = framing(panel);
    const float v0 = frame.v0;
    const qreal titleHeight = painter.fontMetrics().height() + 12;
    const QRectF inner = innerRect(rect, painter.fontMetrics());
    const qreal centreH = 0.5 * (frame.h0 + frame.h1);
    // Centred horizontally; vertically, spare room goes mostly above the heads, so the figures
    // stand low in the panel with little floor below them, as on a stage.
    const qreal slack = std::max(0.0, inner.height() - frame.spanV() * scale);
    const QPointF origin(inner.center().x(), inner.bottom() - 0.25 * slack);
    auto toScreen = [&](float horizontal, float up) {
        return QPointF(origin.x() + (horizontal - centreH) * scale, origin.y() - (up - v0) * scale);
    };
    auto project = [&](const QVector3D& p) { return toScreen(axes.horizontal(p), p.y()); };

    // Floor below the lowest point, and a grid with a readable spacing.
    const qreal floorY = toScreen(0, v0).y();
    painter.fillRect(QRectF(rect.left(), floorY, rect.width(), rect.bottom() - floorY), kFloor);
    const double step = gridStep(scale, 48);
    painter.setPen(QPen(kGrid, 1));
    const double firstH = std::ceil((centreH - rect.width() / (2 * scale)) / step) * step;
    for (double h = firstH; toScreen(float(h), 0).x() < rect.right(); h += step)
        painter.drawLine(QPointF(toScreen(float(h), 0).x(), rect.top() + titleHeight), QPointF(toScreen(float(h), 0).x(), floorY));
    for (double v = v0 + step; toScreen(0, float(v)).y() > rect.top() + titleHeight; v += step)
        painter.drawLine(QPointF(rect.left(), toScreen(0, float(v)).y()), QPointF(rect.right(), toScreen(0, float(v)).y()));
    painter.setPen(QPen(kFloorLine, 1.5));
    painter.drawLine(QPointF(rect.left(), floorY), QPointF(rect.right(), floorY));

    // Title and scale bar, so that a viewer knows what is shown and how big it is.
    painter.setPen(kLabel);
    const QString title = panel == Projection::Side ? tr("Side (from the right)") : tr("Front");
    painter.drawText(rect.adjusted(10, 6, -10, 0), Qt::AlignLeft | Qt::AlignTop, title);
    const qreal barLength = step * scale;
    const QPointF barEnd(rect.right() - 14, rect.bottom() - 12);
    const QPointF barStart(barEnd.x() - barLength, barEnd.y());
    painter.setPen(QPen(kLabel, 1.5));
    painter.drawLine(barStart, barEnd);
    painter.drawLine(barStart + QPointF(0, -4), barStart + QPointF(0, 4));
    painter.drawLine(barEnd + QPointF(0, -4), barEnd + QPointF(0, 4));
    painter.drawText(QRectF(barStart.x() - 80, barStart.y() - 20, barLength + 80, 16), Qt::AlignRight | Qt::AlignBottom,
                     formatLength(step, m_unit));

    const qreal boneWidth = std::clamp(scale * 0.028, 2.0, 9.0);
    m_labelRects.clear(); // keeps its capacity, reserved for every figure in setFigures()
    // Far figures first, so that the nearer one is drawn over them (by their roots' depth).
    m_figureOrder.clear(); // capacity reserved in setFigures()
    for (std::size_t i = 0; i < m_figures.size(); ++i)
        if (!m_figures[i].positions.empty())
            m_figureOrder.push_back(int(i));
    // std::sort with the index as tie-break: stable without stable_sort's temporary buffer.
    std::sort(m_figureOrder.begin(), m_figureOrder.end(), [&](int a, int b) {
        const float da = axes.depth(m_figures[std::size_t(a)].positions.front());
        const float db = axes.depth(m_figures[std::size_t(b)].positions.front());
        return da < db || (da == db && a < b);
    });
    for (int figureIndex : m_figureOrder) {
        Figure& figure = m_figures[std::size_t(figureIndex)];
        const std::vector<QVector3D>& pos = figure.positions;
        const PoseFigure& info = figure.info;
        // Far bones first so that the near arm is drawn over the body.
        std::sort(figure.boneOrder.begin(), figure.boneOrder.end(), [&](int a, int b) {
            const float da = axes.depth(pos[std::size_t(a)]) + axes.depth(pos[std::size_t(info.parents[std::size_t(a)])]);
            const float db = axes.depth(pos[std::size_t(b)]) + axes.depth(pos[std::size_t(info.parents[std::size_t(b)])]);
            return da < db;
        });
        auto sideColor = [&](int joint) {
            const BodySide side = info.sides.empty() ? BodySide::Centre : info.sides[std::size_t(joint)];
            // In the front view the figure's left is on the viewer's right; lighter = left.
            return side == BodySide::Left ? info.color.lighter(135)
                 : side == BodySide::Right ? info.color.darker(140) : info.color;
        };
        for (int joint : figure.boneOrder) {
            const int parent = info.parents[std::size_t(joint)];
            painter.setPen(QPen(sideColor(joint), boneWidth, Qt::SolidLine, Qt::RoundCap));
            painter.drawLine(project(pos[std::size_t(parent)]), project(pos[std::size_t(joint)]));
        }
        painter.setPen(Qt::NoPen);
        painter.setBrush(info.color.darker(170));
        const qreal jointRadius = boneWidth * 0.55;
        for (std::size_t joint = 0; joint < pos.size(); ++joint)
            if (figure.dots[joint])
                painter.drawEllipse(project(pos[joint]), jointRadius, jointRadius);

        // Head: a circle just beyond the head joint, along the neck.
        qreal top = std::numeric_limits<qreal>::max();
        for (const QVector3D& p : pos)
            top = std::min(top, project(p).y());
        if (info.headJoint >= 0 && info.headJoint < int(pos.size())) {
            const QVector3D head = pos[std::size_t(info.headJoint)];
            const int neckJoint = info.parents[std::size_t(info.headJoint)];
            QVector3D up(0, 1, 0);
            if (neckJoint >= 0 && (head - pos[std::size_t(neckJoint)]).length() > 1e-6f)
                up = (head - pos[std::size_t(neckJoint)]).normalized();
            const QPointF centre = project(head + up * info.headRadius);
            const qreal radius = info.headRadius * scale;
            QColor fill = info.color;
            fill.setAlphaF(0.35f);
            painter.setBrush(fill);
            painter.setPen(QPen(info.color, boneWidth * 0.7));
            painter.drawEllipse(centre, radius, radius);
            top = std::min(top, centre.y() - radius);
        }

        if (!info.name.isEmpty()) {
            const QPointF anchor = project(pos.front());
            QFont font = painter.font();
            font.setBold(true);
            painter.setFont(font);
            const qreal width = painter.fontMetrics().horizontalAdvance(info.name) + 8;
            const qreal height = painter.fontMetrics().height();
            QRectF label(anchor.x() - width / 2, top - 6 - height, width, height);
            // Figures standing close together would print their names over each other: stack
            // a label above any placed before it.
            for (bool moved = true; moved;) {
                moved = false;
                for (const QRectF& placed : m_labelRects)
                    if (placed.intersects(label)) {
                        label.moveBottom(placed.top() - 2);
                        moved = true;
                    }
            }
            m_labelRects.push_back(label);
            painter.setPen(info.color.lighter(115));
            painter.drawText(label, Qt::AlignCenter, info.name);
            font.setBold(false);
            painter.setFont(font);
        }
        painter.setBrush(Qt::NoBrush);
    }
    painter.restore();
}

} // namespace thespis::widgets
