// The timeline's pure geometry and snapping, without a widget: time ↔ x round trips at several
// zooms and scroll offsets, exact frame arithmetic, the rows of groups and tracks, hit testing of
// clip edges, body, fade handles, flags and markers, snapping to neighbouring clip edges, markers
// and the playhead within the threshold (and to a frame beyond it), and where a clip drag may
// move clips up or down.

#include <QTest>

#include <cmath>
#include <vector>

#include "widgets/timeline_drag.h"
#include "widgets/timeline_geometry.h"
#include "widgets/timeline_snapping.h"

using namespace thespis::widgets;
using M = TimelineMetrics;

namespace {

constexpr qint64 kTps = 705'600'000;
constexpr qint64 kFrame = kTps / 30;

qint64 sec(double seconds)
{
    return std::llround(seconds * double(kTps));
}

TimelineTrack track(const QString& name, const QString& group, const QString& kind = QStringLiteral("body"),
                    bool locked = false)
{
    TimelineTrack t;
    t.name = name;
    t.group = group;
    t.kind = kind;
    t.locked = locked;
    return t;
}

TimelineClip clip(int id, int trackIndex, qint64 start, qint64 end, qint64 fadeIn = 0, qint64 fadeOut = 0)
{
    TimelineClip c;
    c.id = id;
    c.track = trackIndex;
    c.start = start;
    c.end = end;
    c.fadeIn = fadeIn;
    c.fadeOut = fadeOut;
    return c;
}

// Owns what a TimelineGeometry refers to.
struct Scene {
    std::vector<TimelineTrack> tracks;
    std::vector<TimelineClip> clips;
    std::vector<char> selected;
    std::vector<TimelineMarker> markers;
    std::vector<int> markerWidths;
    TimelineRows rows;

    TimelineGeometry geometry(double pixelsPerSecond = 100.0, QPoint scroll = {}, QSize viewport = {1000, 400})
    {
        rows = TimelineRows::layout(tracks);
        selected.resize(clips.size(), 0);
        markerWidths.resize(markers.size(), 40);
        TimelineGeometry g;
        g.pixelsPerSecond = pixelsPerSecond;
        g.scroll = scroll;
        g.viewport = viewport;
        g.rows = &rows;
        g.tracks = tracks;
        g.clips = clips;
        g.selected = selected;
        g.markers = markers;
        g.markerWidths = markerWidths;
        return g;
    }
};

} // namespace

class TimelineGeometryTest : public QObject {
    Q_OBJECT
private slots:
    void timeAndXRoundTrip_data();
    void timeAndXRoundTrip();
    void openEndMapsToTheRightEdge();
    void framesAreExactInTicks();
    void formatsMinutesSecondsFrames();
    void rowsGroupTracksUnderHeaders();
    void hitTestTellsEdgesFromBody();
    void hitTestFindsFadeHandlesButNotOnLockedTracks();
    void hitTestKeepsABodyOnNarrowClipsAndPrefersSelected();
    void hitTestHeaderRulerAndMarkers();
    void snapTargetsCollectEdgesMarkersAndPlayhead();
    void snapTimeAttractsWithinThresholdOnly();
    void snapDeltaPutsTheNearestEdgeOnATarget();
    void trackOffsetStaysInGroupAndKind();
};

void TimelineGeometryTest::timeAndXRoundTrip_data()
{
    QTest::addColumn<double>("pixelsPerSecond");
    QTest::addColumn<int>("scrollX");
    QTest::newRow("zoomed out") << 0.5 << 0;
    QTest::newRow("default") << 100.0 << 0;
    QTest::newRow("default, scrolled") << 100.0 << 1234;
    QTest::newRow("odd zoom, scrolled") << 37.3 << 517;
    QTest::newRow("frames wide, far scrolled") << 2400.0 << 250000;
}

