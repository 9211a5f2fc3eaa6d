#pragma once
// ArPreviewPanel: the studio's AR Preview (paper §7.2, issue 16 §6) — the scenario played over
// video from a camera, a video file, a folder of pictures or the test pattern, registered on a
// tracked target (a marker board, or a printed picture of a known width). It picks the source,
// the camera file (or calibrates one: ArCalibrationDialog), the target, and where the world
// sits on the target (scale, heading, offset, shadows: the scenario's ArSpec, each change one
// undoable edit); Start / Stop run a core ArSession (capture, tracking and drawing on three
// threads of their own), whose newest composed frame a timer on the GUI thread takes about
// 60 times a second and shows in a VideoView with the frame rate, latency and tracking state.
// Record… writes what is shown to a video.
//
// What plays over the video is the Session's Stage, drawn with the poses the Session publishes
// each tick: scripts, live actions, the playhead and edits show in AR at once. The clock is a
// choice: the studio's transport (the default: play, scrub and loop there), or the video's
// time, which then moves the studio's playhead frame by frame.
//
// Nothing that can go wrong leaves a dialog storm or a frozen window: what is missing or wrong
// (no camera, a camera file that is corrupt or for another size, a board spec that does not
// parse) is said beside the field and in the view, and Start stays disabled until it is fixed;
// a source that ends or fails (a video's end, a frame that cannot be decoded, a camera
// unplugged) stops the preview with the reason in the view, ready to start again.
//
// Owns the session (a stopped one is taken down on a thread of its own, so Stop never waits for
// the drawing thread) and the calibration dialog while it is open.

#include <QPointer>
#include <QString>
#include <QWidget>

#include <memory>
#include <optional>
#include <thread>

#include "ar/board.h"
#include "ar/camera_file.h"
#include "editor/ar_sources.h"
#include "editor/scene_sources.h"
#include "render/ar_session.h"
#include "util/error.h"

class QBoxLayout;
class QButtonGroup;
class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QGridLayout;
class QGroupBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QRadioButton;
class QStackedWidget;
class QTimer;

namespace thespis::widgets {
class VideoView;
}

namespace thespis::editor {

class ArCalibrationDialog;
class Document;
class Session;

class ArPreviewPanel : public QWidget {
    Q_OBJECT
public:
    explicit ArPreviewPanel(QWidget* parent = nullptr);
    ~ArPreviewPanel() override;

    /// The scenario played and placed (null: none). A running preview stops first.
    void setDocument(Document* document);
    Document* document() const { return m_document; }
    /// The session whose stage plays over the video, and whose clock a video clock moves.
    void setSession(Session* session);
    /// Which clock the scenario plays by over the video.
    enum class Clock { Transport, Video };
    void setClock(Clock clock);
    Clock clock() const;

    // ---- What plays (each as choosing it in the panel does) --------------------------------
    void chooseTestPattern();
    void chooseVideoFile(const QString& path);
    void chooseImageFolder(const QString& folder);
    /// A camera by its /dev/video index; shows "No camera found" when there is none.
    void chooseCamera(int index = -1);
    /// Looks for cameras again (one may have been plugged in).
    void refreshCameras();
    const ArSource& source() const { return m_source; }
    /// The camera file (empty: none). Read at once; what is wrong with it is said beside it.
    void setCameraFile(const QString& path);
    void setBoardSpec(const QString& text);
    /// A printed picture as the target, `width` metres wide.
    void setPictureTarget(const QString& path, double width);

    /// Why Start is disabled (the first thing to fix), empty when the preview can start.
    QString readiness() const;
    /// Starts the preview; false (the view says why) when it cannot.
    bool start();
    void stop();
    bool isRunning() const { return m_session != nullptr; }
    /// Records the preview to a video (.mp4 / .avi) until stopRecording() or the end.
    core::Result<void> startRecording(const QString& path);
    void stopRecording();
    bool isRecording() const;
    /// Opens the calibration dialog on the chosen source (the preview stops while it is open).
    ArCalibrationDialog* openCalibration();

    /// The frame shown (−1: none) and its tracking.
    std::int64_t shownFrame() const { return m_snapshot.tracking.frame; }
    const core::render::ArSnapshot& lastSnapshot() const { return m_snapshot; }
    /// The text of the status line (recordings, why a start failed).
    QString statusText() const;

