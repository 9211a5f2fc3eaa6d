#pragma once
// PoseView: paints skeletons as stick figures from joint positions, in an orthographic front
// view, side view or both side by side. It knows nothing of the animation engine: the caller
// describes each figure once (joint parents, colour, which joints are left / right / the head)
// and then feeds world positions whenever the pose changes. Units are whatever the positions
// use (metres for H-Anim); axes follow H-Anim: +Y up, the figure faces +Z, +X is its left.
// Owns a copy of every figure's description and latest positions.

#include <QColor>
#include <QFontMetrics>
#include <QRectF>
#include <QString>
#include <QVector3D>
#include <QWidget>

#include <algorithm>
#include <span>
#include <vector>

namespace thespis::widgets {

/// Which side of the body a joint is on; left and right limbs are drawn in two shades so that a
/// viewer can tell them apart in a front view.
enum class BodySide : unsigned char { Centre, Left, Right };

/// What PoseView needs to know about one figure (a character's skeleton).
struct PoseFigure {
    QString name;               ///< drawn above the figure
    QColor color;
    std::vector<int> parents;   ///< one per joint; -1 for a root. Parents come before children.
    std::vector<BodySide> sides;///< one per joint, or empty (everything Centre)
    int headJoint = -1;         ///< joint drawn with a head circle above it, -1 for none
    float headRadius = 0.1f;    ///< in position units
};

class PoseView : public QWidget {
    Q_OBJECT
public:
    enum class Projection { Front, Side, FrontAndSide };
    Q_ENUM(Projection)

    explicit PoseView(QWidget* parent = nullptr);

    /// Replaces every figure; positions start empty (the figure is not drawn until it has some).
    void setFigures(std::vector<PoseFigure> figures);
    int figureCount() const { return int(m_figures.size()); }
    const PoseFigure& figure(int index) const { return m_figures[std::size_t(index)].info; }

    /// Sets one figure's joint positions (one per joint of its description; a wrong count is
    /// ignored and logged). Copies into storage kept from the previous call, so feeding poses
    /// every frame does not allocate.
    void setFigurePositions(int figure, std::span<const QVector3D> positions);
    std::span<const QVector3D> figurePositions(int figure) const;

    /// The region the views frame, fixed so that a figure walking around does not make the
    /// camera jitter. Without it the framing grows to contain every pose seen so far.
    void setSceneBounds(const QVector3D& min, const QVector3D& max);
    void clearSceneBounds();

    /// Unit of the positions, shown on the scale bar (default "m"). BVH skeletons keep their
    /// file's unit, which the file does not name.
    void setLengthUnit(const QString& unit);
    QString lengthUnit() const { return m_unit; }

    void setProjection(Projection projection);
    Projection projection() const { return m_projection; }

    /// Shown in the middle of the view while there is no figure (e.g. "No scenario loaded").
    void setPlaceholderText(const QString& text);
    QString placeholderText() const { return m_placeholder; }

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    struct Figure {
        PoseFigure info;
        std::vector<QVector3D> positions;
        std::vector<int> boneOrder; // scratch for depth sorting, sized with the figure
        std::vector<char> dots;     // per joint: draw a dot on it
    };
    struct Bounds {
        QVector3D min, max;
        bool valid = false;
    };

    // What a panel frames, in its own axes: horizontal [h0, h1], vertical [v0, v1].
    struct Framing {
        float h0 = 0, h1 = 0, v0 = 0, v1 = 0;
        float spanH() const { return std::max(h1 - h0, 1e-3f); }
        float spanV() const { return std::max(v1 - v0, 1e-3f); }
    };
    Framing framing(Projection panel) const;
    static QRectF innerRect(const QRectF& panel, const QFontMetrics& metrics);
    static qreal fitScale(const Framing& frame, const QRectF& inner);
    void paintPanel(class QPainter& painter, const QRectF& rect, Projection panel, qreal scale);
    void growBounds(std::span<const QVector3D> positions);

    std::vector<Figure> m_figures;
    std::vector<QRectF> m_labelRects; // scratch: name labels placed so far in one panel
    std::vector<int> m_figureOrder;   // scratch: figures far to near in one panel
    Bounds m_sceneBounds; // given by the caller
    Bounds m_seenBounds;  // grown from poses when no scene bounds are given
    Projection m_projection = Projection::FrontAndSide;
    QString m_placeholder;
    QString m_unit = QStringLiteral("m");
};

/// A colour per figure index, distinct for the first eight and readable on the dark viewport.
QColor figureColor(int index);

} // namespace thespis::widgets
