// CurveView: the curve editor's plot. Mapping and framing, and that user gestures (and only they)
// emit intents: selecting, moving and deleting keys, adding keys, dragging tangents, tangent modes.

#include <QAction>
#include <QApplication>
#include <QDir>
#include <QFileInfo>
#include <QImage>
#include <QMenu>
#include <QMouseEvent>
#include <QSignalSpy>
#include <QTest>
#include <QWheelEvent>

#include <cmath>

#include "widgets/curve_view.h"

using thespis::widgets::CurveKeyRef;
using thespis::widgets::CurveTangent;
using thespis::widgets::CurveView;
using thespis::widgets::CurveViewCurve;
using thespis::widgets::CurveViewKey;

namespace {

// Cubic Hermite through the keys with their slopes (what an editor would sample), so that the
// polyline really passes through the keys; Constant holds, Linear is straight.
QVector<QPointF> sampleKeys(const QVector<CurveViewKey>& keys, double start, double end, int count)
{
    QVector<QPointF> samples;
    for (int i = 0; i < count; ++i) {
        const double t = start + (end - start) * i / (count - 1);
        double v = keys.front().value;
        if (t >= keys.back().time) {
            v = keys.back().value;
        } else if (t > keys.front().time) {
            int k = 0;
            while (keys[k + 1].time < t)
                ++k;
            const CurveViewKey& a = keys[k];
            const CurveViewKey& b = keys[k + 1];
            const double h = b.time - a.time, s = (t - a.time) / h;
            if (a.mode == CurveTangent::Constant) {
                v = a.value;
            } else if (a.mode == CurveTangent::Linear) {
                v = a.value + (b.value - a.value) * s;
            } else {
                const double h00 = 2 * s * s * s - 3 * s * s + 1, h10 = s * s * s - 2 * s * s + s;
                const double h01 = -2 * s * s * s + 3 * s * s, h11 = s * s * s - s * s;
                v = h00 * a.value + h10 * h * a.outSlope + h01 * b.value + h11 * h * b.inSlope;
            }
        }
        samples.append(QPointF(t, v));
    }
    return samples;
}

// A keyframed weight (5 keys; key 2 Broken) and a parametric scale (fade in, hold, fade out).
QVector<CurveViewCurve> fixtureCurves()
{
    CurveViewCurve weight;
    weight.name = QStringLiteral("Weight");
    weight.color = QColor(0xed, 0xc9, 0x48);
    weight.keys = {
        {0.0, 0.0, CurveTangent::AutoClamped, 0, 0},
        {0.8, 1.0, CurveTangent::AutoClamped, 0, 0},
        {1.9, 0.55, CurveTangent::Broken, 0.9, -1.4},
        {2.9, 0.85, CurveTangent::Free, 0.2, 0.2},
        {4.0, 0.0, CurveTangent::Linear, 0, 0},
    };
    weight.samples = sampleKeys(weight.keys, 0, 4, 401);

    CurveViewCurve scale;
    scale.name = QStringLiteral("Scale");
    scale.color = QColor(0x4e, 0xa8, 0xde);
    for (int i = 0; i <= 200; ++i) {
        const double t = 4.0 * i / 200;
        const double in = std::clamp(t / 0.6, 0.0, 1.0), out = std::clamp((4.0 - t) / 0.8, 0.0, 1.0);
        const double fade = std::min(in * in * (3 - 2 * in), out * out * (3 - 2 * out));
        scale.samples.append(QPointF(t, 0.8 + 0.45 * fade));
    }
    return {weight, scale};
}

struct Fixture {
    CurveView view;
    Fixture()
    {
        view.resize(700, 320);
        view.setTimeRange(0, 4);
        view.setCurves(fixtureCurves());
        view.setPlayhead(2.35);
    }
    QPoint keyPixel(int key, int curve = 0) const
    {
        const CurveViewKey& k = view.curves()[curve].keys[key];
        return view.toWidget(QPointF(k.time, k.value)).toPoint();
    }
    // The weight curve's sample nearest `t`, in pixels.
    QPoint curvePixel(double t, int curve = 0) const
    {
        for (const QPointF& s : view.curves()[curve].samples)
            if (s.x() >= t)
                return view.toWidget(s).toPoint();
        return {};
    }
};

void sendMouse(QWidget* widget, QEvent::Type type, QPoint pos, Qt::MouseButton button, Qt::MouseButtons buttons,
               Qt::KeyboardModifiers modifiers)
{
    QMouseEvent event(type, QPointF(pos), QPointF(widget->mapToGlobal(pos)), button, buttons, modifiers);
    QApplication::sendEvent(widget, &event);
}

void sendWheel(QWidget* widget, QPoint pos, int angle, Qt::KeyboardModifiers modifiers)
{
    QWheelEvent event(QPointF(pos), QPointF(widget->mapToGlobal(pos)), QPoint(), QPoint(0, angle), Qt::NoButton,
                      modifiers, Qt::NoScrollPhase, false);
    QApplication::sendEvent(widget, &event);
}

// Press, move in steps, release; `held` is pressed after the press (Shift to constrain a move
// rather than toggle the key), `modifiers` all along.
void drag(QWidget* widget, QPoint from, QPoint to, Qt::KeyboardModifiers modifiers = {}, Qt::KeyboardModifiers held = {},
          int steps = 6)
{
    QTest::mousePress(widget, Qt::LeftButton, modifiers, from);
    for (int i = 1; i <= steps; ++i)
        sendMouse(widget, QEvent::MouseMove, from + (to - from) * i / steps, Qt::NoButton, Qt::LeftButton, modifiers | held);
    QTest::mouseRelease(widget, Qt::LeftButton, modifiers | held, to);
}

bool near(double a, double b, double tolerance)
{
    return std::abs(a - b) <= tolerance;
}

} // namespace

