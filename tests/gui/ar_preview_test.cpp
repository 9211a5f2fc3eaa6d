// The studio's AR Preview (issue 16 §6) on the real window and the demo scenario: a synthetic
// board video (written here with its camera file) played with the board's spec, tracked, the
// characters drawn over the board (the shown picture differs from the raw video there), the
// overlay with fps, latency and tracking, a recording that decodes, and the video's end said in
// the view; the test pattern started and stopped (a mirror ball asked for, the overlay says
// whether one lights the characters), the world's placement edited, one undo step each; bad input said beside the field and in the view with Start disabled (a board spec that
// does not parse, a camera file for another size or corrupt, a video that cannot be decoded, no
// camera); a camera calibrated from photos of a chessboard and used. One Stage everywhere: a
// script in the Script dock plays a gesticon gesture and a body clip, and the AR preview, the 3D
// view and the posture chart all show the Session's poses of that tick. Screenshots of the
// preview while it tracks and after the video ended.

#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "ar/camera_file.h"
#include "ar/frame_source.h"
#include "ar/synthetic_source.h"
#include "ar/video_writer.h"
#include "edit/content_edits.h"
#include "editor/ar_calibration_dialog.h"
#include "editor/ar_preview_panel.h"
#include "editor/document.h"
#include "editor/posture_chart_panel.h"
#include "editor/qt_conversions.h"
#include "editor/script_panel.h"
#include "main_window.h"
#include "motion/posture.h"
#include "motion/posture_bases.h"
#include "widgets/video_view.h"

using namespace thespis;
namespace ar = core::ar;

namespace {

constexpr int kTimeout = 60000; // ms: the scene is drawn by a software renderer on a shared machine
const QString kBoard = QStringLiteral("aruco-grid:DICT_4X4_50:4x3:0.04:0.01");

QString demoPath() { return QStringLiteral(THESPIS_RESOURCES "/demo.thespis"); }

void saveScreenshot(QWidget* widget, const QString& name)
{
    QDir().mkpath(QStringLiteral(THESPIS_SCREENSHOT_DIR));
    QTest::qWait(50); // let the layout follow texts that just changed
    QVERIFY(widget->grab().save(QStringLiteral(THESPIS_SCREENSHOT_DIR "/") + name));
}

ar::SyntheticScene boardScene(const QString& board, std::int64_t frames)
{
    ar::SyntheticScene scene;
    scene.board = *ar::parseBoard(board.toStdString());
    scene.camera.width = 640;
    scene.camera.height = 480;
    scene.camera.matrix = {600, 0, 320, 0, 600, 240, 0, 0, 1};
    scene.camera.distortion = {0, 0, 0, 0, 0};
    scene.frames = frames;
    return scene;
}

// Pixels of `area` where the picture shown and the raw frame differ by more than a video codec
// or a resampling would make them.
int differingPixels(const QImage& shown, const ar::VideoFrame& raw, QRect area)
{
    area &= QRect(0, 0, raw.width, raw.height);
    int count = 0;
    for (int y = area.top(); y <= area.bottom(); ++y)
        for (int x = area.left(); x <= area.right(); ++x) {
            const QRgb s = shown.pixel(x, y);
            const std::uint8_t* r = &raw.bgr[(std::size_t(y) * std::size_t(raw.width) + std::size_t(x)) * 3];
            const int d = std::max({std::abs(qRed(s) - r[2]), std::abs(qGreen(s) - r[1]), std::abs(qBlue(s) - r[0])});
            count += d > 60 ? 1 : 0;
        }
    return count;
}

QDockWidget* dockOf(QWidget* content)
{
    return qobject_cast<QDockWidget*>(content->parentWidget());
}

} // namespace

class ArPreviewTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void init();
    void cleanup();
    void videoFileIsTrackedDrawnRecordedAndEnds();
    void testPatternStartsAndStopsAndPlacementIsUndoable();
    void badInputIsSaidAndStartWaits();
    void calibrationFromPhotos();
    void aScriptShowsInEveryViewAndOverTheVideo();
    void onTheVideosTimeThePlayheadFollowsTheVideo();
    void anEditOfTheCastShowsOverTheVideoAtOnce();

