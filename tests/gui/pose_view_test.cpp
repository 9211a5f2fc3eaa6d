// PoseView: draws figures from plain positions (no core), with H-Anim axes in each projection.

#include <QImage>
#include <QTest>

#include "widgets/pose_view.h"

using thespis::widgets::BodySide;
using thespis::widgets::PoseFigure;
using thespis::widgets::PoseView;

namespace {

const QColor kRed(255, 0, 0);

bool isFigurePixel(QRgb pixel)
{
    // The bones are drawn in the figure colour (pure red here, lighter or darker per side); the
    // viewport itself is grey-blue, so "much more red than green and blue" finds the figure.
    return qRed(pixel) > 150 && qGreen(pixel) < 120 && qBlue(pixel) < 120;
}

// Bounding box of the figure's pixels, or a null rect when there are none.
QRect figureExtent(const QImage& image)
{
    QRect box;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            if (isFigurePixel(image.pixel(x, y)))
                box = box.united(QRect(x, y, 1, 1));
    return box;
}

// A T: a spine up from the root and a bar along +X (the figure's left) at the top.
PoseFigure tFigure()
{
    PoseFigure figure;
    figure.color = kRed;
    figure.parents = {-1, 0, 1};
    figure.sides = {BodySide::Centre, BodySide::Centre, BodySide::Left};
    return figure;
}

const QVector3D kT[] = {QVector3D(0, 0, 0), QVector3D(0, 1.5f, 0), QVector3D(0.8f, 1.5f, 0)};

} // namespace

class PoseViewTest : public QObject {
    Q_OBJECT
private slots:
    void showsPlaceholderWithoutPoses();
    void paintsAFigure();
    void frontViewPutsTheFiguresLeftOnTheRight();
    void sideViewLooksAlongX();
    void ignoresPositionsOfTheWrongCount();
    void growsFramingWithoutSceneBounds();
};

void PoseViewTest::showsPlaceholderWithoutPoses()
{
    PoseView view;
    view.resize(400, 300);
    view.setPlaceholderText(QStringLiteral("Nothing here"));
    view.setFigures({tFigure()});
    QCOMPARE(view.figureCount(), 1);
    QVERIFY(view.figurePositions(0).empty());
    QVERIFY(figureExtent(view.grab().toImage()).isNull());
}

void PoseViewTest::paintsAFigure()
{
    PoseView view;
    view.resize(400, 300);
    view.setProjection(PoseView::Projection::Front);
    view.setFigures({tFigure()});
    view.setFigurePositions(0, kT);
    QCOMPARE(view.figurePositions(0).size(), std::size_t(3));
    QCOMPARE(view.figurePositions(0)[2], kT[2]);
    const QRect extent = figureExtent(view.grab().toImage());
    QVERIFY(!extent.isNull());
    // 1.5 m tall and framed to fit: it fills a good part of the height.
    QVERIFY2(extent.height() > 100, qPrintable(QString::number(extent.height())));
}

void PoseViewTest::frontViewPutsTheFiguresLeftOnTheRight()
{
    // Facing the viewer, the figure's left hand (+X) is on the viewer's right.
    PoseView view;
    view.resize(400, 300);
    view.setProjection(PoseView::Projection::Front);
    view.setFigures({tFigure()});
    view.setFigurePositions(0, kT);
    const QImage image = view.grab().toImage();
    const QRect extent = figureExtent(image);
    // The spine is the leftmost part of the figure; the bar reaches out to the right.
    QVERIFY2(extent.width() > 80, qPrintable(QString::number(extent.width())));
    int spineX = -1;
    for (int x = 0; x < image.width() && spineX < 0; ++x)
        if (isFigurePixel(image.pixel(x, extent.bottom() - 10)))
            spineX = x;
    QVERIFY(spineX >= 0);
    QVERIFY2(extent.right() - spineX > 60, "the +X bar should extend to the right of the spine");
    QVERIFY(spineX - extent.left() < 15);
}

void PoseViewTest::sideViewLooksAlongX()
{
    // From the side, a bar along X points at the viewer: the T collapses to a line.
    PoseView view;
    view.resize(400, 300);
    view.setFigures({tFigure()});
    view.setFigurePositions(0, kT);
    view.setProjection(PoseView::Projection::Front);
    const QRect front = figureExtent(view.grab().toImage());
    view.setProjection(PoseView::Projection::Side);
    const QRect side = figureExtent(view.grab().toImage());
    QVERIFY(!side.isNull());
    QVERIFY2(side.width() < front.width() / 3,
             qPrintable(QStringLiteral("side %1 px wide, front %2 px").arg(side.width()).arg(front.width())));
}

void PoseViewTest::ignoresPositionsOfTheWrongCount()
{
    PoseView view;
    view.setFigures({tFigure()});
    view.setFigurePositions(0, kT);
    const QVector3D two[] = {QVector3D(1, 1, 1), QVector3D(2, 2, 2)};
    view.setFigurePositions(0, two);
    QCOMPARE(view.figurePositions(0)[0], kT[0]);
    view.setFigurePositions(5, kT); // no such figure: ignored
    QVERIFY(view.figurePositions(5).empty());
}

void PoseViewTest::growsFramingWithoutSceneBounds()
{
    PoseView view;
    view.resize(400, 300);
    view.setProjection(PoseView::Projection::Front);
    view.setFigures({tFigure()});
    view.setFigurePositions(0, kT);
    const QRect before = figureExtent(view.grab().toImage());
    // A pose far away to the side grows the framing, so the first pose looks smaller.
    const QVector3D far[] = {QVector3D(4, 0, 0), QVector3D(4, 1.5f, 0), QVector3D(4.8f, 1.5f, 0)};
    view.setFigurePositions(0, far);
    view.setFigurePositions(0, kT);
    const QRect after = figureExtent(view.grab().toImage());
    QVERIFY(after.height() < before.height());
    // Fixed scene bounds replace what was seen.
    view.setSceneBounds(QVector3D(0, 0, 0), QVector3D(0.8f, 1.5f, 0));
    QCOMPARE(figureExtent(view.grab().toImage()).height(), before.height());
}

QTEST_MAIN(PoseViewTest)
#include "pose_view_test.moc"
