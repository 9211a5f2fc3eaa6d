// TimelineView: gestures turn into the right intents (moves, trims and fades snapped exactly in
// ticks, selection, scrubbing, track flags, markers, drops), setters stay silent, and zoom keeps
// the time under the mouse. Also saves screenshots of a realistic timeline and reports how long a
// repaint of 1000 clips takes (report only: timings vary too much between machines to assert).

#include <QAction>
#include <QApplication>
#include <QContextMenuEvent>
#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QImage>
#include <QMenu>
#include <QMimeData>
#include <QScrollBar>
#include <QSignalSpy>
#include <QTest>
#include <QTimer>

#include <cmath>
#include <memory>

#include "widgets/timeline_view.h"

using thespis::widgets::TimelineClip;
using thespis::widgets::TimelineEdge;
using thespis::widgets::TimelineMarker;
using thespis::widgets::TimelineTrack;
using thespis::widgets::TimelineTrackFlag;
using thespis::widgets::TimelineView;

namespace {

constexpr qint64 kTps = 705'600'000;
constexpr qint64 kFrame = kTps / 30; // 23,520,000 ticks at the default 30 fps

qint64 sec(double seconds)
{
    return std::llround(seconds * double(kTps));
}

// Ticks that `pixels` of mouse travel stand for at 100 px/s, before snapping.
qint64 rawTicks(int pixels)
{
    return std::llround(pixels * double(kTps) / 100.0);
}

// QTest::mouseMove cannot carry modifiers; a drag with Ctrl held needs its own move events.
void move(QWidget* widget, QPoint pos, Qt::KeyboardModifiers modifiers = {})
{
    QMouseEvent event(QEvent::MouseMove, QPointF(pos), QPointF(widget->mapToGlobal(pos)), Qt::NoButton,
                      Qt::LeftButton, modifiers);
    QApplication::sendEvent(widget, &event);
}

// Press at `from`, move there in `steps`, release: what a user's drag sends.
void drag(QWidget* widget, QPoint from, QPoint to, Qt::KeyboardModifiers modifiers = {}, int steps = 4)
{
    QTest::mousePress(widget, Qt::LeftButton, modifiers, from);
    for (int i = 1; i <= steps; ++i)
        move(widget, from + (to - from) * i / steps, modifiers);
    QTest::mouseRelease(widget, Qt::LeftButton, modifiers, to);
}

QList<int> ids(const QVariant& value)
{
    return value.value<QList<int>>();
}

TimelineClip makeClip(int id, int track, const QString& name, double start, double end, double fadeIn = 0,
                      double fadeOut = 0)
{
    TimelineClip clip;
    clip.id = id;
    clip.track = track;
    clip.name = name;
    clip.start = sec(start);
    clip.end = end < 0 ? TimelineView::OpenEnd : sec(end);
    clip.fadeIn = sec(fadeIn);
    clip.fadeOut = sec(fadeOut);
    return clip;
}

// A smooth weight curve for thumbnails: rises, holds with a wobble, falls.
QVector<float> weightCurve(int samples, float phase)
{
    QVector<float> weight(samples);
    for (int i = 0; i < samples; ++i) {
        const float t = float(i) / float(samples - 1);
        const float envelope = std::min({1.0f, t * 4.0f, (1.0f - t) * 4.0f});
        weight[i] = envelope * (0.75f + 0.22f * std::sin(phase + t * 9.0f));
    }
    return weight;
}

QPalette darkPalette()
{
    QPalette p;
    p.setColor(QPalette::Window, QColor(0x2b, 0x2d, 0x31));
    p.setColor(QPalette::WindowText, QColor(0xd9, 0xdb, 0xdf));
    p.setColor(QPalette::Base, QColor(0x1f, 0x21, 0x25));
    p.setColor(QPalette::AlternateBase, QColor(0x26, 0x28, 0x2c));
    p.setColor(QPalette::Text, QColor(0xe3, 0xe5, 0xe8));
    p.setColor(QPalette::Button, QColor(0x33, 0x36, 0x3b));
    p.setColor(QPalette::ButtonText, QColor(0xd9, 0xdb, 0xdf));
    p.setColor(QPalette::Highlight, QColor(0x3d, 0x8e, 0xd6));
    p.setColor(QPalette::HighlightedText, Qt::white);
    p.setColor(QPalette::Light, QColor(0x45, 0x48, 0x4e));
    p.setColor(QPalette::Midlight, QColor(0x3a, 0x3d, 0x42));
    p.setColor(QPalette::Mid, QColor(0x24, 0x26, 0x2a));
    p.setColor(QPalette::Dark, QColor(0x18, 0x19, 0x1c));
    p.setColor(QPalette::Shadow, Qt::black);
    return p;
}

} // namespace

class TimelineViewTest : public QObject {
    Q_OBJECT
private slots:
    void geometryAndExactFrames();
    void moveDragEmitsSnappedDelta();
    void moveSnapsToOtherClipsEdges();
    void escapeCancelsADrag();
    void verticalDragPicksATrackOfTheGroup();
    void verticalDragEscapes();
    void ctrlBypassesSnapping();
    void moveLeavesLockedClipsOut();
    void trimsEachEdge();
    void trimKeepsOneFrame();
    void dragsFadeHandles();
    void lockedTrackEmitsNothing();
    void rubberBandSelects();
    void clicksSelectAndShiftToggles();
    void ctrlASelectsAllAndDoubleClickActivates();
    void rulerPressSeeks();
    void flagTogglesRequestTrackFlags();
    void markersAddMoveAndRemove();
    void dropRequestsAClip();
    void settersEmitNothing();
    void ctrlWheelZoomsAboutTheMouse();
    void screenshot();
    void repaintTiming();

private:
    // Anna: Body, Face; Ben: Body, Face (locked). 100 px/s, 10 s long, playhead at 8 s, a marker at 7 s.
    static std::unique_ptr<TimelineView> makeView();
    // With kinds: Anna: Body, Gestures (body), Face (face); Ben: Body, Props (body, locked).
    static std::unique_ptr<TimelineView> makeLayeredView();
};

