// TransportBar: time formatting, and that user gestures (and only they) emit intents.

#include <QComboBox>
#include <QLabel>
#include <QSignalSpy>
#include <QSlider>
#include <QStyle>
#include <QTest>
#include <QToolButton>

#include "widgets/transport_bar.h"

using thespis::widgets::TransportBar;

class TransportBarTest : public QObject {
    Q_OBJECT
private slots:
    void formatsTime_data();
    void formatsTime();
    void frameNumbers();
    void draggingTheSliderRequestsSeeks();
    void settingTheTimeEmitsNothing();
    void playButtonAsksForPlayOrPause();
    void loopButtonRequestsLooping();
    void clockDoesNotFightADrag();
    void stepAndEndButtons();
    void frameRateChoice();

private:
    static QSlider* slider(TransportBar& bar) { return bar.findChild<QSlider*>(QStringLiteral("timeSlider")); }
    static QPoint handleCentre(QSlider* slider);
};

void TransportBarTest::formatsTime_data()
{
    QTest::addColumn<double>("seconds");
    QTest::addColumn<QString>("text");
    QTest::newRow("zero") << 0.0 << QStringLiteral("00:00.000");
    QTest::newRow("millis") << 1.234 << QStringLiteral("00:01.234");
    QTest::newRow("rounds up") << 61.2346 << QStringLiteral("01:01.235");
    QTest::newRow("carries into minutes") << 59.9996 << QStringLiteral("01:00.000");
    QTest::newRow("hours fold into minutes") << 3725.5 << QStringLiteral("62:05.500");
    QTest::newRow("negative") << -1.5 << QStringLiteral("-00:01.500");
    QTest::newRow("not finite") << std::numeric_limits<double>::quiet_NaN() << QStringLiteral("--:--.---");
}

void TransportBarTest::formatsTime()
{
    QFETCH(double, seconds);
    QFETCH(QString, text);
    QCOMPARE(TransportBar::formatTime(seconds), text);
}

void TransportBarTest::frameNumbers()
{
    QCOMPARE(TransportBar::frameAt(0.0, 30), 0LL);
    QCOMPARE(TransportBar::frameAt(0.1, 30), 3LL); // 0.1 · 30 = 2.9999999999999996
    QCOMPARE(TransportBar::frameAt(7.0 / 30.0, 30), 7LL);
    QCOMPARE(TransportBar::frameAt(0.0999, 30), 2LL);
    QCOMPARE(TransportBar::frameAt(1.0, 24), 24LL);
}

QPoint TransportBarTest::handleCentre(QSlider* s)
{
    // Where the style draws the handle for the current value.
    const double fraction = double(s->value() - s->minimum()) / double(s->maximum() - s->minimum());
    const int margin = s->style()->pixelMetric(QStyle::PM_SliderLength, nullptr, s) / 2;
    return QPoint(margin + int(std::lround(fraction * (s->width() - 2 * margin))), s->height() / 2);
}

void TransportBarTest::draggingTheSliderRequestsSeeks()
{
    TransportBar bar;
    bar.resize(800, 40);
    bar.setDuration(10.0);
    bar.show();
    QVERIFY(QTest::qWaitForWindowExposed(&bar));
    QSlider* s = slider(bar);
    QVERIFY(s);
    QCOMPARE(s->maximum(), 10000);

    QSignalSpy seeks(&bar, &TransportBar::seekRequested);
    const QPoint start = handleCentre(s);
    const QPoint end(start.x() + s->width() / 2, start.y());
    QTest::mousePress(s, Qt::LeftButton, {}, start);
    QVERIFY(s->isSliderDown());
    for (int step = 1; step <= 5; ++step)
        QTest::mouseMove(s, start + (end - start) * step / 5);
    QTest::mouseRelease(s, Qt::LeftButton, {}, end);

    QVERIFY2(seeks.count() >= 2, "a drag should seek continuously, not only on release");
    const double last = seeks.last().at(0).toDouble();
    // Half the slider's width from the start is about half the duration.
    QVERIFY2(last > 4.0 && last < 6.0, qPrintable(QString::number(last)));
    // The seeks follow the drag: they only grow.
    for (int i = 1; i < seeks.count(); ++i)
        QVERIFY(seeks.at(i).at(0).toDouble() >= seeks.at(i - 1).at(0).toDouble());

    // Keyboard steps seek too (a page is one second).
    seeks.clear();
    s->setFocus();
    QTest::keyClick(s, Qt::Key_PageUp);
    QCOMPARE(seeks.count(), 1);
    QVERIFY(std::abs(seeks.at(0).at(0).toDouble() - (last + 1.0)) < 1e-9);
}

void TransportBarTest::settingTheTimeEmitsNothing()
{
    TransportBar bar;
    bar.setDuration(10.0);
    QSignalSpy seeks(&bar, &TransportBar::seekRequested);
    QSignalSpy plays(&bar, &TransportBar::playRequested);
    bar.setTime(5.25);
    bar.setPlaying(true);
    bar.setLooping(true);
    QCOMPARE(seeks.count(), 0);
    QCOMPARE(plays.count(), 0);
    QCOMPARE(slider(bar)->value(), 5250);
    QCOMPARE(bar.findChild<QLabel*>(QStringLiteral("timeLabel"))->text(), QStringLiteral("00:05.250 / 00:10.000"));
    QCOMPARE(bar.findChild<QLabel*>(QStringLiteral("frameLabel"))->text(), QStringLiteral("frame 157"));
    // Times beyond the end show as they are, with the slider at its end.
    bar.setTime(12.0);
    QCOMPARE(slider(bar)->value(), 10000);
    QCOMPARE(seeks.count(), 0);
}

