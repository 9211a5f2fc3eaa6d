#include "editor/microphone.h"

#include <QAudioSource>
#include <QCoreApplication>
#include <QMediaDevices>

#include <algorithm>
#include <cstring>

#include "speech/resample.h"
#include "speech/sphinx_decoder.h"

namespace thespis::editor {

Microphone::Microphone(QObject* parent)
    : QObject(parent), m_devices(new QMediaDevices(this)), m_device(QMediaDevices::defaultAudioInput())
{
    connect(m_devices, &QMediaDevices::audioInputsChanged, this, [this] {
        const bool was = isAvailable();
        if (!isRecording())
            m_device = QMediaDevices::defaultAudioInput();
        if (was != isAvailable())
            emit availabilityChanged(isAvailable());
    });
}

Microphone::~Microphone()
{
    if (m_source)
        m_source->stop();
}

double Microphone::seconds() const
{
    return isRecording() ? double(m_elapsed.elapsed()) / 1000.0 : 0.0;
}

bool Microphone::start(QString* error)
{
    if (isRecording())
        return true;
    if (m_device.isNull()) {
        if (error)
            *error = QCoreApplication::translate("Microphone", "There is no microphone.");
        return false;
    }
    // What pocketsphinx hears, if the device records it; else what the device prefers.
    QAudioFormat format;
    format.setSampleRate(core::speech::kSphinxRate);
    format.setChannelCount(1);
    format.setSampleFormat(QAudioFormat::Int16);
    m_format = m_device.isFormatSupported(format) ? format : m_device.preferredFormat();
    m_recorded.clear();
    m_source = new QAudioSource(m_device, m_format, this);
    m_input = m_source->start();
    if (!m_input || m_source->error() != QAudio::NoError) {
        if (error)
            *error = QCoreApplication::translate("Microphone", "The microphone “%1” did not open (Qt Multimedia error %2).")
                         .arg(m_device.description())
                         .arg(int(m_source->error()));
        delete m_source;
        m_source = nullptr;
        m_input = nullptr;
        return false;
    }
    connect(m_input, &QIODevice::readyRead, this, &Microphone::readAvailable);
    m_elapsed.start();
    return true;
}

void Microphone::readAvailable()
{
    if (!m_input)
        return;
    const QByteArray more = m_input->readAll();
    const qint64 limit = qint64(kMaxSeconds * m_format.sampleRate()) * m_format.bytesPerFrame();
    if (m_recorded.size() < limit)
        m_recorded.append(more.left(limit - m_recorded.size()));
}

std::vector<std::int16_t> Microphone::stop()
{
    if (!m_source)
        return {};
    readAvailable();
    m_source->stop();
    m_source->deleteLater();
    m_source = nullptr;
    m_input = nullptr;
    std::vector<std::int16_t> samples = toRecogniserFormat(m_recorded, m_format);
    m_recorded.clear();
    const QAudioDevice now = QMediaDevices::defaultAudioInput();
    if (now != m_device) { // it changed while recording
        m_device = now;
        emit availabilityChanged(isAvailable());
    }
    return samples;
}

std::vector<std::int16_t> Microphone::toRecogniserFormat(const QByteArray& bytes, const QAudioFormat& format)
{
    const int frameBytes = format.bytesPerFrame(), sampleBytes = format.bytesPerSample();
    const int channels = format.channelCount();
    if (frameBytes <= 0 || channels <= 0 || format.sampleRate() <= 0)
        return {};
    const qsizetype frames = bytes.size() / frameBytes;
    if (format.sampleFormat() == QAudioFormat::Int16 && channels == 1 && format.sampleRate() == core::speech::kSphinxRate) {
        std::vector<std::int16_t> samples(static_cast<std::size_t>(frames));
        std::memcpy(samples.data(), bytes.constData(), std::size_t(frames) * sizeof(std::int16_t));
        return samples;
    }
    // Mixed down to mono (the channels' mean), then to the recogniser's rate.
    std::vector<float> mono(std::size_t(frames), 0.0f);
    const char* data = bytes.constData();
    for (qsizetype f = 0; f < frames; ++f) {
        float sum = 0;
        for (int c = 0; c < channels; ++c)
            sum += format.normalizedSampleValue(data + f * frameBytes + c * sampleBytes);
        mono[std::size_t(f)] = sum / float(channels);
    }
    if (format.sampleRate() != core::speech::kSphinxRate)
        mono = core::speech::resampled(mono, format.sampleRate(), core::speech::kSphinxRate);
    return core::speech::dithered16(mono);
}

} // namespace thespis::editor
