// The curve view's pure geometry, without a widget: (seconds, value) ↔ pixel round trips for
// several plots and visible ranges, framing, grid steps, tangent handles and the slopes they give
// back, move deltas, and hit testing of keys, handles, curves and boxes.

#include <QTest>

#include <cmath>

#include "widgets/curve_geometry.h"

using namespace thespis::widgets;
using M = CurveMetrics;

Q_DECLARE_METATYPE(thespis::widgets::CurveRange)

namespace {

CurveViewKey key(double time, double value, CurveTangent mode = CurveTangent::AutoClamped, double inSlope = 0,
                 double outSlope = 0)
{
    CurveViewKey k;
    k.time = time;
    k.value = value;
    k.mode = mode;
    k.inSlope = inSlope;
    k.outSlope = outSlope;
    return k;
}

CurveViewCurve keyed(QVector<CurveViewKey> keys)
{
    CurveViewCurve c;
    c.keys = std::move(keys);
    return c;
}

bool near(QPointF a, QPointF b, double tolerance = 1e-6)
{
    return std::abs(a.x() - b.x()) <= tolerance && std::abs(a.y() - b.y()) <= tolerance;
}

// 400 × 200 pixels showing 0..2 s and 0..1: 200 px per second, 200 px per value unit.
const QRectF kPlot(40, 0, 400, 200);
const CurveMapping kMap = CurveMapping::fit(kPlot, {0, 2, 0, 1});

} // namespace

class CurveGeometryTest : public QObject {
    Q_OBJECT
private slots:
    void mapsAndUnmaps_data();
    void mapsAndUnmaps();
    void framesDataInsideThePlot();
    void boundsOfDataAndDomain();
    void gridStepsAreNice();
    void tangentHandlesFollowTheSlopeOnScreen();
    void moveDeltaConstrainsToTheDominantAxis();
    void keyUnderPicksTheNearestWithinReach();
    void handleUnderOnlyForSelectedFreeOrBrokenKeys();
    void curveNearUsesSamplesOrKeyLines();
    void keysInABox();
};

void CurveGeometryTest::mapsAndUnmaps_data()
{
    QTest::addColumn<QRectF>("plot");
    QTest::addColumn<CurveRange>("range");
    QTest::newRow("unit") << QRectF(0, 0, 100, 100) << CurveRange{0, 1, 0, 1};
    QTest::newRow("gutters, weights") << QRectF(46, 0, 654, 296) << CurveRange{-0.1, 1.1, -0.1, 1.1};
    QTest::newRow("zoomed in, panned") << QRectF(46, 0, 300, 180) << CurveRange{12.25, 12.5, 3.0, 3.001};
    QTest::newRow("zoomed out, negative") << QRectF(20, 10, 800, 400) << CurveRange{-5000, 9000, -250, 40};
}

void CurveGeometryTest::mapsAndUnmaps()
{
    QFETCH(QRectF, plot);
    QFETCH(CurveRange, range);
    const CurveMapping m = CurveMapping::fit(plot, range);
    // The range's corners are the plot's corners: t0 left, v0 bottom.
    QVERIFY(near(m.map(range.t0, range.v0), plot.bottomLeft(), 1e-6));
    QVERIFY(near(m.map(range.t1, range.v1), plot.topRight(), 1e-6));
    // Pixels round-trip exactly enough, and so do curve points.
    for (double x = plot.left() - 30; x <= plot.right() + 30; x += 37.5)
        for (double y = plot.top() - 20; y <= plot.bottom() + 20; y += 29.25)
            QVERIFY(near(m.map(m.unmap(QPointF(x, y))), QPointF(x, y), 1e-6));
    const double dt = range.t1 - range.t0, dv = range.v1 - range.v0;
    for (double f : {0.0, 0.13, 0.5, 0.99, 1.7}) {
        const QPointF p(range.t0 + f * dt, range.v0 + (1 - f) * dv);
        QVERIFY(near(m.unmap(m.map(p)), p, 1e-9 * std::max({1.0, std::abs(p.x()), std::abs(p.y())})));
    }
    // Values go up.
    QVERIFY(m.map(range.t0, range.v1).y() < m.map(range.t0, range.v0).y());
}

void CurveGeometryTest::framesDataInsideThePlot()
{
    const CurveRange framed = framedRange(kPlot, {0, 2, 0, 1});
    const CurveMapping m = CurveMapping::fit(kPlot, framed);
    // The data sits FramePadding pixels inside the plot.
    QVERIFY(near(m.map(0, 0), QPointF(kPlot.left() + M::FramePaddingX, kPlot.bottom() - M::FramePaddingY), 1e-9));
    QVERIFY(near(m.map(2, 1), QPointF(kPlot.right() - M::FramePaddingX, kPlot.top() + M::FramePaddingY), 1e-9));

    // Flat data is widened by half a unit each way before padding.
    const CurveRange flat = framedRange(kPlot, {3, 3, 0.5, 0.5});
    QVERIFY(flat.t0 < 2.5 && flat.t1 > 3.5);
    QVERIFY(flat.v0 < 0 && flat.v1 > 1);
    QCOMPARE(0.5 * (flat.t0 + flat.t1), 3.0);

    // A tiny plot pads by at most a quarter of it each side.
    const QRectF tiny(0, 0, 40, 30);
    const CurveMapping t = CurveMapping::fit(tiny, framedRange(tiny, {0, 1, 0, 1}));
    QVERIFY(near(t.map(0, 0), QPointF(10, 22.5), 1e-9));
}

