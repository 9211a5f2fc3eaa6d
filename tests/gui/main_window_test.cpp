// The studio window on the built-in demo scenario: it lists the document's characters and
// actions, plays with Space, seeks with the transport slider, reports a malformed file without
// crashing, and leaves a screenshot in the build folder for people to look at.

#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QLabel>
#include <QMenu>
#include <QMessageBox>
#include <QSlider>
#include <QStyle>
#include <QStatusBar>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTreeView>

#include "editor/scenario_tree_model.h"
#include "editor/translations.h"
#include "fixture_scenario.h"
#include "main_window.h"
#include "scenario/scenario_io.h"
#include "widgets/osg_viewport.h"
#include "widgets/pose_view.h"
#include "widgets/transport_bar.h"

using thespis::editor::ScenarioTreeModel;
using thespis::studio::MainWindow;

namespace {

// Every joint of every figure, flattened, to compare poses.
std::vector<QVector3D> allPositions(const thespis::widgets::PoseView& view)
{
    std::vector<QVector3D> all;
    for (int f = 0; f < view.figureCount(); ++f)
        for (const QVector3D& p : view.figurePositions(f))
            all.push_back(p);
    return all;
}

float largestDifference(const std::vector<QVector3D>& a, const std::vector<QVector3D>& b)
{
    float largest = a.size() == b.size() ? 0.0f : std::numeric_limits<float>::infinity();
    for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i)
        largest = std::max(largest, (a[i] - b[i]).length());
    return largest;
}

} // namespace

class MainWindowTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void showsTheScenarioInTitleAndStatusBar();
    void outlineListsCharactersAndActions();
    void spacePlaysAndPauses();
    void sliderSeeks();
    void malformedScenarioReportsAnError();
    void missingScenarioReportsAnError();
    void viewportShowsTheCharactersLit();
    void viewMenuClosesUpOnAFace();
    void savesAScreenshot();
    void cleanupTestCase();

private:
    QMessageBox* waitForErrorBox();

    std::unique_ptr<MainWindow> m_window;
    QString m_scenarioPath;
    QTemporaryDir m_temp;
};

void MainWindowTest::initTestCase()
{
    QVERIFY(m_temp.isValid());
    thespis::editor::installTranslators(*QCoreApplication::instance(), QLocale(QLocale::English));
    // The built-in demo when it is there; else the fixture, written as a file so the window
    // opens it exactly as a user's file.
    m_scenarioPath = QStringLiteral(THESPIS_RESOURCES "/demo.thespis");
    if (!QFileInfo::exists(m_scenarioPath)) {
        qWarning("no resources/demo.thespis; using the test fixture scenario");
        m_scenarioPath = m_temp.filePath(QStringLiteral("fixture.thespis"));
        auto saved = thespis::core::scenario::saveScenario(m_scenarioPath.toStdString(), thespis::test::makeFixtureScenario());
        QVERIFY2(saved.ok(), saved.ok() ? "" : thespis::core::describe(saved.error()).c_str());
    }
    m_window = std::make_unique<MainWindow>();
    // The same size on every platform (the default depends on the screen, which is small on
    // the offscreen platform), so that the drags below hit the same places.
    m_window->resize(1440, 860);
    m_window->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
    QVERIFY(m_window->openScenario(m_scenarioPath));
    QVERIFY(m_window->document());
}

void MainWindowTest::showsTheScenarioInTitleAndStatusBar()
{
    const auto& scenario = m_window->document()->scenario();
    QVERIFY(!scenario.characters.empty());
    // "[*]" is where Qt shows the unsaved-changes mark.
    QCOMPARE(m_window->windowTitle(), QString::fromStdString(scenario.name) + QStringLiteral("[*] — Thespis Studio"));
    QVERIFY(!m_window->isWindowModified());
    auto* fileLabel = m_window->findChild<QLabel*>(QStringLiteral("fileLabel"));
    QVERIFY(fileLabel);
    QCOMPARE(fileLabel->text(), QFileInfo(m_scenarioPath).fileName());
    QVERIFY(m_window->statusBar()->currentMessage().contains(QStringLiteral("Press Space to play")));
    QCOMPARE(m_window->poseView()->figureCount(), int(scenario.characters.size()));
    QCOMPARE(m_window->transportBar()->duration(), thespis::core::ticksToSeconds(m_window->document()->previewDuration()));
}

