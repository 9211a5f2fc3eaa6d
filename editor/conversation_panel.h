#pragma once
// ConversationPanel: the studio's Conversation dock (paper §5.3, issue 34). The visitor talks to
// a character of the open scenario, which answers with speech, face, gestures and gaze on the
// Session's Stage — the one the 3D view and the AR preview draw — through the same core objects
// as `thespis-cli chat` and scripts' `interactionService`: an AIML bot (dialogue::loadBot), the
// recogniser that listens for what it can answer (dialogue::listenFor) and the interaction service
// (runtime::InteractionService: converse, hear, handBack, saveState).
//  - Load Bot Folder… / Load AIML Files… (and the demo's bot when the studio ships one): its size,
//    the problems of its files by file:line:column (the rest loads), the listening grammar in the
//    inspector. Loading and opening the recogniser run as jobs off the GUI thread with progress.
//  - Converse hands the character to the conversation (it looks at the visitor: the camera, in AR
//    the tracked one); Hand Back gives it to the scenario again. Sending, talking or hearing a
//    recording hands it over when it was not yet.
//  - The visitor types (Send), holds "Hold to Talk" while speaking into the default microphone,
//    or picks a recording (Hear a Recording…); speech is recognised and shown with its confidence
//    ("not understood" below the recogniser's threshold, answered by the bot's XNOTUNDERSTOOD).
//  - The transcript lists each line and the category (file:line) that answered it; answers are
//    spoken from the playhead, which plays on. Save State… / Load State… keep what the visitor
//    told the bot (JSON).
// With no microphone the talk button is off and the dock says so; typing always works.

#include <QPointer>
#include <QStringList>
#include <QWidget>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "util/error.h"

class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QPlainTextEdit;
class QPushButton;
class QTabWidget;
class QTimer;

namespace thespis::core::dialogue {
class Bot;
}
namespace thespis::core::runtime {
class ExternalClock;
class InteractionService;
class SoundService;
class Stage;
}
namespace thespis::core::speech {
class GrammarRecogniser;
}

namespace thespis::editor {

class ConversationTranscript;
class Document;
class JobProgress;
class JobRunner;
class Microphone;
class Session;
class StageAudio;
struct LoadBotJob;
struct TurnJob;

class ConversationPanel : public QWidget {
    Q_OBJECT
public:
    explicit ConversationPanel(QWidget* parent = nullptr);
    ~ConversationPanel() override;

    /// Follows `session` (its document's characters, its stage, its playhead); the answers are
    /// heard through `audio`.
    void setSession(Session* session, StageAudio* audio);
    void setDocument(Document* document);
    /// A bot folder the studio ships (the demo's Antigone), offered by a button; empty: none.
    void setDefaultBot(const QString& folder);

    int currentCharacter() const;
    void setCurrentCharacter(int character);

    /// Loads a bot from folders and AIML files (a job); its recogniser is opened after it (another).
    void loadBot(const QStringList& paths);
    bool hasBot() const { return m_bot != nullptr; }
    /// The recogniser is open: speech can be heard.
    bool isListening() const { return m_recogniser != nullptr; }
    /// A job runs: loading, opening the recogniser, or a turn.
    bool isBusy() const;
    bool isAnswering() const;

    /// Continues here the conversation of the first character that `from` (a script's service)
    /// converses with: the character, the bot and what the visitor told it move to this dock,
    /// whose recogniser then opens for that bot. False when `from` converses with no one.
    bool takeOver(const std::shared_ptr<core::runtime::InteractionService>& from);

    /// Hands the chosen character to the conversation / gives it back.
    bool converse();
    void handBack();
    bool isConversing() const { return !m_conversing.empty(); }

    /// The visitor typed `text`.
    void say(const QString& text);
    /// The visitor said what `samples` hold (16 kHz mono): what letting go of Hold to Talk does.
    void hearSamples(std::vector<std::int16_t> samples);
    /// The visitor said what the recording at `path` holds (WAV, FLAC, OGG; any rate).
    void hearRecording(const QString& path);
    void cancel();

