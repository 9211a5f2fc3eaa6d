#include "widgets/transport_bar.h"

#include <QComboBox>
#include <QFontDatabase>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSlider>
#include <QStyle>
#include <QToolButton>

#include <algorithm>
#include <cmath>

namespace thespis::widgets {

namespace {
// The slider counts milliseconds: fine enough to scrub to any frame up to 1000 fps.
constexpr double kSliderUnitsPerSecond = 1000.0;
} // namespace

TransportBar::TransportBar(QWidget* parent) : QWidget(parent)
{
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(8, 4, 8, 4);
    layout->setSpacing(6);

    m_toStart = new QToolButton(this);
    m_toStart->setObjectName(QStringLiteral("toStartButton"));
    m_toStart->setIcon(style()->standardIcon(QStyle::SP_MediaSkipBackward));
    m_toStart->setToolTip(tr("Go to the start (Home)"));
    m_toStart->setAutoRaise(true);
    connect(m_toStart, &QToolButton::clicked, this, [this] { emit seekRequested(0.0); });

    auto stepButton = [this](const QString& name, QStyle::StandardPixmap icon, const QString& tip, int frames) {
        auto* button = new QToolButton(this);
        button->setObjectName(name);
        button->setIcon(style()->standardIcon(icon));
        button->setToolTip(tip);
        button->setAutoRaise(true);
        button->setAutoRepeat(true); // held down, it keeps stepping
        connect(button, &QToolButton::clicked, this, [this, frames] { emit stepRequested(frames); });
        return button;
    };
    m_stepBack = stepButton(QStringLiteral("stepBackButton"), QStyle::SP_MediaSeekBackward,
                            tr("Previous frame (Left arrow)"), -1);
    m_stepForward = stepButton(QStringLiteral("stepForwardButton"), QStyle::SP_MediaSeekForward,
                               tr("Next frame (Right arrow)"), +1);
    m_toEnd = new QToolButton(this);
    m_toEnd->setObjectName(QStringLiteral("toEndButton"));
    m_toEnd->setIcon(style()->standardIcon(QStyle::SP_MediaSkipForward));
    m_toEnd->setToolTip(tr("Go to the end (End)"));
    m_toEnd->setAutoRaise(true);
    connect(m_toEnd, &QToolButton::clicked, this, [this] { emit seekRequested(m_duration); });

    m_playPause = new QToolButton(this);
    m_playPause->setObjectName(QStringLiteral("playPauseButton"));
    m_playPause->setAutoRaise(true);
    m_playPause->setIconSize(QSize(24, 24));
    connect(m_playPause, &QToolButton::clicked, this, [this] {
        if (m_playing)
            emit pauseRequested();
        else
            emit playRequested();
    });

    m_loop = new QToolButton(this);
    m_loop->setObjectName(QStringLiteral("loopButton"));
    m_loop->setCheckable(true);
    m_loop->setText(tr("Loop"));
    m_loop->setIcon(style()->standardIcon(QStyle::SP_BrowserReload));
    m_loop->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    m_loop->setToolTip(tr("Start again at the end of the scenario (L)"));
    m_loop->setAutoRaise(true);
    connect(m_loop, &QToolButton::toggled, this, &TransportBar::loopRequested);

    m_slider = new QSlider(Qt::Horizontal, this);
    m_slider->setObjectName(QStringLiteral("timeSlider"));
    m_slider->setToolTip(tr("Drag to scrub through the scenario"));
    m_slider->setRange(0, 0);
    m_slider->setSingleStep(33);
    m_slider->setPageStep(1000);
    m_slider->setMinimumWidth(160); // scrubbing needs room, even in a narrow window
    connect(m_slider, &QSlider::valueChanged, this, &TransportBar::onSliderValueChanged);

    const QFont mono = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    m_timeLabel = new QLabel(this);
    m_timeLabel->setObjectName(QStringLiteral("timeLabel"));
    m_timeLabel->setFont(mono);
    m_timeLabel->setToolTip(tr("Current time / length of the scenario (minutes:seconds.milliseconds)"));
    m_frameLabel = new QLabel(this);
    m_frameLabel->setObjectName(QStringLiteral("frameLabel"));
    m_frameLabel->setFont(mono);
    // Room for five-digit frame numbers, so that the slider does not shift as they grow.
    m_frameLabel->setMinimumWidth(QFontMetrics(mono).horizontalAdvance(tr("frame %1").arg(99999)));

    m_frameRateChoice = new QComboBox(this);
    m_frameRateChoice->setObjectName(QStringLiteral("frameRateChoice"));
    m_frameRateChoice->setToolTip(tr("Frames per second for frame numbers, frame steps and snapping"));
    for (const double rate : {24.0, 25.0, 30.0, 50.0, 60.0})
        m_frameRateChoice->addItem(tr("%1 fps").arg(rate), rate);
    connect(m_frameRateChoice, &QComboBox::activated, this,
            [this](int index) { emit frameRateRequested(m_frameRateChoice->itemData(index).toDouble()); });

    layout->addWidget(m_toStart);
    layout->addWidget(m_stepBack);
    layout->addWidget(m_playPause);
    layout->addWidget(m_stepForward);
    layout->addWidget(m_toEnd);
    layout->addWidget(m_loop);
    layout->addWidget(m_slider, 1);
    layout->addSpacing(6);
    layout->addWidget(m_timeLabel);
    layout->addSpacing(10);
    layout->addWidget(m_frameLabel);
    layout->addWidget(m_frameRateChoice);

    updateFrameRateChoice();
    updatePlayButton();
    updateLabels();
}

void TransportBar::setDuration(double seconds)
{
    m_duration = std::isfinite(seconds) ? std::max(0.0, seconds) : 0.0;
    const QSignalBlocker block(m_slider);
    m_slider->setRange(0, int(std::lround(m_duration * kSliderUnitsPerSecond)));
    m_slider->setValue(int(std::lround(std::clamp(m_time, 0.0, m_duration) * kSliderUnitsPerSecond)));
    updateLabels();
}

void TransportBar::setTime(double seconds)
{
    m_time = seconds;
    if (!m_slider->isSliderDown()) {
        m_updatingSlider = true;
        m_slider->setValue(int(std::lround(std::clamp(seconds, 0.0, m_duration) * kSliderUnitsPerSecond)));
        m_updatingSlider = false;
    }
    updateLabels();
}

void TransportBar::setPlaying(bool playing)
{
    if (playing == m_playing)
        return;
    m_playing = playing;
    updatePlayButton();
}

void TransportBar::setLooping(bool looping)
{
    const QSignalBlocker block(m_loop);
    m_loop->setChecked(looping);
}

bool TransportBar::isLooping() const
{
    return m_loop->isChecked();
}

void TransportBar::setFrameRate(double framesPerSecond)
{
    if (framesPerSecond > 0 && std::isfinite(framesPerSecond))
        m_frameRate = framesPerSecond;
    updateFrameRateChoice();
    updateLabels();
}

void TransportBar::updateFrameRateChoice()
{
    int index = m_frameRateChoice->findData(m_frameRate);
    if (index < 0) {
        m_frameRateChoice->addItem(tr("%1 fps").arg(m_frameRate), m_frameRate);
        index = m_frameRateChoice->count() - 1;
    }
    const QSignalBlocker block(m_frameRateChoice);
    m_frameRateChoice->setCurrentIndex(index);
}

QString TransportBar::formatTime(double seconds)
{
    if (!std::isfinite(seconds))
        return QStringLiteral("--:--.---");
    const bool negative = seconds < 0;
    // Round to whole milliseconds first, so 59.9996 s reads 01:00.000 and not 00:60.000.
    const long long millis = std::llround(std::abs(seconds) * 1000.0);
    const long long minutes = millis / 60000;
    const long long secs = (millis / 1000) % 60;
    const long long ms = millis % 1000;
    return QStringLiteral("%1%2:%3.%4")
        .arg(negative ? QStringLiteral("-") : QString())
        .arg(minutes, 2, 10, QLatin1Char('0'))
        .arg(secs, 2, 10, QLatin1Char('0'))
        .arg(ms, 3, 10, QLatin1Char('0'));
}

long long TransportBar::frameAt(double seconds, double framesPerSecond)
{
    // The epsilon keeps t = n / fps on frame n despite floating-point error (e.g. 0.1 · 30).
    return (long long)std::floor(seconds * framesPerSecond + 1e-6);
}

void TransportBar::updateLabels()
{
    m_timeLabel->setText(QStringLiteral("%1 / %2").arg(formatTime(m_time), formatTime(m_duration)));
    m_frameLabel->setText(tr("frame %1").arg(frameAt(m_time, m_frameRate)));
    m_frameLabel->setToolTip(tr("Frame number at %1 frames per second").arg(m_frameRate));
}

void TransportBar::updatePlayButton()
{
    m_playPause->setIcon(style()->standardIcon(m_playing ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
    m_playPause->setToolTip(m_playing ? tr("Pause (Space)") : tr("Play (Space)"));
    m_playPause->setAccessibleName(m_playing ? tr("Pause") : tr("Play"));
}

void TransportBar::onSliderValueChanged(int value)
{
    if (m_updatingSlider)
        return;
    // Dragging, clicking the groove or keyboard steps: the user asks to go there.
    emit seekRequested(double(value) / kSliderUnitsPerSecond);
}

} // namespace thespis::widgets