std::unique_ptr<TimelineView> TimelineViewTest::makeView()
{
    auto view = std::make_unique<TimelineView>();
    view->setTracks({{QStringLiteral("Body"), QStringLiteral("Anna")},
                     {QStringLiteral("Face"), QStringLiteral("Anna")},
                     {QStringLiteral("Body"), QStringLiteral("Ben")},
                     {QStringLiteral("Face"), QStringLiteral("Ben"), false, false, true}});
    view->setClips({makeClip(1, 0, QStringLiteral("Walk"), 1, 3, 0.2, 0.3), makeClip(2, 0, QStringLiteral("Sit"), 5, 6),
                    makeClip(3, 1, QStringLiteral("Smile"), 2, 4), makeClip(4, 2, QStringLiteral("Wave"), 0.5, 2.5),
                    makeClip(5, 3, QStringLiteral("Blink"), 1, 2)});
    view->setMarkers({{QStringLiteral("Cue"), sec(7)}});
    view->setDuration(sec(10));
    view->setPlayhead(sec(8));
    view->setPixelsPerSecond(100);
    view->resize(1100, 320);
    view->show();
    if (!QTest::qWaitForWindowExposed(view.get()))
        qWarning("the timeline was not exposed");
    return view;
}

void TimelineViewTest::geometryAndExactFrames()
{
    {
        TimelineView empty; // nothing to show: paints, and frames a default span
        empty.resize(600, 200);
        empty.frameAll();
        QVERIFY(!empty.grab().isNull());
        QVERIFY(empty.clipRect(1).isNull() && empty.trackRect(0).isNull());
    }
    auto view = makeView();
    QCOMPARE(view->horizontalScrollBar()->value(), 0);
    QCOMPARE(view->timeForX(view->xForTime(sec(2.5))), sec(2.5));
    QCOMPARE(view->xForTime(sec(1)) + 100, view->xForTime(sec(2)));
    const QRect walk = view->clipRect(1);
    QCOMPARE(walk.left(), view->xForTime(sec(1)));
    QCOMPARE(walk.width(), 200);
    QVERIFY(view->trackRect(0).contains(walk));
    QVERIFY(view->trackRect(1).top() >= view->trackRect(0).bottom());
    QVERIFY(view->trackRect(2).top() > view->trackRect(1).bottom() + 1); // Ben's group row between
    QVERIFY(view->rulerRect().bottom() < view->trackRect(0).top());
    QVERIFY(view->trackFlagRect(0, TimelineTrackFlag::Mute).right() < TimelineView::HeaderWidth);
    QVERIFY(view->clipRect(42).isNull());

    // Frames are exact in ticks, also when the frame rate does not divide the tick rate.
    QCOMPARE(view->frameTime(45), 45 * kFrame);
    QCOMPARE(view->roundToFrame(sec(1.47)), 44 * kFrame);
    QCOMPARE(view->roundToFrame(-sec(0.31)), -9 * kFrame);
    view->setFrameRate(24);
    QCOMPARE(view->frameTime(24), kTps);
    QCOMPARE(view->roundToFrame(sec(1.0) + 1), kTps);
    view->setTicksPerSecond(1000);
    view->setFrameRate(30);
    QCOMPARE(view->frameTime(1), 33); // 33.33… rounds to the nearest tick
    QCOMPARE(view->frameTime(30), 1000);

    // An open-ended clip runs to the right edge of the view.
    view->setTicksPerSecond(kTps);
    view->setClips({makeClip(9, 2, QStringLiteral("Idle"), 4, -1)});
    QCOMPARE(view->clipRect(9).left(), view->xForTime(sec(4)));
    QCOMPARE(view->clipRect(9).right(), view->viewport()->width() - 1);
    QVERIFY(view->fadeHandleRect(9, TimelineEdge::End).isNull());
}

void TimelineViewTest::moveDragEmitsSnappedDelta()
{
    auto view = makeView();
    QSignalSpy moves(view.get(), &TimelineView::clipsMoveRequested);
    QSignalSpy selection(view.get(), &TimelineView::selectionChanged);
    const QPoint from = view->clipRect(1).center();
    drag(view->viewport(), from, from + QPoint(47, 0));

    // 47 px = 0.47 s: Walk's start would be at 1.47 s, nothing to snap to within 8 px, so it
    // lands on the nearest frame, 44 (1.4667 s): a delta of 14 frames.
    QVERIFY2(moves.count() >= 2, "moving emits while dragging and once on release");
    for (int i = 0; i < moves.count() - 1; ++i) {
        QCOMPARE(moves.at(i).at(3).toBool(), false);
        QCOMPARE(moves.at(i).at(1).toLongLong() % kFrame, 0);
    }
    const QList<QVariant> last = moves.last();
    QCOMPARE(ids(last.at(0)), QList<int>{1});
    QCOMPARE(last.at(1).toLongLong(), 14 * kFrame);
    QCOMPARE(last.at(2).toInt(), 0); // a horizontal drag stays on its track
    QCOMPARE(last.at(3).toBool(), true);
    QCOMPARE(selection.count(), 1); // the press selected Walk
    QCOMPARE(ids(selection.at(0).at(0)), QList<int>{1});

    // A press and release without movement requests nothing.
    moves.clear();
    QTest::mouseClick(view->viewport(), Qt::LeftButton, {}, view->clipRect(2).center());
    QCOMPARE(moves.count(), 0);
}

void TimelineViewTest::moveSnapsToOtherClipsEdges()
{
    auto view = makeView();
    QSignalSpy moves(view.get(), &TimelineView::clipsMoveRequested);
    const QPoint from = view->clipRect(1).center();
    // 195 px: Walk's end would be at 4.95 s, 5 px from Sit's start at 5 s: it snaps there.
    drag(view->viewport(), from, from + QPoint(195, 0));
    QCOMPARE(moves.last().at(1).toLongLong(), sec(2));
    QCOMPARE(moves.last().at(3).toBool(), true);

    // Nothing moves before 0: a drag far left stops with Walk's start at 0.
    moves.clear();
    drag(view->viewport(), from, from + QPoint(-400, 0));
    QCOMPARE(moves.last().at(1).toLongLong(), -sec(1));
}