private:
    editor::ArPreviewPanel* panel() const { return m_window->arPreview(); }
    QString file(const QString& name) const { return m_data.filePath(name); }
    void showPanel();

    QTemporaryDir m_data;
    ar::SyntheticScene m_scene;
    std::unique_ptr<studio::MainWindow> m_window;
};

void ArPreviewTest::initTestCase()
{
    QVERIFY(m_data.isValid());
    // A board video of 7 s (long enough for the scene to be ready while it plays) and its camera.
    m_scene = boardScene(kBoard, 210);
    auto source = ar::SyntheticSource::create(m_scene);
    QVERIFY(source);
    auto writer = ar::VideoWriter::create(editor::toFsPath(file("board.mp4")), 640, 480, m_scene.fps);
    QVERIFY2(writer, writer ? "" : writer.error().message.c_str());
    ar::VideoFrame frame;
    while (*(*source)->read(frame))
        QVERIFY((*writer)->write(frame));
    QVERIFY((*writer)->finish());
    QVERIFY(ar::writeCameraFile(editor::toFsPath(file("camera.yml")), m_scene.camera));
    ar::CameraIntrinsics hd = m_scene.camera;
    hd.width = 1280;
    hd.height = 720;
    QVERIFY(ar::writeCameraFile(editor::toFsPath(file("camera_720p.yml")), hd));
    QFile corrupt(file("corrupt.yml"));
    QVERIFY(corrupt.open(QIODevice::WriteOnly));
    corrupt.write("%YAML:1.0\nimage_width: 640\nimage_height: [ 480\ncamera_matrix: nonsense\n");
    corrupt.close();
    QFile broken(file("broken.mp4"));
    QVERIFY(broken.open(QIODevice::WriteOnly));
    broken.write(QByteArray(4096, '\x42'));
    broken.close();
}

void ArPreviewTest::init()
{
    QStandardPaths::setTestModeEnabled(true);
    QSettings().clear();
    m_window = std::make_unique<studio::MainWindow>();
    m_window->resize(1500, 950);
    m_window->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
    QVERIFY(m_window->openScenario(demoPath()));
}

void ArPreviewTest::cleanup()
{
    m_window.reset();
}

void ArPreviewTest::showPanel()
{
    QDockWidget* dock = dockOf(panel());
    QVERIFY(dock);
    dock->show();
    dock->raise();
    m_window->resizeDocks({dock}, {560}, Qt::Vertical);
    QApplication::processEvents();
}

