// ArPreviewPanel's controls: building them, and what they say about the source, the camera file
// and the target (the session and the document are in ar_preview_panel.cpp).

#include "editor/ar_preview_panel.h"

#include <QBoxLayout>
#include <QButtonGroup>
#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRadioButton>
#include <QResizeEvent>
#include <QSettings>
#include <QStackedWidget>

#include <algorithm>

#include "edit/ar_edits.h"
#include "editor/ar_preview_settings.h"
#include "editor/document.h"
#include "editor/qt_conversions.h"

namespace thespis::editor {

using namespace ar_preview;

namespace {

namespace ar = core::ar;

QDoubleSpinBox* spinBox(double min, double max, int decimals, const QString& suffix, const QString& name, QWidget* parent)
{
    auto* box = new QDoubleSpinBox(parent);
    box->setObjectName(name);
    box->setRange(min, max);
    box->setDecimals(decimals);
    box->setSuffix(suffix);
    box->setKeyboardTracking(false);
    box->setStepType(QAbstractSpinBox::AdaptiveDecimalStepType);
    return box;
}

// A row of a path field and the button that chooses it.
QWidget* pathRow(QLineEdit* field, QPushButton* button, QWidget* parent, QWidget* extra = nullptr)
{
    auto* row = new QWidget(parent);
    auto* layout = new QHBoxLayout(row);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(field, 1);
    if (extra)
        layout->addWidget(extra);
    layout->addWidget(button);
    return row;
}

QString sizeText(QSize size)
{
    return QStringLiteral("%1 × %2").arg(size.width()).arg(size.height());
}

} // namespace

// ---- Building ----------------------------------------------------------------------------------

void ArPreviewPanel::buildSourceGroup(QGroupBox* group)
{
    m_sourceKind = new QComboBox(group);
    m_sourceKind->setObjectName(QStringLiteral("arSourceKind"));
    m_sourceKind->addItem(tr("Test pattern (a synthetic board)"));
    m_sourceKind->addItem(tr("Video file"));
    m_sourceKind->addItem(tr("Folder of pictures"));
    m_sourceKind->addItem(tr("Camera"));
    m_sourcePages = new QStackedWidget(group);

    auto* pattern = new QLabel(tr("A board moving as if hand-held, seen by a known camera: nothing to print or "
                                  "calibrate. It shows the target's board."),
                               group);
    pattern->setWordWrap(true);
    m_sourcePages->addWidget(pattern);

    m_videoPath = new QLineEdit(group);
    m_videoPath->setObjectName(QStringLiteral("arVideoPath"));
    m_videoPath->setPlaceholderText(tr("No video chosen"));
    auto* chooseVideo = new QPushButton(tr("Choose…"), group);
    m_sourcePages->addWidget(pathRow(m_videoPath, chooseVideo, group));
    connect(chooseVideo, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getOpenFileName(this, tr("Choose a Video"), QFileInfo(m_source.path).absolutePath(),
                                                          tr("Videos (*.mp4 *.avi *.mov *.mkv *.webm);;All files (*)"));
        if (!path.isEmpty())
            chooseVideoFile(path);
    });
    connect(m_videoPath, &QLineEdit::editingFinished, this, [this] {
        if (!m_refreshing && QDir::fromNativeSeparators(m_videoPath->text().trimmed()) != m_source.path)
            chooseVideoFile(QDir::fromNativeSeparators(m_videoPath->text().trimmed()));
    });

