#pragma once
// StageAudio: what the studio hears, in step with the transport. At every tick of the playing
// clock it mixes, from the playhead on, the sounds of the scenario's timeline (its speech lines,
// spoken again from their text when they keep no file) and of the services playing along (a
// script's voiceService, the Speech dock's preview) — core::runtime::SoundService::mix, the
// same mix `play --audio` writes — and pushes a little ahead of the playhead to the default audio
// output (Qt Multimedia's QAudioSink). Pause stops the sound at once; a seek or a loop starts it
// again where the playhead went. With no audio output (these machines have none) the mix still
// follows the transport, unheard, so that what would be heard can be checked.
#include <QObject>
#include <QPointer>
#include <QString>
#include <QStringList>

#include <memory>
#include <vector>

#include "runtime/sound.h"
#include "util/tick.h"

class QAudioSink;
class QIODevice;

namespace thespis::editor {

class Document;
class Session;

class StageAudio : public QObject {
    Q_OBJECT
public:
    explicit StageAudio(Session* session, QObject* parent = nullptr);
    ~StageAudio() override;

    /// The sounds of the document's timeline, made anew at each edit (null without a document).
    const std::shared_ptr<core::runtime::SoundService>& timelineSounds() const { return m_timeline; }
    /// A service whose sounds play along with the timeline's until removed (or the document goes).
    void addSource(std::shared_ptr<core::runtime::SoundService> sound);
    void removeSource(const std::shared_ptr<core::runtime::SoundService>& sound);
    /// The timeline's speech lines that could not be played, one sentence naming the field each.
    QStringList problems() const { return m_problems; }
    /// The audio output's name; empty when there is none.
    QString outputName() const { return m_outputName; }
    /// Seconds mixed ahead of the playhead (default 0.06).
    void setLead(double seconds) { m_lead = core::secondsToTicks(seconds); }

signals:
    /// A block of the mix went out (or would have, with no output): `samples` at 48 kHz from
    /// `start`, the loudest of them `peak`.
    void mixed(core::Tick start, int samples, float peak);

private:
    void setDocument(Document* document);
    void refreshTimeline();
    void onTime(core::Tick now);
    void restart(core::Tick now);

    QPointer<Session> m_session;
    Document* m_document = nullptr;
    std::shared_ptr<core::runtime::SoundService> m_timeline;
    std::vector<std::shared_ptr<core::runtime::SoundService>> m_sources;
    QStringList m_problems;
    QAudioSink* m_sink = nullptr; // null: no audio output
    QIODevice* m_device = nullptr;
    QString m_outputName;
    core::Tick m_lead = core::secondsToTicks(0.06);
    core::Tick m_next = -1;        // where the next block starts; −1: not playing
    std::vector<float> m_block, m_part; // the mix and one source's share: kept, no allocation per tick
    std::vector<qint16> m_pcm;
};

} // namespace thespis::editor
