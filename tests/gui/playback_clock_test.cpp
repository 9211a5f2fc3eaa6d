// PlaybackClock: real-time playback, pause, seek, loop and the end of the timeline.

#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTest>

#include <cmath>
#include <limits>

#include "editor/playback_clock.h"

using thespis::editor::PlaybackClock;

class PlaybackClockTest : public QObject {
    Q_OBJECT
private slots:
    void playsInRealTime();
    void pauseHoldsTheTime();
    void seekClampsIntoTheTimeline();
    void seekWhilePlayingContinuesFromThere();
    void stopsAtTheEnd();
    void playAtTheEndStartsOver();
    void loopsOverTheTimeline();
    void doesNotPlayAnEmptyTimeline();
};

void PlaybackClockTest::playsInRealTime()
{
    PlaybackClock clock;
    clock.setDuration(10.0);
    QSignalSpy playing(&clock, &PlaybackClock::playingChanged);
    QSignalSpy times(&clock, &PlaybackClock::timeChanged);
    QElapsedTimer wall;
    wall.start();
    clock.play();
    QVERIFY(clock.isPlaying());
    QCOMPARE(playing.count(), 1);
    QTest::qWait(300);
    const double elapsed = double(wall.nsecsElapsed()) * 1e-9;
    clock.pause();
    // The time follows the wall clock (within a tick and the test's own scheduling), whatever
    // the number of ticks that were delivered.
    QVERIFY2(std::abs(clock.time() - elapsed) < 0.05,
             qPrintable(QStringLiteral("clock %1 s, wall %2 s").arg(clock.time()).arg(elapsed)));
    QVERIFY2(times.count() >= 5, "ticks at ~60 Hz should have come in 300 ms");
    for (int i = 1; i < times.count(); ++i)
        QVERIFY(times.at(i).at(0).toDouble() > times.at(i - 1).at(0).toDouble());
}

void PlaybackClockTest::pauseHoldsTheTime()
{
    PlaybackClock clock;
    clock.setDuration(10.0);
    clock.play();
    QTest::qWait(100);
    clock.pause();
    QVERIFY(!clock.isPlaying());
    const double paused = clock.time();
    QVERIFY(paused > 0);
    QTest::qWait(100);
    QCOMPARE(clock.time(), paused);
    clock.togglePlayPause();
    QVERIFY(clock.isPlaying());
    clock.togglePlayPause();
    QVERIFY(clock.time() >= paused);
}

void PlaybackClockTest::seekClampsIntoTheTimeline()
{
    PlaybackClock clock;
    clock.setDuration(10.0);
    QSignalSpy times(&clock, &PlaybackClock::timeChanged);
    clock.seek(3.5);
    QCOMPARE(clock.time(), 3.5);
    QCOMPARE(times.count(), 1);
    QCOMPARE(times.at(0).at(0).toDouble(), 3.5);
    clock.seek(-2.0);
    QCOMPARE(clock.time(), 0.0);
    clock.seek(25.0);
    QCOMPARE(clock.time(), 10.0);
    clock.seek(std::numeric_limits<double>::quiet_NaN());
    QCOMPARE(clock.time(), 10.0);
    // Shortening the timeline pulls the playhead in.
    clock.setDuration(4.0);
    QCOMPARE(clock.time(), 4.0);
}

void PlaybackClockTest::seekWhilePlayingContinuesFromThere()
{
    PlaybackClock clock;
    clock.setDuration(10.0);
    clock.play();
    QTest::qWait(50);
    clock.seek(6.0);
    QVERIFY(clock.isPlaying());
    QTest::qWait(150);
    clock.pause();
    QVERIFY2(clock.time() > 6.05 && clock.time() < 6.6, qPrintable(QString::number(clock.time())));
}

void PlaybackClockTest::stopsAtTheEnd()
{
    PlaybackClock clock;
    clock.setDuration(0.2);
    QSignalSpy playing(&clock, &PlaybackClock::playingChanged);
    clock.play();
    QTRY_VERIFY_WITH_TIMEOUT(!clock.isPlaying(), 2000);
    QCOMPARE(clock.time(), 0.2);
    QCOMPARE(playing.count(), 2);
    QCOMPARE(playing.at(1).at(0).toBool(), false);
}

void PlaybackClockTest::playAtTheEndStartsOver()
{
    PlaybackClock clock;
    clock.setDuration(5.0);
    clock.seek(5.0);
    clock.play();
    QVERIFY(clock.isPlaying());
    QVERIFY(clock.time() < 0.1);
    clock.pause();
}

void PlaybackClockTest::loopsOverTheTimeline()
{
    PlaybackClock clock;
    clock.setDuration(0.15);
    QSignalSpy looping(&clock, &PlaybackClock::loopingChanged);
    clock.setLooping(true);
    clock.setLooping(true);
    QCOMPARE(looping.count(), 1);
    QSignalSpy times(&clock, &PlaybackClock::timeChanged);
    clock.play();
    QTest::qWait(500);
    QVERIFY(clock.isPlaying());
    clock.pause();
    int wraps = 0;
    for (int i = 0; i < times.count(); ++i) {
        const double t = times.at(i).at(0).toDouble();
        QVERIFY(t >= 0.0 && t < 0.15);
        if (i > 0 && t < times.at(i - 1).at(0).toDouble())
            ++wraps;
    }
    QVERIFY2(wraps >= 2, qPrintable(QStringLiteral("%1 wraps in 0.5 s of a 0.15 s loop").arg(wraps)));
}

void PlaybackClockTest::doesNotPlayAnEmptyTimeline()
{
    PlaybackClock clock;
    clock.play();
    QVERIFY(!clock.isPlaying());
    clock.setDuration(std::numeric_limits<double>::infinity());
    QCOMPARE(clock.duration(), 0.0);
    clock.play();
    QVERIFY(!clock.isPlaying());
}

QTEST_MAIN(PlaybackClockTest)
#include "playback_clock_test.moc"