void ArPreviewTest::videoFileIsTrackedDrawnRecordedAndEnds()
{
    showPanel();
    editor::ArPreviewPanel* p = panel();
    // The world stands on the board at a tenth of life size: 18 cm characters.
    p->scaleSpin()->setValue(0.1);
    QCOMPARE(m_window->document()->scenario().ar.scale, 0.1);
    p->smoothCheck()->setChecked(false);

    p->chooseVideoFile(file("board.mp4"));
    QVERIFY2(p->sourceInfoLabel()->text().contains(QStringLiteral("640 × 480")), qPrintable(p->sourceInfoLabel()->text()));
    QVERIFY2(p->sourceInfoLabel()->text().contains(QStringLiteral("210 frames")), qPrintable(p->sourceInfoLabel()->text()));
    p->setCameraFile(file("camera.yml"));
    p->setBoardSpec(kBoard);
    QVERIFY2(p->readiness().isEmpty(), qPrintable(p->readiness()));
    QVERIFY(p->startButton()->isEnabled());
    QVERIFY(!p->stopButton()->isEnabled());

    QTest::mouseClick(p->startButton(), Qt::LeftButton);
    QVERIFY2(p->isRunning(), qPrintable(p->view()->messageTitle() + QStringLiteral(": ") + p->view()->messageText()));
    QVERIFY(p->stopButton()->isEnabled());
    QVERIFY(!p->startButton()->isEnabled());
    // Tracked, and the picture moves on.
    QTRY_VERIFY_WITH_TIMEOUT(p->view()->overlayText().contains(QStringLiteral("Tracking")) || !p->isRunning(), kTimeout);
    QVERIFY2(p->isRunning(), qPrintable(p->view()->messageTitle() + QStringLiteral(": ") + p->view()->messageText()));
    const std::int64_t first = p->shownFrame();
    QTRY_VERIFY_WITH_TIMEOUT(p->shownFrame() > first + 3 || !p->isRunning(), kTimeout);
    QTRY_VERIFY_WITH_TIMEOUT(p->lastSnapshot().tracking.tracked || !p->isRunning(), kTimeout);
    QVERIFY(p->isRunning());
    // Looked at where the board leans most (a table top seen from a chair, not a wall), the
    // characters are seen standing on it.
    auto truth = ar::SyntheticSource::create(m_scene);
    std::int64_t leaning = 90;
    double mostLean = 0;
    for (std::int64_t f = 90; f < 170; ++f) {
        const double lean = std::acos(std::abs(ar::rotationMatrix((*truth)->truth(f))[8]));
        if (lean > mostLean)
            mostLean = lean, leaning = f;
    }
    QTRY_VERIFY_WITH_TIMEOUT((p->shownFrame() >= leaning && p->lastSnapshot().tracking.tracked) || !p->isRunning(), kTimeout);
    QVERIFY(p->isRunning());
    const QString overlay = p->view()->overlayText();
    QVERIFY2(overlay.contains(QStringLiteral(" fps")) && overlay.contains(QStringLiteral("latency")), qPrintable(overlay));
    QVERIFY(!p->view()->hasMessage());

    // A character is drawn over the board: the picture shown differs from the raw video there.
    const QImage shown = p->view()->image();
    const std::int64_t index = p->shownFrame();
    QCOMPARE(shown.size(), QSize(640, 480));
    // Recorded while it plays: a video that decodes. Started before the slow check below, which
    // reads the video file up to this frame while the preview plays on towards its end.
    const QString recording = file("recording.avi");
    QVERIFY(p->startRecording(recording));
    QVERIFY(p->isRecording());
    QCOMPARE(p->recordButton()->text(), QStringLiteral("Stop Recording"));
    const std::int64_t recordedFrom = p->shownFrame();
    auto video = ar::openVideoFile(editor::toFsPath(file("board.mp4")));
    QVERIFY(video);
    ar::VideoFrame raw;
    while (raw.index < index) {
        const auto read = (*video)->read(raw);
        QVERIFY2(read && *read, read ? "the video ended early" : read.error().message.c_str());
    }
    const std::array<double, 3> centre = ar::toCamera((*truth)->truth(index), {0.095, 0.07, 0});
    const QPoint onBoard(int(600 * centre[0] / centre[2] + 320), int(600 * centre[1] / centre[2] + 240));
    const QRect boardArea(onBoard - QPoint(180, 180), QSize(360, 360));
    const int drawn = differingPixels(shown, raw, boardArea);
    const int elsewhere = differingPixels(shown, raw, QRect(0, 0, 640, 480)) - drawn;
    QVERIFY2(drawn > 400, qPrintable(QStringLiteral("%1 pixels drawn over the board at (%2, %3), frame %4")
                                         .arg(drawn).arg(onBoard.x()).arg(onBoard.y()).arg(index)));
    QVERIFY2(elsewhere < drawn, qPrintable(QStringLiteral("%1 pixels changed away from the board").arg(elsewhere)));
    saveScreenshot(m_window.get(), QStringLiteral("ar_preview.png"));

    QTRY_VERIFY_WITH_TIMEOUT(p->shownFrame() > recordedFrom + 5 || !p->isRunning(), kTimeout);
    p->stopRecording();
    QVERIFY(!p->isRecording());
    QVERIFY2(p->statusText().contains(QStringLiteral("Recorded to")), qPrintable(p->statusText()));
    auto recorded = ar::openVideoFile(editor::toFsPath(recording));
    QVERIFY2(recorded, recorded ? "" : recorded.error().message.c_str());
    const auto read = (*recorded)->read(raw);
    QVERIFY2(read && *read, read ? "the recording is empty" : read.error().message.c_str());
    QCOMPARE(raw.width, 640);

    // The video ends: the view says so, and the preview can start again.
    QTRY_VERIFY_WITH_TIMEOUT(!p->isRunning(), kTimeout);
    QVERIFY2(p->view()->messageTitle().contains(QStringLiteral("Ended")), qPrintable(p->view()->messageTitle()));
    QVERIFY2(p->view()->messageText().contains(QStringLiteral("ended after")), qPrintable(p->view()->messageText()));
    QVERIFY(!p->view()->image().isNull()); // the last picture stays behind the message
    QVERIFY(p->startButton()->isEnabled());
    QVERIFY(!p->stopButton()->isEnabled());
    saveScreenshot(p, QStringLiteral("ar_preview_ended.png"));
}

