#include "editor/playback_clock.h"

#include <algorithm>
#include <cmath>

namespace thespis::editor {

PlaybackClock::PlaybackClock(QObject* parent) : QObject(parent)
{
    m_timer.setTimerType(Qt::PreciseTimer);
    m_timer.setInterval(16);
    connect(&m_timer, &QTimer::timeout, this, &PlaybackClock::onTick);
}

void PlaybackClock::setDuration(double seconds)
{
    const double duration = std::isfinite(seconds) ? std::max(0.0, seconds) : 0.0;
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
    const double position = m_time * m_frameRate;
    double frame = std::floor(position + 1e-6);
    if (frames < 0 && position - frame > 1e-6)
        ++frame; // between frames: one step back lands on this frame's start
    seek((frame + frames) / m_frameRate);
}

void PlaybackClock::play()
{
    if (isPlaying() || m_duration <= 0)
        return;
    if (!m_looping && m_time >= m_duration)
        setTimeInternal(0.0); // at the end: play again from the start, as every player does
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

void PlaybackClock::seek(double seconds)
{
    if (!std::isfinite(seconds))
        return;
    const double t = std::clamp(seconds, 0.0, m_duration);
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
    double t = m_anchorTime + double(m_sinceAnchor.nsecsElapsed()) * 1e-9;
    if (t >= m_duration) {
        if (m_looping && m_duration > 0) {
            t = std::fmod(t, m_duration);
            // Re-anchor at the wrap so that the error of fmod does not grow over many loops.
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

void PlaybackClock::setTimeInternal(double seconds)
{
    if (seconds == m_time)
        return;
    m_time = seconds;
    emit timeChanged(seconds);
}

} // namespace thespis::editor