class CurveViewTest : public QObject {
    Q_OBJECT
private slots:
    void settersEmitNothing();
    void mappingRoundTrips();
    void framesTheDomainAndFrameAllFitsEverything();
    void openEndedDomainShowsTenSeconds();
    void clickSelectsAndModifiersToggle();
    void draggingKeysRequestsMoves();
    void shiftConstrainsTheMoveToOneAxis();
    void escapeCancelsAMove();
    void boxSelectsTheKeysInside();
    void deleteRequestsDeletion();
    void doubleClickOnAKeyedCurveAddsAKey();
    void parametricCurvesAreNotEditable();
    void draggingATangentHandleRequestsSlopes();
    void contextMenuRequestsTangentModes();
    void wheelZoomsAboutTheCursor();
    void middleDragPans();
    void screenshot();
};

void CurveViewTest::settersEmitNothing()
{
    CurveView view;
    view.resize(700, 320);
    QSignalSpy selection(&view, &CurveView::selectionChanged);
    QSignalSpy adds(&view, &CurveView::keyAddRequested);
    QSignalSpy moves(&view, &CurveView::keysMoveRequested);
    QSignalSpy deletes(&view, &CurveView::keysDeleteRequested);
    QSignalSpy tangents(&view, &CurveView::tangentRequested);
    QSignalSpy modes(&view, &CurveView::tangentModeRequested);

    view.setTimeRange(0, 4);
    view.setCurves(fixtureCurves());
    view.setPlayhead(1.5);
    view.setSelectedKeys({{0, 1}, {0, 3}, {0, 1}, {1, 0}, {0, 9}}); // duplicates and missing keys dropped
    QCOMPARE(view.selectedKeys(), (QList<CurveKeyRef>{{0, 1}, {0, 3}}));
    view.frameAll();
    // Fewer keys: the selection keeps the indices that still exist.
    QVector<CurveViewCurve> curves = fixtureCurves();
    curves[0].keys.resize(3);
    view.setCurves(curves);
    QCOMPARE(view.selectedKeys(), (QList<CurveKeyRef>{{0, 1}}));
    view.setSelectedKeys({});
    QVERIFY(view.minimumSizeHint().width() >= 400 && view.minimumSizeHint().height() >= 200);

    for (QSignalSpy* spy : {&selection, &adds, &moves, &deletes, &tangents, &modes})
        QCOMPARE(spy->count(), 0);
}

void CurveViewTest::mappingRoundTrips()
{
    Fixture f;
    for (const QPointF curvePoint : {QPointF(0, 0), QPointF(1.25, 0.5), QPointF(-3, 7), QPointF(4, 1)}) {
        const QPointF back = f.view.fromWidget(f.view.toWidget(curvePoint));
        QVERIFY(near(back.x(), curvePoint.x(), 1e-9) && near(back.y(), curvePoint.y(), 1e-9));
    }
    for (const QPointF pixel : {QPointF(0, 0), QPointF(350.5, 160.25), QPointF(699, 319)}) {
        const QPointF back = f.view.toWidget(f.view.fromWidget(pixel));
        QVERIFY(near(back.x(), pixel.x(), 1e-9) && near(back.y(), pixel.y(), 1e-9));
    }
    // Time runs right, values run up, inside the plot.
    const QPointF origin = f.view.toWidget({0, 0}), one = f.view.toWidget({1, 1});
    QVERIFY(one.x() > origin.x());
    QVERIFY(one.y() < origin.y());
    QVERIFY(f.view.plotRect().contains(origin) && f.view.plotRect().contains(one));
}

