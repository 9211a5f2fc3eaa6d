#include "editor/ar_calibration_dialog.h"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QProgressBar>
#include <QPushButton>
#include <QTimer>
#include <QVBoxLayout>

#include <algorithm>

#include "ar/calibrate_job.h"
#include "ar/live_capture.h"
#include "editor/job_runner.h"
#include "editor/qt_conversions.h"
#include "widgets/video_view.h"

namespace thespis::editor {

namespace {

namespace ar = core::ar;

const QString kDefaultBoard = QStringLiteral("chessboard:9x6:0.025");
const QString kErrorStyle = QStringLiteral("color: #c0392b;");
constexpr int kLiveIntervalMs = 33;
constexpr int kThumbnailWidth = 96;

// The board text when it can calibrate (a chessboard or a ChArUco board), else the default.
QString calibrationBoard(const QString& text)
{
    const auto board = ar::parseBoard(text.trimmed().toStdString());
    return board && board->kind != ar::BoardKind::ArucoGrid ? text.trimmed() : kDefaultBoard;
}

} // namespace

ArCalibrationDialog::ArCalibrationDialog(const ArSource& source, const QString& board, const QString& folder,
                                         QWidget* parent)
    : QDialog(parent), m_source(source), m_folder(folder), m_job(new JobRunner(this)), m_timer(new QTimer(this))
{
    setObjectName(QStringLiteral("arCalibrationDialog"));
    setWindowTitle(tr("Calibrate the Camera"));

    m_live = new widgets::VideoView(this);
    m_live->setObjectName(QStringLiteral("calibrationLiveView"));
    m_live->setMinimumSize(320, 240);

    m_board = new QLineEdit(calibrationBoard(board), this);
    m_board->setObjectName(QStringLiteral("calibrationBoard"));
    m_board->setToolTip(tr("chessboard:COLUMNSxROWS:SQUARE (inner corners, metres) or "
                           "charuco:DICTIONARY:COLUMNSxROWS:SQUARE:MARKER"));
    m_boardMessage = new QLabel(this);
    m_boardMessage->setWordWrap(true);
    m_boardMessage->setStyleSheet(kErrorStyle);
    m_squarePixels = new QCheckBox(tr("Square pixels (fx = fy)"), this);

    m_views = new QListWidget(this);
    m_views->setObjectName(QStringLiteral("calibrationViews"));
    m_views->setIconSize(QSize(kThumbnailWidth, kThumbnailWidth * 3 / 4));
    m_views->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_capture = new QPushButton(tr("Capture View"), this);
    m_capture->setObjectName(QStringLiteral("captureView"));
    m_capture->setToolTip(tr("Keep the picture shown as a view of the board; hold the board at many angles"));
    m_addPhotos = new QPushButton(tr("Add Photos…"), this);
    m_remove = new QPushButton(tr("Remove"), this);

    m_calibrate = new QPushButton(tr("Calibrate"), this);
    m_calibrate->setObjectName(QStringLiteral("runCalibration"));
    m_cancel = new QPushButton(tr("Cancel"), this);
    m_progress = new QProgressBar(this);
    m_progress->setRange(0, 1);
    m_progress->setValue(0);
    m_progress->setFormat(tr("Not calibrating"));
    m_progress->setAlignment(Qt::AlignCenter);
    m_result = new QLabel(this);
    m_result->setObjectName(QStringLiteral("calibrationResult"));
    m_result->setWordWrap(true);
    m_result->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_save = new QPushButton(tr("Save Camera File…"), this);
    m_save->setObjectName(QStringLiteral("saveCamera"));

    auto* viewButtons = new QHBoxLayout;
    viewButtons->addWidget(m_capture);
    viewButtons->addWidget(m_addPhotos);
    viewButtons->addWidget(m_remove);
    viewButtons->addStretch(1);
    auto* form = new QFormLayout;
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    form->addRow(tr("Board:"), m_board);
    form->addRow(QString(), m_boardMessage);
    form->addRow(QString(), m_squarePixels);
    auto* run = new QHBoxLayout;
    run->addWidget(m_calibrate);
    run->addWidget(m_cancel);
    run->addWidget(m_progress, 1);
    auto* close = new QDialogButtonBox(QDialogButtonBox::Close, this);
    close->addButton(m_save, QDialogButtonBox::ActionRole);

    auto* right = new QVBoxLayout;
    right->addLayout(form);
    right->addWidget(new QLabel(tr("Views of the board:"), this));
    right->addWidget(m_views, 1);
    right->addLayout(viewButtons);
    right->addLayout(run);
    right->addWidget(m_result);
    auto* top = new QHBoxLayout;
    top->addWidget(m_live, 3);
    top->addLayout(right, 2);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(top, 1);
    layout->addWidget(close);

    connect(close, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_capture, &QPushButton::clicked, this, [this] { captureView(); });
    connect(m_addPhotos, &QPushButton::clicked, this, [this] {
        const QStringList paths = QFileDialog::getOpenFileNames(this, tr("Choose Photos of the Board"), m_folder,
                                                                tr("Pictures (*.png *.jpg *.jpeg *.bmp *.tif *.tiff)"));
        addPhotos(paths);
    });
    connect(m_remove, &QPushButton::clicked, this, [this] {
        qDeleteAll(m_views->selectedItems());
        m_camera.reset();
        updateEnabled();
    });
    connect(m_views, &QListWidget::itemSelectionChanged, this, &ArCalibrationDialog::updateEnabled);
    connect(m_calibrate, &QPushButton::clicked, this, &ArCalibrationDialog::calibrate);
    connect(m_cancel, &QPushButton::clicked, this, &ArCalibrationDialog::cancel);
    connect(m_save, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getSaveFileName(this, tr("Save the Camera File"),
                                                          QDir(m_folder).filePath(QStringLiteral("camera.yml")),
                                                          tr("Camera files (*.yml *.yaml *.xml *.json)"));
        if (path.isEmpty())
            return;
        if (auto saved = saveTo(path); !saved)
            setResult(tr("The camera file could not be written: %1").arg(fromUtf8(saved.error().message)), true);
        else
            accept();
    });
    connect(m_board, &QLineEdit::textChanged, this, &ArCalibrationDialog::onBoardEdited);
    connect(m_job, &JobRunner::progress, this, &ArCalibrationDialog::onProgress);
    connect(m_job, &JobRunner::finished, this, &ArCalibrationDialog::onFinished);
    connect(m_timer, &QTimer::timeout, this, &ArCalibrationDialog::pollLive);
    m_timer->setInterval(kLiveIntervalMs);

