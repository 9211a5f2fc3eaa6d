#pragma once
// ScriptPanel: the studio's Script dock (paper §4.5: scripts control the animation service while
// the simulation runs). An editor with Python colouring, Run and Stop, and a console with the
// script's output, its errors and tracebacks. The script runs in a worker thread against the
// Session's Stage, on a clock that follows the playhead: a wait lasts until the playing view
// gets there, and Run starts playback (as the script's start_player() does; stop_player()
// pauses). What it says and plays is heard through the studio's StageAudio. Stop ends a script at once, even one stuck in
// a wait or in an endless loop; the GUI never waits for a script. Scripts kept in the scenario
// are picked from a list and saved back to it; one read from the file (and not edited since) runs
// only once the trust check (the window's: does the user trust that file?) says yes.

#include <QPointer>
#include <QWidget>

#include <functional>
#include <memory>
#include <thread>

#include "runtime/clock.h"
#include "runtime/interaction_service.h"
#include "runtime/sound.h"
#include "runtime/stage.h"
#include "util/error.h"
#include "util/tick.h"

class QComboBox;
class QLabel;
class QPlainTextEdit;
class QPushButton;

namespace thespis::script {
class ScriptRunner;
}

namespace thespis::editor {

class Session;
class StageAudio;

class ScriptPanel : public QWidget {
    Q_OBJECT
public:
    explicit ScriptPanel(QWidget* parent = nullptr);
    ~ScriptPanel() override; ///< stops a running script and waits for its thread

    /// Follows `session` from now on: its stage is what scripts play on (a running script is
    /// stopped when the stage is replaced), its ticks are the scripts' time, its document keeps
    /// the scripts listed and saved (Save Script to Scenario, one undo step).
    void setSession(Session* session);
    /// The stage scripts play on (null: no scenario shown). A running script is stopped when
    /// the stage is replaced.
    void setStage(std::shared_ptr<core::runtime::Stage> stage);
    /// The playhead: scripts' time.
    void setTime(core::Tick time);
    /// What the studio plays aloud: a running script's voiceService and sndService play there.
    void setAudio(StageAudio* audio);
    /// Where the scripts' sound files are found (the scenario's assets).
    void setAssets(const core::scenario::Assets& assets);
    /// The sound service of the script running or run last (null before the first run).
    std::shared_ptr<core::runtime::SoundService> soundService() const { return m_sound; }
    /// The interactionService of the script running or run last (null before the first run): a
    /// character a script hands to a conversation goes on conversing there after it ends.
    std::shared_ptr<core::runtime::InteractionService> interactionService() const { return m_interaction; }

    QString source() const;
    /// Puts the user's text in the editor (as if typed: it is not the scenario's).
    void setSource(const QString& source);
    /// The scripts the scenario keeps, by name (the list shows them after "Scratch"); the one
    /// shown stays when it is still there.
    void setScenarioScripts(const QStringList& names, const QStringList& sources);
    /// Save to Scenario needs an open scenario.
    void setSaveEnabled(bool enabled);
    /// Asked before a script read from the scenario runs; false cancels the run.
    void setTrustCheck(std::function<bool()> check) { m_trustCheck = std::move(check); }
    /// Shows the scenario's script of that name (false when there is none).
    bool showScenarioScript(const QString& name);
    QString output() const;
    bool isRunning() const { return m_worker.joinable(); }

public slots:
    void run();
    void stop();

signals:
    /// A script started and needs time to pass, or called start_player(): the view should play.
    void playRequested();
    /// The script called stop_player(): the view should pause.
    void pauseRequested();
    void runningChanged(bool running);
    /// A run made a new interactionService() (before the script starts).
    void interactionServiceChanged();
    /// The script ended: `message` is empty when it ran to its end, else why not.
    void finished(const QString& message);

private:
    void append(const QString& text, bool error);
    void onFinished(const core::Result<void>& result);
    void updateButtons();
    void onChoice(int index);
    void onSave();
    // The session's stage, assets and scripts, after a new document or an edit.
    void followSession();

    QPlainTextEdit* m_editor = nullptr;
    QPlainTextEdit* m_console = nullptr;
    QPushButton* m_run = nullptr;
    QPushButton* m_stop = nullptr;
    QPushButton* m_save = nullptr;
    QComboBox* m_choice = nullptr;
    QStringList m_sources;  // per scenario script (the list's items after Scratch)
    QString m_scratch;      // the Scratch text while a scenario script is shown
    int m_shown = 0;        // the list's item shown in the editor
    std::function<bool()> m_trustCheck;
    QPointer<Session> m_session;
    QString m_fileName; // the running script's name in tracebacks ("script.py", "NAME.py")
    QLabel* m_status = nullptr;
    std::shared_ptr<core::runtime::Stage> m_stage;
    std::shared_ptr<core::runtime::ExternalClock> m_clock;
    std::unique_ptr<script::ScriptRunner> m_runner; // made at the first Run (it starts Python)
    std::shared_ptr<core::runtime::SoundService> m_sound;
    std::shared_ptr<core::runtime::InteractionService> m_interaction;
    core::scenario::Assets m_assets{"."};
    QPointer<StageAudio> m_audio;
    std::thread m_worker;
};

} // namespace thespis::editor