void MainWindowTest::outlineListsCharactersAndActions()
{
    const auto& scenario = m_window->document()->scenario();
    QAbstractItemModel* model = m_window->outlineView()->model();
    QCOMPARE(model->rowCount(), int(scenario.characters.size()));
    int actions = 0;
    for (int c = 0; c < int(scenario.characters.size()); ++c) {
        const auto& character = scenario.characters[std::size_t(c)];
        const QModelIndex characterIndex = model->index(c, ScenarioTreeModel::NameColumn);
        QCOMPARE(characterIndex.data().toString(), QString::fromStdString(character.name));
        QCOMPARE(model->rowCount(characterIndex), int(character.layers.size()));
        for (int l = 0; l < int(character.layers.size()); ++l) {
            const auto& layer = character.layers[std::size_t(l)];
            const QModelIndex layerIndex = model->index(l, 0, characterIndex);
            QCOMPARE(model->rowCount(layerIndex), int(layer.actions.size()));
            for (int a = 0; a < int(layer.actions.size()); ++a) {
                const auto& action = layer.actions[std::size_t(a)];
                QCOMPARE(model->index(a, ScenarioTreeModel::NameColumn, layerIndex).data().toString(),
                         QString::fromStdString(action.name));
                QCOMPARE(model->index(a, ScenarioTreeModel::ClipColumn, layerIndex).data().toString(),
                         QString::fromStdString(action.clip));
                QCOMPARE(model->index(a, ScenarioTreeModel::StartColumn, layerIndex).data().toString(),
                         QString::number(thespis::core::ticksToSeconds(action.start), 'f', 3));
                ++actions;
            }
            // The outline starts expanded: every action is visible without clicking.
            QVERIFY(m_window->outlineView()->isExpanded(layerIndex));
        }
    }
    QVERIFY(actions > 0);
}

void MainWindowTest::spacePlaysAndPauses()
{
    thespis::editor::PlaybackClock* clock = m_window->clock();
    clock->seek(0);
    const std::vector<QVector3D> before = allPositions(*m_window->poseView());
    QVERIFY(!before.empty());

    // Space plays whichever panel has the focus; here the outline, which uses Space itself.
    m_window->activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(m_window.get()));
    m_window->outlineView()->setFocus();
    QTest::keyClick(m_window->outlineView(), Qt::Key_Space);
    QVERIFY(clock->isPlaying());
    QVERIFY(m_window->transportBar()->isPlaying());
    QTest::qWait(600);
    QVERIFY2(clock->time() > thespis::core::secondsToTicks(0.3), qPrintable(QString::number(clock->time())));
    const std::vector<QVector3D> during = allPositions(*m_window->poseView());
    QVERIFY2(largestDifference(before, during) > 1e-4f, "the figures should move while playing");
    // The transport shows the clock's time.
    QCOMPARE(m_window->transportBar()->time(), thespis::core::ticksToSeconds(clock->time()));
    auto* fps = m_window->findChild<QLabel*>(QStringLiteral("fpsLabel"));
    // The rate is measured over the frames of a while: on a loaded machine it shows later.
    QTRY_VERIFY2_WITH_TIMEOUT(fps->text().contains(QStringLiteral("fps")), qPrintable(fps->text()), 10000);

    QTest::keyClick(m_window->outlineView(), Qt::Key_Space);
    QVERIFY(!clock->isPlaying());
    QVERIFY(!m_window->transportBar()->isPlaying());
    const thespis::core::Tick paused = clock->time();
    QTest::qWait(100);
    QCOMPARE(clock->time(), paused);
    QCOMPARE(fps->text(), QStringLiteral("Paused"));
}

void MainWindowTest::sliderSeeks()
{
    auto* slider = m_window->transportBar()->findChild<QSlider*>(QStringLiteral("timeSlider"));
    QVERIFY(slider);
    m_window->clock()->seek(0);
    const std::vector<QVector3D> atStart = allPositions(*m_window->poseView());

    // Drag the handle from the start to about 60 % of the groove.
    const int margin = slider->style()->pixelMetric(QStyle::PM_SliderLength, nullptr, slider) / 2;
    const QPoint from(margin, slider->height() / 2);
    const QPoint to(margin + int(0.6 * (slider->width() - 2 * margin)), slider->height() / 2);
    QTest::mousePress(slider, Qt::LeftButton, {}, from);
    for (int step = 1; step <= 6; ++step)
        QTest::mouseMove(slider, from + (to - from) * step / 6);
    QTest::mouseRelease(slider, Qt::LeftButton, {}, to);

    const double duration = thespis::core::ticksToSeconds(m_window->document()->previewDuration());
    const double time = thespis::core::ticksToSeconds(m_window->clock()->time());
    QVERIFY2(std::abs(time - 0.6 * duration) < 0.05 * duration,
             qPrintable(QStringLiteral("seeked to %1 of %2 s").arg(time).arg(duration)));
    QVERIFY(!m_window->clock()->isPlaying());
    QCOMPARE(m_window->transportBar()->time(), time);
    // The figures show the pose at the new time: the same as a stage of the document's own
    // playing there.
    QVERIFY(largestDifference(atStart, allPositions(*m_window->poseView())) > 1e-4f);
    const auto& character = m_window->document()->runtime().characters.front();
    thespis::core::runtime::Stage own(m_window->document()->runtime());
    thespis::core::runtime::PoseSet poses = own.makePoseSet();
    own.evaluate(thespis::core::secondsToTicks(time), poses);
    thespis::editor::StickFigure figure(character.name, character.skeleton);
    figure.setPose(poses.characters.front());
    const auto shown = m_window->poseView()->figurePositions(0);
    QCOMPARE(shown.size(), figure.positions().size());
    for (std::size_t j = 0; j < shown.size(); ++j)
        QCOMPARE(shown[j], figure.positions()[j]);
}

