// PlaybackClock: real-time playback, pause, seek, loop and the end of the timeline, in ticks.

#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTest>


#include "editor/playback_clock.h"

using thespis::core::Tick;
using thespis::core::TicksPerSecond;
using thespis::editor::PlaybackClock;

namespace {
Tick ticks(double seconds) { return thespis::core::secondsToTicks(seconds); }
double seconds(Tick ticks) { return thespis::core::ticksToSeconds(ticks); }
} // namespace

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
    void stepsWholeFrames();
};

void PlaybackClockTest::playsInRealTime()
{
    PlaybackClock clock;
    clock.setDuration(ticks(10.0));
    QSignalSpy playing(&clock, &PlaybackClock::playingChanged);
    QSignalSpy times(&clock, &PlaybackClock::timeChanged);
    QElapsedTimer beforePlay, afterPlay;
    beforePlay.start();
    clock.play();
    afterPlay.start();
    QVERIFY(clock.isPlaying());
    QCOMPARE(playing.count(), 1);
    QTRY_VERIFY_WITH_TIMEOUT(times.count() >= 5, 5000); // ticks at ~60 Hz, however busy the machine
    const double atLeast = double(afterPlay.nsecsElapsed()) * 1e-9;
    clock.pause();
    const double atMost = double(beforePlay.nsecsElapsed()) * 1e-9;
    // The time follows the wall clock, whatever the number of ticks that were delivered: it was
    // started between the two timers and read at pause().
    QVERIFY2(seconds(clock.time()) >= atLeast && seconds(clock.time()) <= atMost,
             qPrintable(QStringLiteral("clock %1 s, wall %2 … %3 s").arg(seconds(clock.time())).arg(atLeast).arg(atMost)));
    for (int i = 1; i < times.count(); ++i)
        QVERIFY(times.at(i).at(0).value<Tick>() > times.at(i - 1).at(0).value<Tick>());
}

void PlaybackClockTest::pauseHoldsTheTime()
{
    PlaybackClock clock;
    clock.setDuration(ticks(10.0));
    clock.play();
    QTest::qWait(100);
    clock.pause();
    QVERIFY(!clock.isPlaying());
    const Tick paused = clock.time();
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
    clock.setDuration(ticks(10.0));
    QSignalSpy times(&clock, &PlaybackClock::timeChanged);
    clock.seek(ticks(3.5));
    QCOMPARE(clock.time(), ticks(3.5));
    QCOMPARE(times.count(), 1);
    QCOMPARE(times.at(0).at(0).value<Tick>(), ticks(3.5));
    clock.seek(ticks(-2.0));
    QCOMPARE(clock.time(), ticks(0.0));
    clock.seek(ticks(25.0));
    QCOMPARE(clock.time(), ticks(10.0));
        // Shortening the timeline pulls the playhead in.
    clock.setDuration(ticks(4.0));
    QCOMPARE(clock.time(), ticks(4.0));
}

void PlaybackClockTest::seekWhilePlayingContinuesFromThere()
{
    PlaybackClock clock;
    clock.setDuration(ticks(10.0));
    clock.play();
    QTest::qWait(50);
    QElapsedTimer beforeSeek, afterSeek;
    beforeSeek.start();
    clock.seek(ticks(6.0));
    afterSeek.start();
    QVERIFY(clock.isPlaying());
    QTest::qWait(150);
    const double atLeast = 6.0 + double(afterSeek.nsecsElapsed()) * 1e-9;
    clock.pause();
    const double atMost = 6.0 + double(beforeSeek.nsecsElapsed()) * 1e-9;
    QVERIFY2(seconds(clock.time()) >= atLeast && seconds(clock.time()) <= atMost,
             qPrintable(QStringLiteral("clock %1 s, expected %2 … %3 s").arg(seconds(clock.time())).arg(atLeast).arg(atMost)));
}

void PlaybackClockTest::stopsAtTheEnd()
{
    PlaybackClock clock;
    clock.setDuration(ticks(0.2));
    QSignalSpy playing(&clock, &PlaybackClock::playingChanged);
    clock.play();
    QTRY_VERIFY_WITH_TIMEOUT(!clock.isPlaying(), 2000);
    QCOMPARE(clock.time(), ticks(0.2));
    QCOMPARE(playing.count(), 2);
    QCOMPARE(playing.at(1).at(0).toBool(), false);
}

void PlaybackClockTest::playAtTheEndStartsOver()
{
    PlaybackClock clock;
    clock.setDuration(ticks(5.0));
    clock.seek(ticks(5.0));
    clock.play();
    QVERIFY(clock.isPlaying());
    QVERIFY(clock.time() < ticks(0.1));
    clock.pause();
}

void PlaybackClockTest::loopsOverTheTimeline()
{
    PlaybackClock clock;
    clock.setDuration(ticks(0.15));
    QSignalSpy looping(&clock, &PlaybackClock::loopingChanged);
    clock.setLooping(true);
    clock.setLooping(true);
    QCOMPARE(looping.count(), 1);
    QSignalSpy times(&clock, &PlaybackClock::timeChanged);
    auto wraps = [&times] {
        int count = 0;
        for (int i = 1; i < times.count(); ++i)
            if (times.at(i).at(0).value<Tick>() < times.at(i - 1).at(0).value<Tick>())
                ++count;
        return count;
    };
    clock.play();
    QTRY_VERIFY_WITH_TIMEOUT(wraps() >= 2, 5000); // about 0.3 s; more on a busy machine
    QVERIFY(clock.isPlaying());
    clock.pause();
    for (int i = 0; i < times.count(); ++i) {
        const Tick t = times.at(i).at(0).value<Tick>();
        QVERIFY(t >= 0 && t < ticks(0.15));
    }
}

void PlaybackClockTest::doesNotPlayAnEmptyTimeline()
{
    PlaybackClock clock;
    clock.play();
    QVERIFY(!clock.isPlaying());
    clock.setDuration(-TicksPerSecond);
    QCOMPARE(clock.duration(), Tick(0));
    clock.play();
    QVERIFY(!clock.isPlaying());
}

void PlaybackClockTest::stepsWholeFrames()
{
    PlaybackClock clock;
    clock.setDuration(ticks(2.0));
    clock.setFrameRate(25);
    clock.step(1);
    QCOMPARE(clock.time(), ticks(0.04));
    clock.step(3);
    QCOMPARE(clock.time(), ticks(4 / 25.0));
    clock.seek(ticks(0.5 + 0.01)); // inside frame 12: back lands on its start, forward on 13
    clock.step(-1);
    QCOMPARE(clock.time(), ticks(12 / 25.0));
    clock.step(-1);
    QCOMPARE(clock.time(), ticks(11 / 25.0));
    clock.step(-100);
    QCOMPARE(clock.time(), ticks(0.0));
    clock.seek(ticks(1.99));
    clock.step(5);
    QCOMPARE(clock.time(), ticks(2.0));
    clock.seek(ticks(0.0));
    clock.play();
    QVERIFY(clock.isPlaying());
    clock.step(1); // stepping pauses
    QVERIFY(!clock.isPlaying());
}

QTEST_MAIN(PlaybackClockTest)
#include "playback_clock_test.moc"
