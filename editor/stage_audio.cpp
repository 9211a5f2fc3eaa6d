#include "editor/stage_audio.h"

#include <QAudioDevice>
#include <QAudioFormat>
#include <QAudioSink>
#include <QMediaDevices>

#include <algorithm>
#include <cmath>

#include "editor/document.h"
#include "editor/playback_clock.h"
#include "editor/session.h"
#include "runtime/clock.h"

namespace thespis::editor {
namespace {

constexpr int kRate = 48000; // SoundService's mix rate

} // namespace

StageAudio::StageAudio(Session* session, QObject* parent) : QObject(parent), m_session(session)
{
    const QAudioDevice device = QMediaDevices::defaultAudioOutput();
    QAudioFormat format;
    format.setSampleRate(kRate);
    format.setChannelCount(1);
    format.setSampleFormat(QAudioFormat::Int16);
    if (!device.isNull() && device.isFormatSupported(format)) {
        m_sink = new QAudioSink(device, format, this);
        m_sink->setBufferSize(int(kRate * sizeof(qint16) / 4)); // a quarter of a second at most
        m_outputName = device.description();
    }
    session->addView([this](Document* document) { setDocument(document); }, this);
    connect(session, &Session::edited, this, &StageAudio::refreshTimeline);
    connect(session, &Session::aboutToTick, this, &StageAudio::onTime);
    connect(session->clock(), &PlaybackClock::playingChanged, this, [this](bool playing) {
        if (!playing)
            restart(-1); // silent at once, not when the buffer runs dry
    });
}

StageAudio::~StageAudio()
{
    if (m_sink)
        m_sink->stop();
}

void StageAudio::setDocument(Document* document)
{
    m_document = document;
    m_sources.clear();
    m_timeline = document ? std::make_shared<core::runtime::SoundService>(
                                document->assets(), std::make_shared<core::runtime::ExternalClock>(), kRate)
                          : nullptr;
    restart(-1);
    refreshTimeline();
}

void StageAudio::refreshTimeline()
{
    m_problems.clear();
    if (!m_timeline || !m_document)
        return;
    m_timeline->clear();
    for (const std::string& problem : m_timeline->playSpeech(m_document->scenario()))
        m_problems.push_back(QString::fromStdString(problem));
}

void StageAudio::addSource(std::shared_ptr<core::runtime::SoundService> sound)
{
    if (sound && std::find(m_sources.begin(), m_sources.end(), sound) == m_sources.end())
        m_sources.push_back(std::move(sound));
}

void StageAudio::removeSource(const std::shared_ptr<core::runtime::SoundService>& sound)
{
    std::erase(m_sources, sound);
}

void StageAudio::restart(core::Tick now)
{
    if (m_sink) {
        m_sink->reset(); // what was queued for the old time goes unheard
        m_device = now >= 0 ? m_sink->start() : nullptr;
    }
    m_next = now;
}

void StageAudio::onTime(core::Tick now)
{
    const PlaybackClock* clock = m_session ? m_session->clock() : nullptr;
    if (!clock || !clock->isPlaying() || !m_timeline) {
        if (m_next >= 0)
            restart(-1);
        return;
    }
    const core::Tick ahead = now + m_lead;
    // Started, seeked, looped or fallen behind: the sound starts again at the playhead.
    if (m_next < 0 || m_next < now || m_next > ahead + m_lead)
        restart(now);
    const auto count = std::size_t(std::max(0.0, core::ticksToSeconds(ahead - m_next)) * kRate);
    if (count == 0)
        return;
    m_block.assign(count, 0.0f);
    m_part.resize(count);
    const auto add = [&](const core::runtime::SoundService& sound) {
        sound.mix(m_next, m_part);
        for (std::size_t i = 0; i < count; ++i)
            m_block[i] += m_part[i];
    };
    add(*m_timeline);
    for (const auto& source : m_sources)
        add(*source);
    float peak = 0;
    m_pcm.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        const float s = std::clamp(m_block[i], -1.0f, 1.0f);
        peak = std::max(peak, std::abs(s));
        m_pcm[i] = qint16(std::lround(s * 32767.0f));
    }
    if (m_device)
        m_device->write(reinterpret_cast<const char*>(m_pcm.data()), qint64(count * sizeof(qint16)));
    emit mixed(m_next, int(count), peak);
    m_next += core::secondsToTicks(double(count) / kRate);
}

} // namespace thespis::editor