QMessageBox* MainWindowTest::waitForErrorBox()
{
    // Null when no error box shows up within 5 s (callers QVERIFY it).
    QElapsedTimer waited;
    waited.start();
    while (waited.elapsed() < 5000) {
        auto* box = m_window->findChild<QMessageBox*>(QStringLiteral("errorMessageBox"));
        if (box && box->isVisible())
            return box;
        QTest::qWait(20);
    }
    return nullptr;
}

void MainWindowTest::malformedScenarioReportsAnError()
{
    const QString title = m_window->windowTitle();
    const thespis::editor::Document* before = m_window->document();
    // A real scenario with one field of the wrong type: the reader must name the field.
    const QString path = QStringLiteral(THESPIS_TEST_DATA "/gui/malformed_start.thespis");
    QVERIFY(QFileInfo::exists(path));
    QVERIFY(!m_window->openScenario(path));

    QMessageBox* box = waitForErrorBox();
    QVERIFY(box);
    QCOMPARE(box->windowTitle(), QStringLiteral("The file is damaged"));
    QVERIFY(box->text().contains(QStringLiteral("malformed_start.thespis")));
    QVERIFY2(box->informativeText().contains(QStringLiteral("start")), qPrintable(box->informativeText()));
    box->close();
    QTRY_VERIFY(!m_window->findChild<QMessageBox*>(QStringLiteral("errorMessageBox")));
    // What was open stays open.
    QCOMPARE(m_window->document(), before);
    QCOMPARE(m_window->windowTitle(), title);

    // Not JSON at all.
    const QString garbage = m_temp.filePath(QStringLiteral("garbage.thespis"));
    QFile file(garbage);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("{\"format\": \"thespis-scenario\", \"version\": 1, \"characters\": [");
    file.close();
    QVERIFY(!m_window->openScenario(garbage));
    box = waitForErrorBox();
    QVERIFY(box);
    QVERIFY(!box->informativeText().isEmpty());
    box->close();
    QTRY_VERIFY(!m_window->findChild<QMessageBox*>(QStringLiteral("errorMessageBox")));
    QCOMPARE(m_window->document(), before);
}

void MainWindowTest::missingScenarioReportsAnError()
{
    QVERIFY(!m_window->openScenario(m_temp.filePath(QStringLiteral("does-not-exist.thespis"))));
    QMessageBox* box = waitForErrorBox();
    QVERIFY(box);
    QCOMPARE(box->windowTitle(), QStringLiteral("File not found"));
    box->close();
    QTRY_VERIFY(!m_window->findChild<QMessageBox*>(QStringLiteral("errorMessageBox")));
}

// Pixels of the viewport that are not the clear colour: the characters and the ground.
int drawnPixels(const QImage& image, QRgb clear)
{
    int count = 0;
    for (int y = 0; y < image.height(); y += 2)
        for (int x = 0; x < image.width(); x += 2)
            count += image.pixel(x, y) != clear ? 1 : 0;
    return count;
}