void TimelineGeometryTest::timeAndXRoundTrip()
{
    QFETCH(double, pixelsPerSecond);
    QFETCH(int, scrollX);
    Scene scene;
    const TimelineGeometry g = scene.geometry(pixelsPerSecond, QPoint(scrollX, 0));
    QCOMPARE(g.originX(), M::HeaderWidth + M::TimePad - scrollX);
    QCOMPARE(g.xForTime(0), g.originX());

    // A pixel maps to a time that maps back to the same pixel.
    for (int x = -50; x <= 1200; x += 37)
        QCOMPARE(g.xForTime(g.timeForX(x)), x);
    // A time comes back within half a pixel's worth of ticks.
    const double halfPixel = g.ticksPerPixel() / 2 + 1;
    for (qint64 t : {qint64(0), kFrame, sec(1.5), sec(12.25) + 7, sec(600)}) {
        const qint64 back = g.timeForX(g.xForTime(t));
        QVERIFY2(std::abs(double(back - t)) <= halfPixel, qPrintable(QStringLiteral("%1 → %2").arg(t).arg(back)));
    }
    // One second is pixelsPerSecond pixels wherever it is.
    QVERIFY(std::abs(g.xForTime(sec(11)) - g.xForTime(sec(10)) - pixelsPerSecond) <= 1.0);
    QCOMPARE(g.ticksForPixels(0), qint64(0));
    QCOMPARE(g.timeForX(g.originX() + 10) - g.timeForX(g.originX()), g.ticksForPixels(10));
}

void TimelineGeometryTest::openEndMapsToTheRightEdge()
{
    Scene scene;
    scene.tracks = {track("Body", {})};
    scene.clips = {clip(1, 0, sec(1), TimelineOpenEnd)};
    const TimelineGeometry g = scene.geometry(100.0, {}, QSize(900, 300));
    QCOMPARE(g.xForTime(TimelineOpenEnd), 900);
    const QRect r = g.clipRect(0);
    QCOMPARE(r.left(), g.xForTime(sec(1)));
    QCOMPARE(r.left() + r.width(), 900);
    QVERIFY(g.fadeHandleRect(0, TimelineEdge::End).isNull());
    QVERIFY(!g.fadeHandleRect(0, TimelineEdge::Start).isNull());
}

void TimelineGeometryTest::framesAreExactInTicks()
{
    const TimelineTimebase time; // 705,600,000 ticks per second, 30 fps
    QCOMPARE(time.frameTime(1), kFrame);
    QCOMPARE(time.frameTime(-3), -3 * kFrame);
    QCOMPARE(time.roundToFrame(5 * kFrame + kFrame / 2 - 1), 5 * kFrame);
    QCOMPARE(time.roundToFrame(5 * kFrame + kFrame / 2 + 1), 6 * kFrame);
    QCOMPARE(time.roundToFrame(-kFrame / 3), qint64(0));
    QCOMPARE(time.roundToFrame(TimelineOpenEnd), TimelineOpenEnd);
    QCOMPARE(time.frameAt(2 * kFrame - 1), qint64(1));
    QCOMPARE(time.frameAt(-1), qint64(-1));

    // A frame rate that does not divide the tick rate: the nearest tick, never drifting.
    const TimelineTimebase odd{1000, 30};
    QCOMPARE(odd.frameTime(1), qint64(33));
    QCOMPARE(odd.frameTime(2), qint64(67));
    QCOMPARE(odd.frameTime(30), qint64(1000));
    QCOMPARE(odd.roundToFrame(40), qint64(33));
    QCOMPARE(odd.roundToFrame(60), qint64(67));
}

void TimelineGeometryTest::formatsMinutesSecondsFrames()
{
    const TimelineTimebase time;
    QCOMPARE(time.format(0), QStringLiteral("0:00+00"));
    QCOMPARE(time.format(sec(65) + 12 * kFrame), QStringLiteral("1:05+12"));
    QCOMPARE(time.format(-sec(2)), QStringLiteral("-0:02+00"));
}

