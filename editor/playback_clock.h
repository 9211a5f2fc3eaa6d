#pragma once
// PlaybackClock: the preview's current time, in ticks (core/util/tick.h) like the Stage, the
// scene and the AR session. Plays in real time (a ~60 Hz QTimer for ticks, a QElapsedTimer for
// the time itself, so that late ticks never slow playback down), pauses, seeks, steps frame by
// frame at its frame rate, and at the end either stops or loops over [0, duration) — in whole
// ticks, so a loop never drifts. Emits timeChanged for every new time; views follow it, nothing
// else moves the playhead.

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

#include <concepts>

#include "util/tick.h"

namespace thespis::editor {

class PlaybackClock : public QObject {
    Q_OBJECT
public:
    explicit PlaybackClock(QObject* parent = nullptr);

    core::Tick time() const { return m_time; }
    core::Tick duration() const { return m_duration; }
    bool isPlaying() const { return m_timer.isActive(); }
    bool isLooping() const { return m_looping; }

    /// Length (negative counts as 0); the time is clamped into it.
    void setDuration(core::Tick duration);
#ifndef Q_MOC_RUN
    // Seconds are not ticks: a double would silently become a tick count.
    template <std::floating_point Seconds> void setDuration(Seconds) = delete;
    template <std::floating_point Seconds> void seek(Seconds) = delete;
#endif
    /// Milliseconds between ticks while playing (default 16, ~60 Hz).
    void setTickInterval(int milliseconds);
    /// Frames per second of frame steps (default 30); non-positive or non-finite values are ignored.
    void setFrameRate(double framesPerSecond);
    double frameRate() const { return m_frameRate; }

public slots:
    /// Starts from the current time; at the end of a non-looping clock, starts over from 0.
    /// Does nothing when the duration is 0.
    void play();
    void pause();
    void togglePlayPause();
    /// Moves the playhead (clamped into [0, duration]); playing continues from there.
    void seek(core::Tick time);
    void setLooping(bool looping);
    /// Pauses and moves `frames` whole frames from the frame the playhead is in (−1: the
    /// previous frame's start, or this frame's start when between frames), clamped into the
    /// timeline.
    void step(int frames);

signals:
    void timeChanged(core::Tick time);
    void playingChanged(bool playing);
    void loopingChanged(bool looping);
    void durationChanged(core::Tick duration);

private:
    void onTick();
    void setTimeInternal(core::Tick time);

    QTimer m_timer;
    QElapsedTimer m_sinceAnchor; // real time since m_anchorTime was the current time
    core::Tick m_anchorTime = 0;
    core::Tick m_time = 0;
    core::Tick m_duration = 0;
    double m_frameRate = 30;
    bool m_looping = false;
};

} // namespace thespis::editor
