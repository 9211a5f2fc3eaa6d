#pragma once
// TransportBar: the playback controls under a preview — go to start, step back a frame,
// play/pause, step forward, go to end, loop, a scrubbing slider, the current time as mm:ss.fff
// with the frame number, and the frame rate frames are counted in. A pure view:
// clicking and dragging emit intents (playRequested, seekRequested, …); what is shown changes
// only through the setters, which emit nothing, so a clock can drive it without feedback loops.

#include <QWidget>

class QComboBox;
class QLabel;
class QSlider;
class QToolButton;

namespace thespis::widgets {

class TransportBar : public QWidget {
    Q_OBJECT
public:
    explicit TransportBar(QWidget* parent = nullptr);

    /// Length of the timeline in seconds (the slider's range); negative values count as 0.
    void setDuration(double seconds);
    double duration() const { return m_duration; }
    /// The playhead. Ignored by the slider while the user holds it, so a playing clock does not
    /// fight the drag.
    void setTime(double seconds);
    double time() const { return m_time; }
    void setPlaying(bool playing);
    bool isPlaying() const { return m_playing; }
    void setLooping(bool looping);
    bool isLooping() const;
    /// Frames per second used for the frame number and frame steps (default 30); a rate that
    /// is not among the choices is added to them.
    void setFrameRate(double framesPerSecond);
    double frameRate() const { return m_frameRate; }

    /// "mm:ss.fff"; hours are folded into minutes ("75:00.000"); negative times get a '-'.
    static QString formatTime(double seconds);
    /// The frame shown at `seconds` at `framesPerSecond`: floor(t · fps), robust to rounding.
    static long long frameAt(double seconds, double framesPerSecond);

signals:
    void playRequested();
    void pauseRequested();
    void seekRequested(double seconds);
    void loopRequested(bool enabled);
    /// Step back (−1) or forward (+1) by one frame.
    void stepRequested(int frames);
    /// The user picked another frame rate.
    void frameRateRequested(double framesPerSecond);

private:
    void updateLabels();
    void updatePlayButton();
    void onSliderValueChanged(int value);

    void updateFrameRateChoice();

    QToolButton* m_toStart = nullptr;
    QToolButton* m_stepBack = nullptr;
    QToolButton* m_playPause = nullptr;
    QToolButton* m_stepForward = nullptr;
    QToolButton* m_toEnd = nullptr;
    QComboBox* m_frameRateChoice = nullptr;
    QToolButton* m_loop = nullptr;
    QSlider* m_slider = nullptr;
    QLabel* m_timeLabel = nullptr;
    QLabel* m_frameLabel = nullptr;
    double m_duration = 0;
    double m_time = 0;
    double m_frameRate = 30;
    bool m_playing = false;
    bool m_updatingSlider = false; // set while setTime() moves the slider: not a user seek
};

} // namespace thespis::widgets