void CurveViewTest::framesTheDomainAndFrameAllFitsEverything()
{
    Fixture f;
    // Automatic framing: the domain and 0..1 (and the scale curve above 1) are in view.
    const QRectF plot = f.view.plotRect();
    for (const QPointF p : {QPointF(0, 0), QPointF(4, 0), QPointF(0, 1.25), QPointF(4, 1)})
        QVERIFY2(plot.contains(f.view.toWidget(p)), qPrintable(QStringLiteral("%1, %2").arg(p.x()).arg(p.y())));

    // Data far outside the domain: frameAll fits all of it, and uses most of the plot.
    QVector<CurveViewCurve> curves = fixtureCurves();
    curves[0].keys.append({12.0, -2.0, CurveTangent::Linear, 0, 0});
    curves[1].samples.prepend(QPointF(-3.0, 5.0));
    f.view.setCurves(curves);
    f.view.frameAll();
    double minX = 1e9, maxX = -1e9, minY = 1e9, maxY = -1e9;
    auto check = [&](QPointF p) {
        const QPointF pixel = f.view.toWidget(p);
        QVERIFY2(plot.contains(pixel), qPrintable(QStringLiteral("%1, %2").arg(p.x()).arg(p.y())));
        minX = std::min(minX, pixel.x());
        maxX = std::max(maxX, pixel.x());
        minY = std::min(minY, pixel.y());
        maxY = std::max(maxY, pixel.y());
    };
    for (const CurveViewCurve& curve : f.view.curves()) {
        for (const QPointF& s : curve.samples)
            check(s);
        for (const CurveViewKey& k : curve.keys)
            check({k.time, k.value});
    }
    QVERIFY(maxX - minX > 0.8 * plot.width());
    QVERIFY(maxY - minY > 0.7 * plot.height());

    // The user framed it: later data does not move the view; a new domain frames again.
    const QRectF framed = f.view.visibleRange();
    f.view.setCurves(fixtureCurves());
    QCOMPARE(f.view.visibleRange(), framed);
    f.view.setTimeRange(10, 20);
    QVERIFY(plot.contains(f.view.toWidget({10, 0.5})) && plot.contains(f.view.toWidget({20, 0.5})));

    // 'F' frames all too.
    f.view.setTimeRange(0, 4);
    f.view.setCurves(curves);
    QTest::keyClick(&f.view, Qt::Key_F);
    QCOMPARE(f.view.visibleRange(), framed);
}

void CurveViewTest::openEndedDomainShowsTenSeconds()
{
    CurveView view;
    view.resize(700, 320);
    view.setTimeRange(2, std::numeric_limits<double>::infinity());
    const QRectF range = view.visibleRange();
    QVERIFY(range.left() < 2 && range.left() > 1);
    QVERIFY(range.right() > 12 && range.right() < 13);
}

void CurveViewTest::clickSelectsAndModifiersToggle()
{
    Fixture f;
    QSignalSpy selection(&f.view, &CurveView::selectionChanged);
    QSignalSpy moves(&f.view, &CurveView::keysMoveRequested);
    QTest::mouseClick(&f.view, Qt::LeftButton, {}, f.keyPixel(2));
    QCOMPARE(f.view.selectedKeys(), (QList<CurveKeyRef>{{0, 2}}));
    QCOMPARE(selection.count(), 1);
    QTest::mouseClick(&f.view, Qt::LeftButton, Qt::ShiftModifier, f.keyPixel(4));
    QCOMPARE(f.view.selectedKeys(), (QList<CurveKeyRef>{{0, 2}, {0, 4}}));
    QTest::mouseClick(&f.view, Qt::LeftButton, Qt::ControlModifier, f.keyPixel(2));
    QCOMPARE(f.view.selectedKeys(), (QList<CurveKeyRef>{{0, 4}}));
    QCOMPARE(selection.count(), 3);
    // A plain click on one of several selected keys selects just it.
    f.view.setSelectedKeys({{0, 1}, {0, 3}});
    QTest::mouseClick(&f.view, Qt::LeftButton, {}, f.keyPixel(3));
    QCOMPARE(f.view.selectedKeys(), (QList<CurveKeyRef>{{0, 3}}));
    // Clicking empty space (far from any curve) clears.
    const QPoint empty = f.view.toWidget({3.5, 1.6}).toPoint();
    QTest::mouseClick(&f.view, Qt::LeftButton, {}, empty);
    QVERIFY(f.view.selectedKeys().isEmpty());
    QCOMPARE(selection.count(), 5);
    QTest::mouseClick(&f.view, Qt::LeftButton, {}, empty);
    QCOMPARE(selection.count(), 5); // nothing changed: no signal
    // Ctrl+A selects every key.
    QTest::keyClick(&f.view, Qt::Key_A, Qt::ControlModifier);
    QCOMPARE(f.view.selectedKeys().size(), 5);
    QCOMPARE(moves.count(), 0);
}

