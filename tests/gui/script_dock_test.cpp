// The Script dock on the real window (paper §4.5: scripts drive the animation service while the
// simulation runs): the paper's Antigone/Creon script runs while the view plays and its live
// actions show in the 3D view; Stop ends a script stuck in a wait or in an endless loop while
// the view plays on; an error shows its traceback and puts the cursor on its line. A script kept
// in the scenario runs only once the user trusts the file; saving one to the scenario is one undo step.

#include <QApplication>
#include <QComboBox>
#include <QDockWidget>
#include <QInputDialog>
#include <QLineEdit>
#include <QMessageBox>
#include <QTimer>
#include <QUndoStack>

#include <functional>
#include <QLabel>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSettings>
#include <QStandardPaths>
#include <QSignalSpy>
#include <QTest>

#include "editor/document.h"
#include "editor/playback_clock.h"
#include "editor/scene_preview.h"
#include "editor/script_panel.h"
#include "editor/stage_audio.h"
#include "main_window.h"
#include "render/scenario_scene.h"

using namespace thespis;
using core::runtime::Track;

namespace {

QString demoPath() { return QStringLiteral(THESPIS_RESOURCES "/demo.thespis"); }

void saveScreenshot(QWidget* widget, const QString& name)
{
    QDir().mkpath(QStringLiteral(THESPIS_SCREENSHOT_DIR));
    QVERIFY(widget->grab().save(QStringLiteral(THESPIS_SCREENSHOT_DIR "/") + name));
}

// Runs `act` on the next modal dialog of type T once it is up (a user answering it).
template <class T>
void whenModal(std::function<void(T*)> act)
{
    auto* timer = new QTimer;
    timer->setInterval(50);
    QObject::connect(timer, &QTimer::timeout, [timer, act] {
        if (auto* dialog = qobject_cast<T*>(QApplication::activeModalWidget())) {
            timer->stop();
            timer->deleteLater();
            act(dialog);
        }
    });
    timer->start();
}

QAbstractButton* buttonNamed(QMessageBox* box, const QString& text)
{
    for (QAbstractButton* button : box->buttons())
        if (button->text() == text)
            return button;
    return nullptr;
}

} // namespace

class ScriptDockTest : public QObject {
    Q_OBJECT
private slots:
    void init();
    void cleanup();
    void thePapersScriptPlaysWhileTheViewPlays();
    void stopEndsAScriptStuckInAWaitAndTheViewPlaysOn();
    void stopEndsAnEndlessLoop();
    void anErrorShowsItsTracebackAndLine();
    void aScenarioScriptRunsOnlyOnceTheFileIsTrusted();
    void savingAScriptToTheScenarioIsOneUndoStep();
    void aVoiceStartsWithTheView();
    void stopPlayerPausesTheTransportAndStartPlayerPlaysIt();

private:
    editor::ScriptPanel* panel() const { return m_window->findChild<editor::ScriptPanel*>(); }
    QPushButton* button(const char* name) const { return panel()->findChild<QPushButton*>(QLatin1String(name)); }
    std::unique_ptr<studio::MainWindow> m_window;
};

void ScriptDockTest::init()
{
    QStandardPaths::setTestModeEnabled(true);
    QSettings().clear();
    m_window = std::make_unique<studio::MainWindow>();
    m_window->resize(1500, 950);
    m_window->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
    QVERIFY(m_window->openScenario(demoPath()));
    QVERIFY(panel());
    auto* dock = m_window->findChild<QDockWidget*>(QStringLiteral("scriptDock"));
    QVERIFY(dock);
    dock->raise();
    QVERIFY(button("runScript")->isEnabled());
    QVERIFY(!button("stopScript")->isEnabled());
}

void ScriptDockTest::cleanup() { m_window.reset(); }

void ScriptDockTest::thePapersScriptPlaysWhileTheViewPlays()
{
    // The dock opens with the paper's script (resources/scripts/antigone_creon.py).
    QVERIFY(panel()->source().contains(QLatin1String("voiceService.activateAction(Creon, \"CreonSpeech.Cam01CreonP1\", 1.0)")));
    QVERIFY(!m_window->clock()->isPlaying());
    QSignalSpy mixed(m_window->audio(), &editor::StageAudio::mixed);
    QTest::mouseClick(button("runScript"), Qt::LeftButton);
    QVERIFY(panel()->isRunning());
    QVERIFY(m_window->clock()->isPlaying()); // Run plays the view: the script's waits need time
    QVERIFY(button("stopScript")->isEnabled());

    // Antigone's wave is live (her authored wave comes earlier): the 3D view's stage plays it
    // while the script waits for her words; Creon's speech line moves his lips before.
    core::render::ScenarioScene* scene = m_window->scenePreview()->scene();
    QVERIFY(scene);
    bool sawLiveWave = false, sawCreonSpeak = false;
    QTRY_VERIFY_WITH_TIMEOUT((sawLiveWave = sawLiveWave || *scene->stage().isPlaying(
                                  "Antigone", Track::Body, "antigone_wave",
                                  m_window->clock()->time()),
                              sawCreonSpeak = sawCreonSpeak || *scene->stage().isPlaying(
                                  "Creon", Track::Face, "speech CreonSpeech.Cam01CreonP1",
                                  m_window->clock()->time()),
                              !panel()->isRunning()),
                             30000);
    QVERIFY(sawLiveWave);
    QVERIFY(sawCreonSpeak);
    // What the script's voiceService says is in what the studio plays aloud.
    QVERIFY(std::any_of(mixed.begin(), mixed.end(), [](const QList<QVariant>& block) { return block.at(2).toFloat() > 0.05f; }));
    QVERIFY2(panel()->output().contains(QLatin1String("Antigone answered Creon at")), qPrintable(panel()->output()));
    QCOMPARE(panel()->findChild<QLabel*>(QStringLiteral("scriptStatus"))->text(), QStringLiteral("Finished."));
    saveScreenshot(m_window.get(), QStringLiteral("script_dock.png"));
}