void TimelineGeometryTest::rowsGroupTracksUnderHeaders()
{
    Scene scene;
    scene.tracks = {track("Body", "Ana"), track("Face", "Ana", "face"), track("Camera", {}), track("Body", "Ben")};
    const TimelineGeometry g = scene.geometry(100.0, QPoint(0, 15));
    const std::vector<TimelineRow>& rows = scene.rows.rows;
    QCOMPARE(int(rows.size()), 6);
    QCOMPARE(rows[0].track, -1); // Ana's header
    QCOMPARE(rows[0].group, 0);
    QCOMPARE(rows[1].top, M::GroupHeight);
    QCOMPARE(rows[1].group, 0);
    QCOMPARE(rows[2].top, M::GroupHeight + M::TrackHeight);
    QCOMPARE(rows[3].track, 2); // no group: no header
    QCOMPARE(rows[3].group, -1);
    QCOMPARE(rows[4].track, -1); // Ben's header
    QCOMPARE(rows[4].group, 3);
    QCOMPARE(scene.rows.contentHeight(), 2 * M::GroupHeight + 4 * M::TrackHeight);

    // Scrolled down by 15 pixels.
    QCOMPARE(g.trackY(0), M::RulerHeight + M::GroupHeight - 15);
    QCOMPARE(g.trackY(3), M::RulerHeight + 2 * M::GroupHeight + 3 * M::TrackHeight - 15);
    QCOMPARE(g.trackAtY(g.trackY(1)), 1);
    QCOMPARE(g.trackAtY(g.trackY(1) + M::TrackHeight - 1), 1);
    QCOMPARE(g.trackAtY(g.trackY(1) + M::TrackHeight), 2);
    QCOMPARE(g.trackAtY(g.trackY(3) - 1), -1); // Ben's header row
    QCOMPARE(g.trackAtY(M::RulerHeight - 1), -1);
    QCOMPARE(g.trackRect(2), QRect(M::HeaderWidth, g.trackY(2), 1000 - M::HeaderWidth, M::TrackHeight));
    QVERIFY(g.trackRect(4).isNull());
}

void TimelineGeometryTest::hitTestTellsEdgesFromBody()
{
    Scene scene;
    scene.tracks = {track("Body", {})};
    scene.clips = {clip(1, 0, sec(1), sec(3))};
    const TimelineGeometry g = scene.geometry();
    const QRect r = g.clipRect(0);
    QCOMPARE(r.left(), g.xForTime(sec(1)));
    QCOMPARE(r.width(), 200);
    const int y = r.center().y();
    auto kindAt = [&](int x) { return g.hitTest(QPoint(x, y)).kind; };

    QCOMPARE(kindAt(r.left()), TimelineHitKind::StartEdge);
    QCOMPARE(kindAt(r.left() + M::EdgeGrip - 1), TimelineHitKind::StartEdge);
    QCOMPARE(kindAt(r.left() + M::EdgeGrip), TimelineHitKind::Body);
    QCOMPARE(kindAt(r.center().x()), TimelineHitKind::Body);
    QCOMPARE(kindAt(r.right() - M::EdgeGrip + 1), TimelineHitKind::EndEdge);
    QCOMPARE(kindAt(r.right() - M::EdgeGrip), TimelineHitKind::Body);
    // Just outside, within the grip: still the edge; beyond it, the empty lane.
    QCOMPARE(kindAt(r.left() - M::EdgeGrip), TimelineHitKind::StartEdge);
    QCOMPARE(kindAt(r.left() - M::EdgeGrip - 1), TimelineHitKind::Lane);
    QCOMPARE(kindAt(r.left() + r.width() + M::EdgeGrip), TimelineHitKind::EndEdge);
    QCOMPARE(kindAt(r.left() + r.width() + M::EdgeGrip + 1), TimelineHitKind::Lane);
    QCOMPARE(g.hitTest(QPoint(r.center().x(), y)).clip, 0);
    QCOMPARE(g.hitTest(QPoint(r.left() - M::EdgeGrip - 1, y)).clip, -1);

    // An open-ended clip has no end edge to trim.
    scene.clips = {clip(1, 0, sec(1), TimelineOpenEnd)};
    const TimelineGeometry open = scene.geometry();
    QCOMPARE(open.hitTest(QPoint(999, y)).kind, TimelineHitKind::Body);
}