    widgets::VideoView* view() const { return m_view; }
    QComboBox* sourceKindCombo() const { return m_sourceKind; }
    QComboBox* cameraCombo() const { return m_cameras; }
    QComboBox* cameraSizeCombo() const { return m_cameraSize; }
    QComboBox* cameraRateCombo() const { return m_cameraRate; }
    QLabel* sourceInfoLabel() const { return m_sourceInfo; }
    QLabel* cameraFileLabel() const { return m_cameraMessage; }
    QLineEdit* boardEdit() const { return m_board; }
    QLabel* targetMessageLabel() const { return m_targetMessage; }
    QDoubleSpinBox* scaleSpin() const { return m_scale; }
    QDoubleSpinBox* headingSpin() const { return m_heading; }
    QDoubleSpinBox* offsetXSpin() const { return m_offset[0]; }
    QDoubleSpinBox* offsetYSpin() const { return m_offset[1]; }
    QCheckBox* shadowsCheck() const { return m_shadows; }
    QCheckBox* smoothCheck() const { return m_smooth; }
    QCheckBox* mirrorBallCheck() const { return m_mirrorBall; }
    QCheckBox* lookAtCameraCheck() const { return m_lookAtCamera; }
    QComboBox* clockCombo() const { return m_clock; }
    QPushButton* startButton() const { return m_start; }
    QPushButton* stopButton() const { return m_stop; }
    QPushButton* recordButton() const { return m_record; }
    QPushButton* calibrateButton() const { return m_calibrate; }

signals:
    /// The preview started or stopped (by the user, or because its source ended or failed).
    void runningChanged(bool running);

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    void buildSourceGroup(QGroupBox* group);
    void buildCameraGroup(QGroupBox* group);
    void buildTargetGroup(QGroupBox* group);
    void buildPlacementGroup(QGroupBox* group);
    void arrange(bool wide);
    void onSourceKindChosen();
    void probeSource();
    void onTargetEdited();
    void checkTarget();
    void checkCamera();
    void refreshPlacement();
    void pushPlacement();
    void updateEnabled();
    void poll();
    /// Turns every character to the camera, or lets go, as "Characters look at the camera" says.
    void applyLookAtCamera(bool look);
    void showSnapshot();
    void followVideo();
    // After an edit: the same scene plays on, or the preview starts again with the new one.
    void onStudioEdited(bool stageReplaced);
    void onSessionEnded();
    void retire();
    void forgetFailedStart();
    void setStatus(const QString& text, bool error);
    std::optional<core::ar::BoardSpec> board() const;
    std::optional<core::ar::TrackingTarget> target() const;

    QPointer<Document> m_document;
    QPointer<Session> m_studio; // the Session (m_session is the AR session)
    ArSource m_source;
    std::optional<ArSourceInfo> m_sourceInfoValue; // what the source gives, once probed
    QString m_sourceError;                        // why it cannot be read
    QString m_cameraPath;
    std::optional<core::ar::CameraIntrinsics> m_camera;
    QString m_cameraError;
    QString m_targetError;
    std::unique_ptr<core::render::ArSession> m_session;
    std::jthread m_retiring; // takes a stopped session down
    core::render::ArSnapshot m_snapshot;
    std::uint64_t m_probeVersion = 0; // of the mirror ball's picture shown
    QString m_recordingPath;
    QString m_endTitle, m_endText; // how the last run ended, or why it could not start
    SceneSources m_sources;        // what the running session's scene was built from
    bool m_startFailed = false;    // m_end* say why a start failed
    QTimer* m_timer = nullptr;
    QPointer<ArCalibrationDialog> m_calibration;
    bool m_refreshing = false;
    bool m_wide = false;

    QBoxLayout* m_layout = nullptr;
    QGridLayout* m_groups = nullptr;
    QList<QGroupBox*> m_groupBoxes;
    QWidget* m_controls = nullptr;
    widgets::VideoView* m_view = nullptr;
    QComboBox* m_sourceKind = nullptr;
    QStackedWidget* m_sourcePages = nullptr;
    QLineEdit* m_videoPath = nullptr;
    QLineEdit* m_folderPath = nullptr;
    QDoubleSpinBox* m_folderFps = nullptr;
    QComboBox* m_cameras = nullptr;
    QComboBox* m_cameraSize = nullptr; ///< data: the size asked of the camera (empty: the camera file's)
    QComboBox* m_cameraRate = nullptr; ///< data: frames a second asked of the camera
    QLabel* m_sourceInfo = nullptr;
    QLineEdit* m_cameraFile = nullptr;
    QPushButton* m_chooseCameraFile = nullptr;
    QPushButton* m_calibrate = nullptr;
    QLabel* m_cameraMessage = nullptr;
    QRadioButton* m_boardChoice = nullptr;
    QRadioButton* m_pictureChoice = nullptr;
    QLineEdit* m_board = nullptr;
    QLineEdit* m_picturePath = nullptr;
    QPushButton* m_choosePicture = nullptr;
    QDoubleSpinBox* m_pictureWidth = nullptr;
    QLabel* m_targetMessage = nullptr;
    QDoubleSpinBox* m_scale = nullptr;
    QDoubleSpinBox* m_heading = nullptr;
    QDoubleSpinBox* m_offset[2] = {nullptr, nullptr};
    QCheckBox* m_shadows = nullptr;
    QCheckBox* m_mirrorBall = nullptr;
    QCheckBox* m_smooth = nullptr;
    QCheckBox* m_lookAtCamera = nullptr;
    QComboBox* m_clock = nullptr; ///< data: Clock
    QPushButton* m_start = nullptr;
    QPushButton* m_stop = nullptr;
    QPushButton* m_record = nullptr;
    QLabel* m_status = nullptr;
};

} // namespace thespis::editor