void ScriptDockTest::stopEndsAScriptStuckInAWaitAndTheViewPlaysOn()
{
    panel()->setSource(QStringLiteral("anim.activateAction_body('Creon', 'creon_wave')\nprint('waiting')\nanim.wait(1000)\nprint('never')\n"));
    QTest::mouseClick(button("runScript"), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(panel()->output().contains(QLatin1String("waiting")), 5000);
    QVERIFY(panel()->isRunning());
    QTest::mouseClick(button("stopScript"), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(!panel()->isRunning(), 5000);
    QVERIFY(!panel()->output().contains(QLatin1String("never")));
    QCOMPARE(panel()->findChild<QLabel*>(QStringLiteral("scriptStatus"))->text(), QStringLiteral("Stopped."));
    // The view was never held up: it plays on after the stop.
    QVERIFY(m_window->clock()->isPlaying());
    const core::Tick before = m_window->clock()->time();
    QTRY_VERIFY_WITH_TIMEOUT(m_window->clock()->time() > before, 2000);
    QVERIFY(button("runScript")->isEnabled());
}

void ScriptDockTest::stopEndsAnEndlessLoop()
{
    panel()->setSource(QStringLiteral("print('looping')\nwhile True:\n    pass\n"));
    QTest::mouseClick(button("runScript"), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(panel()->output().contains(QLatin1String("looping")), 5000);
    // The window stays responsive while the loop spins in its thread.
    const core::Tick before = m_window->clock()->time();
    QTRY_VERIFY_WITH_TIMEOUT(m_window->clock()->time() > before, 2000);
    QTest::mouseClick(button("stopScript"), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(!panel()->isRunning(), 5000);
}

void ScriptDockTest::anErrorShowsItsTracebackAndLine()
{
    panel()->setSource(QStringLiteral("anim.activateAction_body('Creon', 'creon_wave')\n\nanim.activateAction_body('Creon', 'creon_dance')\n"));
    QString message;
    connect(panel(), &editor::ScriptPanel::finished, this, [&message](const QString& m) { message = m; });
    QTest::mouseClick(button("runScript"), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(!panel()->isRunning(), 5000);
    QVERIFY2(message.startsWith(QLatin1String("script.py, line 3: KeyError")), qPrintable(message));
    QVERIFY(message.contains(QLatin1String("creon_dance")) && message.contains(QLatin1String("creon_idle")));
    QVERIFY(panel()->output().contains(QLatin1String("Traceback")));
    auto* editorView = panel()->findChild<QPlainTextEdit*>(QStringLiteral("scriptEditor"));
    QCOMPARE(editorView->textCursor().blockNumber(), 2);
    saveScreenshot(m_window.get(), QStringLiteral("script_dock_error.png"));
    // The stage plays on: the action activated before the error is live.
    QVERIFY(*m_window->scenePreview()->scene()->stage().isPlaying(
        "Creon", Track::Body, "creon_wave", m_window->clock()->time()));
}

void ScriptDockTest::aScenarioScriptRunsOnlyOnceTheFileIsTrusted()
{
    auto* choice = panel()->findChild<QComboBox*>(QStringLiteral("scriptChoice"));
    QCOMPARE(choice->count(), 2); // Scratch, and the demo's own antigone_creon
    QVERIFY(panel()->showScenarioScript(QStringLiteral("antigone_creon")));
    QVERIFY(panel()->source().contains(QLatin1String("animService.activateAction_body(Antigone, \"antigone_wave\")")));
    // Not trusted yet: the user is asked, and Cancel runs nothing.
    bool asked = false;
    whenModal<QMessageBox>([&](QMessageBox* box) {
        asked = true;
        QVERIFY(box->text().contains(QLatin1String("demo.thespis")));
        saveScreenshot(box, QStringLiteral("script_trust.png"));
        box->reject();
    });
    QTest::mouseClick(button("runScript"), Qt::LeftButton);
    QTRY_VERIFY(asked);
    QVERIFY(!panel()->isRunning());
    QVERIFY(panel()->findChild<QLabel*>(QStringLiteral("scriptStatus"))->text().startsWith(QLatin1String("Not run")));
    // Trusted: it runs, and is not asked about again.
    asked = false;
    whenModal<QMessageBox>([&](QMessageBox* box) {
        asked = true;
        QAbstractButton* trust = buttonNamed(box, QStringLiteral("Trust This File and Run"));
        QVERIFY(trust);
        trust->click();
    });
    QTest::mouseClick(button("runScript"), Qt::LeftButton);
    QTRY_VERIFY(asked);
    QTRY_VERIFY(panel()->isRunning());
    QTest::mouseClick(button("stopScript"), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(!panel()->isRunning(), 5000);
    QTest::mouseClick(button("runScript"), Qt::LeftButton);
    QVERIFY(panel()->isRunning()); // no question this time
    QTest::mouseClick(button("stopScript"), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(!panel()->isRunning(), 5000);
}

void ScriptDockTest::savingAScriptToTheScenarioIsOneUndoStep()
{
    editor::Document& document = *m_window->document();
    const auto before = document.scenario().scripts;
    panel()->setSource(QStringLiteral("anim.activateAction_body('Creon', 'creon_nod')\n"));
    whenModal<QInputDialog>([](QInputDialog* dialog) {
        dialog->setTextValue(QStringLiteral("greet"));
        dialog->accept();
    });
    QTest::mouseClick(panel()->findChild<QPushButton*>(QStringLiteral("saveScript")), Qt::LeftButton);
    QTRY_VERIFY(document.scenario().findScript("greet"));
    QCOMPARE(QString::fromStdString(document.scenario().findScript("greet")->source),
             QStringLiteral("anim.activateAction_body('Creon', 'creon_nod')\n"));
    auto* choice = panel()->findChild<QComboBox*>(QStringLiteral("scriptChoice"));
    QCOMPARE(choice->currentText(), QStringLiteral("greet"));
    // A script the user wrote runs without asking (it is not the file's).
    panel()->setSource(QStringLiteral("anim.activateAction_body('Creon', 'creon_nod')\nprint('mine')\n"));
    QTest::mouseClick(button("runScript"), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(panel()->output().contains(QLatin1String("mine")), 5000);
    QTRY_VERIFY_WITH_TIMEOUT(!panel()->isRunning(), 5000);
    document.undoStack()->undo();
    QCOMPARE(document.scenario().scripts, before);
    QCOMPARE(choice->count(), 2);
    document.undoStack()->redo();
    QVERIFY(document.scenario().findScript("greet"));
}

void ScriptDockTest::aVoiceStartsWithTheView()
{
    // The paper's voiceService on a real recording: it starts at the playhead's time (played
    // through the studio's StageAudio; the machine may have no sound device, which is not an error).
    const QString speech = QStringLiteral(THESPIS_SHARED_DATA "/speech/pocketsphinx/cards/001.wav");
    panel()->setSource(QStringLiteral("anim.wait(0.3)\nvoiceService.activateAction('Creon', %1, 1.0)\nprint('spoke')\n")
                           .arg(QLatin1Char('\'') + speech + QLatin1Char('\'')));
    QTest::mouseClick(button("runScript"), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(panel()->output().contains(QLatin1String("spoke")), 5000);
    QTRY_VERIFY_WITH_TIMEOUT(!panel()->isRunning(), 5000);
    const auto activations = panel()->soundService()->activations();
    QCOMPARE(activations.size(), std::size_t(1));
    QCOMPARE(activations[0].owner, std::string("Creon"));
    QVERIFY(core::ticksToSeconds(activations[0].start) >= 0.3);
    QVERIFY(activations[0].end > activations[0].start);
}

void ScriptDockTest::stopPlayerPausesTheTransportAndStartPlayerPlaysIt()
{
    // The paper's start_player / stop_player: the studio's Session is the player, so they play
    // and pause the transport. The script waits for half a second of playing, then pauses it.
    panel()->setSource(QStringLiteral("anim.start_player()\nanim.wait(0.5)\nanim.stop_player()\nprint('paused at', anim.now())\n"));
    QTest::mouseClick(button("runScript"), Qt::LeftButton);
    QVERIFY(m_window->clock()->isPlaying());
    QTRY_VERIFY_WITH_TIMEOUT(!panel()->isRunning(), 10000);
    QTRY_VERIFY_WITH_TIMEOUT(!m_window->clock()->isPlaying(), 5000);
    QVERIFY2(panel()->output().contains(QLatin1String("paused at")), qPrintable(panel()->output()));
    QVERIFY(m_window->clock()->time() >= core::TicksPerSecond / 2);
    // Paused, a script that starts the player plays the view again.
    m_window->clock()->pause();
    panel()->setSource(QStringLiteral("anim.stop_player()\nanim.start_player()\n"));
    QTest::mouseClick(button("runScript"), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(!panel()->isRunning(), 10000);
    QTRY_VERIFY_WITH_TIMEOUT(m_window->clock()->isPlaying(), 5000);
}

QTEST_MAIN(ScriptDockTest)
#include "script_dock_test.moc"