    m_folderPath = new QLineEdit(group);
    m_folderPath->setObjectName(QStringLiteral("arFolderPath"));
    m_folderPath->setPlaceholderText(tr("No folder chosen"));
    m_folderFps = spinBox(1, 240, 1, tr(" fps"), QStringLiteral("arFolderFps"), group);
    m_folderFps->setValue(30);
    m_folderFps->setToolTip(tr("How many pictures a second the folder plays"));
    auto* chooseFolder = new QPushButton(tr("Choose…"), group);
    m_sourcePages->addWidget(pathRow(m_folderPath, chooseFolder, group, m_folderFps));
    connect(chooseFolder, &QPushButton::clicked, this, [this] {
        const QString folder = QFileDialog::getExistingDirectory(this, tr("Choose a Folder of Pictures"), m_source.path);
        if (!folder.isEmpty())
            chooseImageFolder(folder);
    });
    connect(m_folderPath, &QLineEdit::editingFinished, this, [this] {
        if (!m_refreshing && QDir::fromNativeSeparators(m_folderPath->text().trimmed()) != m_source.path)
            chooseImageFolder(QDir::fromNativeSeparators(m_folderPath->text().trimmed()));
    });
    connect(m_folderFps, &QDoubleSpinBox::valueChanged, this, [this](double fps) {
        m_source.fps = fps;
        if (m_source.kind == ArSource::Kind::ImageFolder)
            probeSource();
    });

    m_cameras = new QComboBox(group);
    m_cameras->setObjectName(QStringLiteral("arCameras"));
    auto* rescan = new QPushButton(tr("Rescan"), group);
    rescan->setToolTip(tr("Look for cameras again (after plugging one in)"));
    m_cameraSize = new QComboBox(group);
    m_cameraSize->setObjectName(QStringLiteral("arCameraSize"));
    m_cameraSize->setToolTip(tr("The picture size asked of the camera; its camera file must be for the same size"));
    m_cameraSize->addItem(tr("Camera file's size"), QSize());
    for (const QSize size : {QSize(640, 480), QSize(1280, 720), QSize(1920, 1080)})
        m_cameraSize->addItem(sizeText(size), size);
    m_cameraRate = new QComboBox(group);
    m_cameraRate->setObjectName(QStringLiteral("arCameraRate"));
    m_cameraRate->setToolTip(tr("Frames a second asked of the camera (it may give fewer in dim light)"));
    for (const double fps : {15.0, 24.0, 25.0, 30.0, 60.0})
        m_cameraRate->addItem(tr("%1 fps").arg(fps), fps);
    m_cameraRate->setCurrentIndex(m_cameraRate->findData(30.0));
    auto* cameraPage = new QWidget(group);
    auto* cameraLayout = new QGridLayout(cameraPage);
    cameraLayout->setContentsMargins(0, 0, 0, 0);
    cameraLayout->addWidget(m_cameras, 0, 0, 1, 2);
    cameraLayout->addWidget(rescan, 0, 2);
    cameraLayout->addWidget(m_cameraSize, 1, 0);
    cameraLayout->addWidget(m_cameraRate, 1, 1, 1, 2);
    m_sourcePages->addWidget(cameraPage);
    connect(rescan, &QPushButton::clicked, this, &ArPreviewPanel::refreshCameras);
    connect(m_cameras, &QComboBox::activated, this, [this] { chooseCamera(m_cameras->currentData().toInt()); });
    connect(m_cameraSize, &QComboBox::activated, this, [this] {
        const QSize size = m_cameraSize->currentData().toSize();
        storeSetting("cameraSize", size.isEmpty() ? QString() : QStringLiteral("%1x%2").arg(size.width()).arg(size.height()));
        if (m_source.kind == ArSource::Kind::Camera)
            chooseCamera();
    });
    connect(m_cameraRate, &QComboBox::activated, this, [this] {
        storeSetting("cameraFps", m_cameraRate->currentData());
        if (m_source.kind == ArSource::Kind::Camera)
            chooseCamera();
    });

    m_sourceInfo = new QLabel(group);
    m_sourceInfo->setObjectName(QStringLiteral("arSourceInfo"));
    m_sourceInfo->setWordWrap(true);
    auto* layout = new QVBoxLayout(group);
    layout->addWidget(m_sourceKind);
    layout->addWidget(m_sourcePages);
    layout->addWidget(m_sourceInfo);
    connect(m_sourceKind, &QComboBox::activated, this, &ArPreviewPanel::onSourceKindChosen);
}