    resize(960, 560);
    onBoardEdited();
    openLive();
}

ArCalibrationDialog::~ArCalibrationDialog()
{
    // The job's thread reports to this dialog: stop it before the widgets go.
    disconnect(m_job, nullptr, this, nullptr);
    delete m_job;
    m_liveCapture.reset();
}

void ArCalibrationDialog::done(int result)
{
    cancel();
    m_timer->stop();
    m_liveCapture.reset(); // give the camera back to the preview at once
    QDialog::done(result);
}

void ArCalibrationDialog::openLive()
{
    m_timer->stop();
    m_liveCapture.reset();
    m_lastFrame = QImage();
    m_live->clearImage();
    const auto board = ar::parseBoard(m_board->text().trimmed().toStdString());
    if (m_source.kind == ArSource::Kind::TestPattern && !board) {
        m_live->setMessage(tr("No picture"), tr("The test pattern shows the board typed here: fix its spec."));
        updateEnabled();
        return;
    }
    auto source = openArSource(m_source, board ? *board : ar::BoardSpec{}, {});
    if (!source) {
        m_live->setMessage(tr("No live picture"),
                           tr("%1\nAdd photos of the board instead.").arg(fromUtf8(source.error().message)));
        updateEnabled();
        return;
    }
    m_liveCapture = std::make_unique<ar::LiveCapture>(std::move(source).value());
    m_live->setMessage(tr("Waiting for the first picture…"));
    m_timer->start();
    updateEnabled();
}

