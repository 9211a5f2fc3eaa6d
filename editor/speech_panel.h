#pragma once
// SpeechPanel: the studio's Speech dock (paper §5.1–5.2). For the chosen character: what it says,
// as tagged text (`<begin_gesture id=".." anim=".."/> … <end_gesture id=".."/>`) or a BML block, the espeak-ng
// voice, rate and pitch, and the viseme set with each viseme's α, weight and spread (VisemeTable).
//  - Preview speaks it (a core SpeakJob, with progress and Cancel) and plays it live from the
//    playhead: its visemes and face gestures on the Stage (runtime::performSpeech) and its audio
//    through StageAudio, following the transport — the document unchanged; a close-up on request.
//  - Insert puts it on the timeline at the playhead as one undo step (edit::insertSpeech): the
//    line kept on the character (its text re-spoken when played), its visemes on the Speech face
//    layer, its gestures over their words.
//  - Lip Sync a Recording… aligns a WAV with the text as its transcript (a core LipSyncJob;
//    without text the words are recognised) and inserts it the same way, the WAV as its audio.
#include <QPointer>
#include <QWidget>

#include <memory>
#include <string>

#include "speech/espeak_voice.h"
#include "util/tick.h"

class QCheckBox;
class QComboBox;
class QPlainTextEdit;
class QPushButton;
class QSpinBox;

namespace thespis::core::runtime {
class SoundService;
}
namespace thespis::core::speech {
struct SpeakJob;
}

namespace thespis::editor {

class Document;
class JobProgress;
class JobRunner;
class Session;
class StageAudio;
class VisemeTable;

class SpeechPanel : public QWidget {
    Q_OBJECT
public:
    explicit SpeechPanel(QWidget* parent = nullptr);
    ~SpeechPanel() override;

    void setSession(Session* session, StageAudio* audio);
    void setDocument(Document* document);
    int currentCharacter() const;
    void setCurrentCharacter(int character);

    QString text() const;
    void setText(const QString& text);
    core::speech::VoiceSettings voice() const;
    /// Picks the voice by identifier or name; false when none is installed.
    bool setVoice(const QString& voice);
    void setRate(int wordsPerMinute);
    void setPitch(int pitch);
    VisemeTable* visemeTable() const { return m_visemes; }
    void setCloseUp(bool closeUp);

    /// Speaks the text and plays it live from the playhead (see above).
    void preview();
    /// Speaks the text and inserts it at the playhead, one undo step.
    void insert();
    /// Aligns the recording at `wav` with the text and inserts it at the playhead.
    void lipSync(const QString& wav);
    void cancel();
    bool isBusy() const;
    /// What the last action did, or why not.
    QString message() const;

signals:
    /// The 3D view should turn to a close-up of this character's face.
    void closeUpRequested(int character);
    /// The view should play (a preview starts).
    void playRequested();

private:
    enum class Then { Preview, Insert, LipSync };
    void start(Then then);
    void onFinished(bool ok);
    void playPreview();
    void previewBml(const core::speech::SpeakJob& job, const std::string& character, core::Tick at);
    void insertSpoken();
    void insertBml(const core::speech::SpeakJob& job);
    void insertLipSync();
    void updateEnabled();

    QPointer<Session> m_session;
    QPointer<StageAudio> m_audio;
    Document* m_document = nullptr;
    std::shared_ptr<core::runtime::SoundService> m_previewSound; // the preview's voice, in StageAudio
    JobRunner* m_runner = nullptr;
    Then m_then = Then::Preview;
    QString m_recording; // the WAV being lip-synced
    QComboBox* m_characters = nullptr;
    QComboBox* m_voices = nullptr;
    QSpinBox* m_rate = nullptr;
    QSpinBox* m_pitch = nullptr;
    QPlainTextEdit* m_text = nullptr;
    QPushButton* m_preview = nullptr;
    QPushButton* m_insert = nullptr;
    QPushButton* m_lipSync = nullptr;
    QPushButton* m_cancel = nullptr;
    QCheckBox* m_closeUp = nullptr;
    JobProgress* m_progress = nullptr;
    VisemeTable* m_visemes = nullptr;
};

} // namespace thespis::editor
