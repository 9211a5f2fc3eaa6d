// Bringing your own content, as a new user would, on the real window: File ▸ New (empty), add
// the built-in humanoid and a glTF character through Character ▸ Add Character…, import two CMU
// files through File ▸ Import Motion… (the file dialog driven by the test), drop clips on tracks,
// pick a light probe, save, reopen and render headless — the characters stand on the ground at
// their size — then undo everything back to the empty document. Also: a file that does not
// parse adds nothing, a corrected mapping, files dropped from the file manager on a track, the
// Messages dock. Each step leaves a screenshot.

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDialog>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QMimeData>
#include <QPushButton>
#include <QRegularExpression>
#include <QSettings>
#include <QSlider>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QSignalSpy>
#include <QTest>
#include <QTimer>
#include <QTreeView>
#include <QTreeWidget>
#include <QUndoStack>
#include <QUrl>

#include <functional>

#include "editor/content_actions.h"
#include "gui_support.h"
#include "editor/character_dialog.h"
#include "editor/character_properties.h"
#include "editor/document.h"
#include "editor/import_motion_dialog.h"
#include "editor/lighting_dialog.h"
#include "editor/scene_preview.h"
#include "editor/messages_panel.h"
#include "editor/properties_panel.h"
#include "editor/scenario_tree_model.h"
#include "editor/timeline_panel.h"
#include "editor/translations.h"
#include "main_window.h"
#include "render/offscreen_renderer.h"
#include "render/scenario_scene.h"
#include "scenario/scenario_io.h"
#include "widgets/timeline_view.h"

using namespace thespis;
using test::saveScreenshot;
using test::whenModal;

namespace {

QString shared(const QString& relative)
{
    return QStringLiteral(THESPIS_SHARED_DATA "/") + relative;
}

int trackOf(widgets::TimelineView* view, const QString& character, const QString& layer)
{
    for (int t = 0; t < view->tracks().size(); ++t)
        if (view->tracks()[t].group == character && view->tracks()[t].name == layer)
            return t;
    return -1;
}

// Drops `mime` on a track of the timeline at `seconds`, as Qt's drag and drop delivers it.
void dropOnTrack(widgets::TimelineView* view, int track, double seconds, QMimeData* mime)
{
    const QPoint at(view->xForTime(qint64(seconds * core::TicksPerSecond)), view->trackRect(track).center().y());
    QDragEnterEvent enter(at, Qt::CopyAction, mime, Qt::LeftButton, {});
    QApplication::sendEvent(view->viewport(), &enter);
    QDragMoveEvent move(at, Qt::CopyAction, mime, Qt::LeftButton, {});
    QApplication::sendEvent(view->viewport(), &move);
    QDropEvent drop(at, Qt::CopyAction, mime, Qt::LeftButton, {});
    QApplication::sendEvent(view->viewport(), &drop);
}

/// Chooses a probe in the Lighting dialog and waits for it to be read off the GUI thread:
/// whether it could be used.
bool chooseProbe(editor::LightingDialog* dialog, const QString& path)
{
    QSignalSpy loaded(dialog, &editor::LightingDialog::loaded);
    dialog->setProbeFile(path);
    if (!loaded.wait(60000))
        return false;
    return !dialog->isLoading() && loaded.count() == 1 && loaded.last().at(0).toBool();
}

} // namespace

class BringContentTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void init();
    void cleanup();
    void fromNothingToARenderedScenarioAndBack();
    void aBrokenFileAddsNothingAndAMappingCanBeCorrected();
    void filesDroppedOnATrackImportAndPlayThere();

private:
    void selectCharacter(int character);
    std::unique_ptr<studio::MainWindow> m_window;
    QTemporaryDir m_dir;
};

void BringContentTest::initTestCase()
{
    editor::installTranslators(*QCoreApplication::instance(), QLocale(QLocale::English));
}

void BringContentTest::init()
{
    QStandardPaths::setTestModeEnabled(true);
    QSettings().clear();
    m_window = std::make_unique<studio::MainWindow>();
    m_window->resize(1500, 950);
    m_window->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
}

void BringContentTest::cleanup()
{
    m_window.reset();
}

void BringContentTest::selectCharacter(int character)
{
    m_window->selectCharacter(character);
    QApplication::processEvents();
}