void ArPreviewPanel::buildCameraGroup(QGroupBox* group)
{
    m_cameraFile = new QLineEdit(group);
    m_cameraFile->setObjectName(QStringLiteral("arCameraFile"));
    m_cameraFile->setPlaceholderText(tr("No camera file chosen"));
    m_cameraFile->setToolTip(tr("The camera's intrinsics as OpenCV writes them (.yml, .yaml, .xml, .json)"));
    m_chooseCameraFile = new QPushButton(tr("Choose…"), group);
    m_calibrate = new QPushButton(tr("Calibrate…"), group);
    m_calibrate->setObjectName(QStringLiteral("arCalibrate"));
    m_calibrate->setToolTip(tr("Calibrate the camera from views of a chessboard or a ChArUco board"));
    m_cameraMessage = new QLabel(group);
    m_cameraMessage->setObjectName(QStringLiteral("arCameraMessage"));
    m_cameraMessage->setWordWrap(true);
    auto* layout = new QVBoxLayout(group);
    QWidget* row = pathRow(m_cameraFile, m_chooseCameraFile, group);
    row->layout()->addWidget(m_calibrate);
    layout->addWidget(row);
    layout->addWidget(m_cameraMessage);
    connect(m_chooseCameraFile, &QPushButton::clicked, this, [this] {
        const QString folder = m_cameraPath.isEmpty() ? (m_document ? m_document->baseDir() : QString())
                                                      : QFileInfo(m_cameraPath).absolutePath();
        const QString path = QFileDialog::getOpenFileName(this, tr("Choose a Camera File"), folder,
                                                          tr("Camera files (*.yml *.yaml *.xml *.json);;All files (*)"));
        if (!path.isEmpty())
            setCameraFile(path);
    });
    connect(m_cameraFile, &QLineEdit::editingFinished, this, [this] {
        if (!m_refreshing && QDir::fromNativeSeparators(m_cameraFile->text().trimmed()) != m_cameraPath)
            setCameraFile(QDir::fromNativeSeparators(m_cameraFile->text().trimmed()));
    });
    connect(m_calibrate, &QPushButton::clicked, this, [this] { openCalibration(); });
}

void ArPreviewPanel::buildTargetGroup(QGroupBox* group)
{
    m_boardChoice = new QRadioButton(tr("Board:"), group);
    m_boardChoice->setChecked(true);
    m_pictureChoice = new QRadioButton(tr("Picture:"), group);
    auto* choices = new QButtonGroup(group);
    choices->addButton(m_boardChoice);
    choices->addButton(m_pictureChoice);
    m_board = new QLineEdit(group);
    m_board->setObjectName(QStringLiteral("arBoard"));
    m_board->setPlaceholderText(kDefaultBoard);
    m_board->setToolTip(tr("aruco-grid:DICTIONARY:COLUMNSxROWS:MARKER:GAP or "
                           "charuco:DICTIONARY:COLUMNSxROWS:SQUARE:MARKER, lengths in metres"));
    m_picturePath = new QLineEdit(group);
    m_picturePath->setPlaceholderText(tr("A printed picture (PNG, JPEG)"));
    m_choosePicture = new QPushButton(tr("Choose…"), group);
    m_pictureWidth = spinBox(0.01, 10, 3, tr(" m wide"), QStringLiteral("arPictureWidth"), group);
    m_pictureWidth->setValue(0.2);
    m_targetMessage = new QLabel(group);
    m_targetMessage->setObjectName(QStringLiteral("arTargetMessage"));
    m_targetMessage->setWordWrap(true);
    auto* form = new QFormLayout(group);
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    form->addRow(m_boardChoice, m_board);
    form->addRow(m_pictureChoice, pathRow(m_picturePath, m_choosePicture, group));
    form->addRow(tr("Printed:"), m_pictureWidth);
    form->addRow(m_targetMessage);
    connect(m_board, &QLineEdit::textChanged, this, [this] {
        if (m_refreshing)
            return;
        m_boardChoice->setChecked(true);
        storeSetting("board", m_board->text().trimmed());
        onTargetEdited();
    });
    connect(m_boardChoice, &QRadioButton::toggled, this, &ArPreviewPanel::onTargetEdited);
    connect(m_picturePath, &QLineEdit::editingFinished, this, &ArPreviewPanel::onTargetEdited);
    connect(m_pictureWidth, &QDoubleSpinBox::valueChanged, this, &ArPreviewPanel::onTargetEdited);
    connect(m_choosePicture, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getOpenFileName(this, tr("Choose the Printed Picture"), QString(),
                                                          tr("Pictures (*.png *.jpg *.jpeg *.bmp)"));
        if (!path.isEmpty())
            setPictureTarget(path, m_pictureWidth->value());
    });
}