void CurveViewTest::draggingKeysRequestsMoves()
{
    Fixture f;
    f.view.setSelectedKeys({{0, 1}, {0, 3}});
    QSignalSpy moves(&f.view, &CurveView::keysMoveRequested);
    QSignalSpy selection(&f.view, &CurveView::selectionChanged);

    // A click without movement emits no move (it selects just the clicked key).
    QTest::mouseClick(&f.view, Qt::LeftButton, {}, f.keyPixel(1));
    QCOMPARE(moves.count(), 0);
    QCOMPARE(f.view.selectedKeys(), (QList<CurveKeyRef>{{0, 1}}));
    f.view.setSelectedKeys({{0, 1}, {0, 3}});
    selection.clear();

    const QPoint from = f.keyPixel(1);
    const QPoint offset(60, 40); // right and down
    drag(&f.view, from, from + offset);
    QVERIFY2(moves.count() >= 3, qPrintable(QString::number(moves.count())));
    int finished = 0;
    for (int i = 0; i < moves.count(); ++i) {
        QCOMPARE(moves.at(i).at(0).value<QList<CurveKeyRef>>(), (QList<CurveKeyRef>{{0, 1}, {0, 3}}));
        finished += moves.at(i).at(2).toBool() ? 1 : 0;
    }
    QCOMPARE(finished, 1);
    QVERIFY(moves.last().at(2).toBool());
    // Dragging a selected key keeps the whole selection.
    QCOMPARE(selection.count(), 0);
    const QPointF delta = moves.last().at(1).toPointF();
    const QPointF pixel = f.view.fromWidget(QPointF(1, 1)) - f.view.fromWidget(QPointF(0, 0)); // one pixel
    const QPointF expected = f.view.fromWidget(from + offset) - f.view.fromWidget(from);
    QVERIFY2(near(delta.x(), expected.x(), std::abs(pixel.x())) && near(delta.y(), expected.y(), std::abs(pixel.y())),
             qPrintable(QStringLiteral("%1, %2 vs %3, %4").arg(delta.x()).arg(delta.y()).arg(expected.x()).arg(expected.y())));
    QVERIFY(delta.x() > 0 && delta.y() < 0);
    // Unfinished deltas grow with the drag.
    QVERIFY(moves.first().at(1).toPointF().x() < delta.x());

    // Pressing an unselected key selects it and drags it alone.
    moves.clear();
    drag(&f.view, f.keyPixel(4), f.keyPixel(4) + QPoint(-30, 0));
    QCOMPARE(f.view.selectedKeys(), (QList<CurveKeyRef>{{0, 4}}));
    QCOMPARE(moves.last().at(0).value<QList<CurveKeyRef>>(), (QList<CurveKeyRef>{{0, 4}}));
    QVERIFY(moves.last().at(1).toPointF().x() < 0);
}

void CurveViewTest::shiftConstrainsTheMoveToOneAxis()
{
    Fixture f;
    QSignalSpy moves(&f.view, &CurveView::keysMoveRequested);
    f.view.setSelectedKeys({{0, 2}});
    drag(&f.view, f.keyPixel(2), f.keyPixel(2) + QPoint(50, 12), {}, Qt::ShiftModifier);
    QVERIFY(moves.last().at(2).toBool());
    QCOMPARE(moves.last().at(1).toPointF().y(), 0.0);
    QVERIFY(moves.last().at(1).toPointF().x() > 0);
    moves.clear();
    drag(&f.view, f.keyPixel(2), f.keyPixel(2) + QPoint(8, -45), {}, Qt::ShiftModifier);
    QCOMPARE(moves.last().at(1).toPointF().x(), 0.0);
    QVERIFY(moves.last().at(1).toPointF().y() > 0);
    QCOMPARE(f.view.selectedKeys(), (QList<CurveKeyRef>{{0, 2}}));
    // Shift+press on an unselected key adds it, and the drag moves both, constrained.
    moves.clear();
    drag(&f.view, f.keyPixel(3), f.keyPixel(3) + QPoint(-40, 5), Qt::ShiftModifier);
    QCOMPARE(f.view.selectedKeys(), (QList<CurveKeyRef>{{0, 2}, {0, 3}}));
    QCOMPARE(moves.last().at(0).value<QList<CurveKeyRef>>(), (QList<CurveKeyRef>{{0, 2}, {0, 3}}));
    QCOMPARE(moves.last().at(1).toPointF().y(), 0.0);
}