void TransportBarTest::playButtonAsksForPlayOrPause()
{
    TransportBar bar;
    bar.setDuration(3.0);
    auto* button = bar.findChild<QToolButton*>(QStringLiteral("playPauseButton"));
    QVERIFY(button);
    QSignalSpy plays(&bar, &TransportBar::playRequested);
    QSignalSpy pauses(&bar, &TransportBar::pauseRequested);
    QTest::mouseClick(button, Qt::LeftButton);
    QCOMPARE(plays.count(), 1);
    QCOMPARE(pauses.count(), 0);
    // The bar does not decide it is playing: it waits to be told.
    QVERIFY(!bar.isPlaying());
    bar.setPlaying(true);
    QTest::mouseClick(button, Qt::LeftButton);
    QCOMPARE(plays.count(), 1);
    QCOMPARE(pauses.count(), 1);

    QSignalSpy seeks(&bar, &TransportBar::seekRequested);
    QTest::mouseClick(bar.findChild<QToolButton*>(QStringLiteral("toStartButton")), Qt::LeftButton);
    QCOMPARE(seeks.count(), 1);
    QCOMPARE(seeks.at(0).at(0).toDouble(), 0.0);
}

void TransportBarTest::loopButtonRequestsLooping()
{
    TransportBar bar;
    auto* button = bar.findChild<QToolButton*>(QStringLiteral("loopButton"));
    QSignalSpy loops(&bar, &TransportBar::loopRequested);
    QTest::mouseClick(button, Qt::LeftButton);
    QCOMPARE(loops.count(), 1);
    QCOMPARE(loops.at(0).at(0).toBool(), true);
    bar.setLooping(false); // the clock said no: shown, not re-requested
    QCOMPARE(loops.count(), 1);
    QVERIFY(!bar.isLooping());
}

void TransportBarTest::clockDoesNotFightADrag()
{
    TransportBar bar;
    bar.resize(800, 40);
    bar.setDuration(10.0);
    bar.show();
    QVERIFY(QTest::qWaitForWindowExposed(&bar));
    QSlider* s = slider(bar);
    QTest::mousePress(s, Qt::LeftButton, {}, handleCentre(s));
    QVERIFY(s->isSliderDown());
    const int held = s->value();
    bar.setTime(7.0); // a playing clock ticks while the user holds the handle
    QCOMPARE(s->value(), held);
    QCOMPARE(bar.time(), 7.0);
    QTest::mouseRelease(s, Qt::LeftButton, {}, handleCentre(s));
    bar.setTime(7.0);
    QCOMPARE(s->value(), 7000);
}

void TransportBarTest::stepAndEndButtons()
{
    TransportBar bar;
    bar.setDuration(12.5);
    QSignalSpy steps(&bar, &TransportBar::stepRequested);
    QSignalSpy seeks(&bar, &TransportBar::seekRequested);
    QTest::mouseClick(bar.findChild<QToolButton*>(QStringLiteral("stepForwardButton")), Qt::LeftButton);
    QTest::mouseClick(bar.findChild<QToolButton*>(QStringLiteral("stepBackButton")), Qt::LeftButton);
    QCOMPARE(steps.size(), 2);
    QCOMPARE(steps.at(0).at(0).toInt(), 1);
    QCOMPARE(steps.at(1).at(0).toInt(), -1);
    QTest::mouseClick(bar.findChild<QToolButton*>(QStringLiteral("toEndButton")), Qt::LeftButton);
    QCOMPARE(seeks.size(), 1);
    QCOMPARE(seeks.at(0).at(0).toDouble(), 12.5);
}

void TransportBarTest::frameRateChoice()
{
    TransportBar bar;
    auto* choice = bar.findChild<QComboBox*>(QStringLiteral("frameRateChoice"));
    QVERIFY(choice);
    QCOMPARE(choice->currentData().toDouble(), 30.0);
    QSignalSpy requests(&bar, &TransportBar::frameRateRequested);
    bar.setFrameRate(24); // the clock's rate: shown, not requested back
    QCOMPARE(choice->currentData().toDouble(), 24.0);
    bar.setFrameRate(29.97); // not among the choices: added
    QCOMPARE(choice->currentData().toDouble(), 29.97);
    QCOMPARE(requests.size(), 0);
    bar.setTime(1.0);
    QVERIFY(bar.findChild<QLabel*>(QStringLiteral("frameLabel"))->text().contains(QStringLiteral("29")));
    const int sixty = choice->findData(60.0);
    QVERIFY(sixty >= 0);
    emit choice->activated(sixty); // what a user's pick emits
    QCOMPARE(requests.size(), 1);
    QCOMPARE(requests.at(0).at(0).toDouble(), 60.0);
}

QTEST_MAIN(TransportBarTest)
#include "transport_bar_test.moc"
