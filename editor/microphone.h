#pragma once
// Microphone: push-to-talk capture from the default audio input through Qt Multimedia
// (QMediaDevices, QAudioSource), as the recogniser hears it: 16 kHz mono 16-bit. The device is
// asked for that format; one that does not take it records in its preferred format, and what it
// recorded is mixed down to mono and resampled (core/speech/resample.h) when the button is let go.
// With no input device (these machines, CI) it is simply unavailable — a state, not an error —
// and it follows devices coming and going.

#include <QAudioDevice>
#include <QAudioFormat>
#include <QByteArray>
#include <QElapsedTimer>
#include <QObject>
#include <QString>

#include <cstdint>
#include <vector>

class QAudioSource;
class QIODevice;
class QMediaDevices;

namespace thespis::editor {

class Microphone : public QObject {
    Q_OBJECT
public:
    explicit Microphone(QObject* parent = nullptr);
    ~Microphone() override;

    /// A default audio input exists.
    bool isAvailable() const { return !m_device.isNull(); }
    /// Its name, empty when there is none.
    QString deviceName() const { return m_device.description(); }
    bool isRecording() const { return m_source != nullptr; }
    /// Seconds recorded so far.
    double seconds() const;

    /// Starts recording from the default input; false (with `error` set) when there is none or it
    /// will not open.
    bool start(QString* error = nullptr);
    /// Stops and returns what was recorded, 16 kHz mono (empty when nothing was).
    std::vector<std::int16_t> stop();

    /// Recordings longer than this are cut (push-to-talk held down and forgotten).
    static constexpr double kMaxSeconds = 30;

    /// `bytes` recorded in `format` as 16 kHz mono 16-bit samples.
    static std::vector<std::int16_t> toRecogniserFormat(const QByteArray& bytes, const QAudioFormat& format);

signals:
    /// An input device came or went.
    void availabilityChanged(bool available);

private:
    void readAvailable();

    QMediaDevices* m_devices = nullptr;
    QAudioDevice m_device;
    QAudioFormat m_format;
    QAudioSource* m_source = nullptr; // while recording
    QIODevice* m_input = nullptr;
    QByteArray m_recorded;
    QElapsedTimer m_elapsed;
};

} // namespace thespis::editor
