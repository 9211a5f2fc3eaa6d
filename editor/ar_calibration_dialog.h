#pragma once
// ArCalibrationDialog: the AR preview's "Calibrate…". Views of a chessboard or a ChArUco board
// are captured from the live source (its raw frames, shown here; the preview is stopped while the
// dialog is open, since a camera has one reader) or chosen as photos; the calibration runs as
// core's CalibrateJob in a JobRunner with a progress bar and Cancel, then shows the RMS
// reprojection error, how surely the focal lengths are known and which views took part; Save…
// writes the camera file (OpenCV YAML) and hands its path back (cameraSaved).
//
// Owns the live capture, the captured views (a temporary folder, gone with the dialog) and its
// JobRunner; closing the dialog cancels a running calibration.

#include <QDialog>
#include <QImage>
#include <QTemporaryDir>

#include <memory>
#include <optional>

#include "ar/camera_file.h"
#include "editor/ar_sources.h"
#include "util/error.h"

class QCheckBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QProgressBar;
class QPushButton;
class QTimer;

namespace thespis::core::ar {
class LiveCapture;
}
namespace thespis::widgets {
class VideoView;
}

namespace thespis::editor {

class JobRunner;

class ArCalibrationDialog : public QDialog {
    Q_OBJECT
public:
    /// `source`: where views are captured from; `board`: the board text to start with (a
    /// chessboard or ChArUco board; anything else starts with a 9 × 6 chessboard); `folder`: where
    /// Save… proposes the camera file.
    ArCalibrationDialog(const ArSource& source, const QString& board, const QString& folder, QWidget* parent = nullptr);
    ~ArCalibrationDialog() override;

    /// The newest live frame as a view; false when there is none yet.
    bool captureView();
    /// Photos of the board as views.
    void addPhotos(const QStringList& paths);
    int viewCount() const;
    /// Runs the calibration over the views (refused with a message when the board does not parse
    /// or there are too few views).
    void calibrate();
    void cancel();
    bool isRunning() const;
    /// The calibrated camera, after a calibration succeeded.
    const std::optional<core::ar::CameraIntrinsics>& camera() const { return m_camera; }
    /// Writes the calibrated camera to `path`; emits cameraSaved. Errors: none calibrated, the writer's.
    core::Result<void> saveTo(const QString& path);

    QLineEdit* boardEdit() const { return m_board; }
    QListWidget* viewList() const { return m_views; }
    QPushButton* captureButton() const { return m_capture; }
    QPushButton* calibrateButton() const { return m_calibrate; }
    QPushButton* cancelButton() const { return m_cancel; }
    QPushButton* saveButton() const { return m_save; }
    QProgressBar* progressBar() const { return m_progress; }
    /// The outcome: RMS and deviations, or why it failed.
    QString resultText() const;
    widgets::VideoView* liveView() const { return m_live; }

signals:
    void cameraSaved(const QString& path);

protected:
    void done(int result) override;

private:
    void openLive();
    void pollLive();
    void onBoardEdited();
    void onProgress(const QString& stage, qint64 done, qint64 total);
    void onFinished(const core::Result<void>& result);
    void updateEnabled();
    void setResult(const QString& text, bool error);
    void addView(const QString& path);

    ArSource m_source;
    QString m_folder;
    QTemporaryDir m_captures;
    int m_captured = 0;
    std::unique_ptr<core::ar::LiveCapture> m_liveCapture; // null when the source cannot be read
    QImage m_lastFrame;
    JobRunner* m_job = nullptr;
    std::optional<core::ar::CameraIntrinsics> m_camera;
    QTimer* m_timer = nullptr;

    widgets::VideoView* m_live = nullptr;
    QLineEdit* m_board = nullptr;
    QLabel* m_boardMessage = nullptr;
    QCheckBox* m_squarePixels = nullptr;
    QListWidget* m_views = nullptr;
    QPushButton* m_capture = nullptr;
    QPushButton* m_addPhotos = nullptr;
    QPushButton* m_remove = nullptr;
    QPushButton* m_calibrate = nullptr;
    QPushButton* m_cancel = nullptr;
    QPushButton* m_save = nullptr;
    QProgressBar* m_progress = nullptr;
    QLabel* m_result = nullptr;
};

} // namespace thespis::editor