    bool saveState(const QString& path);
    bool loadState(const QString& path);

    // What the dock shows, for tests and the window.
    ConversationTranscript* transcript() const { return m_transcript; }
    QListWidget* problems() const { return m_problems; }
    QPlainTextEdit* grammarView() const { return m_grammar; }
    QString grammarSummary() const;
    QString botSummary() const;
    QString heard() const;
    QString status() const;
    /// The last job's message (errors in red).
    QString message() const;
    QPushButton* talkButton() const { return m_talk; }
    QPushButton* sendButton() const { return m_send; }
    QPushButton* converseButton() const { return m_converse; }
    QLineEdit* input() const { return m_input; }
    const std::shared_ptr<core::runtime::InteractionService>& interactionService() const { return m_service; }
    /// What the character says, mixed into what the studio plays aloud.
    const std::shared_ptr<core::runtime::SoundService>& soundService() const { return m_sound; }

signals:
    /// An answer is to be spoken from the playhead: the view should play.
    void playRequested();

private:
    enum class Preparing { Bot, Recogniser };
    std::string characterName() const;
    void makeService();
    void followStage();
    /// Hands the chosen character to a conversation (continuing `state`); `note` goes in the transcript.
    bool startConversing(const std::string& state = {}, const QString& note = {});
    void startTurn(std::unique_ptr<TurnJob> job);
    void onPrepared(const core::Result<void>& result);
    void showBot(const LoadBotJob& job);                        // conversation_bot_view.cpp
    void showPronounced(const std::vector<std::string>& guessed); // conversation_bot_view.cpp
    void onTurn(const core::Result<void>& result);
    void showTurn(const TurnJob& job);
    void addEvent(const QString& text);
    void startTalking();
    void stopTalking();
    void showProgress(const QString& stage, qint64 done, qint64 total);
    void syncClock();
    void updateEnabled();
    void updateStatus();

    QPointer<Session> m_session;
    QPointer<StageAudio> m_audio;
    Document* m_document = nullptr;
    std::shared_ptr<core::runtime::ExternalClock> m_clock;
    std::shared_ptr<core::runtime::SoundService> m_sound;
    std::shared_ptr<core::runtime::InteractionService> m_service;
    std::shared_ptr<core::runtime::Stage> m_serviceStage; // the stage m_service plays on
    std::shared_ptr<const core::dialogue::Bot> m_bot;
    std::shared_ptr<core::speech::GrammarRecogniser> m_recogniser;
    QString m_botName;
    QString m_loadMessage; // what loading the bot said
    QString m_defaultBot;
    std::string m_conversing; // the character conversing; empty: none
    JobRunner* m_prepare = nullptr; // loading the bot, then opening its recogniser
    JobRunner* m_turns = nullptr;   // one turn at a time
    Preparing m_preparing = Preparing::Bot;
    Microphone* m_microphone = nullptr;
    QTimer* m_talkTimer = nullptr;

    QComboBox* m_characters = nullptr;
    QPushButton* m_converse = nullptr;
    QCheckBox* m_speak = nullptr;
    QLabel* m_botLabel = nullptr;
    QPushButton* m_loadFolder = nullptr;
    QPushButton* m_loadFiles = nullptr;
    QPushButton* m_loadDemo = nullptr;
    QListWidget* m_problems = nullptr;
    QTabWidget* m_tabs = nullptr;
    ConversationTranscript* m_transcript = nullptr;
    QLabel* m_grammarLabel = nullptr;
    QPlainTextEdit* m_grammar = nullptr;
    QLabel* m_heard = nullptr;
    QLineEdit* m_input = nullptr;
    QPushButton* m_send = nullptr;
    QPushButton* m_talk = nullptr;
    QPushButton* m_hearRecording = nullptr;
    QPushButton* m_saveState = nullptr;
    QPushButton* m_loadState = nullptr;
    QLabel* m_status = nullptr;
    JobProgress* m_progress = nullptr;
    QPushButton* m_cancel = nullptr;
};

} // namespace thespis::editor