void BringContentTest::fromNothingToARenderedScenarioAndBack()
{
    // File ▸ New, "Empty".
    whenModal<QMessageBox>([](QMessageBox* box) {
        box->findChild<QPushButton*>(QStringLiteral("newEmpty"))->click();
    }, QStringLiteral("content_0_new.png"));
    m_window->findChild<QAction*>(QStringLiteral("newScenario"))->trigger();
    QTRY_VERIFY(m_window->document() != nullptr);
    QTRY_VERIFY(m_window->document()->scenario().characters.empty());
    QTRY_VERIFY(QApplication::activeModalWidget() == nullptr);
    editor::Document* document = m_window->document();
    const core::scenario::Scenario empty = document->scenario();
    editor::ContentActions* content = m_window->contentActions();
    QVERIFY(!content->importMotionAction()->isEnabled()); // nothing to import into yet

    // Character ▸ Add Character…: the built-in humanoid, the paper's 25 joints.
    whenModal<editor::CharacterDialog>([](editor::CharacterDialog* dialog) {
        dialog->nameEdit()->setText(QStringLiteral("Walker"));
        dialog->levelChoice()->setCurrentIndex(1);
        dialog->accept();
    }, QStringLiteral("content_1_add_humanoid.png"));
    content->addCharacterAction()->trigger();
    QTRY_COMPARE(int(document->scenario().characters.size()), 1);
    QCOMPARE(document->scenario().characters[0].name, std::string("Walker"));
    QCOMPARE(document->scenario().characters[0].skeleton, std::string("hanim-25"));

    // …and a glTF character, RobotExpressive, with its own animations as clips.
    whenModal<editor::CharacterDialog>([](editor::CharacterDialog* dialog) {
        dialog->setModelFile(shared(QStringLiteral("characters/RobotExpressive/RobotExpressive.glb")));
        QVERIFY(dialog->importClipsCheck()->isChecked());
        QCOMPARE(int(dialog->clips().size()), 14);
        saveScreenshot(dialog, QStringLiteral("content_2_add_robot.png"));
        dialog->accept();
    });
    content->addCharacterAction()->trigger();
    QTRY_COMPARE(int(document->scenario().characters.size()), 2);
    const auto& robot = document->scenario().characters[1];
    QCOMPARE(robot.name, std::string("RobotExpressive"));
    QCOMPARE(robot.skeleton, std::string("model"));
    QCOMPARE(int(robot.clips.size()), 14);
    QVERIFY(!robot.model.empty() && robot.model.front() != '/'); // relative to the scenario's folder

    // Place the robot beside the walker, facing it a little (Properties of the character).
    selectCharacter(1);
    QVERIFY(m_window->properties()->characterPage()->isVisible());
    m_window->properties()->characterPage()->positionEdit(0)->setValue(2.5);
    m_window->properties()->characterPage()->headingEdit()->setValue(-30.0);
    QCOMPARE(document->scenario().characters[1].position.x, 2.5f);
    QCOMPARE(document->scenario().characters[1].heading, -30.0);
    QApplication::processEvents();
    saveScreenshot(m_window.get(), QStringLiteral("content_2_placed_robot.png"));

    // File ▸ Import Motion… into the walker: the file dialog picks two CMU files, the report
    // shows what was found, Import adds both.
    selectCharacter(0);
    whenModal<QFileDialog>([](QFileDialog* files) {
        files->setDirectory(shared(QStringLiteral("mocap/cmu")));
        // Typed as a user would: two names in quotes in the "File name" field.
        files->findChild<QLineEdit*>(QStringLiteral("fileNameEdit"))
            ->setText(QStringLiteral("\"02_01.bvh\" \"141_16.bvh\""));
        saveScreenshot(files, QStringLiteral("content_3_file_dialog.png"));
        QMetaObject::invokeMethod(files, "accept");
    });
    whenModal<editor::ImportMotionDialog>([](editor::ImportMotionDialog* dialog) {
        QCOMPARE(dialog->characterChoice()->currentText(), QStringLiteral("Walker"));
        QCOMPARE(dialog->fileTree()->topLevelItemCount(), 2);
        QVERIFY(dialog->reportLabel()->text().contains(QStringLiteral("CMU")));
        QVERIFY(dialog->mappingTable()->rowCount() >= 31);
        QCOMPARE(dialog->clipNames(), (QStringList{QStringLiteral("02_01"), QStringLiteral("141_16")}));
        saveScreenshot(dialog, QStringLiteral("content_4_import_report.png"));
        dialog->importButton()->click();
    });
    content->importMotionAction()->trigger();
    QTRY_COMPARE(int(document->scenario().characters[0].clips.size()), 2);
    QCOMPARE(document->undoStack()->undoText(), QStringLiteral("Import 2 Clips"));

    // A gestures layer for the walker (Character ▸ Add Body Layer), then drop clips on tracks.
    for (QAction* action : m_window->findChildren<QAction*>())
        if (action->objectName() == QStringLiteral("addBodyLayer"))
            action->trigger();
    QCOMPARE(int(document->scenario().characters[0].layers.size()), 3);
    widgets::TimelineView* view = m_window->timeline()->view();
    qobject_cast<QDockWidget*>(m_window->timeline()->parentWidget())->raise();
    view->setPixelsPerSecond(60);
    QApplication::processEvents();
    const auto dropClip = [&](const QString& character, const QString& layer, const QString& clip, double at) {
        auto mime = std::make_unique<QMimeData>();
        mime->setData(QString::fromLatin1(widgets::TimelineView::ClipMimeType), clip.toUtf8());
        const int track = trackOf(view, character, layer);
        QVERIFY2(track >= 0, qPrintable(character + QLatin1Char('/') + layer));
        dropOnTrack(view, track, at, mime.get());
    };
    dropClip(QStringLiteral("Walker"), QStringLiteral("body"), QStringLiteral("02_01"), 0.0);
    dropClip(QStringLiteral("Walker"), QStringLiteral("body 2"), QStringLiteral("141_16"), 0.5);
    dropClip(QStringLiteral("RobotExpressive"), QStringLiteral("body"), QStringLiteral("Walking"), 0.0);
    QCOMPARE(int(document->scenario().characters[0].layers[0].actions.size()), 1);
    QCOMPARE(int(document->scenario().characters[0].layers[2].actions.size()), 1);
    QCOMPARE(int(document->scenario().characters[1].layers[0].actions.size()), 1);
    QCOMPARE(document->scenario().characters[0].layers[0].actions[0].placement, core::scenario::Placement::Continue);

    // View ▸ Lighting…: a probe, turned.
    whenModal<editor::LightingDialog>([](editor::LightingDialog* dialog) {
        QVERIFY(chooseProbe(dialog, shared(QStringLiteral("probes/polyhaven_1k/venice_sunset_1k.hdr"))));
        dialog->rotationSlider()->setValue(120);
        QVERIFY(!dialog->probePicture()->pixmap().isNull());
        QVERIFY(!dialog->lightPicture()->pixmap().isNull());
        saveScreenshot(dialog, QStringLiteral("content_5_lighting.png"));
        dialog->accept();
    });
    content->lightingAction()->trigger();
    QTRY_COMPARE(document->scenario().lighting.rotation, 120.0);
    QVERIFY(document->scenario().lighting.probe.ends_with("venice_sunset_1k.hdr"));
    // The 3D view projects the probe off the GUI thread, then lights the scene with it.
    if (editor::ScenePreview* preview = m_window->scenePreview()) {
        QTRY_VERIFY_WITH_TIMEOUT(!preview->isLightLoading(), 60000);
        QVERIFY2(preview->warnings().filter(QStringLiteral("probe")).isEmpty(), qPrintable(preview->warnings().join(u'\n')));
    }
    m_window->clock()->seek(core::secondsToTicks(1.0));
    QApplication::processEvents();
    saveScreenshot(m_window.get(), QStringLiteral("content_6_built.png"));

    // Save; the file reads back as the same document.
    const QString path = m_dir.filePath(QStringLiteral("mine.thespis"));
    QVERIFY(m_window->saveAs(path));
    const core::scenario::Scenario saved = document->scenario();
    auto reread = core::scenario::loadScenario(path.toStdString());
    QVERIFY(reread.ok());
    QVERIFY(*reread == saved);
    QVERIFY(m_window->messagesPanel()->count() >= 1); // what the robot's model brought (its IK feet …)

    // Render headless from the saved file: everyone on the ground, at their own size.
    auto scene = core::render::ScenarioScene::create(*reread, std::filesystem::path(m_dir.path().toStdString()));
    QVERIFY2(scene.ok(), scene.ok() ? "" : scene.error().message.c_str());
    (*scene)->playAt(core::secondsToTicks(-1.0));
    std::vector<double> restHeight;
    for (std::size_t c = 0; c < (*scene)->scene().characterCount(); ++c) {
        const auto b = (*scene)->scene().character(c).bounds();
        restHeight.push_back(b.max.y - b.min.y);
    }
    for (double t : {0.5, 1.5, 2.5}) {
        (*scene)->playAt(core::secondsToTicks(t));
        for (std::size_t c = 0; c < (*scene)->scene().characterCount(); ++c) {
            const auto b = (*scene)->scene().character(c).bounds();
            const double cm = std::max(restHeight[c], 1.8) / 180.0;
            QVERIFY2(b.min.y > -4 * cm && b.min.y < 6 * cm,
                     qPrintable(QStringLiteral("t %1, character %2: lowest %3").arg(t).arg(c).arg(b.min.y)));
            QVERIFY(b.max.y - b.min.y > 0.8 * restHeight[c] && b.max.y - b.min.y < 1.15 * restHeight[c]);
        }
    }
    if (auto renderer = core::render::OffscreenRenderer::create(960, 540, 4)) {
        (*scene)->playAt(core::secondsToTicks(1.5));
        const auto camera = core::render::frameBounds((*scene)->boundsOverTimeline(), 20.0, 8.0, 960.0 / 540.0, 40.0);
        if (auto picture = (*renderer)->render((*scene)->scene(), camera))
            QVERIFY(core::render::writePng(THESPIS_SCREENSHOT_DIR "/content_7_rendered.png", *picture).ok());
    }

    // Undo everything, step by step: the empty scenario again. Redo it all: the saved one.
    QUndoStack* undo = document->undoStack();
    const int steps = undo->index();
    // Two characters, move and turn, the import, a layer, three drops, the light.
    QCOMPARE(steps, 10);
    while (undo->canUndo())
        undo->undo();
    QVERIFY(document->scenario() == empty);
    saveScreenshot(m_window.get(), QStringLiteral("content_undone.png"));
    while (undo->canRedo())
        undo->redo();
    QVERIFY(document->scenario() == saved);

    // And the file opens in the studio.
    QVERIFY(m_window->openScenario(path));
    QVERIFY(m_window->document()->scenario() == saved);
}

