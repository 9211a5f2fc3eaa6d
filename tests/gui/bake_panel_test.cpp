// The bake panel (editor::BakePanel) and its background job (core's TransferBakeJob in an editor::JobRunner) on a copy of the
// demo scenario: a long bake cancelled after its first progress changes nothing (same scenario,
// same undo history, no file); a small bake run to completion is exactly one undo step that sets
// the character's bake, whose file reads back, fits the body and is what a ScenarioScene built
// from the document draws; undo / redo; a stale bake after a tag edit; bad settings and an
// unwritable folder start nothing; the PRT / Phong check box; a job destroyed while it runs.
// Screenshots of the panel mid-bake and after a bake.

#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QFile>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

#include <chrono>
#include <memory>
#include <optional>

#include "edit/document_edits.h"
#include "editor/bake_panel.h"
#include "editor/document.h"
#include "editor/job_runner.h"
#include "editor/qt_conversions.h"
#include "editor/playback_clock.h"
#include "editor/scene_preview.h"
#include "editor/session.h"
#include "lighting/transfer_bake.h"
#include "lighting/transfer_bake_job.h"
#include "render/scenario_scene.h"
#include "scenario/scenario_character.h"
#include "widgets/osg_viewport.h"

using namespace thespis;
namespace lighting = core::lighting;

namespace {

void saveScreenshot(QWidget* widget, const QString& name)
{
    QDir().mkpath(QStringLiteral(THESPIS_SCREENSHOT_DIR));
    QTest::qWait(50); // let the layout follow texts that just changed
    QVERIFY(widget->grab().save(QStringLiteral(THESPIS_SCREENSHOT_DIR "/") + name));
}

lighting::BakeSettings bakeSettings(int order, int rays)
{
    lighting::BakeSettings settings;
    settings.order = order;
    settings.raysPerVertex = rays;
    settings.transfer = lighting::TransferKind::DiffuseShadowedMerged;
    return settings;
}

// Every file in `folder` (temporary files too); none when it does not exist.
QStringList filesIn(const QString& folder)
{
    return QDir(folder).entryList(QDir::Files | QDir::Hidden | QDir::System);
}

// Records the job's finished() result.
struct FinishedRecorder {
    std::optional<core::Result<void>> result;
    int count = 0;
    explicit FinishedRecorder(editor::JobRunner* job)
    {
        QObject::connect(job, &editor::JobRunner::finished, job, [this](const core::Result<void>& r) {
            result = r;
            ++count;
        });
    }
};

} // namespace

class BakePanelTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void init();
    void cleanup();
    void cancelledBakeChangesNothing();
    void completedBakeIsOneUndoStepTheSceneUses();
    void bakeOfACharacterEditedMeanwhileIsThrownAway();
    void badEpsilonStartsNothing();
    void unwritableFolderIsRefused();
    void prtToggleEmitsOnlyForTheUser();
    void destroyingARunningJobCancelsIt();

private:
    QString bakesFolder() const { return m_folder.filePath(QStringLiteral("bakes")); }

    QTemporaryDir m_folder;
    QString m_scenarioPath;
    // The document as the studio holds it: the Session's, which its views (the 3D view) follow.
    editor::PlaybackClock m_clock;
    std::unique_ptr<editor::Session> m_session;
    editor::Document* m_document = nullptr;
    std::unique_ptr<editor::BakePanel> m_panel;
    int m_antigone = -1;
};

void BakePanelTest::initTestCase()
{
    QVERIFY(m_folder.isValid());
    // The demo refers to one other file, the idle motion database (inline clips, built-in
    // bodies, no probe): it moves along.
    m_scenarioPath = m_folder.filePath(QStringLiteral("demo.thespis"));
    QVERIFY(QFile::copy(QStringLiteral(THESPIS_RESOURCES "/demo.thespis"), m_scenarioPath));
    QVERIFY(QDir(m_folder.path()).mkpath(QStringLiteral("motion")));
    QVERIFY(QFile::copy(QStringLiteral(THESPIS_RESOURCES "/motion/cmu_standing.idle"),
                        m_folder.filePath(QStringLiteral("motion/cmu_standing.idle"))));
}