void ArPreviewTest::testPatternStartsAndStopsAndPlacementIsUndoable()
{
    showPanel();
    editor::ArPreviewPanel* p = panel();
    editor::Document& document = *m_window->document();
    p->smoothCheck()->setChecked(false);
    p->mirrorBallCheck()->setChecked(true); // the overlay says whether it lights the characters
    p->chooseTestPattern();
    p->setBoardSpec(kBoard);
    QVERIFY2(p->readiness().isEmpty(), qPrintable(p->readiness()));
    QVERIFY(p->start());
    QTRY_VERIFY_WITH_TIMEOUT(p->view()->overlayText().contains(QStringLiteral("Tracking")) || !p->isRunning(), kTimeout);
    QVERIFY2(p->isRunning(), qPrintable(p->view()->messageText()));
    QTRY_VERIFY_WITH_TIMEOUT(p->view()->overlayText().contains(QStringLiteral("mirror ball")) || !p->isRunning(), kTimeout);
    QVERIFY2(p->isRunning(), qPrintable(p->view()->messageText()));

    // The placement, edited while it plays: one undo step per change, undone and redone.
    const int steps = document.undoStack()->count();
    p->headingSpin()->setValue(30);
    p->scaleSpin()->setValue(0.08);
    QCOMPARE(document.undoStack()->count(), steps + 2);
    QCOMPARE(document.scenario().ar.heading, 30.0);
    QCOMPARE(document.scenario().ar.scale, 0.08);
    document.undoStack()->undo();
    QCOMPARE(document.scenario().ar.scale, 1.0);
    QCOMPARE(p->scaleSpin()->value(), 1.0);
    document.undoStack()->redo();
    QCOMPARE(p->scaleSpin()->value(), 0.08);
    QVERIFY(p->isRunning());

    // "Characters look at the camera": every character gazes at the camera the video is tracked
    // from, which the session hands the stage; unchecked, they let go.
    core::runtime::Stage& stage = *m_window->session()->stage();
    QTest::mouseClick(p->lookAtCameraCheck(), Qt::LeftButton);
    QVERIFY(p->lookAtCameraCheck()->isChecked());
    QVERIFY(!stage.characterNames().empty());
    for (const std::string& name : stage.characterNames())
        QVERIFY2(*stage.gazeState(name), name.c_str());
    QTRY_VERIFY_WITH_TIMEOUT(stage.cameraPosition().has_value(), kTimeout);
    saveScreenshot(m_window.get(), QStringLiteral("ar_look_at_camera.png"));
    QTest::mouseClick(p->lookAtCameraCheck(), Qt::LeftButton);
    for (const std::string& name : stage.characterNames())
        QVERIFY2(!*stage.gazeState(name) || (*stage.gazeState(name))->released, name.c_str());

    QTest::mouseClick(p->stopButton(), Qt::LeftButton);
    QVERIFY(!p->isRunning());
    QCOMPARE(p->view()->messageTitle(), QStringLiteral("Stopped"));
    QVERIFY(p->startButton()->isEnabled());
}

