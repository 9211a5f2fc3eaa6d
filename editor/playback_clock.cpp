#include "editor/playback_clock.h"

#include <algorithm>
#include <cmath>

namespace thespis::editor {

namespace {

// Nanoseconds to ticks, exactly (705 600 000 ticks per second = 7056 ticks per 10 000 ns).
core::Tick ticksOfNanoseconds(qint64 nanoseconds)
{
    static_assert(core::TicksPerSecond % 100'000 == 0);
    return core::Tick(nanoseconds) * (core::TicksPerSecond / 100'000) / 10'000;
}

} // namespace

PlaybackClock::PlaybackClock(QObject* parent) : QObject(parent)
{
    m_timer.setTimerType(Qt::PreciseTimer);
    m_timer.setInterval(16);
    connect(&m_timer, &QTimer::timeout, this, &PlaybackClock::onTick);
}

void PlaybackClock::setDuration(core::Tick duration)
{
    duration = std::max<core::Tick>(0, duration);
    if (duration != m_duration) {
        m_duration = duration;
        emit durationChanged(m_duration);
    }
    if (m_duration <= 0 && isPlaying())
        pause();
    if (m_time > m_duration)
        seek(m_duration);
}

void PlaybackClock::setTickInterval(int milliseconds)
{
    m_timer.setInterval(std::max(1, milliseconds));
}

void PlaybackClock::setFrameRate(double framesPerSecond)
{
    if (framesPerSecond > 0 && std::isfinite(framesPerSecond))
        m_frameRate = framesPerSecond;
}

void PlaybackClock::step(int frames)
{
    pause();
    // The frame the playhead is in; the epsilon keeps t = n / fps on frame n despite rounding.
    const double position = core::ticksToSeconds(m_time) * m_frameRate;
    double frame = std::floor(position + 1e-6);
    if (frames < 0 && position - frame > 1e-6)
        ++frame; // between frames: one step back lands on this frame's start
    const double target = std::clamp((frame + frames) / m_frameRate, 0.0, core::ticksToSeconds(m_duration));
    seek(core::secondsToTicks(target));
}

void PlaybackClock::play()
{
    if (isPlaying() || m_duration <= 0)
        return;
    if (!m_looping && m_time >= m_duration)
        setTimeInternal(0); // at the end: play again from the start, as every player does
    m_anchorTime = m_time;
    m_sinceAnchor.start();
    m_timer.start();
    emit playingChanged(true);
}

void PlaybackClock::pause()
{
    if (!isPlaying())
        return;
    onTick(); // catch up to the real time, so pausing keeps what was seen last
    if (!isPlaying()) // the tick may have reached the end and stopped already
        return;
    m_timer.stop();
    emit playingChanged(false);
}

void PlaybackClock::togglePlayPause()
{
    if (isPlaying())
        pause();
    else
        play();
}

void PlaybackClock::seek(core::Tick time)
{
    const core::Tick t = std::clamp<core::Tick>(time, 0, m_duration);
    m_anchorTime = t;
    if (isPlaying())
        m_sinceAnchor.start();
    setTimeInternal(t);
}

void PlaybackClock::setLooping(bool looping)
{
    if (looping == m_looping)
        return;
    m_looping = looping;
    emit loopingChanged(looping);
}

void PlaybackClock::onTick()
{
    core::Tick t = m_anchorTime + ticksOfNanoseconds(m_sinceAnchor.nsecsElapsed());
    if (t >= m_duration) {
        if (m_looping && m_duration > 0) {
            // Whole ticks wrap exactly; re-anchoring keeps the elapsed count small.
            t %= m_duration;
            m_anchorTime = t;
            m_sinceAnchor.start();
        } else {
            setTimeInternal(m_duration);
            m_timer.stop();
            emit playingChanged(false);
            return;
        }
    }
    setTimeInternal(t);
}

void PlaybackClock::setTimeInternal(core::Tick time)
{
    if (time == m_time)
        return;
    m_time = time;
    emit timeChanged(time);
}

} // namespace thespis::editor