void ArPreviewPanel::buildPlacementGroup(QGroupBox* group)
{
    m_scale = spinBox(0.001, 1000, 3, QString(), QStringLiteral("arScale"), group);
    m_scale->setToolTip(tr("Of life size: 0.1 stands a 1.8 m character 18 cm tall on a desk"));
    m_heading = spinBox(-360, 360, 1, QStringLiteral("°"), QStringLiteral("arHeading"), group);
    m_heading->setWrapping(true);
    m_heading->setSingleStep(5);
    m_heading->setStepType(QAbstractSpinBox::DefaultStepType);
    m_heading->setToolTip(tr("How far the world turns about the target's normal"));
    auto* offsets = new QHBoxLayout;
    const char* axes[] = {"x", "y"};
    for (int axis = 0; axis < 2; ++axis) {
        m_offset[axis] = spinBox(-100, 100, 3, tr(" m"), QStringLiteral("arOffset_") + QLatin1String(axes[axis]), group);
        m_offset[axis]->setPrefix(QLatin1String(axes[axis]) + QStringLiteral(" "));
        m_offset[axis]->setToolTip(tr("Where the world's origin is on the target, from its centre along its own axes"));
        offsets->addWidget(m_offset[axis]);
    }
    m_shadows = new QCheckBox(tr("Shadows on the real ground"), group);
    m_shadows->setObjectName(QStringLiteral("arShadows"));
    auto* form = new QFormLayout(group);
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    form->addRow(tr("Scale:"), m_scale);
    form->addRow(tr("Heading:"), m_heading);
    form->addRow(tr("Offset:"), offsets);
    form->addRow(m_shadows);
    for (QDoubleSpinBox* box : {m_scale, m_heading, m_offset[0], m_offset[1]})
        connect(box, &QDoubleSpinBox::valueChanged, this, &ArPreviewPanel::pushPlacement);
    connect(m_shadows, &QCheckBox::toggled, this, [this](bool on) {
        if (m_refreshing || !m_document)
            return;
        if (auto done = m_document->edit(core::edit::setArShadowCatcher(m_document->scenario(), on),
                                         on ? tr("Show AR Shadows") : tr("Hide AR Shadows"));
            !done) {
            setStatus(fromUtf8(done.error().message), true);
            refreshPlacement();
        }
    });
}

void ArPreviewPanel::arrange(bool wide)
{
    m_wide = wide;
    m_layout->setDirection(wide ? QBoxLayout::LeftToRight : QBoxLayout::TopToBottom);
    for (QGroupBox* group : m_groupBoxes)
        m_groups->removeWidget(group);
    // Wide: what plays on the left, how it is placed and run on the right; tall: one column.
    const int count = int(m_groupBoxes.size());
    const int columns[] = {0, 0, 0, 1, 1};
    const int rows[] = {0, 1, 2, 0, 1};
    for (int i = 0; i < count; ++i)
        m_groups->addWidget(m_groupBoxes[i], wide ? rows[i] : i, wide ? columns[i] : 0, Qt::AlignTop);
    for (int row = 0; row <= count; ++row)
        m_groups->setRowStretch(row, 0);
    m_groups->setRowStretch(wide ? 3 : count, 1); // the rest of the height below the groups
}