void ArCalibrationDialog::pollLive()
{
    if (!m_liveCapture)
        return;
    ar::VideoFrame frame;
    if (m_liveCapture->takeNewest(frame)) {
        m_lastFrame = toQImage(frame);
        m_live->setImage(m_lastFrame);
        m_live->setMessage({});
        m_live->setOverlay({{tr("Hold the board at many angles, filling the picture"), tr("%n view(s) so far", nullptr, viewCount())},
                            widgets::VideoOverlay::Status::Neutral});
    } else if (m_liveCapture->state() != ar::CaptureState::Running) {
        m_timer->stop();
        m_live->setMessage(m_liveCapture->state() == ar::CaptureState::Ended ? tr("Ended") : tr("Stopped"),
                           fromUtf8(m_liveCapture->message()));
    }
    updateEnabled();
}

bool ArCalibrationDialog::captureView()
{
    if (m_lastFrame.isNull() || !m_captures.isValid())
        return false;
    const QString path = m_captures.filePath(QStringLiteral("view-%1.png").arg(++m_captured, 3, 10, QChar(u'0')));
    if (!m_lastFrame.save(path)) {
        setResult(tr("The view could not be kept in %1.").arg(QDir::toNativeSeparators(m_captures.path())), true);
        return false;
    }
    addView(path);
    return true;
}

void ArCalibrationDialog::addPhotos(const QStringList& paths)
{
    for (const QString& path : paths)
        addView(path);
}

void ArCalibrationDialog::addView(const QString& path)
{
    auto* item = new QListWidgetItem(QFileInfo(path).fileName(), m_views);
    item->setData(Qt::UserRole, path);
    item->setToolTip(QDir::toNativeSeparators(path));
    const QImage picture(path);
    if (!picture.isNull())
        item->setIcon(QPixmap::fromImage(picture.scaledToWidth(kThumbnailWidth, Qt::SmoothTransformation)));
    m_camera.reset();
    updateEnabled();
}

int ArCalibrationDialog::viewCount() const
{
    return m_views->count();
}

void ArCalibrationDialog::onBoardEdited()
{
    const auto board = ar::parseBoard(m_board->text().trimmed().toStdString());
    if (!board)
        m_boardMessage->setText(fromUtf8(board.error().message));
    else if (board->kind == ar::BoardKind::ArucoGrid)
        m_boardMessage->setText(tr("An ArUco grid is for tracking only: calibrate with a chessboard or a ChArUco board."));
    else
        m_boardMessage->clear();
    m_boardMessage->setVisible(!m_boardMessage->text().isEmpty());
    if (m_source.kind == ArSource::Kind::TestPattern && board)
        openLive(); // the test pattern shows the board being calibrated with
    updateEnabled();
}

void ArCalibrationDialog::calibrate()
{
    if (isRunning())
        return;
    const auto board = ar::parseBoard(m_board->text().trimmed().toStdString());
    if (!board) {
        setResult(fromUtf8(board.error().message), true);
        return;
    }
    auto job = std::make_unique<ar::CalibrateJob>();
    job->board = *board;
    job->fixAspectRatio = m_squarePixels->isChecked();
    for (int i = 0; i < m_views->count(); ++i)
        job->images.push_back(toFsPath(m_views->item(i)->data(Qt::UserRole).toString()));
    m_camera.reset();
    if (auto started = m_job->start(std::move(job)); !started) {
        setResult(fromUtf8(started.error().message), true);
        return;
    }
    onProgress({}, 0, m_views->count());
    setResult(tr("Calibrating from %n view(s)…", nullptr, m_views->count()), false);
    updateEnabled();
}

void ArCalibrationDialog::cancel()
{
    m_job->cancel();
}

bool ArCalibrationDialog::isRunning() const
{
    return m_job->isRunning();
}

void ArCalibrationDialog::onProgress(const QString& stage, qint64 done, qint64 total)
{
    const QString name = stage == QLatin1String(ar::CalibrateJob::SolvingStage) ? tr("Calibrating")
                                                                                 : tr("Finding the board");
    m_progress->setRange(0, int(std::max<qint64>(total, 1)));
    m_progress->setValue(int(std::min(done, std::max<qint64>(total, 1))));
    m_progress->setFormat(total > 0 ? tr("%1: %2 / %3").arg(name).arg(done).arg(total) : name);
}