void CurveGeometryTest::boundsOfDataAndDomain()
{
    QVector<CurveViewCurve> curves(2);
    curves[0].samples = {{-1, 0.2}, {0.5, 2.5}, {9, -3}, {10, std::nan("")}};
    curves[1].keys = {key(0.25, 0.5), key(4, -0.5), key(std::nan(""), 100)};

    const CurveRange data = *curveDataBounds(curves);
    QCOMPARE(data.t0, -1.0);
    QCOMPARE(data.t1, 9.0);
    QCOMPARE(data.v0, -3.0);
    QCOMPARE(data.v1, 2.5);
    QVERIFY(!curveDataBounds({}).has_value());
    QVERIFY(!curveDataBounds({CurveViewCurve{}}).has_value());

    // The domain 0..2: samples outside it do not count, keys do; values at least 0..1.
    const CurveRange domain = domainBounds(curves, 0, 2);
    QCOMPARE(domain.t0, 0.0);
    QCOMPARE(domain.t1, 4.0);
    QCOMPARE(domain.v0, -0.5);
    QCOMPARE(domain.v1, 2.5);
    const CurveRange empty = domainBounds({}, 1, 3);
    QCOMPARE(empty.t0, 1.0);
    QCOMPARE(empty.t1, 3.0);
    QCOMPARE(empty.v0, 0.0);
    QCOMPARE(empty.v1, 1.0);
}

void CurveGeometryTest::gridStepsAreNice()
{
    int minor = 0;
    QCOMPARE(niceGridStep(100, 50, &minor), 0.5); // 0.5 units = 50 px
    QCOMPARE(minor, 5);
    QCOMPARE(niceGridStep(100, 51, &minor), 1.0);
    QCOMPARE(niceGridStep(100, 120, &minor), 2.0);
    QCOMPARE(minor, 4);
    QCOMPARE(niceGridStep(0.01, 80, &minor), 10000.0);
    QVERIFY(std::abs(niceGridStep(2e5, 40, &minor) - 2e-4) < 1e-15);
}

void CurveGeometryTest::tangentHandlesFollowTheSlopeOnScreen()
{
    // Out slope 0.5 at 200 px per second and per unit: on screen, right and up, 1 px up per 2 across.
    const CurveViewKey k = key(1, 0.5, CurveTangent::Broken, -1, 0.5);
    const QPointF centre = kMap.map(1, 0.5);
    const QPointF out = tangentHandlePoint(kMap, k, true);
    const QPointF in = tangentHandlePoint(kMap, k, false);
    QVERIFY(std::abs(std::hypot(out.x() - centre.x(), out.y() - centre.y()) - M::HandleLength) < 1e-9);
    QVERIFY(std::abs(std::hypot(in.x() - centre.x(), in.y() - centre.y()) - M::HandleLength) < 1e-9);
    QVERIFY(out.x() > centre.x() && out.y() < centre.y()); // right and up
    QVERIFY(in.x() < centre.x() && in.y() < centre.y());   // in slope −1: left and up
    QVERIFY(std::abs((out.y() - centre.y()) / (out.x() - centre.x()) + 0.5) < 1e-9);

    // Pointing a handle back at itself gives the key's own slope.
    QVERIFY(std::abs(tangentSlopeTowards(kMap, k, out, true) - 0.5) < 1e-9);
    QVERIFY(std::abs(tangentSlopeTowards(kMap, k, in, false) + 1) < 1e-9);
    // The out handle never goes left of its key: at worst it is steep.
    const double steep = tangentSlopeTowards(kMap, k, centre + QPointF(-30, -60), true);
    QVERIFY(std::abs(steep - 60.0) < 1e-9); // 60 px up over 1 px: (60 / 200) / (1 / 200)
}

void CurveGeometryTest::moveDeltaConstrainsToTheDominantAxis()
{
    const QPointF from(100, 100);
    QVERIFY(near(keyMoveDelta(kMap, from, from + QPointF(40, -20), false), QPointF(0.2, 0.1)));
    QVERIFY(near(keyMoveDelta(kMap, from, from + QPointF(40, -20), true), QPointF(0.2, 0)));
    QVERIFY(near(keyMoveDelta(kMap, from, from + QPointF(10, 30), true), QPointF(0, -0.15)));
}

