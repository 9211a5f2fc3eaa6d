#pragma once
// ScriptPanel: the studio's Script dock (paper §4.5: scripts control the animation service while
// the simulation runs). An editor with Python colouring, Run and Stop, and a console with the
// script's output, its errors and tracebacks. The script runs in a worker thread against the
// Stage the 3D view plays, on a clock that follows the playhead: a wait lasts until the
// playing view gets there, and Run starts playback. Stop ends a script at once, even one stuck in
// a wait or in an endless loop; the GUI never waits for a script.

#include <QWidget>

#include <memory>
#include <thread>

#include "runtime/clock.h"
#include "runtime/stage.h"
#include "util/error.h"

class QLabel;
class QPlainTextEdit;
class QPushButton;

namespace thespis::script {
class ScriptRunner;
}

namespace thespis::editor {

class ScriptPanel : public QWidget {
    Q_OBJECT
public:
    explicit ScriptPanel(QWidget* parent = nullptr);
    ~ScriptPanel() override; ///< stops a running script and waits for its thread

    /// The stage scripts play on (null: no scenario shown). A running script is stopped when
    /// the stage is replaced.
    void setStage(std::shared_ptr<core::runtime::Stage> stage);
    /// The playhead: scripts' time.
    void setTime(double seconds);

    QString source() const;
    void setSource(const QString& source);
    QString output() const;
    bool isRunning() const { return m_worker.joinable(); }

public slots:
    void run();
    void stop();

signals:
    /// A script started and needs time to pass: the view should play.
    void playRequested();
    void runningChanged(bool running);
    /// The script ended: `message` is empty when it ran to its end, else why not.
    void finished(const QString& message);

private:
    void append(const QString& text, bool error);
    void onFinished(const core::Result<void>& result);
    void updateButtons();

    QPlainTextEdit* m_editor = nullptr;
    QPlainTextEdit* m_console = nullptr;
    QPushButton* m_run = nullptr;
    QPushButton* m_stop = nullptr;
    QLabel* m_status = nullptr;
    std::shared_ptr<core::runtime::Stage> m_stage;
    std::shared_ptr<core::runtime::ExternalClock> m_clock;
    std::unique_ptr<script::ScriptRunner> m_runner; // made at the first Run (it starts Python)
    std::thread m_worker;
};

} // namespace thespis::editor