void CurveViewTest::escapeCancelsAMove()
{
    Fixture f;
    QSignalSpy moves(&f.view, &CurveView::keysMoveRequested);
    const QPoint from = f.keyPixel(3);
    QTest::mousePress(&f.view, Qt::LeftButton, {}, from);
    QTest::mouseMove(&f.view, from + QPoint(40, 0));
    QTest::keyClick(&f.view, Qt::Key_Escape);
    QVERIFY(moves.count() >= 2);
    QVERIFY(moves.last().at(2).toBool());
    QCOMPARE(moves.last().at(1).toPointF(), QPointF(0, 0));
    const int count = moves.count();
    QTest::mouseRelease(&f.view, Qt::LeftButton, {}, from + QPoint(40, 0));
    QCOMPARE(moves.count(), count); // the release after a cancel emits nothing

    // Ctrl+Z does the same, and the window's Undo and Redo do not fire under the drag.
    QAction undo(QStringLiteral("Undo")), redo(QStringLiteral("Redo"));
    undo.setShortcut(QKeySequence::Undo);
    redo.setShortcut(QKeySequence::Redo);
    f.view.addAction(&undo);
    f.view.addAction(&redo);
    QSignalSpy undone(&undo, &QAction::triggered), redone(&redo, &QAction::triggered);
    f.view.show();
    QVERIFY(QTest::qWaitForWindowActive(&f.view));
    moves.clear();
    QTest::mousePress(&f.view, Qt::LeftButton, {}, from);
    QTest::mouseMove(&f.view, from + QPoint(40, 0));
    QVERIFY(!moves.isEmpty());
    QTest::keySequence(&f.view, QKeySequence::Redo);
    QTest::keySequence(&f.view, QKeySequence::Undo);
    QCOMPARE(undone.count(), 0);
    QCOMPARE(redone.count(), 0);
    QVERIFY(moves.last().at(2).toBool());
    QCOMPARE(moves.last().at(1).toPointF(), QPointF(0, 0));
    QTest::mouseRelease(&f.view, Qt::LeftButton, {}, from + QPoint(40, 0));
    QTest::keySequence(&f.view, QKeySequence::Undo);
    QCOMPARE(undone.count(), 1);
}

void CurveViewTest::boxSelectsTheKeysInside()
{
    Fixture f;
    QSignalSpy selection(&f.view, &CurveView::selectionChanged);
    QSignalSpy moves(&f.view, &CurveView::keysMoveRequested);
    // A box around keys 1 and 2 (0.8 s and 1.9 s), starting in empty space above them.
    const QPoint from = f.view.toWidget({0.5, 1.35}).toPoint();
    const QPoint to = f.view.toWidget({2.2, 0.3}).toPoint();
    drag(&f.view, from, to);
    QCOMPARE(f.view.selectedKeys(), (QList<CurveKeyRef>{{0, 1}, {0, 2}}));
    QCOMPARE(selection.count(), 1);
    QCOMPARE(moves.count(), 0);
    // Shift adds to the selection.
    drag(&f.view, f.view.toWidget({3.7, 0.3}).toPoint(), f.view.toWidget({4.2, -0.1}).toPoint(), Qt::ShiftModifier);
    QCOMPARE(f.view.selectedKeys(), (QList<CurveKeyRef>{{0, 1}, {0, 2}, {0, 4}}));
    // Without a modifier a new box replaces it.
    drag(&f.view, f.view.toWidget({3.7, 0.3}).toPoint(), f.view.toWidget({4.2, -0.1}).toPoint());
    QCOMPARE(f.view.selectedKeys(), (QList<CurveKeyRef>{{0, 4}}));
}

void CurveViewTest::deleteRequestsDeletion()
{
    Fixture f;
    QSignalSpy deletes(&f.view, &CurveView::keysDeleteRequested);
    QTest::keyClick(&f.view, Qt::Key_Delete);
    QCOMPARE(deletes.count(), 0); // nothing selected
    f.view.setSelectedKeys({{0, 3}, {0, 1}});
    QSignalSpy selection(&f.view, &CurveView::selectionChanged);
    QTest::keyClick(&f.view, Qt::Key_Delete);
    QCOMPARE(deletes.count(), 1);
    QCOMPARE(deletes.at(0).at(0).value<QList<CurveKeyRef>>(), (QList<CurveKeyRef>{{0, 1}, {0, 3}}));
    QVERIFY(f.view.selectedKeys().isEmpty());
    QCOMPARE(selection.count(), 1);
    f.view.setSelectedKeys({{0, 2}});
    QTest::keyClick(&f.view, Qt::Key_Backspace);
    QCOMPARE(deletes.count(), 2);
    QCOMPARE(deletes.at(1).at(0).value<QList<CurveKeyRef>>(), (QList<CurveKeyRef>{{0, 2}}));
    // The context menu's entry does the same.
    f.view.setSelectedKeys({{0, 4}});
    auto* action = f.view.findChild<QAction*>(QStringLiteral("deleteKeysAction"));
    QVERIFY(action && action->isEnabled());
    action->trigger();
    QCOMPARE(deletes.count(), 3);
    QVERIFY(!action->isEnabled());
}