std::unique_ptr<TimelineView> TimelineViewTest::makeLayeredView()
{
    auto view = std::make_unique<TimelineView>();
    const QString anna = QStringLiteral("Anna"), ben = QStringLiteral("Ben");
    const QString body = QStringLiteral("body"), face = QStringLiteral("face");
    view->setTracks({{QStringLiteral("Body"), anna, false, false, false, body},
                     {QStringLiteral("Gestures"), anna, false, false, false, body},
                     {QStringLiteral("Face"), anna, false, false, false, face},
                     {QStringLiteral("Body"), ben, false, false, false, body},
                     {QStringLiteral("Props"), ben, false, false, true, body}});
    view->setClips({makeClip(1, 0, QStringLiteral("Walk"), 1, 3, 0.2, 0.3), makeClip(2, 1, QStringLiteral("Nod"), 4, 5),
                    makeClip(3, 2, QStringLiteral("Smile"), 2, 4), makeClip(4, 3, QStringLiteral("Wave"), 0.5, 2.5)});
    view->setDuration(sec(10));
    view->setPixelsPerSecond(100);
    view->resize(1100, 360);
    view->show();
    if (!QTest::qWaitForWindowExposed(view.get()))
        qWarning("the timeline was not exposed");
    return view;
}

void TimelineViewTest::verticalDragPicksATrackOfTheGroup()
{
    auto view = makeLayeredView();
    QWidget* vp = view->viewport();
    QSignalSpy moves(view.get(), &TimelineView::clipsMoveRequested);
    const QPoint walk = view->clipRect(1).center();
    auto yOf = [&](int track) { return view->trackRect(track).center().y(); };

    // Straight down onto Anna's Gestures track: one track, no time change.
    drag(vp, walk, QPoint(walk.x(), yOf(1)));
    QCOMPARE(ids(moves.last().at(0)), QList<int>{1});
    QCOMPARE(moves.last().at(1).toLongLong(), 0);
    QCOMPARE(moves.last().at(2).toInt(), 1);
    QCOMPARE(moves.last().at(3).toBool(), true);
    for (int i = 0; i < moves.count() - 1; ++i)
        QCOMPARE(moves.at(i).at(3).toBool(), false);

    // Down and right at once: time and track together (0.3 s = 9 frames).
    moves.clear();
    drag(vp, walk, QPoint(walk.x() + 30, yOf(1)));
    QCOMPARE(moves.last().at(1).toLongLong(), 9 * kFrame);
    QCOMPARE(moves.last().at(2).toInt(), 1);

    // Further down, onto the Face track, Ben's tracks or below them all: held on Gestures, the
    // last body track of Anna. The group row between the characters counts as the nearest track.
    for (const int y : {yOf(2), yOf(3), yOf(2) + TimelineView::TrackHeight / 2 + TimelineView::GroupHeight / 2,
                        view->viewport()->height() + 200}) {
        moves.clear();
        drag(vp, walk, QPoint(walk.x(), y));
        QCOMPARE(moves.last().at(2).toInt(), 1);
    }
    // Above the first track: nothing to go to, the clip stays on its track (only a time move can be
    // asked; here none, so the release asks nothing).
    moves.clear();
    drag(vp, walk, QPoint(walk.x(), 2));
    for (const QList<QVariant>& m : std::as_const(moves))
        QCOMPARE(m.at(2).toInt(), 0);

    // Ben's Wave: Props below is locked, Anna's tracks above are another group: it stays.
    const QPoint wave = view->clipRect(4).center();
    for (const int y : {yOf(4), yOf(1)}) {
        moves.clear();
        drag(vp, wave, QPoint(wave.x() + 20, y));
        QCOMPARE(ids(moves.last().at(0)), QList<int>{4});
        QCOMPARE(moves.last().at(1).toLongLong(), 6 * kFrame);
        QCOMPARE(moves.last().at(2).toInt(), 0);
    }

    // Walk and Nod together: one track down would put Nod on the face track, one up would put Walk
    // above the first track; only a time move is left. Up from Nod to Body: refused as well.
    view->setSelectedClips({1, 2});
    moves.clear();
    drag(vp, walk, QPoint(walk.x(), yOf(1)));
    for (const QList<QVariant>& m : std::as_const(moves))
        QCOMPARE(m.at(2).toInt(), 0);
    QCOMPARE(view->selectedClips(), (QList<int>{1, 2}));
    const QPoint nod = view->clipRect(2).center();
    moves.clear();
    drag(vp, nod, QPoint(nod.x() + 20, yOf(0)));
    QCOMPARE(ids(moves.last().at(0)), (QList<int>{1, 2}));
    QCOMPARE(moves.last().at(2).toInt(), 0);
}

void TimelineViewTest::verticalDragEscapes()
{
    auto view = makeLayeredView();
    view->setPalette(darkPalette());
    QWidget* vp = view->viewport();
    QSignalSpy moves(view.get(), &TimelineView::clipsMoveRequested);
    const QPoint walk = view->clipRect(1).center();
    const QRect target = view->clipRect(1).translated(0, view->trackRect(1).top() - view->trackRect(0).top());
    const QImage before = vp->grab(target).toImage();

    QTest::mousePress(vp, Qt::LeftButton, {}, walk);
    move(vp, walk + QPoint(0, 12));
    move(vp, QPoint(walk.x(), view->trackRect(1).center().y()));
    QCOMPARE(moves.count(), 1);
    QCOMPARE(moves.last().at(2).toInt(), 1);
    QCOMPARE(moves.last().at(3).toBool(), false);
    // Nothing moved the clip (no editor here): a ghost shows where it lands.
    QApplication::processEvents();
    const QImage during = vp->grab(target).toImage();
    QVERIFY2(during != before, "the ghost is drawn on the target track");
    QDir().mkpath(QStringLiteral(THESPIS_SCREENSHOT_DIR));
    QVERIFY(view->grab().save(QStringLiteral(THESPIS_SCREENSHOT_DIR "/timeline_view_vertical_drag.png")));

    QTest::keyClick(view.get(), Qt::Key_Escape);
    QCOMPARE(moves.count(), 2); // asked back: same time, same track, finished
    QCOMPARE(moves.last().at(1).toLongLong(), 0);
    QCOMPARE(moves.last().at(2).toInt(), 0);
    QCOMPARE(moves.last().at(3).toBool(), true);
    QApplication::processEvents();
    QCOMPARE(vp->grab(target).toImage(), before); // the ghost is gone
    move(vp, QPoint(walk.x(), view->trackRect(0).center().y()));
    QTest::mouseRelease(vp, Qt::LeftButton, {}, walk);
    QCOMPARE(moves.count(), 2);
}