void TimelineGeometryTest::hitTestFindsFadeHandlesButNotOnLockedTracks()
{
    Scene scene;
    scene.tracks = {track("Body", {}), track("Face", {}, "face", true)};
    scene.clips = {clip(1, 0, sec(1), sec(3), sec(0.5), sec(0.25)), clip(2, 1, sec(1), sec(3), sec(0.5))};
    const TimelineGeometry g = scene.geometry();
    const QRect fadeIn = g.fadeHandleRect(0, TimelineEdge::Start);
    QCOMPARE(fadeIn.center().x(), g.xForTime(sec(1.5)));
    QCOMPARE(fadeIn.width(), 2 * M::FadeHandleRadius + 1);
    QCOMPARE(g.fadeHandleRect(0, TimelineEdge::End).center().x(), g.xForTime(sec(2.75)));
    QCOMPARE(g.hitTest(fadeIn.center()).kind, TimelineHitKind::FadeIn);
    QCOMPARE(g.hitTest(g.fadeHandleRect(0, TimelineEdge::End).center()).kind, TimelineHitKind::FadeOut);
    // Below the handle, the body.
    QCOMPARE(g.hitTest(fadeIn.center() + QPoint(0, 12)).kind, TimelineHitKind::Body);

    const TimelineHit locked = g.hitTest(g.fadeHandleRect(1, TimelineEdge::Start).center());
    QCOMPARE(locked.kind, TimelineHitKind::Body);
    QCOMPARE(locked.clip, 1);
    QVERIFY(g.trackLocked(1));
    QVERIFY(!g.trackLocked(0));
    QVERIFY(!g.trackLocked(7));
}

void TimelineGeometryTest::hitTestKeepsABodyOnNarrowClipsAndPrefersSelected()
{
    Scene scene;
    scene.tracks = {track("Body", {})};
    // 12 pixels wide: the edge zones shrink to 3 pixels each.
    scene.clips = {clip(1, 0, sec(1), sec(1.12)), clip(2, 0, sec(5), sec(7)), clip(3, 0, sec(6), sec(8))};
    TimelineGeometry g = scene.geometry();
    const QRect narrow = g.clipRect(0);
    QCOMPARE(narrow.width(), 12);
    const int y = narrow.center().y();
    QCOMPARE(g.hitTest(QPoint(narrow.left() + 2, y)).kind, TimelineHitKind::StartEdge);
    QCOMPARE(g.hitTest(QPoint(narrow.left() + 3, y)).kind, TimelineHitKind::Body);
    QCOMPARE(g.hitTest(QPoint(narrow.right() - 3, y)).kind, TimelineHitKind::Body);
    QCOMPARE(g.hitTest(QPoint(narrow.right() - 2, y)).kind, TimelineHitKind::EndEdge);

    // Overlapping clips: the later one wins, unless the earlier one is selected (drawn on top).
    const QPoint overlap(g.xForTime(sec(6.5)), y);
    QCOMPARE(g.hitTest(overlap).clip, 2);
    scene.selected[1] = 1;
    QCOMPARE(g.hitTest(overlap).clip, 1);
}