void BringContentTest::aBrokenFileAddsNothingAndAMappingCanBeCorrected()
{
    m_window->newScenario(true);
    editor::Document* document = m_window->document();
    QCOMPARE(int(document->scenario().characters.size()), 1);
    const QString broken = m_dir.filePath(QStringLiteral("broken.bvh"));
    QFile file(broken);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("HIERARCHY\nROOT Hips\n{\n  OFFSET 0 0\n");
    file.close();
    const core::scenario::Scenario before = document->scenario();

    whenModal<editor::ImportMotionDialog>([broken](editor::ImportMotionDialog* dialog) {
        QCOMPARE(dialog->fileTree()->topLevelItemCount(), 3);
        // The broken file: its reader's words, nothing to import from it.
        dialog->fileTree()->setCurrentItem(dialog->fileTree()->topLevelItem(0));
        QVERIFY2(dialog->reportLabel()->text().contains(QStringLiteral("broken.bvh, line 4")),
                 qPrintable(dialog->reportLabel()->text()));
        // The CMU wave: take the left arm out of the mapping.
        dialog->fileTree()->setCurrentItem(dialog->fileTree()->topLevelItem(1));
        QTableWidget* table = dialog->mappingTable();
        for (int row = 0; row < table->rowCount(); ++row)
            if (table->item(row, 0)->text() == QStringLiteral("LeftArm"))
                table->item(row, 1)->setText(QString());
        dialog->applyMappingButton()->click();
        // The file's LeftArm keeps its name; the character's left shoulder is left at rest.
        QVERIFY(dialog->reportLabel()->text().contains(QStringLiteral("LeftArm")));
        QVERIFY2(dialog->reportLabel()->text().contains(QRegularExpression(QStringLiteral("leaves at rest: [^<]*l_shoulder"))),
                 qPrintable(dialog->reportLabel()->text()));
        QVERIFY(dialog->saveMapping(QFileInfo(broken).dir().filePath(QStringLiteral("wave.map"))));
        saveScreenshot(dialog, QStringLiteral("content_8_broken_and_mapping.png"));
        // MakeHuman's walk: its jaw, tongue and eyes move nothing of a 25-joint body.
        dialog->fileTree()->setCurrentItem(dialog->fileTree()->topLevelItem(2));
        QVERIFY2(dialog->reportLabel()->text().contains(QStringLiteral("nothing of this character")),
                 qPrintable(dialog->reportLabel()->text()));
        QCOMPARE(dialog->clipNames(), (QStringList{QStringLiteral("141_16"), QStringLiteral("walk1")}));
        dialog->importButton()->click();
    });
    QVERIFY(m_window->contentActions()->importFiles(
        {broken, shared(QStringLiteral("mocap/cmu/141_16.bvh")), shared(QStringLiteral("mocap/makehuman/walk1.bvh"))}, 0));
    const auto& clips = document->scenario().characters[0].clips;
    QCOMPARE(int(clips.size()), int(before.characters[0].clips.size()) + 2);
    const core::scenario::ClipAsset& wave = clips[clips.size() - 2];
    QCOMPARE(wave.name, std::string("141_16"));
    QVERIFY(!wave.mapping.empty());
    QVERIFY(wave.mapping.count("LeftArm") == 0);
    QVERIFY(QFile::exists(m_dir.filePath(QStringLiteral("wave.map"))));
    // The Messages dock tells what the file brought, and shows its clip on a double-click.
    editor::MessagesPanel* messages = m_window->messagesPanel();
    QCOMPARE(messages->count(), 1);
    QVERIFY2(messages->item(0)->text().contains(QStringLiteral("clip \"walk1\": 18 joints")),
             qPrintable(messages->item(0)->text()));
    emit messages->itemActivated(messages->item(0));
    qobject_cast<QDockWidget*>(messages->parentWidget())->raise();
    QApplication::processEvents();
    saveScreenshot(m_window.get(), QStringLiteral("content_9_messages.png"));

    // A probe that cannot be read keeps the one before and says why; the light is unchanged.
    const core::scenario::LightingSpec light = document->scenario().lighting;
    whenModal<editor::LightingDialog>([broken](editor::LightingDialog* dialog) {
        QVERIFY(chooseProbe(dialog, shared(QStringLiteral("probes/polyhaven_1k/venice_sunset_1k.hdr"))));
        QVERIFY(!chooseProbe(dialog, broken));
        QVERIFY(dialog->lighting().probe.ends_with("venice_sunset_1k.hdr"));
        QVERIFY2(dialog->messageLabel()->text().contains(QStringLiteral("broken.bvh")),
                 qPrintable(dialog->messageLabel()->text()));
        QVERIFY(!dialog->probePicture()->pixmap().isNull());
        dialog->reject();
    });
    m_window->contentActions()->lightingAction()->trigger();
    QVERIFY(document->scenario().lighting == light);
}