void CurveViewTest::doubleClickOnAKeyedCurveAddsAKey()
{
    Fixture f;
    QSignalSpy adds(&f.view, &CurveView::keyAddRequested);
    // On the weight curve between keys 3 and 4, a couple of pixels off the line.
    const QPoint onCurve = f.curvePixel(3.4) + QPoint(0, 3);
    QTest::mouseClick(&f.view, Qt::LeftButton, {}, onCurve);
    QTest::mouseDClick(&f.view, Qt::LeftButton, {}, onCurve);
    QTest::mouseRelease(&f.view, Qt::LeftButton, {}, onCurve);
    QCOMPARE(adds.count(), 1);
    QCOMPARE(adds.at(0).at(0).toInt(), 0);
    const QPointF at = adds.at(0).at(1).toPointF();
    const QPointF clicked = f.view.fromWidget(onCurve);
    QVERIFY(near(at.x(), 3.4, 0.02));
    QCOMPARE(at, clicked);

    // Ctrl+click does the same.
    QTest::mouseClick(&f.view, Qt::LeftButton, Qt::ControlModifier, f.curvePixel(0.4));
    QCOMPARE(adds.count(), 2);
    QVERIFY(near(adds.at(1).at(1).toPointF().x(), 0.4, 0.02));

    // Far from any curve, or on a key: nothing.
    const QPoint empty = f.view.toWidget({3.5, 1.6}).toPoint();
    QTest::mouseDClick(&f.view, Qt::LeftButton, {}, empty);
    QTest::mouseRelease(&f.view, Qt::LeftButton, {}, empty);
    QTest::mouseDClick(&f.view, Qt::LeftButton, {}, f.keyPixel(2));
    QTest::mouseRelease(&f.view, Qt::LeftButton, {}, f.keyPixel(2));
    QCOMPARE(adds.count(), 2);

    // A keyed curve without keys (all deleted) still takes new ones.
    QVector<CurveViewCurve> curves = fixtureCurves();
    curves[0].keys.clear();
    curves[0].keyable = true;
    curves[0].samples = {QPointF(0, 0.5), QPointF(4, 0.5)};
    f.view.setCurves(curves);
    const QPoint flat = f.view.toWidget({2.0, 0.5}).toPoint();
    QTest::mouseDClick(&f.view, Qt::LeftButton, {}, flat);
    QTest::mouseRelease(&f.view, Qt::LeftButton, {}, flat);
    QCOMPARE(adds.count(), 3);
    QCOMPARE(adds.at(2).at(0).toInt(), 0);
}

void CurveViewTest::parametricCurvesAreNotEditable()
{
    Fixture f;
    QSignalSpy adds(&f.view, &CurveView::keyAddRequested);
    QSignalSpy moves(&f.view, &CurveView::keysMoveRequested);
    QSignalSpy deletes(&f.view, &CurveView::keysDeleteRequested);
    QSignalSpy tangents(&f.view, &CurveView::tangentRequested);
    QSignalSpy modes(&f.view, &CurveView::tangentModeRequested);
    // The scale curve's hold at 1.25, away from the weight curve.
    const QPoint onScale = f.curvePixel(2.4, 1);
    QVERIFY(std::abs(onScale.y() - f.curvePixel(2.4, 0).y()) > 30);
    QTest::mouseDClick(&f.view, Qt::LeftButton, {}, onScale);
    QTest::mouseRelease(&f.view, Qt::LeftButton, {}, onScale);
    QTest::mouseClick(&f.view, Qt::LeftButton, Qt::ControlModifier, onScale);
    drag(&f.view, onScale, onScale + QPoint(20, 20));
    // A box over the scale curve alone selects nothing.
    drag(&f.view, f.view.toWidget({1.0, 1.35}).toPoint(), f.view.toWidget({1.6, 1.15}).toPoint());
    QVERIFY(f.view.selectedKeys().isEmpty());
    // Selecting keys of a curve without keys is refused.
    f.view.setSelectedKeys({{1, 0}});
    QVERIFY(f.view.selectedKeys().isEmpty());
    QTest::keyClick(&f.view, Qt::Key_Delete);
    f.view.findChild<QAction*>(QStringLiteral("tangentLinearAction"))->trigger();
    for (QSignalSpy* spy : {&adds, &moves, &deletes, &tangents, &modes})
        QCOMPARE(spy->count(), 0);
}