void TimelineViewTest::escapeCancelsADrag()
{
    auto view = makeView();
    QSignalSpy moves(view.get(), &TimelineView::clipsMoveRequested);
    const QPoint from = view->clipRect(1).center();
    QTest::mousePress(view->viewport(), Qt::LeftButton, {}, from);
    move(view->viewport(), from + QPoint(60, 0));
    QCOMPARE(moves.count(), 1);
    QTest::keyClick(view.get(), Qt::Key_Escape);
    QCOMPARE(moves.count(), 2); // asked back: no change, finished
    QCOMPARE(moves.last().at(1).toLongLong(), 0);
    QCOMPARE(moves.last().at(2).toInt(), 0);
    QCOMPARE(moves.last().at(3).toBool(), true);
    move(view->viewport(), from + QPoint(90, 0));
    QTest::mouseRelease(view->viewport(), Qt::LeftButton, {}, from + QPoint(90, 0));
    QCOMPARE(moves.count(), 2); // the rest of the gesture is ignored

    // Ctrl+Z during a drag asks back as Escape does, and the window's Undo and Redo (which would
    // pull the document from under the drag) do not fire; after the drag they do again.
    QAction undo(QStringLiteral("Undo")), redo(QStringLiteral("Redo"));
    undo.setShortcut(QKeySequence::Undo);
    redo.setShortcut(QKeySequence::Redo);
    view->addAction(&undo);
    view->addAction(&redo);
    QSignalSpy undone(&undo, &QAction::triggered), redone(&redo, &QAction::triggered);
    view->show();
    QVERIFY(QTest::qWaitForWindowActive(view.get()));
    moves.clear();
    QTest::mousePress(view->viewport(), Qt::LeftButton, {}, from);
    move(view->viewport(), from + QPoint(60, 0));
    QCOMPARE(moves.count(), 1);
    QTest::keySequence(view.get(), QKeySequence::Redo);
    QTest::keySequence(view.get(), QKeySequence::Undo);
    QCOMPARE(undone.count(), 0);
    QCOMPARE(redone.count(), 0);
    QCOMPARE(moves.count(), 2);
    QCOMPARE(moves.last().at(1).toLongLong(), 0);
    QCOMPARE(moves.last().at(3).toBool(), true);
    QTest::mouseRelease(view->viewport(), Qt::LeftButton, {}, from + QPoint(60, 0));
    QCOMPARE(moves.count(), 2);
    QTest::keySequence(view.get(), QKeySequence::Undo);
    QCOMPARE(undone.count(), 1);
}

void TimelineViewTest::ctrlBypassesSnapping()
{
    auto view = makeView();
    QSignalSpy moves(view.get(), &TimelineView::clipsMoveRequested);
    const QPoint from = view->clipRect(1).center();
    drag(view->viewport(), from, from + QPoint(47, 0), Qt::ControlModifier);
    QCOMPARE(moves.last().at(1).toLongLong(), rawTicks(47));
    QVERIFY(rawTicks(47) % kFrame != 0);

    moves.clear();
    drag(view->viewport(), from, from + QPoint(195, 0), Qt::ControlModifier); // no pull to Sit's start
    QCOMPARE(moves.last().at(1).toLongLong(), rawTicks(195));

    // With snapping off the delta is raw too.
    moves.clear();
    view->setSnapping(false);
    QVERIFY(!view->snapping());
    drag(view->viewport(), from, from + QPoint(47, 0));
    QCOMPARE(moves.last().at(1).toLongLong(), rawTicks(47));
}

void TimelineViewTest::moveLeavesLockedClipsOut()
{
    auto view = makeView();
    view->setSelectedClips({1, 2, 5}); // Blink (5) is on Ben's locked Face track
    QSignalSpy moves(view.get(), &TimelineView::clipsMoveRequested);
    const QPoint from = view->clipRect(2).center();
    drag(view->viewport(), from, from + QPoint(30, 0));
    QCOMPARE(ids(moves.last().at(0)), (QList<int>{1, 2}));
    QCOMPARE(moves.last().at(1).toLongLong(), 9 * kFrame); // 0.3 s
    QCOMPARE(view->selectedClips(), (QList<int>{1, 2, 5})); // a drag keeps the selection
}

void TimelineViewTest::trimsEachEdge()
{
    auto view = makeView();
    QSignalSpy trims(view.get(), &TimelineView::clipTrimRequested);
    QSignalSpy moves(view.get(), &TimelineView::clipsMoveRequested);
    const QRect walk = view->clipRect(1);

    // The start edge, 31 px left: 0.69 s → frame 21 (0.7 s).
    const QPoint start(walk.left() + 1, walk.center().y());
    drag(view->viewport(), start, start + QPoint(-31, 0));
    QVERIFY(trims.count() >= 2);
    QCOMPARE(trims.last().at(0).toInt(), 1);
    QCOMPARE(trims.last().at(1).value<TimelineEdge>(), TimelineEdge::Start);
    QCOMPARE(trims.last().at(2).toLongLong(), 21 * kFrame);
    QCOMPARE(trims.last().at(3).toBool(), true);
    QCOMPARE(trims.first().at(3).toBool(), false);

    // The end edge, from just outside the clip, 63 px right: 3.63 s → frame 109.
    trims.clear();
    const QPoint end(walk.left() + walk.width() + 2, walk.center().y());
    drag(view->viewport(), end, end + QPoint(63, 0));
    QCOMPARE(trims.last().at(1).value<TimelineEdge>(), TimelineEdge::End);
    QCOMPARE(trims.last().at(2).toLongLong(), 109 * kFrame);
    QCOMPARE(trims.last().at(3).toBool(), true);
    QCOMPARE(moves.count(), 0);

    // The cursor tells the user that the edge trims.
    QTest::mouseMove(view->viewport(), start);
    QCOMPARE(view->viewport()->cursor().shape(), Qt::SizeHorCursor);
    QTest::mouseMove(view->viewport(), walk.center());
    QCOMPARE(view->viewport()->cursor().shape(), Qt::ArrowCursor);
}