void ArPreviewTest::badInputIsSaidAndStartWaits()
{
    showPanel();
    editor::ArPreviewPanel* p = panel();
    p->chooseVideoFile(file("board.mp4"));
    p->setCameraFile(file("camera.yml"));
    p->setBoardSpec(kBoard);
    QVERIFY(p->startButton()->isEnabled());

    // A board spec that does not parse: its message beside it and in the view, Start disabled.
    p->setBoardSpec(QStringLiteral("aruco-grid:DICT_4X4_50:4x:0.04:0.01"));
    QVERIFY2(p->targetMessageLabel()->text().contains(QStringLiteral("does not parse")),
             qPrintable(p->targetMessageLabel()->text()));
    QVERIFY(!p->startButton()->isEnabled());
    QVERIFY(!p->start());
    QVERIFY(p->view()->messageText().contains(p->targetMessageLabel()->text()));
    // A chessboard parses but cannot be tracked.
    p->setBoardSpec(QStringLiteral("chessboard:9x6:0.025"));
    QVERIFY2(p->targetMessageLabel()->text().contains(QStringLiteral("cannot be tracked")),
             qPrintable(p->targetMessageLabel()->text()));
    QVERIFY(!p->startButton()->isEnabled());
    p->setBoardSpec(kBoard);
    QVERIFY(p->startButton()->isEnabled());

    // A camera file for another size is refused before starting; a corrupt one names its file.
    p->setCameraFile(file("camera_720p.yml"));
    QVERIFY2(p->cameraFileLabel()->text().contains(QStringLiteral("1280 × 720")) &&
                 p->cameraFileLabel()->text().contains(QStringLiteral("640 × 480")),
             qPrintable(p->cameraFileLabel()->text()));
    QVERIFY(!p->startButton()->isEnabled());
    QVERIFY(!p->start());
    QVERIFY(!p->isRunning());
    p->setCameraFile(file("corrupt.yml"));
    QVERIFY2(p->cameraFileLabel()->text().contains(QStringLiteral("corrupt.yml")), qPrintable(p->cameraFileLabel()->text()));
    QVERIFY(!p->startButton()->isEnabled());
    p->setCameraFile(file("camera.yml"));
    QVERIFY(p->startButton()->isEnabled());

    // A video that cannot be decoded.
    p->chooseVideoFile(file("broken.mp4"));
    QVERIFY2(p->sourceInfoLabel()->text().contains(QStringLiteral("broken.mp4")), qPrintable(p->sourceInfoLabel()->text()));
    QVERIFY(!p->startButton()->isEnabled());
    QVERIFY(p->view()->messageText().contains(QStringLiteral("broken.mp4")));

    // No camera: the choice says so, and so does the view.
    if (!ar::listCameras().empty())
        QSKIP("This machine has a camera: the no-camera state cannot be shown.");
    p->chooseCamera();
    QCOMPARE(p->cameraCombo()->currentText(), QStringLiteral("No camera found"));
    QVERIFY(!p->cameraCombo()->isEnabled());
    QVERIFY(!p->startButton()->isEnabled());
    QVERIFY2(p->view()->messageText().contains(QStringLiteral("No camera found")), qPrintable(p->view()->messageText()));
    saveScreenshot(p, QStringLiteral("ar_preview_no_camera.png"));

    // The size and frame rate asked of a camera are chosen beside it, kept for the next session,
    // and are what opening the camera asks for; by default the camera file's size at 30 fps.
    QVERIFY(p->cameraSizeCombo()->isVisible() && p->cameraRateCombo()->isVisible());
    editor::ArSource camera = p->source();
    camera.camera = 0; // as if a camera were plugged in
    core::ar::CameraRequest asked = editor::cameraRequest(camera, QSize(800, 600));
    QCOMPARE(QSize(asked.width, asked.height), QSize(800, 600));
    QCOMPARE(asked.fps, 30.0);
    const auto choose = [](QComboBox* combo, const QString& text) {
        const int index = combo->findText(text);
        QVERIFY2(index >= 0, qPrintable(text));
        combo->setCurrentIndex(index);
        emit combo->activated(index);
    };
    choose(p->cameraSizeCombo(), QStringLiteral("1280 × 720"));
    choose(p->cameraRateCombo(), QStringLiteral("60 fps"));
    camera = p->source();
    QCOMPARE(camera.kind, editor::ArSource::Kind::Camera);
    camera.camera = 0;
    asked = editor::cameraRequest(camera, QSize(800, 600));
    QCOMPARE(QSize(asked.width, asked.height), QSize(1280, 720));
    QCOMPARE(asked.fps, 60.0);
    QCOMPARE(QSettings().value(QStringLiteral("arPreview/cameraSize")).toString(), QStringLiteral("1280x720"));
    QCOMPARE(QSettings().value(QStringLiteral("arPreview/cameraFps")).toDouble(), 60.0);
    choose(p->cameraSizeCombo(), QStringLiteral("Camera file's size"));
    choose(p->cameraRateCombo(), QStringLiteral("30 fps"));
    QVERIFY(p->source().size.isEmpty());
}