void CurveViewTest::draggingATangentHandleRequestsSlopes()
{
    Fixture f;
    QSignalSpy tangents(&f.view, &CurveView::tangentRequested);
    QSignalSpy moves(&f.view, &CurveView::keysMoveRequested);
    const CurveKeyRef broken{0, 2};
    // No handles on an unselected key.
    QTest::mouseClick(&f.view, Qt::LeftButton, {}, f.view.tangentHandle(broken, true).toPoint());
    QCOMPARE(tangents.count(), 0);
    QVERIFY(f.view.tangentHandle({0, 42}, true).isNull());

    f.view.setSelectedKeys({broken});
    const QPointF key = f.view.toWidget({1.9, 0.55});
    // The handles point along the slopes as seen on screen, on either side of the key.
    const QPointF out = f.view.tangentHandle(broken, true), in = f.view.tangentHandle(broken, false);
    QVERIFY(out.x() > key.x() && in.x() < key.x());
    const auto slopeOf = [&](QPointF handle) {
        const QPointF a = f.view.fromWidget(key), b = f.view.fromWidget(handle);
        return (b.y() - a.y()) / (b.x() - a.x());
    };
    QVERIFY(near(slopeOf(out), -1.4, 1e-6));
    QVERIFY(near(slopeOf(in), 0.9, 1e-6));

    // Drag the out handle up and right: a positive slope; the in side keeps its slope.
    const QPoint target = (key + QPointF(50, -30)).toPoint();
    drag(&f.view, out.toPoint(), target);
    QVERIFY(tangents.count() >= 2);
    int finished = 0;
    for (const QList<QVariant>& call : tangents) {
        QCOMPARE(call.at(0).value<CurveKeyRef>(), broken);
        QVERIFY(near(call.at(1).toDouble(), 0.9, 1e-12));
        finished += call.at(3).toBool() ? 1 : 0;
    }
    QCOMPARE(finished, 1);
    QVERIFY(tangents.last().at(3).toBool());
    const double expected = slopeOf(target);
    QVERIFY2(near(tangents.last().at(2).toDouble(), expected, 1e-9),
             qPrintable(QStringLiteral("%1 vs %2").arg(tangents.last().at(2).toDouble()).arg(expected)));
    QVERIFY(expected > 0);
    QCOMPARE(moves.count(), 0); // the key itself does not move
    QCOMPARE(f.view.selectedKeys(), (QList<CurveKeyRef>{broken}));

    // Free: the in handle sets both slopes.
    tangents.clear();
    const CurveKeyRef free{0, 3};
    f.view.setSelectedKeys({free});
    const QPointF freeKey = f.view.toWidget({2.9, 0.85});
    const QPoint freeTarget = (freeKey + QPointF(-40, -25)).toPoint();
    drag(&f.view, f.view.tangentHandle(free, false).toPoint(), freeTarget);
    QVERIFY(tangents.last().at(3).toBool());
    const double in2 = tangents.last().at(1).toDouble(), out2 = tangents.last().at(2).toDouble();
    QCOMPARE(in2, out2);
    const QPointF a = f.view.fromWidget(freeKey), b = f.view.fromWidget(freeTarget);
    QVERIFY(near(in2, (b.y() - a.y()) / (b.x() - a.x()), 1e-9));
    QVERIFY(in2 < 0); // up and to the left: falling into the key

    // Auto clamped keys have no handles: dragging where one would be does not request slopes.
    tangents.clear();
    f.view.setSelectedKeys({{0, 1}});
    const QPointF autoHandle = f.view.tangentHandle({0, 1}, true);
    drag(&f.view, autoHandle.toPoint(), autoHandle.toPoint() + QPoint(10, -20));
    QCOMPARE(tangents.count(), 0);
}