void TimelineViewTest::trimKeepsOneFrame()
{
    auto view = makeView();
    QSignalSpy trims(view.get(), &TimelineView::clipTrimRequested);
    const QRect walk = view->clipRect(1);
    const QPoint start(walk.left() + 1, walk.center().y());
    drag(view->viewport(), start, start + QPoint(400, 0));
    QCOMPARE(trims.last().at(2).toLongLong(), sec(3) - kFrame);
    trims.clear();
    const QPoint end(walk.right() - 1, walk.center().y());
    drag(view->viewport(), end, end + QPoint(-400, 0));
    QCOMPARE(trims.last().at(2).toLongLong(), sec(1) + kFrame);
}

void TimelineViewTest::dragsFadeHandles()
{
    auto view = makeView();
    QSignalSpy fades(view.get(), &TimelineView::clipFadeRequested);
    QSignalSpy trims(view.get(), &TimelineView::clipTrimRequested);
    QSignalSpy moves(view.get(), &TimelineView::clipsMoveRequested);

    // Fade in: the handle sits at start + fadeIn (1.2 s); 20 px right makes the fade 0.4 s.
    const QRect in = view->fadeHandleRect(1, TimelineEdge::Start);
    QCOMPARE(in.center().x(), view->xForTime(sec(1.2)));
    drag(view->viewport(), in.center(), in.center() + QPoint(20, 0));
    QVERIFY(fades.count() >= 2);
    QCOMPARE(fades.last().at(0).toInt(), 1);
    QCOMPARE(fades.last().at(1).value<TimelineEdge>(), TimelineEdge::Start);
    QCOMPARE(fades.last().at(2).toLongLong(), sec(0.4));
    QCOMPARE(fades.last().at(3).toBool(), true);

    // Fade out: dragged far past the start, it is clamped to the clip's length (2 s).
    fades.clear();
    const QRect out = view->fadeHandleRect(1, TimelineEdge::End);
    QCOMPARE(out.center().x(), view->xForTime(sec(2.7)));
    drag(view->viewport(), out.center(), out.center() + QPoint(-300, 0));
    QCOMPARE(fades.last().at(1).value<TimelineEdge>(), TimelineEdge::End);
    QCOMPARE(fades.last().at(2).toLongLong(), sec(2));
    // … and back past the end: 0.
    fades.clear();
    drag(view->viewport(), out.center(), out.center() + QPoint(300, 0));
    QCOMPARE(fades.last().at(2).toLongLong(), 0);
    QCOMPARE(trims.count(), 0);
    QCOMPARE(moves.count(), 0);
}

void TimelineViewTest::lockedTrackEmitsNothing()
{
    auto view = makeView();
    QSignalSpy moves(view.get(), &TimelineView::clipsMoveRequested);
    QSignalSpy trims(view.get(), &TimelineView::clipTrimRequested);
    QSignalSpy fades(view.get(), &TimelineView::clipFadeRequested);
    const QRect blink = view->clipRect(5);
    drag(view->viewport(), blink.center(), blink.center() + QPoint(60, 0));
    drag(view->viewport(), QPoint(blink.left() + 1, blink.center().y()), QPoint(blink.left() - 50, blink.center().y()));
    drag(view->viewport(), QPoint(blink.right() - 1, blink.center().y()), QPoint(blink.right() + 50, blink.center().y()));
    drag(view->viewport(), blink.topLeft() + QPoint(4, 4), blink.topLeft() + QPoint(60, 4)); // where a fade handle would be
    QCOMPARE(moves.count(), 0);
    QCOMPARE(trims.count(), 0);
    QCOMPARE(fades.count(), 0);
    QTest::mouseMove(view->viewport(), QPoint(blink.left() + 1, blink.center().y()));
    QCOMPARE(view->viewport()->cursor().shape(), Qt::ArrowCursor); // no trim cursor either
    // A locked clip can still be selected (to look at it), just not edited.
    QCOMPARE(view->selectedClips(), QList<int>{5});
}

void TimelineViewTest::rubberBandSelects()
{
    auto view = makeView();
    QSignalSpy selection(view.get(), &TimelineView::selectionChanged);
    // From empty space on Anna's Body track at 3.5 s to Ben's Body track at 2.2 s: Walk [1,3],
    // Smile [2,4] and Wave [0.5,2.5] are touched; Sit [5,6] and Blink (Ben's Face) are not.
    const QPoint from(view->xForTime(sec(3.5)), view->trackRect(0).center().y());
    const QPoint to(view->xForTime(sec(2.2)), view->trackRect(2).center().y());
    drag(view->viewport(), from, to);
    QCOMPARE(selection.count(), 1);
    QCOMPARE(ids(selection.at(0).at(0)), (QList<int>{1, 3, 4}));
    QCOMPARE(view->selectedClips(), (QList<int>{1, 3, 4}));

    // Shift adds to the selection.
    selection.clear();
    const QPoint sit = view->clipRect(2).center();
    drag(view->viewport(), sit + QPoint(-80, 0), sit + QPoint(0, 5), Qt::ShiftModifier);
    QCOMPARE(view->selectedClips(), (QList<int>{1, 2, 3, 4}));

    // A click on empty space clears it.
    selection.clear();
    QTest::mouseClick(view->viewport(), Qt::LeftButton, {}, QPoint(view->xForTime(sec(8.5)), view->trackRect(1).center().y()));
    QCOMPARE(selection.count(), 1);
    QCOMPARE(ids(selection.at(0).at(0)), QList<int>{});
}