void MainWindowTest::viewportShowsTheCharactersLit()
{
    QVERIFY(m_window->openScenario(m_scenarioPath));
    QCOMPARE(m_window->views()->currentWidget(), m_window->viewport());
    thespis::widgets::OsgViewport* viewport = m_window->viewport();
    QVERIFY2(viewport->glErrorText().isEmpty(), qPrintable(viewport->glErrorText()));
    QVERIFY(m_window->scenePreview()->scene());
    QCOMPARE(m_window->scenePreview()->scene()->scene().characterCount(), m_window->document()->scenario().characters.size());
    m_window->clock()->seek(thespis::core::secondsToTicks(1.0));
    const QImage prt = viewport->grabFramebuffer();
    const QRgb clear = prt.pixel(2, 2);
    const int samples = (prt.width() / 2) * (prt.height() / 2);
    const int drawn = drawnPixels(prt, clear);
    QVERIFY2(drawn > samples / 50 && drawn < samples * 9 / 10, qPrintable(QStringLiteral("%1 of %2").arg(drawn).arg(samples)));

    auto* unlit = m_window->findChild<QAction*>(QStringLiteral("shading_unlit"));
    auto* prtAction = m_window->findChild<QAction*>(QStringLiteral("shading_prt"));
    QVERIFY(unlit && prtAction);
    unlit->trigger();
    QVERIFY(viewport->grabFramebuffer() != prt);
    prtAction->trigger();
    QCOMPARE(viewport->grabFramebuffer(), prt);

    // Playing moves the characters in the viewport too.
    m_window->clock()->seek(thespis::core::secondsToTicks(3.0));
    QVERIFY(viewport->grabFramebuffer() != prt);
}

// View ▸ Close-up ▸ a character turns the 3D view to that character's face as it is now; Home
// goes back. Saved as studio_close_up.png, mid-blink (the demo's Creon blinks at 0.43 s).
void MainWindowTest::viewMenuClosesUpOnAFace()
{
    QVERIFY(m_window->openScenario(m_scenarioPath));
    thespis::widgets::OsgViewport* viewport = m_window->viewport();
    m_window->clock()->seek(thespis::core::secondsToTicks(0.4333));
    auto* menu = m_window->findChild<QMenu*>(QStringLiteral("closeUpMenu"));
    QVERIFY(menu);
    emit menu->aboutToShow();
    const auto& characters = m_window->document()->scenario().characters;
    QCOMPARE(menu->actions().size(), qsizetype(characters.size()));
    const QVector3D homeCentre = viewport->centre();
    QAction* creon = nullptr;
    for (QAction* action : menu->actions())
        if (action->text() == QStringLiteral("Creon"))
            creon = action;
    QVERIFY(creon && creon->isEnabled());
    creon->trigger();
    const auto head = m_window->scenePreview()->scene()->head("Creon");
    QVERIFY(head.ok());
    const auto centre = head->bounds.centre();
    const QVector3D headCentre(float(centre.x), float(centre.y), float(centre.z));
    QVERIFY2((viewport->centre() - headCentre).length() < 0.01f, "the camera looks at Creon's head");
    QVERIFY2((viewport->eye() - headCentre).length() < 1.0f, "from close by");
    QVERIFY((homeCentre - headCentre).length() > 0.2f);
    QTest::qWait(100);
    const QString dir = QStringLiteral(THESPIS_SCREENSHOT_DIR);
    QVERIFY(QDir().mkpath(dir));
    QVERIFY(viewport->grabFramebuffer().save(QDir(dir).filePath(QStringLiteral("studio_close_up.png"))));
    m_window->viewport()->home();
    QVERIFY((viewport->centre() - homeCentre).length() < 1e-4f);
}

void MainWindowTest::savesAScreenshot()
{
    // Fresh from the file, as a user who just opened it would see it (no earlier test's state).
    QVERIFY(m_window->openScenario(m_scenarioPath));
    // The moment where the figures move farthest from their first pose (someone waves), so
    // that the picture shows the blending at work.
    const double duration = thespis::core::ticksToSeconds(m_window->document()->previewDuration());
    double best = 0, bestTime = 0;
    std::vector<QVector3D> first;
    for (double t = 0; t <= duration; t += 0.25) {
        m_window->clock()->seek(thespis::core::secondsToTicks(t));
        const std::vector<QVector3D> pose = allPositions(*m_window->poseView());
        if (first.empty())
            first = pose;
        if (const float d = largestDifference(first, pose); d > best) {
            best = d;
            bestTime = t;
        }
    }
    m_window->clock()->seek(thespis::core::secondsToTicks(bestTime));
    QTest::qWait(100);
    const QString dir = QStringLiteral(THESPIS_SCREENSHOT_DIR);
    QVERIFY(QDir().mkpath(dir));
    const QString path = QDir(dir).filePath(QStringLiteral("studio_main.png"));
    const QImage image = m_window->grab().toImage();
    QVERIFY(image.width() >= 1000);
    QVERIFY(image.save(path));
    QVERIFY(QFileInfo(path).size() > 10000);
    qInfo("screenshot: %s", qPrintable(path));
}

void MainWindowTest::cleanupTestCase()
{
    m_window.reset();
}

QTEST_MAIN(MainWindowTest)
#include "main_window_test.moc"