void BringContentTest::filesDroppedOnATrackImportAndPlayThere()
{
    m_window->newScenario(true);
    editor::Document* document = m_window->document();
    widgets::TimelineView* view = m_window->timeline()->view();
    qobject_cast<QDockWidget*>(m_window->timeline()->parentWidget())->raise();
    view->setPixelsPerSecond(60);
    QApplication::processEvents();
    whenModal<editor::ImportMotionDialog>([](editor::ImportMotionDialog* dialog) { dialog->importButton()->click(); });
    auto mime = std::make_unique<QMimeData>();
    mime->setUrls({QUrl::fromLocalFile(shared(QStringLiteral("mocap/cmu/02_01.bvh")))});
    dropOnTrack(view, trackOf(view, QStringLiteral("Actor"), QStringLiteral("body")), 4.0, mime.get());
    QTRY_COMPARE(int(document->scenario().characters[0].clips.size()), 2);
    const auto& actions = document->scenario().characters[0].layers[0].actions;
    QCOMPARE(int(actions.size()), 2);
    QCOMPARE(actions.back().clip, std::string("02_01"));
    QVERIFY(std::abs(core::ticksToSeconds(actions.back().start) - 4.0) < 0.05);
    // One undo step takes both the clip and the action away.
    document->undoStack()->undo();
    QCOMPARE(int(document->scenario().characters[0].clips.size()), 1);
    QCOMPARE(int(document->scenario().characters[0].layers[0].actions.size()), 1);
}

QTEST_MAIN(BringContentTest)
#include "bring_content_test.moc"