void ArPreviewPanel::resizeEvent(QResizeEvent* event)
{
    QWidget::resizeEvent(event);
    const bool wide = event->size().width() > event->size().height() * 5 / 4;
    if (wide != m_wide)
        arrange(wide);
}

// ---- Source, camera and target -----------------------------------------------------------------

void ArPreviewPanel::onSourceKindChosen()
{
    switch (m_sourceKind->currentIndex()) {
    case 0: chooseTestPattern(); break;
    case 1: chooseVideoFile(QDir::fromNativeSeparators(m_videoPath->text().trimmed())); break;
    case 2: chooseImageFolder(QDir::fromNativeSeparators(m_folderPath->text().trimmed())); break;
    default: chooseCamera(m_cameras->currentData().isValid() ? m_cameras->currentData().toInt() : -1); break;
    }
}

void ArPreviewPanel::chooseTestPattern()
{
    m_source = ArSource{ArSource::Kind::TestPattern};
    storeSetting("source", QStringLiteral("test"));
    probeSource();
}

void ArPreviewPanel::chooseVideoFile(const QString& path)
{
    m_source = ArSource{ArSource::Kind::VideoFile, path};
    m_refreshing = true;
    m_videoPath->setText(QDir::toNativeSeparators(path));
    m_refreshing = false;
    storeSetting("source", QStringLiteral("video"));
    if (!path.isEmpty())
        storeSetting("video", path);
    probeSource();
}

void ArPreviewPanel::chooseImageFolder(const QString& folder)
{
    m_source = ArSource{ArSource::Kind::ImageFolder, folder};
    m_source.fps = m_folderFps->value();
    m_refreshing = true;
    m_folderPath->setText(QDir::toNativeSeparators(folder));
    m_refreshing = false;
    storeSetting("source", QStringLiteral("folder"));
    if (!folder.isEmpty())
        storeSetting("folder", folder);
    probeSource();
}

void ArPreviewPanel::chooseCamera(int index)
{
    if (index >= 0)
        m_cameras->setCurrentIndex(std::max(0, m_cameras->findData(index)));
    m_source = ArSource{ArSource::Kind::Camera};
    m_source.camera = m_cameras->currentData().isValid() ? m_cameras->currentData().toInt() : -1;
    m_source.size = m_cameraSize->currentData().toSize();
    m_source.fps = m_cameraRate->currentData().toDouble();
    storeSetting("source", QStringLiteral("camera"));
    probeSource();
}

void ArPreviewPanel::refreshCameras()
{
    const int current = m_cameras->currentData().isValid() ? m_cameras->currentData().toInt() : -1;
    m_cameras->clear();
    for (const ar::CameraDevice& device : ar::listCameras())
        m_cameras->addItem(tr("%1 (%2)").arg(fromUtf8(device.name), fromUtf8(device.path)), device.index);
    m_cameras->setEnabled(m_cameras->count() > 0);
    if (m_cameras->count() == 0)
        m_cameras->addItem(tr("No camera found"));
    else
        m_cameras->setCurrentIndex(std::max(0, m_cameras->findData(current)));
    if (m_source.kind == ArSource::Kind::Camera)
        chooseCamera(-1);
}