void TimelineGeometryTest::hitTestHeaderRulerAndMarkers()
{
    Scene scene;
    scene.tracks = {track("Body", {}), track("Face", {}, "face")};
    scene.markers = {TimelineMarker{"Start", sec(1)}, TimelineMarker{"Wave", sec(4)}};
    const TimelineGeometry g = scene.geometry();
    QCOMPARE(g.hitTest(QPoint(5, 5)).kind, TimelineHitKind::Corner);
    QCOMPARE(g.hitTest(QPoint(g.xForTime(sec(2.5)), 5)).kind, TimelineHitKind::Ruler);
    const TimelineHit marker = g.hitTest(g.markerRect(1).center());
    QCOMPARE(marker.kind, TimelineHitKind::Marker);
    QCOMPARE(marker.marker, 1);
    QVERIFY(g.markerRect(2).isNull());

    for (TimelineTrackFlag flag : TimelineTrackFlags) {
        const TimelineHit hit = g.hitTest(g.trackFlagRect(1, flag).center());
        QCOMPARE(hit.kind, TimelineHitKind::Flag);
        QCOMPARE(hit.flag, flag);
        QCOMPARE(hit.track, 1);
    }
    QCOMPARE(g.hitTest(QPoint(4, g.trackY(1) + 4)).kind, TimelineHitKind::Header);
    QVERIFY(g.trackFlagRect(0, TimelineTrackFlag::Mute).right() < g.trackFlagRect(0, TimelineTrackFlag::Solo).left());
    QVERIFY(g.trackFlagRect(0, TimelineTrackFlag::Lock).right() < M::HeaderWidth);
}

void TimelineGeometryTest::snapTargetsCollectEdgesMarkersAndPlayhead()
{
    const std::vector<TimelineClip> clips = {clip(1, 0, sec(1), sec(2)), clip(2, 0, sec(2), TimelineOpenEnd),
                                             clip(3, 1, sec(5), sec(6))};
    const std::vector<TimelineMarker> markers = {{"A", sec(3)}, {"B", sec(4)}};
    TimelineSnapTargets targets;
    targets.collect(clips, {}, markers, -1, sec(10), sec(7));
    QCOMPARE(targets.times(), (std::vector<qint64>{0, sec(1), sec(2), sec(3), sec(4), sec(5), sec(6), sec(7), sec(10)}));

    // The dragged clip, the dragged marker and the playhead left out; no duration.
    const std::vector<char> exclude = {0, 0, 1};
    targets.collect(clips, exclude, markers, 0, 0, std::nullopt);
    QCOMPARE(targets.times(), (std::vector<qint64>{0, sec(1), sec(2), sec(4)}));
}

void TimelineGeometryTest::snapTimeAttractsWithinThresholdOnly()
{
    const std::vector<TimelineClip> clips = {clip(1, 0, sec(2), sec(3))};
    const std::vector<TimelineMarker> markers = {{"A", sec(5) + 1234}};
    TimelineSnapTargets targets;
    targets.collect(clips, {}, markers, -1, 0, sec(4) + 77);
    const TimelineTimebase time;
    const double ticksPerPixel = double(kTps) / 100.0;
    const qint64 threshold = timelineSnapThreshold(ticksPerPixel);
    QCOMPARE(threshold, std::llround(M::SnapDistance * ticksPerPixel));

    // A neighbouring clip's edge, from either side, up to the threshold.
    TimelineSnap snap = targets.snapTime(sec(3) - threshold, threshold, time);
    QCOMPARE(snap.value, sec(3));
    QCOMPARE(snap.target, sec(3));
    snap = targets.snapTime(sec(2) + threshold / 2, threshold, time);
    QCOMPARE(snap.value, sec(2));
    // The playhead and a marker, even off the frame grid.
    QCOMPARE(targets.snapTime(sec(4) + 77 + threshold / 3, threshold, time).value, sec(4) + 77);
    QCOMPARE(targets.snapTime(sec(5) - threshold / 3, threshold, time).target, sec(5) + 1234);
    // One tick beyond the threshold: only the frame grid.
    snap = targets.snapTime(sec(3) - threshold - 1, threshold, time);
    QCOMPARE(snap.target, qint64(-1));
    QCOMPARE(snap.value, time.roundToFrame(sec(3) - threshold - 1));
    QVERIFY(snap.value != sec(3));

    // Between two targets, the nearer one; on a tie, the later.
    qint64 nearest = 0;
    QVERIFY(targets.nearest(sec(2) + 10, nearest));
    QCOMPARE(nearest, sec(2));
    QVERIFY(targets.nearest(sec(2.5), nearest));
    QCOMPARE(nearest, sec(3));
    TimelineSnapTargets none;
    QVERIFY(!none.nearest(sec(1), nearest));
    QCOMPARE(none.snapTime(sec(1) + 5, threshold, time).value, sec(1));
}