void TimelineViewTest::clicksSelectAndShiftToggles()
{
    auto view = makeView();
    QSignalSpy selection(view.get(), &TimelineView::selectionChanged);
    QWidget* vp = view->viewport();
    QTest::mouseClick(vp, Qt::LeftButton, {}, view->clipRect(1).center());
    QCOMPARE(ids(selection.last().at(0)), QList<int>{1});
    QTest::mouseClick(vp, Qt::LeftButton, Qt::ShiftModifier, view->clipRect(2).center());
    QCOMPARE(ids(selection.last().at(0)), (QList<int>{1, 2}));
    QTest::mouseClick(vp, Qt::LeftButton, Qt::ControlModifier, view->clipRect(3).center());
    QCOMPARE(ids(selection.last().at(0)), (QList<int>{1, 2, 3}));
    QTest::mouseClick(vp, Qt::LeftButton, Qt::ShiftModifier, view->clipRect(1).center());
    QCOMPARE(ids(selection.last().at(0)), (QList<int>{2, 3}));
    QCOMPARE(selection.count(), 4);
    // A plain click on a selected clip narrows the selection to it.
    QTest::mouseClick(vp, Qt::LeftButton, {}, view->clipRect(3).center());
    QCOMPARE(ids(selection.last().at(0)), QList<int>{3});
    QCOMPARE(selection.count(), 5);
}

void TimelineViewTest::ctrlASelectsAllAndDoubleClickActivates()
{
    auto view = makeView();
    QSignalSpy selection(view.get(), &TimelineView::selectionChanged);
    QSignalSpy activated(view.get(), &TimelineView::clipActivated);
    view->setFocus();
    QTest::keyClick(view.get(), Qt::Key_A, Qt::ControlModifier);
    QCOMPARE(selection.count(), 1);
    QCOMPARE(ids(selection.at(0).at(0)), (QList<int>{1, 2, 3, 4, 5}));
    QTest::mouseDClick(view->viewport(), Qt::LeftButton, {}, view->clipRect(3).center());
    QCOMPARE(activated.count(), 1);
    QCOMPARE(activated.at(0).at(0).toInt(), 3);
}

void TimelineViewTest::rulerPressSeeks()
{
    auto view = makeView();
    QSignalSpy seeks(view.get(), &TimelineView::seekRequested);
    const int y = view->rulerRect().center().y();
    QTest::mousePress(view->viewport(), Qt::LeftButton, {}, QPoint(view->xForTime(sec(2)), y));
    QCOMPARE(seeks.count(), 1);
    QCOMPARE(seeks.at(0).at(0).toLongLong(), sec(2));
    // Scrubbing: continuous, on whole frames, never past the end.
    for (int i = 1; i <= 5; ++i)
        move(view->viewport(), QPoint(view->xForTime(sec(2)) + i * 51 - 5, y));
    QVERIFY(seeks.count() >= 5);
    for (const QList<QVariant>& seek : std::as_const(seeks))
        QCOMPARE(seek.at(0).toLongLong() % kFrame, 0);
    QCOMPARE(seeks.last().at(0).toLongLong(), sec(4.5)); // 4.5 s exactly: 135 frames
    move(view->viewport(), QPoint(view->xForTime(sec(14)), y));
    QCOMPARE(seeks.last().at(0).toLongLong(), sec(10));
    QTest::mouseRelease(view->viewport(), Qt::LeftButton, {}, QPoint(view->xForTime(sec(14)), y));
}

void TimelineViewTest::flagTogglesRequestTrackFlags()
{
    auto view = makeView();
    QSignalSpy flags(view.get(), &TimelineView::trackFlagRequested);
    QWidget* vp = view->viewport();
    QTest::mouseClick(vp, Qt::LeftButton, {}, view->trackFlagRect(0, TimelineTrackFlag::Mute).center());
    QTest::mouseClick(vp, Qt::LeftButton, {}, view->trackFlagRect(1, TimelineTrackFlag::Solo).center());
    QTest::mouseClick(vp, Qt::LeftButton, {}, view->trackFlagRect(3, TimelineTrackFlag::Lock).center());
    QCOMPARE(flags.count(), 3);
    QCOMPARE(flags.at(0).at(0).toInt(), 0);
    QCOMPARE(flags.at(0).at(1).value<TimelineTrackFlag>(), TimelineTrackFlag::Mute);
    QCOMPARE(flags.at(0).at(2).toBool(), true);
    QCOMPARE(flags.at(1).at(0).toInt(), 1);
    QCOMPARE(flags.at(1).at(1).value<TimelineTrackFlag>(), TimelineTrackFlag::Solo);
    QCOMPARE(flags.at(1).at(2).toBool(), true);
    QCOMPARE(flags.at(2).at(0).toInt(), 3);
    QCOMPARE(flags.at(2).at(1).value<TimelineTrackFlag>(), TimelineTrackFlag::Lock);
    QCOMPARE(flags.at(2).at(2).toBool(), false); // Ben's Face is locked: the toggle unlocks
    // The view waits to be told: the track is still unmuted until the editor says so.
    QVERIFY(!view->tracks().at(0).muted);
}