void ArPreviewPanel::probeSource()
{
    using Kind = ArSource::Kind;
    m_sourcePages->setCurrentIndex(int(m_source.kind));
    {
        const QSignalBlocker blocker(m_sourceKind);
        m_sourceKind->setCurrentIndex(int(m_source.kind));
    }
    m_sourceInfoValue.reset();
    m_sourceError.clear();
    QString info;
    switch (m_source.kind) {
    case Kind::TestPattern: {
        const ar::SyntheticScene scene = testPatternScene(board().value_or(ar::BoardSpec{}));
        m_sourceInfoValue = ArSourceInfo{QSize(scene.camera.width, scene.camera.height), scene.fps, scene.frames};
        break;
    }
    case Kind::Camera:
        if (m_source.camera < 0)
            m_sourceError = tr("No camera found: plug one in and press Rescan, or choose a video file or the test pattern.");
        else if (!m_source.size.isEmpty())
            m_sourceInfoValue = ArSourceInfo{m_source.size, m_source.fps, -1};
        else
            info = tr("The camera file's size is asked for, at %1 fps.").arg(m_source.fps);
        break;
    case Kind::VideoFile:
    case Kind::ImageFolder:
        if (m_source.path.isEmpty()) {
            m_sourceError = m_source.kind == Kind::VideoFile ? tr("Choose a video file.") : tr("Choose a folder of pictures.");
            break;
        }
        if (auto probed = probeArSource(m_source, ar::BoardSpec{}); probed)
            m_sourceInfoValue = *probed;
        else
            m_sourceError = fromUtf8(probed.error().message);
        break;
    }
    if (m_sourceInfoValue) {
        const ArSourceInfo& s = *m_sourceInfoValue;
        info = sizeText(s.size);
        if (s.fps > 0)
            info += tr(", %1 fps").arg(s.fps, 0, 'f', 1);
        if (s.frames > 0)
            info += s.fps > 0 ? tr(", %1 frames (%2 s)").arg(s.frames).arg(double(s.frames) / s.fps, 0, 'f', 1)
                              : tr(", %1 frames").arg(s.frames);
    }
    m_sourceInfo->setText(m_sourceError.isEmpty() ? info : m_sourceError);
    m_sourceInfo->setStyleSheet(m_sourceError.isEmpty() ? QString() : kErrorStyle);
    checkTarget();
    checkCamera();
}

void ArPreviewPanel::setCameraFile(const QString& path)
{
    m_cameraPath = path;
    m_refreshing = true;
    m_cameraFile->setText(QDir::toNativeSeparators(path));
    m_refreshing = false;
    storeSetting("cameraFile", path);
    m_camera.reset();
    m_cameraError.clear();
    if (!path.isEmpty()) {
        if (auto read = ar::readCameraFile(toFsPath(path)); read)
            m_camera = *read;
        else
            m_cameraError = tr("This camera file cannot be used: %1").arg(fromUtf8(read.error().message));
    }
    checkCamera();
}

void ArPreviewPanel::checkCamera()
{
    forgetFailedStart();
    const bool testPattern = m_source.kind == ArSource::Kind::TestPattern;
    m_cameraFile->setEnabled(!testPattern);
    m_chooseCameraFile->setEnabled(!testPattern);
    QString text, error = m_camera ? QString() : m_cameraError;
    if (testPattern) {
        text = tr("The test pattern's camera is known exactly: no file needed.");
        error.clear();
    } else if (m_camera && m_sourceInfoValue && !m_sourceInfoValue->size.isEmpty()
               && m_sourceInfoValue->size != QSize(m_camera->width, m_camera->height)) {
        error = tr("The camera file is for %1 pictures, but the source gives %2: calibrate the camera at the size it "
                   "films at.")
                    .arg(sizeText(QSize(m_camera->width, m_camera->height)), sizeText(m_sourceInfoValue->size));
    } else if (m_camera) {
        text = tr("%1, fx %2 px").arg(sizeText(QSize(m_camera->width, m_camera->height))).arg(m_camera->fx(), 0, 'f', 1);
        if (m_camera->reprojectionError >= 0)
            text += tr(", RMS %1 px").arg(m_camera->reprojectionError, 0, 'f', 2);
    } else if (error.isEmpty()) {
        error = tr("Choose the camera file of the camera that filmed it, or calibrate one.");
    }
    m_cameraMessage->setText(error.isEmpty() ? text : error);
    m_cameraMessage->setStyleSheet(error.isEmpty() ? QString() : kErrorStyle);
    m_cameraMessage->setProperty("problem", error);
    updateEnabled();
}