void TimelineGeometryTest::snapDeltaPutsTheNearestEdgeOnATarget()
{
    // A neighbour at 3 s – 4 s; the dragged clip (1 s – 2 s) is not among the targets.
    const std::vector<TimelineClip> clips = {clip(1, 0, sec(1), sec(2)), clip(2, 0, sec(3), sec(4))};
    const std::vector<char> moving = {1, 0};
    TimelineSnapTargets targets;
    targets.collect(clips, moving, {}, -1, 0, std::nullopt);
    const std::vector<qint64> edges = {sec(1), sec(2)};
    const TimelineTimebase time;
    const qint64 threshold = timelineSnapThreshold(double(kTps) / 100.0);

    // Dragged right until its end nears the neighbour's start: the end lands on it.
    TimelineSnap snap = targets.snapDelta(sec(1) - threshold + 5, edges, sec(1), threshold, time);
    QCOMPARE(snap.value, sec(1));
    QCOMPARE(snap.target, sec(3));
    // Its start near the neighbour's end, from beyond: the start lands there.
    snap = targets.snapDelta(sec(3) + threshold, edges, sec(1), threshold, time);
    QCOMPARE(snap.value, sec(3));
    QCOMPARE(snap.target, sec(4));
    // Too far from everything: the start goes to a whole frame.
    const qint64 delta = sec(0.5) + kFrame / 3;
    snap = targets.snapDelta(delta, edges, sec(1), threshold, time);
    QCOMPARE(snap.target, qint64(-1));
    QCOMPARE(snap.value, sec(0.5));
    QCOMPARE(time.roundToFrame(sec(1) + snap.value), sec(1) + snap.value);
}

void TimelineGeometryTest::trackOffsetStaysInGroupAndKind()
{
    Scene scene;
    scene.tracks = {track("Body", "Ana"), track("Body 2", "Ana"), track("Face", "Ana", "face"),
                    track("Body 3", "Ana", "body", true), track("Body 4", "Ana"), track("Body", "Ben")};
    const TimelineGeometry g = scene.geometry();
    const std::vector<TimelineClip> moving = {clip(1, 0, 0, sec(1))};
    QVERIFY(trackOffsetFits(scene.tracks, moving, 0));
    QVERIFY(trackOffsetFits(scene.tracks, moving, 1));
    QVERIFY(!trackOffsetFits(scene.tracks, moving, 2)); // another kind
    QVERIFY(!trackOffsetFits(scene.tracks, moving, 3)); // locked
    QVERIFY(trackOffsetFits(scene.tracks, moving, 4));
    QVERIFY(!trackOffsetFits(scene.tracks, moving, 5)); // another group
    QVERIFY(!trackOffsetFits(scene.tracks, moving, -1));

    auto centre = [&](int t) { return g.trackY(t) + M::TrackHeight / 2; };
    QCOMPARE(clipDragTrackOffset(g, moving, 0, centre(0)), 0);
    QCOMPARE(clipDragTrackOffset(g, moving, 0, centre(1) - 5), 1);
    // Over the face track or the locked one: the nearest track that fits.
    QCOMPARE(clipDragTrackOffset(g, moving, 0, centre(2)), 1);
    QCOMPARE(clipDragTrackOffset(g, moving, 0, centre(3)), 4);
    // Over the other character: as far as the clip may go.
    QCOMPARE(clipDragTrackOffset(g, moving, 0, centre(5)), 4);
    QCOMPARE(clipDragTrackOffset(g, moving, 9, centre(1)), 0); // no such track
}

QTEST_MAIN(TimelineGeometryTest)
#include "timeline_geometry_test.moc"