void ArCalibrationDialog::onFinished(const core::Result<void>& result)
{
    const auto* job = m_job->jobAs<ar::CalibrateJob>();
    // Which views took part, and how well each fits.
    if (job)
        for (const ar::CalibrateJob::View& view : job->views)
            for (int i = 0; i < m_views->count(); ++i) {
                QListWidgetItem* item = m_views->item(i);
                if (toFsPath(item->data(Qt::UserRole).toString()) != view.image)
                    continue;
                const QString name = QFileInfo(item->data(Qt::UserRole).toString()).fileName();
                item->setText(view.found ? (view.error >= 0 ? tr("%1 — %2 px").arg(name).arg(view.error, 0, 'f', 2)
                                                            : tr("%1 — found").arg(name))
                                         : tr("%1 — board not found").arg(name));
            }
    m_progress->setRange(0, 1);
    m_progress->setValue(result ? 1 : 0);
    if (!result) {
        const bool cancelled = result.error().code == core::ErrorCode::Cancelled;
        m_progress->setFormat(cancelled ? tr("Cancelled") : tr("Failed"));
        setResult(cancelled ? tr("Cancelled.") : fromUtf8(result.error().message), !cancelled);
        updateEnabled();
        return;
    }
    m_camera = job->camera;
    int used = 0;
    for (const ar::CalibrateJob::View& view : job->views)
        used += view.found ? 1 : 0;
    m_progress->setFormat(tr("Done"));
    setResult(tr("RMS reprojection error %1 px over %2 of %3 views, %4 × %5.\n"
                 "fx %6 ± %7, fy %8 ± %9, centre (%10, %11) px.")
                  .arg(m_camera->reprojectionError, 0, 'f', 3)
                  .arg(used)
                  .arg(job->views.size())
                  .arg(m_camera->width)
                  .arg(m_camera->height)
                  .arg(m_camera->fx(), 0, 'f', 1)
                  .arg(job->deviations[0], 0, 'f', 1)
                  .arg(m_camera->fy(), 0, 'f', 1)
                  .arg(job->deviations[1], 0, 'f', 1)
                  .arg(m_camera->cx(), 0, 'f', 1)
                  .arg(m_camera->cy(), 0, 'f', 1),
              false);
    updateEnabled();
}

core::Result<void> ArCalibrationDialog::saveTo(const QString& path)
{
    if (!m_camera)
        return core::makeError(core::ErrorCode::InvalidArgument, tr("Calibrate first.").toStdString());
    if (auto written = ar::writeCameraFile(toFsPath(path), *m_camera); !written)
        return written;
    emit cameraSaved(path);
    return {};
}

QString ArCalibrationDialog::resultText() const
{
    return m_result->text();
}

void ArCalibrationDialog::updateEnabled()
{
    const bool running = isRunning();
    const auto board = ar::parseBoard(m_board->text().trimmed().toStdString());
    const bool boardOk = board && board->kind != ar::BoardKind::ArucoGrid;
    m_capture->setEnabled(!running && !m_lastFrame.isNull());
    m_addPhotos->setEnabled(!running);
    m_remove->setEnabled(!running && !m_views->selectedItems().isEmpty());
    m_board->setEnabled(!running);
    m_squarePixels->setEnabled(!running);
    m_calibrate->setEnabled(!running && boardOk && m_views->count() >= ar::CalibrateJob::MinimumViews);
    m_calibrate->setToolTip(m_views->count() < ar::CalibrateJob::MinimumViews
                                ? tr("At least %1 views of the board are needed").arg(ar::CalibrateJob::MinimumViews)
                                : QString());
    m_cancel->setEnabled(running);
    m_save->setEnabled(!running && m_camera.has_value());
}

void ArCalibrationDialog::setResult(const QString& text, bool error)
{
    m_result->setText(text);
    m_result->setStyleSheet(error ? kErrorStyle : QString());
}

} // namespace thespis::editor