void TimelineViewTest::markersAddMoveAndRemove()
{
    auto view = makeView();
    QSignalSpy adds(view.get(), &TimelineView::markerAddRequested);
    QSignalSpy moves(view.get(), &TimelineView::markerMoveRequested);
    QSignalSpy removes(view.get(), &TimelineView::markerRemoveRequested);

    view->setPlayhead(sec(4.2));
    view->setFocus();
    QTest::keyClick(view.get(), Qt::Key_M);
    QCOMPARE(adds.count(), 1);
    QCOMPARE(adds.at(0).at(0).toLongLong(), sec(4.2));

    // A double-click in the ruler adds one there.
    adds.clear();
    QTest::mouseDClick(view->viewport(), Qt::LeftButton, {}, QPoint(view->xForTime(sec(6)), 6));
    QCOMPARE(adds.count(), 1);
    QCOMPARE(adds.at(0).at(0).toLongLong(), sec(6));

    // Dragging the flag moves the marker (0.3 s right).
    const QPoint flag = view->markerRect(0).center();
    drag(view->viewport(), flag, flag + QPoint(30, 0));
    QVERIFY(moves.count() >= 2);
    QCOMPARE(moves.last().at(0).toInt(), 0);
    QCOMPARE(moves.last().at(1).toLongLong(), sec(7.3));
    QCOMPARE(moves.last().at(2).toBool(), true);

    // Its context menu removes it.
    QTimer::singleShot(0, this, [] {
        auto* menu = qobject_cast<QMenu*>(QApplication::activePopupWidget());
        QVERIFY(menu);
        QVERIFY(menu->actions().first()->text().contains(QStringLiteral("Cue")));
        menu->actions().first()->trigger();
        menu->close();
    });
    QContextMenuEvent menuEvent(QContextMenuEvent::Mouse, flag, view->viewport()->mapToGlobal(flag));
    QApplication::sendEvent(view->viewport(), &menuEvent);
    QCOMPARE(removes.count(), 1);
    QCOMPARE(removes.at(0).at(0).toInt(), 0);
}