void CurveGeometryTest::keyUnderPicksTheNearestWithinReach()
{
    const QVector<CurveViewCurve> curves = {keyed({key(0.5, 0.5), key(1, 0.25)}), keyed({key(0.5, 0.5)})};
    const QPointF p = kMap.map(1, 0.25);
    QCOMPARE(curveKeyUnder(kMap, curves, p + QPointF(3, -3)), (CurveKeyRef{0, 1}));
    QCOMPARE(curveKeyUnder(kMap, curves, p + QPointF(M::KeyHitRadius - 0.1, 0)), (CurveKeyRef{0, 1}));
    QCOMPARE(curveKeyUnder(kMap, curves, p + QPointF(M::KeyHitRadius + 0.1, 0)), CurveKeyRef{});
    // Two keys on one spot: the later curve, drawn on top.
    QCOMPARE(curveKeyUnder(kMap, curves, kMap.map(0.5, 0.5)), (CurveKeyRef{1, 0}));
}

void CurveGeometryTest::handleUnderOnlyForSelectedFreeOrBrokenKeys()
{
    const QVector<CurveViewCurve> curves = {
        keyed({key(0.5, 0.5, CurveTangent::Free, 1, 1), key(1.5, 0.5, CurveTangent::Linear, 1, 1)})};
    const QPointF freeOut = tangentHandlePoint(kMap, curves[0].keys[0], true);
    const QPointF linearOut = tangentHandlePoint(kMap, curves[0].keys[1], true);
    bool outSide = false;
    QCOMPARE(curveHandleUnder(kMap, curves, {}, freeOut, &outSide), CurveKeyRef{}); // not selected
    const QList<CurveKeyRef> both = {{0, 0}, {0, 1}};
    QCOMPARE(curveHandleUnder(kMap, curves, both, freeOut + QPointF(2, 2), &outSide), (CurveKeyRef{0, 0}));
    QVERIFY(outSide);
    const QPointF freeIn = tangentHandlePoint(kMap, curves[0].keys[0], false);
    QCOMPARE(curveHandleUnder(kMap, curves, both, freeIn, &outSide), (CurveKeyRef{0, 0}));
    QVERIFY(!outSide);
    QCOMPARE(curveHandleUnder(kMap, curves, both, freeIn + QPointF(M::HandleHitRadius, 0), &outSide), CurveKeyRef{});
    QCOMPARE(curveHandleUnder(kMap, curves, both, linearOut, &outSide), CurveKeyRef{}); // Linear: no handles
}

void CurveGeometryTest::curveNearUsesSamplesOrKeyLines()
{
    CurveViewCurve sampled;
    sampled.keys = {key(0, 0), key(2, 1)};
    for (int i = 0; i <= 20; ++i)
        sampled.samples.append(QPointF(i * 0.1, 0.25)); // flat at 0.25 whatever the keys say
    CurveViewCurve parametric; // samples only: drawn, not editable
    parametric.samples = {{0, 0.75}, {2, 0.75}};
    CurveViewCurve lines = keyed({key(0, 1), key(2, 0)}); // no samples: the line between its keys
    const QVector<CurveViewCurve> curves = {sampled, parametric, lines};

    QCOMPARE(editableCurveNear(kMap, curves, kMap.map(0.33, 0.25) + QPointF(0, 4)), 0);
    QCOMPARE(editableCurveNear(kMap, curves, kMap.map(0.33, 0.25) + QPointF(0, M::CurveHitDistance + 1)), -1);
    QCOMPARE(editableCurveNear(kMap, curves, kMap.map(1.0, 0.75)), -1); // only the parametric curve there
    QCOMPARE(editableCurveNear(kMap, curves, kMap.map(1.0, 0.5) + QPointF(3, 0)), 2);

    CurveViewCurve keyable; // no keys, but accepts them: its samples count
    keyable.keyable = true;
    keyable.samples = {{0, 0.75}, {2, 0.75}};
    QCOMPARE(editableCurveNear(kMap, {keyable}, kMap.map(1.0, 0.75)), 0);
}

void CurveGeometryTest::keysInABox()
{
    const QVector<CurveViewCurve> curves = {keyed({key(0.5, 0.5), key(1, 0.9)}), keyed({key(0.6, 0.4)})};
    // Dragged from bottom-right to top-left: any corner order.
    const QRectF box(kMap.map(0.7, 0.3), kMap.map(0.4, 0.6));
    QCOMPARE(curveKeysIn(kMap, curves, box), (QList<CurveKeyRef>{{0, 0}, {1, 0}}));
    QVERIFY(curveKeysIn(kMap, curves, QRectF(kMap.map(1.5, 0), kMap.map(2, 0.2))).isEmpty());
}

QTEST_MAIN(CurveGeometryTest)
#include "curve_geometry_test.moc"