void BakePanelTest::init()
{
    QDir(bakesFolder()).removeRecursively();
    auto document = editor::Document::open(m_scenarioPath);
    QVERIFY2(document.ok(), document ? "" : document.error().message.c_str());
    m_session = std::make_unique<editor::Session>(&m_clock);
    m_session->setDocument(std::move(document).value());
    m_document = m_session->document();
    const core::scenario::Character* antigone = m_document->scenario().findCharacter("Antigone");
    QVERIFY(antigone);
    m_antigone = int(antigone - m_document->scenario().characters.data());
    m_panel = std::make_unique<editor::BakePanel>();
    m_panel->resize(420, 420);
    m_panel->setDocument(m_document);
    m_panel->setCurrentCharacter(m_antigone);
    m_panel->show();
    QCOMPARE(m_panel->currentCharacter(), m_antigone);
}

void BakePanelTest::cleanup()
{
    m_panel.reset();
    m_session.reset();
    m_document = nullptr;
}

void BakePanelTest::cancelledBakeChangesNothing()
{
    editor::BakePanel& panel = *m_panel;
    QCOMPARE(panel.currentBakeText(), QStringLiteral("none — unshadowed (DU)"));
    QVERIFY(!panel.cancelButton()->isEnabled());
    // ~1.2·10⁴ vertices × 4096 rays on one thread: many seconds of work on any machine.
    lighting::BakeSettings large = bakeSettings(5, 4096);
    large.threads = 1;
    panel.setSettings(large);
    const core::scenario::Scenario original = m_document->scenario();
    const int undoCount = m_document->undoStack()->count();
    QSignalSpy progress(panel.job(), &editor::JobRunner::progress);
    FinishedRecorder finished(panel.job());

    const auto started = std::chrono::steady_clock::now();
    QTest::mouseClick(panel.startButton(), Qt::LeftButton);
    QVERIFY(panel.isRunning());
    QVERIFY(!panel.startButton()->isEnabled());
    QVERIFY(panel.cancelButton()->isEnabled());
    QVERIFY(!panel.orderSpin()->isEnabled() && !panel.epsilonEdit()->isEnabled() && !panel.characterCombo()->isEnabled());
    QTRY_VERIFY_WITH_TIMEOUT(!progress.isEmpty() && progress.last().at(1).toLongLong() > 0, 60000);
    // A little further, so that the screenshot shows the bar moving (not required to pass).
    (void)QTest::qWaitFor([&] { return panel.progressBar()->value() * 10 >= panel.progressBar()->maximum(); }, 4000);
    QVERIFY(panel.isRunning()); // still baking: this bake takes well over a second
    const qint64 total = progress.last().at(2).toLongLong();
    QVERIFY(total > 1000);
    QCOMPARE(panel.progressBar()->maximum(), int(total));
    QVERIFY2(panel.progressBar()->text().contains(QStringLiteral(" vertices")) &&
                 panel.progressBar()->text().contains(QStringLiteral("% — ")),
             qPrintable(panel.progressBar()->text()));
    saveScreenshot(&panel, QStringLiteral("bake_panel_running.png"));

    QTest::mouseClick(panel.cancelButton(), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(finished.result.has_value(), 30000);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    QVERIFY2(seconds < 40, qPrintable(QString::number(seconds)));
    QCOMPARE(finished.count, 1);
    QVERIFY(!*finished.result);
    QCOMPARE(finished.result->error().code, core::ErrorCode::Cancelled);
    QVERIFY(QString::fromStdString(finished.result->error().message).contains(QStringLiteral("cancelled")));
    QVERIFY(!panel.isRunning());
    QVERIFY(panel.startButton()->isEnabled() && !panel.cancelButton()->isEnabled() && panel.orderSpin()->isEnabled());
    QVERIFY(m_document->scenario() == original);
    QCOMPARE(m_document->undoStack()->count(), undoCount);
    QVERIFY(!m_document->isModified());
    QVERIFY2(filesIn(bakesFolder()).isEmpty(), qPrintable(filesIn(bakesFolder()).join(u' ')));
    QCOMPARE(panel.statusText(), QStringLiteral("Cancelled — nothing changed."));
    QCOMPARE(panel.currentBakeText(), QStringLiteral("none — unshadowed (DU)"));
}

void BakePanelTest::completedBakeIsOneUndoStepTheSceneUses()
{
    editor::BakePanel& panel = *m_panel;
    // Order 4, not the viewport's unbaked DU order 3, so that the scene's use of it shows.
    panel.setSettings(bakeSettings(4, 64));
    QCOMPARE(panel.orderSpin()->value(), 4);
    QCOMPARE(panel.raysCombo()->currentData().toInt(), 64);
    const core::scenario::Scenario original = m_document->scenario();
    const int undoCount = m_document->undoStack()->count();
    QSignalSpy edited(m_document, &editor::Document::edited);
    FinishedRecorder finished(panel.job());
    // The studio's preview, a view of the session: it must rebuild its scene (keeping the time)
    // when a bake or the tags change, and only then.
    widgets::OsgViewport viewport; // never shown: no drawing, only the scene
    editor::ScenePreview preview(&viewport);
    preview.setSession(m_session.get());
    QVERIFY2(preview.problem().isEmpty(), qPrintable(preview.problem()));
    m_clock.setDuration(core::secondsToTicks(10));
    m_clock.seek(core::secondsToTicks(1.5));
    auto previewOrder = [&] { return preview.scene()->scene().character(std::size_t(m_antigone)).transferOrder(); };
    QCOMPARE(previewOrder(), 3);

    panel.start();
    QVERIFY(panel.isRunning());
    QTRY_VERIFY_WITH_TIMEOUT(finished.result.has_value(), 90000);
    QVERIFY2(*finished.result, finished.result->ok() ? "" : finished.result->error().message.c_str());
    QVERIFY(!panel.isRunning());

    // Exactly one undoable step, named after the character and the bake.
    QCOMPARE(m_document->undoStack()->count(), undoCount + 1);
    QCOMPARE(edited.count(), 1);
    QCOMPARE(m_document->undoStack()->undoText(), QStringLiteral("Bake Antigone (DSM, order 4)"));
    QVERIFY(m_document->isModified());
    const std::string bake = m_document->scenario().characters[std::size_t(m_antigone)].bake;
    const QRegularExpression name(QStringLiteral("^bakes/demo-Antigone-dsm-o4-[0-9a-f]{8}\\.prt$"));
    QVERIFY2(name.match(QString::fromStdString(bake)).hasMatch(), bake.c_str());
    core::scenario::Scenario expected = original;
    expected.characters[std::size_t(m_antigone)].bake = bake;
    QVERIFY(m_document->scenario() == expected); // nothing else changed
    const QString bakePath = QDir(m_folder.path()).absoluteFilePath(QString::fromStdString(bake));
    QVERIFY(QFileInfo::exists(bakePath));
    QCOMPARE(filesIn(bakesFolder()).size(), 1); // no temporary file left

    // The file reads back and fits the body the scene builds.
    const std::filesystem::path base = editor::toFsPath(m_folder.path());
    auto file = lighting::readBakeFile(base / bake);
    QVERIFY2(file.ok(), file.ok() ? "" : file.error().message.c_str());
    QCOMPARE(file->order, 4);
    QCOMPARE(file->raysPerVertex, 64);
    QCOMPARE(file->transferKind, lighting::TransferKind::DiffuseShadowedMerged);
    auto body = core::scenario::loadCharacterBody(m_document->scenario(), std::size_t(m_antigone), base);
    QVERIFY(body.ok());
    QVERIFY(lighting::checkBakeMatchesMesh(*file, body->mesh).ok());
    QCOMPARE(panel.job()->jobAs<lighting::TransferBakeJob>()->statistics.vertices, file->vertexCount); // the demo has no occluder segments
    QVERIFY(panel.job()->jobAs<lighting::TransferBakeJob>()->statistics.seconds > 0);

    auto scene = core::render::ScenarioScene::create(m_document->scenario(), base);
    QVERIFY(scene.ok());
    for (const std::string& warning : (*scene)->warnings())
        QVERIFY2(warning.find("bake") == std::string::npos, warning.c_str());
    QCOMPARE((*scene)->scene().character(std::size_t(m_antigone)).transferOrder(), 4);
    QCOMPARE(previewOrder(), 4);
    QCOMPARE(preview.scene()->time(), core::secondsToTicks(1.5));
    QVERIFY(preview.warnings().filter(QStringLiteral("bake")).isEmpty());

    const QString fileName = QFileInfo(QString::fromStdString(bake)).fileName();
    QVERIFY2(panel.currentBakeText() == fileName + QStringLiteral("\nDSM, order 4, 64 rays per vertex"), qPrintable(panel.currentBakeText()));
    QVERIFY2(panel.statusText().startsWith(QStringLiteral("Last bake: DSM, order 4, 64 rays per vertex — ")) &&
                 panel.statusText().contains(QStringLiteral("Mrays/s")),
             qPrintable(panel.statusText()));
    QCOMPARE(panel.progressBar()->value(), panel.progressBar()->maximum());
    saveScreenshot(&panel, QStringLiteral("bake_panel_done.png"));

    // Undo takes the bake away (the file stays, for redo); redo puts it back.
    m_document->undoStack()->undo();
    QVERIFY(m_document->scenario() == original);
    QCOMPARE(panel.currentBakeText(), QStringLiteral("none — unshadowed (DU)"));
    QCOMPARE(previewOrder(), 3);
    QVERIFY(QFileInfo::exists(bakePath));
    m_document->undoStack()->redo();
    QCOMPARE(m_document->scenario().characters[std::size_t(m_antigone)].bake, bake);
    QVERIFY(panel.currentBakeText().startsWith(fileName));
    QCOMPARE(previewOrder(), 4);
    // An edit of the schedules alone keeps the scene (no rebuild).
    const core::render::ScenarioScene* kept = preview.scene();
    QVERIFY(m_document->edit(core::edit::setLayerFlag(m_document->scenario(), {m_antigone, 0}, core::edit::LayerFlag::Mute, true),
                             QStringLiteral("Mute")));
    QCOMPARE(preview.scene(), kept);
    m_document->undoStack()->undo();
    QCOMPARE(preview.scene(), kept);

    // A tag edit that changes what shadows what makes the DSM bake stale: the panel says so and the
    // scene falls back to DU with a warning naming the character and the file.
    const std::vector<core::scene::SegmentTag> tags{{"hair", core::scene::SegmentRole::Receiver}};
    QVERIFY(m_document->edit(core::edit::setSegmentTags(m_document->scenario(), m_antigone, tags), QStringLiteral("Tag")));
    QVERIFY2(panel.currentBakeText().contains(QStringLiteral("stale")), qPrintable(panel.currentBakeText()));
    saveScreenshot(&panel, QStringLiteral("bake_panel_stale.png"));
    auto stale = core::render::ScenarioScene::create(m_document->scenario(), base);
    QVERIFY(stale.ok());
    QCOMPARE((*stale)->scene().character(std::size_t(m_antigone)).transferOrder(), 3);
    QCOMPARE(previewOrder(), 3); // rebuilt for the tags: the stale bake is left out
    QCOMPARE(preview.warnings().filter(QStringLiteral("Antigone: its bake")).size(), 1);
    QCOMPARE(preview.scene()->time(), core::secondsToTicks(1.5));
    bool warned = false;
    for (const std::string& warning : (*stale)->warnings())
        warned = warned || (warning.starts_with("Antigone: ") && warning.find(bake) != std::string::npos);
    QVERIFY(warned);
    m_document->undoStack()->undo();
    QVERIFY(!panel.currentBakeText().contains(QStringLiteral("stale")));
    QCOMPARE(previewOrder(), 4);

    // Saved into another folder, the scenario still names the same bake file.
    QVERIFY(QDir(m_folder.path()).mkpath(QStringLiteral("elsewhere")));
    QVERIFY(m_document->saveAs(m_folder.filePath(QStringLiteral("elsewhere/moved.thespis"))).ok());
    QCOMPARE(m_document->scenario().characters[std::size_t(m_antigone)].bake, "../" + bake);
    auto moved = core::render::ScenarioScene::create(m_document->scenario(), base / "elsewhere");
    QVERIFY(moved.ok());
    QCOMPARE((*moved)->scene().character(std::size_t(m_antigone)).transferOrder(), 4);
    QVERIFY(panel.currentBakeText().startsWith(fileName + u'\n'));
}

void BakePanelTest::bakeOfACharacterEditedMeanwhileIsThrownAway()
{
    editor::BakePanel& panel = *m_panel;
    panel.setSettings(bakeSettings(2, 16));
    FinishedRecorder finished(panel.job());
    panel.start();
    QVERIFY(panel.isRunning());
    // The result can only arrive through the event loop, so this edit lands while it bakes.
    const std::vector<core::scene::SegmentTag> tags{{"hair", core::scene::SegmentRole::Receiver}};
    QVERIFY(m_document->edit(core::edit::setSegmentTags(m_document->scenario(), m_antigone, tags), QStringLiteral("Tag")));
    const core::scenario::Scenario tagged = m_document->scenario();
    QTRY_VERIFY_WITH_TIMEOUT(finished.result.has_value(), 60000);
    QVERIFY(!panel.isRunning());
    QVERIFY(m_document->scenario() == tagged); // the bake was not applied
    QCOMPARE(m_document->undoStack()->count(), 1);
    QVERIFY2(panel.statusText().contains(QStringLiteral("changed while baking")), qPrintable(panel.statusText()));
    QVERIFY2(filesIn(bakesFolder()).isEmpty(), qPrintable(filesIn(bakesFolder()).join(u' ')));
}

void BakePanelTest::badEpsilonStartsNothing()
{
    editor::BakePanel& panel = *m_panel;
    const int undoCount = m_document->undoStack()->count();
    QSignalSpy progress(panel.job(), &editor::JobRunner::progress);
    for (const QString& text : {QStringLiteral("-1"), QStringLiteral("abc"), QStringLiteral("nan"), QStringLiteral("5")}) {
        panel.epsilonEdit()->setText(text);
        QVERIFY(!panel.settings().ok());
        panel.start();
        QVERIFY(!panel.isRunning());
        QVERIFY2(panel.statusText().contains(QStringLiteral("ε")) && panel.statusText().contains(text) &&
                     panel.statusText().contains(QStringLiteral("metres")),
                 qPrintable(panel.statusText()));
        QVERIFY(panel.startButton()->isEnabled());
    }
    QVERIFY(progress.isEmpty());
    QCOMPARE(m_document->undoStack()->count(), undoCount);
    QVERIFY(filesIn(bakesFolder()).isEmpty());
    // Good values are taken, in metres.
    panel.epsilonEdit()->setText(QStringLiteral("2.5e-3"));
    auto settings = panel.settings();
    QVERIFY(settings.ok());
    QCOMPARE(settings->epsilon, 2.5e-3f);
    panel.epsilonEdit()->setText(QString());
    QCOMPARE(panel.settings()->epsilon, 1.71e-4f); // empty: the default
}

void BakePanelTest::unwritableFolderIsRefused()
{
    // A folder that cannot be made (a file is in the way), whoever runs the test.
    QFile blocker(m_folder.filePath(QStringLiteral("not_a_folder")));
    QVERIFY(blocker.open(QIODevice::WriteOnly));
    blocker.close();
    const QString inside = blocker.fileName() + QStringLiteral("/inside");
    // Its files named absolutely (no path goes through the file in the way).
    core::scenario::Scenario moved = m_document->scenario();
    for (core::scenario::Character& character : moved.characters)
        for (core::scenario::ClipAsset& clip : character.clips)
            if (clip.idle)
                clip.idle->database = (editor::toFsPath(m_folder.path()) / clip.idle->database).string();
    auto document = editor::Document::fromScenario(std::move(moved), inside);
    QVERIFY(document.ok());
    m_panel->setDocument(document->get());
    m_panel->setCurrentCharacter(m_antigone);
    m_panel->setSettings(bakeSettings(2, 16));
    m_panel->start();
    QVERIFY(!m_panel->isRunning());
    QVERIFY2(m_panel->statusText().startsWith(QStringLiteral("Save the scenario in a folder you can write to first: ")) &&
                 m_panel->statusText().contains(QStringLiteral("inside")),
             qPrintable(m_panel->statusText()));
    QCOMPARE((*document)->undoStack()->count(), 0);
    m_panel->setDocument(nullptr);
    QVERIFY(!m_panel->startButton()->isEnabled());
}

void BakePanelTest::prtToggleEmitsOnlyForTheUser()
{
    editor::BakePanel& panel = *m_panel;
    QSignalSpy toggled(&panel, &editor::BakePanel::prtPreviewToggled);
    QVERIFY(panel.prtPreview());
    panel.setPrtPreview(false);
    QVERIFY(!panel.prtPreview());
    QVERIFY(toggled.isEmpty());
    QTest::mouseClick(panel.prtPreviewCheck(), Qt::LeftButton, {}, QPoint(8, panel.prtPreviewCheck()->height() / 2));
    QCOMPARE(toggled.count(), 1);
    QCOMPARE(toggled.first().at(0).toBool(), true);
    QVERIFY(panel.prtPreview());
}

void BakePanelTest::destroyingARunningJobCancelsIt()
{
    auto body = core::scenario::loadCharacterBody(m_document->scenario(), std::size_t(m_antigone),
                                                  editor::toFsPath(m_folder.path()));
    QVERIFY(body.ok());
    QDir().mkpath(bakesFolder());
    const QString path = QDir(bakesFolder()).filePath(QStringLiteral("destroyed.prt"));
    auto bakeJob = [&](const lighting::BakeSettings& settings) {
        auto bake = std::make_unique<lighting::TransferBakeJob>();
        bake->mesh = body->mesh;
        bake->settings = settings;
        bake->output = editor::toFsPath(path);
        return bake;
    };
    auto job = std::make_unique<editor::JobRunner>();
    FinishedRecorder finished(job.get());
    // Refused without starting: bad settings, a second start.
    QVERIFY(!job->start(bakeJob(bakeSettings(0, 64))).ok());
    QVERIFY(!job->isRunning());
    QSignalSpy progress(job.get(), &editor::JobRunner::progress);
    lighting::BakeSettings large = bakeSettings(5, 4096);
    large.threads = 1;
    QVERIFY(job->start(bakeJob(large)).ok());
    QVERIFY(!job->start(bakeJob(bakeSettings(2, 16))).ok());
    QTRY_VERIFY_WITH_TIMEOUT(!progress.isEmpty(), 60000);
    QVERIFY(job->isRunning());
    const auto before = std::chrono::steady_clock::now();
    job.reset(); // cancels and joins
    QVERIFY(std::chrono::steady_clock::now() - before < std::chrono::seconds(10));
    QCoreApplication::processEvents();
    QCOMPARE(finished.count, 0);
    QVERIFY2(filesIn(bakesFolder()).isEmpty(), qPrintable(filesIn(bakesFolder()).join(u' ')));
}

QTEST_MAIN(BakePanelTest)
#include "bake_panel_test.moc"