void TimelineViewTest::dropRequestsAClip()
{
    auto view = makeView();
    QSignalSpy drops(view.get(), &TimelineView::clipDropRequested);
    QWidget* vp = view->viewport();
    QMimeData mime;
    mime.setData(QString::fromLatin1(TimelineView::ClipMimeType), QStringLiteral("Wave hello").toUtf8());

    // Over Ben's Body track at 3.31 s: dropped at frame 99 (3.3 s).
    const QPoint pos(view->xForTime(sec(3.31)), view->trackRect(2).center().y());
    QDragEnterEvent enter(pos, Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(vp, &enter);
    QVERIFY(enter.isAccepted());
    QDragMoveEvent over(pos, Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(vp, &over);
    QVERIFY(over.isAccepted());
    QDropEvent drop(QPointF(pos), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(vp, &drop);
    QVERIFY(drop.isAccepted());
    QCOMPARE(drops.count(), 1);
    QCOMPARE(drops.at(0).at(0).toInt(), 2);
    QCOMPARE(drops.at(0).at(1).toLongLong(), 99 * kFrame);
    QCOMPARE(drops.at(0).at(2).toString(), QStringLiteral("Wave hello"));

    // Not on a locked track, not on the header.
    const QPoint locked(view->xForTime(sec(3)), view->trackRect(3).center().y());
    QDragMoveEvent overLocked(locked, Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(vp, &overLocked);
    QVERIFY(!overLocked.isAccepted());
    QDropEvent dropLocked(QPointF(locked), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(vp, &dropLocked);
    QDropEvent dropHeader(QPointF(40, view->trackRect(2).center().y()), Qt::CopyAction, &mime, Qt::LeftButton,
                          Qt::NoModifier);
    QApplication::sendEvent(vp, &dropHeader);
    QCOMPARE(drops.count(), 1);

    // Other data is not accepted at all.
    QMimeData text;
    text.setText(QStringLiteral("hello"));
    QDragEnterEvent other(pos, Qt::CopyAction, &text, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(vp, &other);
    QVERIFY(!other.isAccepted());
}

void TimelineViewTest::settersEmitNothing()
{
    auto view = makeView();
    QSignalSpy selection(view.get(), &TimelineView::selectionChanged);
    QSignalSpy moves(view.get(), &TimelineView::clipsMoveRequested);
    QSignalSpy trims(view.get(), &TimelineView::clipTrimRequested);
    QSignalSpy fades(view.get(), &TimelineView::clipFadeRequested);
    QSignalSpy seeks(view.get(), &TimelineView::seekRequested);
    QSignalSpy flags(view.get(), &TimelineView::trackFlagRequested);
    QSignalSpy markerAdds(view.get(), &TimelineView::markerAddRequested);
    QSignalSpy markerMoves(view.get(), &TimelineView::markerMoveRequested);

    view->setSelectedClips({1, 2, 99});
    QCOMPARE(view->selectedClips(), (QList<int>{1, 2}));
    // New clips keep the selection of the ids still there.
    view->setClips({makeClip(1, 0, QStringLiteral("Walk"), 1.5, 3.5), makeClip(3, 1, QStringLiteral("Smile"), 2, 4)});
    QCOMPARE(view->selectedClips(), QList<int>{1});
    view->setTracks({{QStringLiteral("Body"), QStringLiteral("Anna"), true, true, true}});
    view->setMarkers({});
    view->setDuration(sec(20));
    view->setPlayhead(sec(3));
    view->setFrameRate(24);
    view->setTicksPerSecond(kTps);
    view->setSnapping(false);
    view->setPixelsPerSecond(250);
    QCOMPARE(view->pixelsPerSecond(), 250.0);
    view->frameAll();
    QVERIFY(view->xForTime(sec(20)) <= view->viewport()->width());
    QVERIFY(view->xForTime(sec(20)) > view->viewport()->width() - 60);
    QCOMPARE(selection.count() + moves.count() + trims.count() + fades.count() + seeks.count() + flags.count()
                 + markerAdds.count() + markerMoves.count(),
             0);
}

void TimelineViewTest::ctrlWheelZoomsAboutTheMouse()
{
    auto view = makeView();
    QWidget* vp = view->viewport();
    const QPoint mouse(640, view->trackRect(1).center().y());
    const qint64 under = view->timeForX(mouse.x());
    auto wheel = [&](int delta, Qt::KeyboardModifiers modifiers) {
        QWheelEvent event(QPointF(mouse), QPointF(vp->mapToGlobal(mouse)), QPoint(), QPoint(0, delta), Qt::NoButton,
                          modifiers, Qt::NoScrollPhase, false);
        QApplication::sendEvent(vp, &event);
    };
    for (int i = 0; i < 3; ++i)
        wheel(120, Qt::ControlModifier);
    QVERIFY(view->pixelsPerSecond() > 150);
    QVERIFY2(std::abs(view->xForTime(under) - mouse.x()) <= 1, "the time under the mouse stays under it");
    const double zoomedIn = view->pixelsPerSecond();
    for (int i = 0; i < 2; ++i)
        wheel(-120, Qt::ControlModifier);
    QVERIFY(view->pixelsPerSecond() < zoomedIn);
    QVERIFY2(std::abs(view->xForTime(under) - mouse.x()) <= 1, "zooming out too");

    // Shift+wheel pans the time, the plain wheel scrolls the tracks.
    view->setPixelsPerSecond(400);
    const int scrolled = view->horizontalScrollBar()->value();
    wheel(-120, Qt::ShiftModifier);
    QVERIFY(view->horizontalScrollBar()->value() > scrolled);
    view->resize(1100, 150);
    QVERIFY(view->verticalScrollBar()->maximum() > 0);
    wheel(-120, {});
    QVERIFY(view->verticalScrollBar()->value() > 0);
    QCOMPARE(view->rulerRect().top(), 0); // the ruler stays put
}

void TimelineViewTest::screenshot()
{
    const QString dir = QStringLiteral(THESPIS_SCREENSHOT_DIR);
    QVERIFY(QDir().mkpath(dir));
    for (const bool dark : {true, false}) {
        TimelineView view;
        if (dark)
            view.setPalette(darkPalette());
        view.setTracks({{QStringLiteral("Body"), QStringLiteral("Anna")},
                        {QStringLiteral("Face"), QStringLiteral("Anna")},
                        {QStringLiteral("Body"), QStringLiteral("Ben"), true},
                        {QStringLiteral("Face"), QStringLiteral("Ben"), false, false, true}});
        QVector<TimelineClip> clips = {
            makeClip(1, 0, QStringLiteral("Walk to the window"), 0.0, 3.2, 0.4, 0.5),
            makeClip(2, 0, QStringLiteral("Lean on sill"), 3.0, 6.5, 0.5, 0.6),
            makeClip(3, 0, QStringLiteral("Turn around"), 6.8, 9.0, 0.3, 0.4),
            makeClip(4, 1, QStringLiteral("Smile"), 0.6, 2.4, 0.3, 0.3),
            makeClip(5, 1, QStringLiteral("Talk: \"It's raining again\""), 2.8, 6.2, 0.2, 0.2),
            makeClip(6, 1, QStringLiteral("Blink"), 7.0, 7.4, 0.05, 0.05),
            makeClip(7, 2, QStringLiteral("Idle breathing"), 0.0, 4.5, 0.0, 0.8),
            makeClip(8, 2, QStringLiteral("Wave"), 4.0, 6.0, 0.4, 0.4),
            makeClip(9, 3, QStringLiteral("Frown"), 1.0, 3.0, 0.4, 0.6),
            makeClip(10, 3, QStringLiteral("Look at Anna"), 5.2, -1, 0.5),
        };
        for (int i = 0; i < clips.size(); ++i)
            clips[i].weight = weightCurve(48, float(i));
        view.setClips(clips);
        view.setMarkers({{QStringLiteral("Door opens"), sec(4.0)}});
        view.setDuration(sec(10));
        view.setPlayhead(sec(4.6));
        view.setSelectedClips({2, 8});
        view.resize(1100, 260);
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        view.frameAll();
        const QString path = QDir(dir).filePath(dark ? QStringLiteral("timeline_view.png") : QStringLiteral("timeline_view_light.png"));
        const QImage image = view.grab().toImage();
        QCOMPARE(image.size(), QSize(1100, 260));
        QVERIFY(image.save(path));
        QVERIFY(QFileInfo(path).size() > 10000);
        qInfo("screenshot: %s", qPrintable(path));
    }
}

void TimelineViewTest::repaintTiming()
{
    TimelineView view;
    QVector<TimelineTrack> tracks;
    for (int i = 0; i < 8; ++i)
        tracks.push_back({i % 2 ? QStringLiteral("Face") : QStringLiteral("Body"), QStringLiteral("Character %1").arg(i / 2 + 1)});
    view.setTracks(tracks);
    QVector<TimelineClip> clips;
    for (int i = 0; i < 1000; ++i) {
        const int track = i % 8, slot = i / 8;
        TimelineClip clip = makeClip(i + 1, track, QStringLiteral("Clip %1").arg(i + 1), slot * 1.2 + track * 0.1,
                                     slot * 1.2 + track * 0.1 + 1.0, 0.2, 0.2);
        clip.weight = weightCurve(64, float(i));
        clips.push_back(clip);
    }
    view.setClips(clips);
    view.setDuration(sec(151));
    view.setPlayhead(sec(40));
    view.setMarkers({{QStringLiteral("A"), sec(10)}, {QStringLiteral("B"), sec(60)}});
    QList<int> selected;
    for (int i = 1; i <= 1000; i += 7)
        selected.push_back(i);
    view.setSelectedClips(selected);
    view.resize(1200, 400);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));

    QImage image(view.viewport()->size(), QImage::Format_ARGB32_Premultiplied);
    auto measure = [&](const char* what) {
        view.viewport()->render(&image); // warm the caches (elided names)
        QElapsedTimer timer;
        timer.start();
        for (int i = 0; i < 100; ++i)
            view.viewport()->render(&image);
        qInfo("repaint, 1000 clips on 8 tracks, 1200x400, %s: %.3f ms", what, timer.nsecsElapsed() / 1e6 / 100.0);
    };
    view.frameAll(); // every clip on screen
    measure("all 1000 visible");
    view.setPixelsPerSecond(100); // about 80 clips with names, fades and thumbnails
    measure("zoomed to 100 px/s");
    view.setPixelsPerSecond(30);
    measure("zoomed to 30 px/s");
}

QTEST_MAIN(TimelineViewTest)
#include "timeline_view_test.moc"