std::optional<ar::BoardSpec> ArPreviewPanel::board() const
{
    const QString text = m_board->text().trimmed();
    auto parsed = ar::parseBoard((text.isEmpty() ? kDefaultBoard : text).toStdString());
    return parsed ? std::optional<ar::BoardSpec>(*parsed) : std::nullopt;
}

std::optional<ar::TrackingTarget> ArPreviewPanel::target() const
{
    ar::TrackingTarget target;
    if (m_boardChoice->isChecked()) {
        target.board = board();
        if (!target.board)
            return std::nullopt;
    } else {
        target.picture = toFsPath(QDir::fromNativeSeparators(m_picturePath->text().trimmed()));
        target.pictureWidth = m_pictureWidth->value();
    }
    return target;
}

void ArPreviewPanel::setBoardSpec(const QString& text)
{
    m_board->setText(text); // textChanged checks it
}

void ArPreviewPanel::setPictureTarget(const QString& path, double width)
{
    m_picturePath->setText(QDir::toNativeSeparators(path));
    m_pictureWidth->setValue(width);
    m_pictureChoice->setChecked(true);
    onTargetEdited();
}

void ArPreviewPanel::onTargetEdited()
{
    if (m_source.kind == ArSource::Kind::TestPattern)
        probeSource(); // it shows the target's board, and checks the target
    else
        checkTarget();
}

void ArPreviewPanel::checkTarget()
{
    forgetFailedStart();
    m_targetError.clear();
    QString info;
    if (m_boardChoice->isChecked()) {
        const QString text = m_board->text().trimmed();
        auto parsed = ar::parseBoard((text.isEmpty() ? kDefaultBoard : text).toStdString());
        if (!parsed)
            m_targetError = tr("The board spec does not parse: %1").arg(fromUtf8(parsed.error().message));
        else if (parsed->kind == ar::BoardKind::Chessboard)
            m_targetError = tr("A chessboard calibrates a camera but cannot be tracked: use an ArUco grid or a ChArUco board.");
        else if (parsed->kind == ar::BoardKind::ArucoGrid)
            info = tr("ArUco grid, %1 × %2 markers of %3 cm, %4 × %5 cm in all")
                       .arg(parsed->columns)
                       .arg(parsed->rows)
                       .arg(parsed->square * 100, 0, 'f', 1)
                       .arg((parsed->columns * parsed->square + (parsed->columns - 1) * parsed->second) * 100, 0, 'f', 1)
                       .arg((parsed->rows * parsed->square + (parsed->rows - 1) * parsed->second) * 100, 0, 'f', 1);
        else
            info = tr("ChArUco board, %1 × %2 squares of %3 cm")
                       .arg(parsed->columns)
                       .arg(parsed->rows)
                       .arg(parsed->square * 100, 0, 'f', 1);
    } else {
        const QString path = QDir::fromNativeSeparators(m_picturePath->text().trimmed());
        if (path.isEmpty())
            m_targetError = tr("Choose the printed picture to track.");
        else if (!QFileInfo(path).isFile())
            m_targetError = tr("%1: no such picture.").arg(QDir::toNativeSeparators(path));
        else if (m_source.kind == ArSource::Kind::TestPattern)
            m_targetError = tr("The test pattern shows a board: track a board with it.");
        else
            info = tr("%1, %2 m wide").arg(QFileInfo(path).fileName()).arg(m_pictureWidth->value(), 0, 'f', 3);
    }
    m_targetMessage->setText(m_targetError.isEmpty() ? info : m_targetError);
    m_targetMessage->setStyleSheet(m_targetError.isEmpty() ? QString() : kErrorStyle);
    updateEnabled();
}

QString ArPreviewPanel::readiness() const
{
    if (!m_sourceError.isEmpty())
        return m_sourceError;
    if (!m_targetError.isEmpty())
        return m_targetError;
    if (m_source.kind != ArSource::Kind::TestPattern) {
        const QString camera = m_cameraMessage->property("problem").toString();
        if (!camera.isEmpty())
            return camera;
    }
    return {};
}

} // namespace thespis::editor
