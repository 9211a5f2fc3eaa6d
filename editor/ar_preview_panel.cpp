#include "editor/ar_preview_panel.h"

#include <QBoxLayout>
#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QGridLayout>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QScrollArea>
#include <QSettings>
#include <QTimer>

#include <algorithm>

#include "edit/ar_edits.h"
#include "editor/ar_calibration_dialog.h"
#include "editor/ar_preview_settings.h"
#include "editor/document.h"
#include "editor/playback_clock.h"
#include "editor/qt_conversions.h"
#include "editor/session.h"
#include "widgets/video_view.h"

namespace thespis::editor {

using namespace ar_preview;

namespace {

namespace ar = core::ar;
using core::render::ArSessionState;

constexpr int kPollIntervalMs = 16; // about 60 Hz: the newest composed frame, when there is one

} // namespace

ArPreviewPanel::ArPreviewPanel(QWidget* parent) : QWidget(parent), m_timer(new QTimer(this))
{
    setObjectName(QStringLiteral("arPreviewPanel"));
    m_view = new widgets::VideoView(this);
    m_view->setObjectName(QStringLiteral("arVideoView"));

    m_controls = new QWidget;
    m_groups = new QGridLayout(m_controls);
    m_groups->setContentsMargins(0, 0, 0, 0);
    const QString titles[] = {tr("Source"), tr("Camera"), tr("Target"), tr("Placement on the Target"), tr("Preview")};
    for (const QString& title : titles)
        m_groupBoxes << new QGroupBox(title, m_controls);
    buildSourceGroup(m_groupBoxes[0]);
    buildCameraGroup(m_groupBoxes[1]);
    buildTargetGroup(m_groupBoxes[2]);
    buildPlacementGroup(m_groupBoxes[3]);

    // The preview's own options and its buttons.
    QGroupBox* preview = m_groupBoxes[4];
    m_mirrorBall = new QCheckBox(tr("Light from a mirror ball in view"), preview);
    m_mirrorBall->setToolTip(tr("Find a chrome ball in the picture and light the characters with what it mirrors"));
    m_smooth = new QCheckBox(tr("Smooth edges (slower)"), preview);
    m_smooth->setObjectName(QStringLiteral("arSmoothEdges"));
    m_smooth->setChecked(QSettings().value(kSettingsGroup + QStringLiteral("smooth"), true).toBool());
    m_lookAtCamera = new QCheckBox(tr("Characters look at the camera"), preview);
    m_lookAtCamera->setObjectName(QStringLiteral("arLookAtCamera"));
    m_lookAtCamera->setToolTip(tr("Their eyes, heads and chests turn to the real camera as it is tracked: they look "
                                  "at the visitor"));
    m_clock = new QComboBox(preview);
    m_clock->setObjectName(QStringLiteral("arClock"));
    m_clock->addItem(tr("Plays with the studio's transport"), int(Clock::Transport));
    m_clock->addItem(tr("Plays on the video's time"), int(Clock::Video));
    m_clock->setToolTip(tr("The transport: play, scrub and loop in the studio, and the video shows it. The video's "
                           "time: the playhead follows the video frame by frame, as a recording would."));
    m_clock->setCurrentIndex(setting("clock") == QStringLiteral("video") ? 1 : 0);
    m_start = new QPushButton(tr("Start"), preview);
    m_start->setObjectName(QStringLiteral("arStart"));
    m_stop = new QPushButton(tr("Stop"), preview);
    m_stop->setObjectName(QStringLiteral("arStop"));
    m_record = new QPushButton(tr("Record…"), preview);
    m_record->setObjectName(QStringLiteral("arRecord"));
    m_record->setToolTip(tr("Write what the preview shows to a video (.mp4 or .avi)"));
    m_status = new QLabel(preview);
    m_status->setObjectName(QStringLiteral("arStatus"));
    m_status->setWordWrap(true);
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(m_start, 1);
    buttons->addWidget(m_stop, 1);
    buttons->addWidget(m_record, 1);
    auto* previewLayout = new QVBoxLayout(preview);
    previewLayout->addWidget(m_clock);
    previewLayout->addWidget(m_mirrorBall);
    previewLayout->addWidget(m_smooth);
    previewLayout->addWidget(m_lookAtCamera);
    previewLayout->addLayout(buttons);
    previewLayout->addWidget(m_status);

    auto* scroll = new QScrollArea(this);
    scroll->setWidget(m_controls);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_layout = new QBoxLayout(QBoxLayout::TopToBottom, this);
    m_layout->setContentsMargins(4, 4, 4, 4);
    m_layout->addWidget(m_view, 3);
    m_layout->addWidget(scroll, 2);
    arrange(false);

    connect(m_start, &QPushButton::clicked, this, [this] { start(); });
    connect(m_stop, &QPushButton::clicked, this, &ArPreviewPanel::stop);
    connect(m_record, &QPushButton::clicked, this, [this] {
        if (isRecording()) {
            stopRecording();
            return;
        }
        const QString folder = m_document && !m_document->baseDir().isEmpty() ? m_document->baseDir() : QDir::homePath();
        const QString path = QFileDialog::getSaveFileName(this, tr("Record the AR Preview"),
                                                          QDir(folder).filePath(QStringLiteral("ar-preview.mp4")),
                                                          tr("Videos (*.mp4 *.avi)"));
        if (!path.isEmpty())
            (void)startRecording(path);
    });
    connect(m_smooth, &QCheckBox::toggled, this, [](bool on) { storeSetting("smooth", on); });
    connect(m_lookAtCamera, &QCheckBox::toggled, this, &ArPreviewPanel::applyLookAtCamera);
    connect(m_clock, &QComboBox::currentIndexChanged, this, [this] {
        storeSetting("clock", clock() == Clock::Video ? QStringLiteral("video") : QStringLiteral("transport"));
    });
    connect(m_timer, &QTimer::timeout, this, &ArPreviewPanel::poll);
    m_timer->setInterval(kPollIntervalMs);

    // Where the last session left off.
    m_refreshing = true;
    m_board->setText(setting("board", kDefaultBoard));
    m_videoPath->setText(QDir::toNativeSeparators(setting("video")));
    m_folderPath->setText(QDir::toNativeSeparators(setting("folder")));
    const QStringList cameraSize = setting("cameraSize").split(QLatin1Char('x'));
    if (cameraSize.size() == 2)
        m_cameraSize->setCurrentIndex(std::max(0, m_cameraSize->findData(QSize(cameraSize[0].toInt(), cameraSize[1].toInt()))));
    m_cameraRate->setCurrentIndex(std::max(0, m_cameraRate->findData(setting("cameraFps", QStringLiteral("30")).toDouble())));
    m_refreshing = false;
    refreshCameras();
    const QString kind = setting("source", m_cameras->isEnabled() ? QStringLiteral("camera") : QStringLiteral("test"));
    const QStringList kinds{QStringLiteral("test"), QStringLiteral("video"), QStringLiteral("folder"), QStringLiteral("camera")};
    m_sourceKind->setCurrentIndex(int(std::max<qsizetype>(0, kinds.indexOf(kind))));
    onSourceKindChosen();
    setCameraFile(setting("cameraFile"));
    checkTarget();
    setDocument(nullptr);
}

ArPreviewPanel::~ArPreviewPanel()
{
    m_timer->stop();
    if (m_session) {
        (void)m_session->stopRecording();
        m_session.reset();
    }
    if (m_retiring.joinable())
        m_retiring.join();
}

// ---- The document ------------------------------------------------------------------------------

void ArPreviewPanel::setDocument(Document* document)
{
    if (document == m_document && document)
        return;
    if (m_session)
        stop();
    if (m_document)
        disconnect(m_document, nullptr, this, nullptr);
    m_document = document;
    if (m_document)
        connect(m_document, &Document::edited, this, [this] {
            refreshPlacement();
            if (m_session)
                m_session->setPlacement(m_document->scenario().ar);
        });
    refreshPlacement();
    updateEnabled();
}

void ArPreviewPanel::setSession(Session* session)
{
    if (m_studio)
        disconnect(m_studio, nullptr, this, nullptr);
    m_studio = session;
    if (m_studio)
        connect(m_studio, &Session::edited, this, &ArPreviewPanel::onStudioEdited);
    updateEnabled();
}

void ArPreviewPanel::onStudioEdited(bool stageReplaced)
{
    // New schedules play on the same stage at once; other bodies, light or cast need a new scene:
    // the preview starts again over its source — unless it records, which a restart would end.
    if (!m_session || !m_document || (!stageReplaced && SceneSources::of(m_document->scenario(), m_document->assets()) == m_sources))
        return;
    if (isRecording()) {
        stop();
        m_endTitle = tr("Stopped");
        m_endText = tr("The characters changed, which ended the recording.\nPress Start to see them over the video.");
        updateEnabled();
        return;
    }
    retire();
    if (start())
        setStatus(tr("The characters changed: the preview started again with them."), false);
}

void ArPreviewPanel::setClock(Clock clock)
{
    m_clock->setCurrentIndex(m_clock->findData(int(clock)));
}

ArPreviewPanel::Clock ArPreviewPanel::clock() const
{
    return Clock(m_clock->currentData().toInt());
}

void ArPreviewPanel::refreshPlacement()
{
    m_refreshing = true;
    const core::scenario::ArSpec spec = m_document ? m_document->scenario().ar : core::scenario::ArSpec{};
    m_scale->setValue(spec.scale);
    m_heading->setValue(spec.heading);
    m_offset[0]->setValue(spec.offset[0]);
    m_offset[1]->setValue(spec.offset[1]);
    m_shadows->setChecked(spec.shadowCatcher);
    m_refreshing = false;
    m_groupBoxes[3]->setEnabled(m_document != nullptr);
}

void ArPreviewPanel::pushPlacement()
{
    if (m_refreshing || !m_document)
        return;
    auto made = core::edit::setArPlacement(m_document->scenario(), {m_offset[0]->value(), m_offset[1]->value()},
                                           m_heading->value(), m_scale->value());
    if (auto done = m_document->edit(std::move(made), tr("Place the World on the Target")); !done) {
        setStatus(fromUtf8(done.error().message), true);
        refreshPlacement();
    }
}

// ---- Running -----------------------------------------------------------------------------------

bool ArPreviewPanel::start()
{
    if (m_session)
        return true;
    if (!readiness().isEmpty()) {
        updateEnabled(); // the view says what to fix
        return false;
    }
    if (m_calibration)
        m_calibration->reject(); // it holds the source (a camera has one reader)
    if (m_retiring.joinable())
        m_retiring.join(); // the last session still holds its source
    const std::optional<ar::BoardSpec> spec = board();
    const bool testPattern = m_source.kind == ArSource::Kind::TestPattern;
    const QSize cameraSize = m_camera && !testPattern ? QSize(m_camera->width, m_camera->height) : QSize();
    auto source = openArSource(m_source, spec.value_or(ar::BoardSpec{}), cameraSize);
    auto fail = [this](const QString& why) {
        m_endTitle = tr("Cannot start");
        m_endText = why;
        m_startFailed = true;
        setStatus(why, true);
        updateEnabled();
        return false;
    };
    if (!source)
        return fail(fromUtf8(source.error().message));

    core::render::ArSessionSettings settings;
    settings.camera = testPattern ? testPatternScene(*spec).camera : *m_camera;
    settings.target = *target();
    settings.compositor.samples = m_smooth->isChecked() ? 4 : 1;
    if (m_mirrorBall->isChecked())
        settings.probe = ar::LiveProbeSettings{};
    static const core::scenario::Scenario nothing; // without a document: the video and the tracking only
    const bool playing = m_document && m_studio && m_studio->stage();
    const core::scenario::Assets assets = playing ? m_document->assets() : core::scenario::Assets();
    if (playing) {
        settings.stage = m_studio->stage();
        settings.poses = m_studio->mailbox();
        m_sources = SceneSources::of(m_document->scenario(), m_document->assets());
    }
    auto session = core::render::ArSession::start(std::move(source).value(), playing ? m_document->scenario() : nothing,
                                                  assets, settings);
    if (!session)
        return fail(fromUtf8(session.error().message));
    m_session = std::move(session).value();
    if (m_lookAtCamera->isChecked())
        applyLookAtCamera(true);
    m_snapshot = {};
    m_recordingPath.clear();
    m_endTitle.clear();
    m_endText.clear();
    m_startFailed = false;
    setStatus({}, false);
    m_view->setOverlay({});
    m_view->setInset({});
    m_probeVersion = 0;
    m_view->setMessage(tr("Starting…"), tr("Reading the first frames and preparing the scene."));
    m_timer->start();
    updateEnabled();
    emit runningChanged(true);
    return true;
}

void ArPreviewPanel::stop()
{
    if (!m_session)
        return;
    stopRecording();
    m_endTitle = tr("Stopped");
    m_endText = tr("Press Start to go on.");
    retire();
}

void ArPreviewPanel::poll()
{
    if (!m_session)
        return;
    if (m_session->takeSnapshot(m_snapshot)) {
        showSnapshot();
        followVideo();
    }
    if (m_session->state() == ArSessionState::Running)
        return;
    if (m_session->takeSnapshot(m_snapshot)) // the last frame, drawn as it stopped
        showSnapshot();
    onSessionEnded();
}

void ArPreviewPanel::followVideo()
{
    // On the video's time the playhead goes where the frame just shown is; the Session's tick
    // then publishes the poses the next frame is drawn with.
    if (clock() != Clock::Video || !m_studio || !m_studio->document())
        return;
    PlaybackClock* playhead = m_studio->clock();
    playhead->pause();
    playhead->seek(m_snapshot.videoTime);
}

void ArPreviewPanel::showSnapshot()
{
    m_view->setImage(toQImage(m_snapshot.frame));
    m_view->setMessage({});
    const ar::TrackedFrame& tracking = m_snapshot.tracking;
    widgets::VideoOverlay overlay;
    overlay.lines << tr("%1 fps").arg(m_snapshot.fps, 0, 'f', 1)
                  << tr("latency %1 ms").arg(m_snapshot.latency * 1000, 0, 'f', 0);
    if (tracking.tracked) {
        overlay.lines << tr("Tracking: %n feature(s)", nullptr, tracking.measured.features);
        // Blur and an unsure tilt make a frame count for less (the filter weighs it so): said, so
        // that a jumpy placement has its reason on screen.
        if (tracking.measured.blur.length >= 2)
            overlay.lines << tr("motion blur %1 px").arg(tracking.measured.blur.length, 0, 'f', 1);
        if (tracking.measured.ambiguity > 0 && tracking.measured.ambiguity < 3)
            overlay.lines << tr("tilt unsure (ratio %1)").arg(tracking.measured.ambiguity, 0, 'f', 1);
        overlay.status = widgets::VideoOverlay::Status::Good;
    } else if (tracking.hasPose) {
        overlay.lines << tr("Target lost: holding its last place");
        overlay.status = widgets::VideoOverlay::Status::Warning;
    } else {
        overlay.lines << tr("Searching for the target…");
        overlay.status = widgets::VideoOverlay::Status::Bad;
    }
    overlay.lines << tr("frame %1").arg(tracking.frame);
    if (m_snapshot.dropped > 0)
        overlay.lines << tr("dropped: %1").arg(m_snapshot.dropped);
    if (m_snapshot.lit)
        overlay.lines << tr("lit by the mirror ball");
    else if (m_mirrorBall->isChecked() && !m_snapshot.probeStatus.empty())
        overlay.lines << tr("mirror ball: %1").arg(fromUtf8(m_snapshot.probeStatus));
    if (m_snapshot.probeVersion != m_probeVersion) {
        // The ball as the camera sees it, copied only when the session made a new one.
        m_probeVersion = m_snapshot.probeVersion;
        const core::lighting::PreviewImage& ball = m_snapshot.probePicture;
        const QImage picture = ball.rgba.size() == std::size_t(ball.width) * std::size_t(ball.height) * 4 && ball.width > 0
                                   ? QImage(ball.rgba.data(), ball.width, ball.height, qsizetype(ball.width) * 4,
                                            QImage::Format_RGBA8888)
                                         .copy()
                                   : QImage();
        m_view->setInset(picture, tr("Mirror ball"));
    }
    overlay.recording = m_session && m_session->recording();
    overlay.recordingText = tr("REC");
    m_view->setOverlay(overlay);
}

void ArPreviewPanel::onSessionEnded()
{
    const ArSessionState state = m_session->state();
    const QString message = fromUtf8(m_session->message());
    if (state == ArSessionState::Ended) {
        m_endTitle = tr("Ended");
        m_endText = tr("%1.\nPress Start to play it again.").arg(message);
    } else if (state == ArSessionState::Failed) {
        m_endTitle = tr("Stopped by a problem");
        m_endText = tr("%1\nFix it, then press Start.").arg(message);
        setStatus(message, true);
    } else {
        m_endTitle = tr("Stopped");
        m_endText = tr("Press Start to go on.");
    }
    if (!m_recordingPath.isEmpty()) // the session finished the recording as it ended
        setStatus(tr("Recorded to %1.").arg(QDir::toNativeSeparators(m_recordingPath)), false);
    m_recordingPath.clear();
    retire();
}

void ArPreviewPanel::retire()
{
    m_timer->stop();
    if (m_retiring.joinable())
        m_retiring.join();
    // Taking a session down joins its threads, which may be busy drawing or still building the
    // scene: not on the GUI thread.
    m_retiring = std::jthread([session = std::move(m_session)]() mutable { session.reset(); });
    widgets::VideoOverlay overlay = m_view->overlay(); // the last frame's facts stay, no longer live
    overlay.recording = false;
    overlay.status = widgets::VideoOverlay::Status::Neutral;
    m_view->setOverlay(overlay);
    updateEnabled();
    emit runningChanged(false);
}

core::Result<void> ArPreviewPanel::startRecording(const QString& path)
{
    if (!m_session) {
        const QString why = tr("Start the preview first, then record it.");
        setStatus(why, true);
        return core::makeError(core::ErrorCode::InvalidArgument, why.toStdString());
    }
    if (auto started = m_session->startRecording(toFsPath(path)); !started) {
        setStatus(tr("Cannot record: %1").arg(fromUtf8(started.error().message)), true);
        return started;
    }
    m_recordingPath = path;
    setStatus(tr("Recording to %1…").arg(QDir::toNativeSeparators(path)), false);
    updateEnabled();
    return {};
}

void ArPreviewPanel::stopRecording()
{
    // The session may have finished the file already, as its video ended before this was polled.
    if (!m_session || m_recordingPath.isEmpty())
        return;
    if (auto finished = m_session->stopRecording(); !finished)
        setStatus(tr("The recording could not be finished: %1").arg(fromUtf8(finished.error().message)), true);
    else
        setStatus(tr("Recorded to %1.").arg(QDir::toNativeSeparators(m_recordingPath)), false);
    m_recordingPath.clear();
    updateEnabled();
}

bool ArPreviewPanel::isRecording() const
{
    return m_session && m_session->recording();
}

ArCalibrationDialog* ArPreviewPanel::openCalibration()
{
    if (m_calibration) {
        m_calibration->raise();
        return m_calibration;
    }
    stop(); // the dialog reads the source itself
    if (m_retiring.joinable())
        m_retiring.join();
    const QString folder = m_document && !m_document->baseDir().isEmpty() ? m_document->baseDir() : QDir::homePath();
    auto* dialog = new ArCalibrationDialog(m_source, m_board->text(), folder, this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &ArCalibrationDialog::cameraSaved, this, &ArPreviewPanel::setCameraFile);
    m_calibration = dialog;
    dialog->show();
    return dialog;
}

void ArPreviewPanel::updateEnabled()
{
    const bool running = m_session != nullptr;
    const QString why = readiness();
    m_start->setEnabled(!running && why.isEmpty());
    m_start->setToolTip(why.isEmpty() ? tr("Play the scenario over the video") : why);
    m_stop->setEnabled(running);
    m_record->setEnabled(running);
    m_record->setText(isRecording() ? tr("Stop Recording") : tr("Record…"));
    for (int group = 0; group < 3; ++group)
        m_groupBoxes[group]->setEnabled(!running);
    m_mirrorBall->setEnabled(!running);
    m_smooth->setEnabled(!running);
    m_clock->setEnabled(m_document != nullptr);
    if (running)
        return;
    // What the view says while nothing plays: how the last run ended, and what to fix first.
    if (!why.isEmpty())
        m_view->setMessage(m_endTitle.isEmpty() ? tr("AR Preview") : m_endTitle,
                           m_endTitle.isEmpty() ? why : m_endText + QStringLiteral("\n\n") + why);
    else if (!m_endTitle.isEmpty())
        m_view->setMessage(m_endTitle, m_endText);
    else
        m_view->setMessage(tr("AR Preview"), tr("Press Start to play the scenario over the video."));
}

void ArPreviewPanel::forgetFailedStart()
{
    // A start refused for what was chosen then says nothing about what is chosen now.
    if (!m_startFailed)
        return;
    m_startFailed = false;
    m_endTitle.clear();
    m_endText.clear();
}

void ArPreviewPanel::setStatus(const QString& text, bool error)
{
    m_status->setText(text);
    m_status->setStyleSheet(error ? kErrorStyle : QString());
    m_status->setVisible(!text.isEmpty());
}

QString ArPreviewPanel::statusText() const
{
    return m_status->text();
}

void ArPreviewPanel::applyLookAtCamera(bool look)
{
    if (!m_studio || !m_studio->stage())
        return;
    core::runtime::Stage& stage = *m_studio->stage();
    const core::Tick now = m_studio->clock()->time();
    core::motion::GazeSettings listening; // the visitor is the one who talks
    // A camera over a table-top target is often high above the characters: the whole body turns.
    listening.influence = core::motion::GazeInfluence::Waist;
    for (const std::string& name : stage.characterNames()) {
        if (look)
            (void)stage.gaze(name, {core::runtime::GazeTarget::Kind::Camera, {}, {}, {}}, listening, now);
        else
            (void)stage.stopGaze(name, now);
    }
}

} // namespace thespis::editor