void ArPreviewTest::calibrationFromPhotos()
{
    showPanel();
    editor::ArPreviewPanel* p = panel();
    // Photos of a chessboard held at several angles.
    const QString chessboard = QStringLiteral("chessboard:9x6:0.025");
    ar::SyntheticScene scene = boardScene(chessboard, 300);
    scene.nearest = 0.45;
    scene.farthest = 0.7;
    auto source = ar::SyntheticSource::create(scene);
    QVERIFY(source);
    QStringList photos;
    ar::VideoFrame frame;
    while (*(*source)->read(frame))
        if (frame.index % 25 == 0) {
            photos << file(QStringLiteral("view-%1.png").arg(frame.index));
            QVERIFY(ar::writePicture(editor::toFsPath(photos.back()), frame));
        }
    p->chooseVideoFile(file("board.mp4"));
    editor::ArCalibrationDialog* dialog = p->openCalibration();
    QVERIFY(dialog);
    QVERIFY(QTest::qWaitForWindowExposed(dialog));
    dialog->boardEdit()->setText(chessboard);
    QVERIFY(!dialog->calibrateButton()->isEnabled());
    dialog->addPhotos(photos);
    QCOMPARE(dialog->viewCount(), int(photos.size()));
    QVERIFY(dialog->calibrateButton()->isEnabled());
    // The live video is there to capture views from, too.
    QTRY_VERIFY_WITH_TIMEOUT(dialog->captureButton()->isEnabled(), kTimeout);
    QTest::mouseClick(dialog->calibrateButton(), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(!dialog->isRunning(), kTimeout);
    QVERIFY2(dialog->camera().has_value(), qPrintable(dialog->resultText()));
    QVERIFY2(dialog->resultText().contains(QStringLiteral("RMS")), qPrintable(dialog->resultText()));
    QVERIFY(std::abs(dialog->camera()->fx() - 600) < 30);
    QVERIFY(dialog->saveButton()->isEnabled());
    saveScreenshot(dialog, QStringLiteral("ar_calibration.png"));
    QVERIFY(dialog->saveTo(file("calibrated.yml")));
    // The preview uses the camera just calibrated.
    QVERIFY2(p->cameraFileLabel()->text().contains(QStringLiteral("640 × 480")), qPrintable(p->cameraFileLabel()->text()));
    QVERIFY2(p->readiness().isEmpty(), qPrintable(p->readiness()));
    dialog->close();
}

void ArPreviewTest::aScriptShowsInEveryViewAndOverTheVideo()
{
    showPanel();
    editor::ArPreviewPanel* p = panel();
    editor::Session* session = m_window->session();
    p->scaleSpin()->setValue(0.1);
    p->smoothCheck()->setChecked(false);
    p->setClock(editor::ArPreviewPanel::Clock::Transport);
    p->chooseVideoFile(file("board.mp4"));
    p->setCameraFile(file("camera.yml"));
    p->setBoardSpec(kBoard);
    QVERIFY(p->start());
    QTRY_VERIFY_WITH_TIMEOUT(p->lastSnapshot().tracking.tracked || !p->isRunning(), kTimeout);
    QVERIFY(p->isRunning());

    // The script: Creon's gesticon gesture "greet" and Antigone's body clip "wave", from now.
    auto* script = m_window->findChild<editor::ScriptPanel*>();
    QVERIFY(script);
    m_window->clock()->seek(core::secondsToTicks(1.0));
    script->setSource(QStringLiteral("animService.activateAction_body('Creon', 'greet')\n"
                                     "animService.activateAction_body('Antigone', 'wave')\n"));
    script->run();
    QTRY_VERIFY_WITH_TIMEOUT(!script->isRunning(), kTimeout);
    QVERIFY2(script->output().indexOf(QStringLiteral("Error")) < 0, qPrintable(script->output()));
    // At a moment the gesture and the clip play (their fades done), the transport paused there.
    m_window->clock()->pause();
    m_window->clock()->seek(core::secondsToTicks(2.0));
    const core::runtime::PoseSet shown = session->poses();
    QCOMPARE(shown.time, core::secondsToTicks(2.0));
    core::runtime::Stage& stage = *session->stage();
    QVERIFY(*stage.isPlaying("Creon", core::runtime::Track::Body, "greet", shown.time));
    QVERIFY(*stage.isPlaying("Antigone", core::runtime::Track::Body, "wave", shown.time));
    // Those poses are the live actions' (the document alone poses both otherwise).
    core::runtime::Stage authored(stage.runtimeCopy());
    core::runtime::PoseSet document = authored.makePoseSet();
    authored.evaluate(shown.time, document);
    QVERIFY(shown.characters[0].body != document.characters[0].body);
    QVERIFY(shown.characters[1].body != document.characters[1].body);

    // The AR preview draws exactly those poses over the video ...
    QTRY_VERIFY_WITH_TIMEOUT(p->lastSnapshot().poses.time == shown.time || !p->isRunning(), kTimeout);
    QVERIFY(p->isRunning());
    for (std::size_t c = 0; c < shown.characters.size(); ++c) {
        QVERIFY(p->lastSnapshot().poses.characters[c].body == shown.characters[c].body);
        QCOMPARE(p->lastSnapshot().poses.characters[c].placement, shown.characters[c].placement);
    }
    // ... the 3D view too ...
    if (editor::ScenePreview* preview = m_window->scenePreview()) {
        QCOMPARE(preview->scene()->poses().time, shown.time);
        for (std::size_t c = 0; c < shown.characters.size(); ++c)
            QVERIFY(preview->scene()->poses().characters[c].body == shown.characters[c].body);
    }
    // ... and the posture chart's bars are the projection of Creon's pose on screen.
    const auto& creon = stage.runtime().characters[0];
    auto bases = core::motion::readPostureBasesFile(editor::toFsPath(QStringLiteral(THESPIS_RESOURCES "/motion/cmu_postures.pca")));
    QVERIFY(bases);
    auto map = core::motion::PostureMap::create(creon.skeleton, core::motion::PostureSet::UpperBody);
    QVERIFY(map);
    std::vector<float> frame = shown.characters[0].body;
    shown.characters[0].placement.apply(*creon.skeleton.frameLayout(), frame);
    std::vector<float> posture(std::size_t(map->layout().size())), pcs(posture.size());
    map->toPosture(frame, posture);
    bases->upper.project(posture, pcs);
    const std::vector<float>& bars = m_window->postureChart()->components();
    QCOMPARE(bars.size(), pcs.size());
    for (std::size_t i = 0; i < pcs.size(); ++i)
        QVERIFY2(std::abs(bars[i] - std::abs(pcs[i])) < 1e-5f, qPrintable(QStringLiteral("PC %1").arg(i + 1)));
    saveScreenshot(m_window.get(), QStringLiteral("ar_preview_script.png"));

    // With every view open (3D, stick figures, chart, AR), a tick evaluates the stage once and
    // skins each character of the 3D view once.
    editor::ScenePreview* preview = m_window->scenePreview();
    QVERIFY(preview);
    const std::uint64_t evaluations = stage.ticks();
    std::vector<std::uint64_t> skinned;
    for (std::size_t c = 0; c < preview->scene()->scene().characterCount(); ++c)
        skinned.push_back(preview->scene()->scene().character(c).poseCount());
    m_window->clock()->seek(core::secondsToTicks(2.5));
    QCOMPARE(stage.ticks(), evaluations + 1);
    for (std::size_t c = 0; c < skinned.size(); ++c)
        QCOMPARE(preview->scene()->scene().character(c).poseCount(), skinned[c] + 1);
    p->stop();
}

// Removing a character while the preview runs: the preview starts again by itself with the new
// cast (no Stop / Start), and undoing brings both characters back over the video.
void ArPreviewTest::anEditOfTheCastShowsOverTheVideoAtOnce()
{
    showPanel();
    editor::ArPreviewPanel* p = panel();
    editor::Document& document = *m_window->document();
    p->smoothCheck()->setChecked(false);
    p->chooseTestPattern();
    p->setBoardSpec(kBoard);
    QVERIFY(p->start());
    QTRY_VERIFY_WITH_TIMEOUT(p->lastSnapshot().poses.characters.size() == 2 || !p->isRunning(), kTimeout);
    QVERIFY(p->isRunning());

    QVERIFY(document.edit(core::edit::removeCharacter(document.scenario(), 1), QStringLiteral("Remove")).ok());
    QVERIFY(p->isRunning());
    QVERIFY2(p->statusText().contains(QStringLiteral("started again")), qPrintable(p->statusText()));
    QTRY_VERIFY_WITH_TIMEOUT(p->lastSnapshot().poses.characters.size() == 1 || !p->isRunning(), kTimeout);
    QVERIFY2(p->isRunning(), qPrintable(p->view()->messageText()));

    document.undoStack()->undo();
    QVERIFY(p->isRunning());
    QTRY_VERIFY_WITH_TIMEOUT(p->lastSnapshot().poses.characters.size() == 2 || !p->isRunning(), kTimeout);
    QVERIFY(p->isRunning());
    // An edit of the schedules only plays on the same session.
    const auto before = p->lastSnapshot().tracking.frame;
    m_window->clock()->seek(core::secondsToTicks(1.0));
    QVERIFY(document.edit(core::edit::setCharacterPlacement(document.scenario(), 0, {0.2f, 0, 0}, 0), QStringLiteral("Move")).ok());
    QTRY_VERIFY_WITH_TIMEOUT(p->lastSnapshot().tracking.frame > before + 2 || !p->isRunning(), kTimeout);
    QVERIFY(p->isRunning());
    p->stop();
}

void ArPreviewTest::onTheVideosTimeThePlayheadFollowsTheVideo()
{
    showPanel();
    editor::ArPreviewPanel* p = panel();
    p->setClock(editor::ArPreviewPanel::Clock::Video);
    QCOMPARE(QSettings().value(QStringLiteral("arPreview/clock")).toString(), QStringLiteral("video"));
    p->smoothCheck()->setChecked(false);
    p->chooseVideoFile(file("board.mp4"));
    p->setCameraFile(file("camera.yml"));
    p->setBoardSpec(kBoard);
    QVERIFY(p->start());
    // The playhead goes where each frame shown is in the video (30 fps), the transport paused,
    // and the frames after it are drawn with the poses of that time.
    QTRY_VERIFY_WITH_TIMEOUT(p->shownFrame() >= 30 || !p->isRunning(), kTimeout);
    QVERIFY(p->isRunning());
    QVERIFY(!m_window->clock()->isPlaying());
    QCOMPARE(m_window->clock()->time(), p->lastSnapshot().videoTime);
    QCOMPARE(m_window->clock()->time(), p->shownFrame() * core::ticksPerFrame(30));
    const core::Tick drawnAt = p->lastSnapshot().poses.time;
    QTRY_VERIFY_WITH_TIMEOUT(p->lastSnapshot().poses.time > drawnAt || !p->isRunning(), kTimeout);
    QVERIFY(p->lastSnapshot().poses.time <= p->lastSnapshot().videoTime);
    p->stop();
}

QTEST_MAIN(ArPreviewTest)
#include "ar_preview_test.moc"