void CurveViewTest::contextMenuRequestsTangentModes()
{
    Fixture f;
    QSignalSpy modes(&f.view, &CurveView::tangentModeRequested);
    const char* names[] = {"tangentAutoClampedAction", "tangentLinearAction", "tangentConstantAction",
                           "tangentFreeAction", "tangentBrokenAction"};
    for (const char* name : names) {
        auto* action = f.view.findChild<QAction*>(QLatin1String(name));
        QVERIFY2(action, name);
        QVERIFY(!action->isEnabled()); // nothing selected
    }
    QVERIFY(f.view.findChild<QAction*>(QStringLiteral("frameAllAction")));

    f.view.setSelectedKeys({{0, 1}, {0, 3}});
    for (int mode = 0; mode < 5; ++mode) {
        auto* action = f.view.findChild<QAction*>(QLatin1String(names[mode]));
        QVERIFY(action->isEnabled());
        action->trigger();
        QCOMPARE(modes.count(), mode + 1);
        QCOMPARE(modes.last().at(0).value<QList<CurveKeyRef>>(), (QList<CurveKeyRef>{{0, 1}, {0, 3}}));
        QCOMPARE(modes.last().at(1).value<CurveTangent>(), CurveTangent(mode));
    }
    // The check mark shows the selected keys' mode when they agree.
    f.view.setSelectedKeys({{0, 2}});
    QVERIFY(f.view.findChild<QAction*>(QStringLiteral("tangentBrokenAction"))->isChecked());
    QVERIFY(!f.view.findChild<QAction*>(QStringLiteral("tangentFreeAction"))->isChecked());
    f.view.setSelectedKeys({{0, 2}, {0, 3}});
    for (const char* name : names)
        QVERIFY(!f.view.findChild<QAction*>(QLatin1String(name))->isChecked());

    // Right-clicking an unselected key selects it and opens the menu on it.
    f.view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&f.view));
    QSignalSpy selection(&f.view, &CurveView::selectionChanged);
    QContextMenuEvent event(QContextMenuEvent::Mouse, f.keyPixel(4), f.view.mapToGlobal(f.keyPixel(4)));
    QApplication::sendEvent(&f.view, &event);
    QCOMPARE(f.view.selectedKeys(), (QList<CurveKeyRef>{{0, 4}}));
    QCOMPARE(selection.count(), 1);
    auto* menu = f.view.findChild<QMenu*>(QStringLiteral("curveViewMenu"));
    QVERIFY(menu);
    QTRY_VERIFY(menu->isVisible());
    QVERIFY(f.view.findChild<QAction*>(QStringLiteral("tangentLinearAction"))->isChecked());
    menu->close();
}

void CurveViewTest::wheelZoomsAboutTheCursor()
{
    Fixture f;
    const QPoint cursor(300, 120);
    const QPointF before = f.view.fromWidget(cursor);
    const QRectF range = f.view.visibleRange();
    sendWheel(&f.view, cursor, 240, {}); // zoom in
    const QRectF zoomed = f.view.visibleRange();
    QVERIFY(zoomed.width() < range.width() && zoomed.height() < range.height());
    const QPointF after = f.view.fromWidget(cursor);
    QVERIFY(near(after.x(), before.x(), 1e-9) && near(after.y(), before.y(), 1e-9));
    // Ctrl: values only; Shift: time only.
    sendWheel(&f.view, cursor, -120, Qt::ControlModifier);
    QCOMPARE(f.view.visibleRange().width(), zoomed.width());
    QVERIFY(f.view.visibleRange().height() > zoomed.height());
    const QRectF valueZoomed = f.view.visibleRange();
    sendWheel(&f.view, cursor, -120, Qt::ShiftModifier);
    QCOMPARE(f.view.visibleRange().height(), valueZoomed.height());
    QVERIFY(f.view.visibleRange().width() > valueZoomed.width());
}

void CurveViewTest::middleDragPans()
{
    Fixture f;
    const QPointF grabbed = f.view.fromWidget(QPointF(200, 100));
    sendMouse(&f.view, QEvent::MouseButtonPress, QPoint(200, 100), Qt::MiddleButton, Qt::MiddleButton, {});
    sendMouse(&f.view, QEvent::MouseMove, QPoint(260, 130), Qt::NoButton, Qt::MiddleButton, {});
    sendMouse(&f.view, QEvent::MouseButtonRelease, QPoint(260, 130), Qt::MiddleButton, Qt::NoButton, {});
    // What was under the cursor followed it.
    const QPointF now = f.view.fromWidget(QPointF(260, 130));
    QVERIFY(near(now.x(), grabbed.x(), 1e-9) && near(now.y(), grabbed.y(), 1e-9));
}

void CurveViewTest::screenshot()
{
    Fixture f;
    f.view.setTimeRange(0, 4);
    f.view.setSelectedKeys({{0, 2}});
    // A little room around the domain, so the shading outside it shows.
    sendWheel(&f.view, f.view.toWidget({2, 0.6}).toPoint(), -150, Qt::ShiftModifier);
    f.view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&f.view));
    const QString dir = QStringLiteral(THESPIS_SCREENSHOT_DIR);
    QVERIFY(QDir().mkpath(dir));
    const QString path = QDir(dir).filePath(QStringLiteral("curve_view.png"));
    const QImage image = f.view.grab().toImage();
    QCOMPARE(image.size() / image.devicePixelRatio(), QSize(700, 320));
    QVERIFY(image.save(path));
    QVERIFY(QFileInfo(path).size() > 10000);
    qInfo("screenshot: %s", qPrintable(path));
}

QTEST_MAIN(CurveViewTest)
#include "curve_view_test.moc"
