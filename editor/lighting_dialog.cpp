#include "editor/lighting_dialog.h"

#include <QButtonGroup>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QImage>
#include <QLabel>
#include <QPixmap>
#include <QPushButton>
#include <QRadioButton>
#include <QSlider>
#include <QSpinBox>
#include <QVBoxLayout>

#include <cmath>

#include "editor/job_runner.h"
#include "editor/qt_conversions.h"
#include "lighting/probe_preview.h"
#include "lighting/probe_projection_job.h"

namespace thespis::editor {

namespace {

// The light's order in the pictures: the renderer's (render::ScenarioSceneOptions::lightOrder).
constexpr int kLightOrder = 6;
constexpr int kPictureWidth = 320;

QPixmap toPixmap(const core::lighting::PreviewImage& image)
{
    const QImage picture(image.rgba.data(), image.width, image.height, image.width * 4, QImage::Format_RGBA8888);
    return QPixmap::fromImage(picture.copy());
}

} // namespace

LightingDialog::LightingDialog(const QString& baseDir, const core::scenario::LightingSpec& current, QWidget* parent)
    : QDialog(parent), m_baseDir(baseDir)
{
    setObjectName(QStringLiteral("lightingDialog"));
    setWindowTitle(tr("Lighting"));
    m_projection = new JobRunner(this);
    connect(m_projection, &JobRunner::finished, this, &LightingDialog::onProjected);
    m_sky = new QRadioButton(tr("No probe: the default sky"), this);
    m_sky->setObjectName(QStringLiteral("skyChoice"));
    m_probeChoice = new QRadioButton(tr("A light probe (HDR or EXR)"), this);
    m_probeChoice->setObjectName(QStringLiteral("probeChoice"));
    auto* group = new QButtonGroup(this);
    group->addButton(m_sky);
    group->addButton(m_probeChoice);
    m_file = new QLabel(this);
    m_file->setWordWrap(true);
    m_browse = new QPushButton(tr("Browse…"), this);
    m_layout = new QComboBox(this);
    m_layout->setObjectName(QStringLiteral("layoutChoice"));
    m_layout->addItem(tr("Latitude–longitude"), QStringLiteral("latlong"));
    m_layout->addItem(tr("Angular map (mirrored ball, unwrapped)"), QStringLiteral("angular"));
    m_layout->addItem(tr("Mirror ball (a photograph)"), QStringLiteral("mirrorball"));
    m_layout->addItem(tr("Vertical cross"), QStringLiteral("cross"));
    m_rotation = new QSlider(Qt::Horizontal, this);
    m_rotation->setObjectName(QStringLiteral("rotationSlider"));
    m_rotation->setRange(-180, 180);
    auto* rotationValue = new QSpinBox(this);
    rotationValue->setRange(-180, 180);
    rotationValue->setSuffix(QStringLiteral("°"));
    m_intensity = new QDoubleSpinBox(this);
    m_intensity->setObjectName(QStringLiteral("intensityEdit"));
    m_intensity->setRange(0.0, 20.0);
    m_intensity->setDecimals(2);
    m_intensity->setSingleStep(0.1);
    m_probePicture = new QLabel(this);
    m_probePicture->setObjectName(QStringLiteral("probePicture"));
    m_lightPicture = new QLabel(this);
    m_lightPicture->setObjectName(QStringLiteral("lightPicture"));
    for (QLabel* picture : {m_probePicture, m_lightPicture}) {
        picture->setFixedSize(kPictureWidth, kPictureWidth / 2);
        picture->setAlignment(Qt::AlignCenter);
        picture->setFrameShape(QFrame::StyledPanel);
    }
    m_message = new QLabel(this);
    m_message->setObjectName(QStringLiteral("lightingMessage"));
    m_message->setWordWrap(true);

    auto* fileRow = new QHBoxLayout;
    fileRow->addWidget(m_file, 1);
    fileRow->addWidget(m_browse);
    auto* rotationRow = new QHBoxLayout;
    rotationRow->addWidget(m_rotation, 1);
    rotationRow->addWidget(rotationValue);
    auto* form = new QFormLayout;
    form->addRow(m_sky);
    form->addRow(m_probeChoice, fileRow);
    form->addRow(tr("Layout:"), m_layout);
    form->addRow(tr("Turned about the vertical:"), rotationRow);
    form->addRow(tr("Intensity:"), m_intensity);
    auto* pictures = new QGridLayout;
    pictures->addWidget(new QLabel(tr("The probe"), this), 0, 0);
    pictures->addWidget(new QLabel(tr("The light the characters receive"), this), 0, 1);
    pictures->addWidget(m_probePicture, 1, 0);
    pictures->addWidget(m_lightPicture, 1, 1);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Cancel, this);
    m_ok = buttons->addButton(tr("Set Light"), QDialogButtonBox::AcceptRole);
    m_ok->setObjectName(QStringLiteral("setLightButton"));
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addLayout(pictures);
    layout->addWidget(m_message);
    layout->addWidget(buttons);

    m_rotation->setValue(int(std::lround(current.rotation)));
    rotationValue->setValue(m_rotation->value());
    m_intensity->setValue(current.intensity);
    if (const int index = m_layout->findData(QString::fromStdString(current.layout)); index >= 0)
        m_layout->setCurrentIndex(index);
    if (!current.probe.empty())
        m_probePath = QDir(baseDir).absoluteFilePath(fromUtf8(current.probe));
    (m_probePath.isEmpty() ? m_sky : m_probeChoice)->setChecked(true);
    load();

    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_browse, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getOpenFileName(this, tr("Choose a Light Probe"), m_baseDir,
                                                          tr("HDR images (*.hdr *.exr)"));
        if (!path.isEmpty())
            setProbeFile(path);
    });
    connect(m_rotation, &QSlider::valueChanged, rotationValue, &QSpinBox::setValue);
    connect(rotationValue, &QSpinBox::valueChanged, m_rotation, &QSlider::setValue);
    connect(m_rotation, &QSlider::valueChanged, this, &LightingDialog::updatePictures);
    connect(m_intensity, &QDoubleSpinBox::valueChanged, this, &LightingDialog::updatePictures);
    connect(m_layout, &QComboBox::currentIndexChanged, this, [this] { load(); });
    connect(m_sky, &QRadioButton::toggled, this, [this] { load(); });
}

void LightingDialog::setProbeFile(const QString& path)
{
    if (!m_fallbackPath)
        m_fallbackPath = m_probePath;
    m_probePath = QFileInfo(path).absoluteFilePath();
    if (m_probeChoice->isChecked())
        load();
    else
        m_probeChoice->setChecked(true); // loads, through the sky button's toggle
}

bool LightingDialog::isLoading() const
{
    return m_projection->isRunning();
}

void LightingDialog::load()
{
    const bool wantProbe = m_probeChoice->isChecked();
    m_file->setText(m_probePath.isEmpty() ? tr("No file chosen.") : QDir::toNativeSeparators(m_probePath));
    m_layout->setEnabled(wantProbe);
    if (m_projection->isRunning()) {
        m_reloadWanted = true; // once the running one has stopped
        m_projection->cancel();
        return;
    }
    m_message->clear();
    if (!wantProbe || m_probePath.isEmpty()) {
        m_probe.reset();
        m_fallbackPath.reset();
        m_ok->setEnabled(!wantProbe);
        updatePictures();
        return;
    }
    auto job = std::make_unique<core::lighting::ProbeProjectionJob>();
    job->path = toFsPath(m_probePath);
    job->layout = *core::lighting::parseProbeLayout(m_layout->currentData().toString().toStdString());
    job->order = kLightOrder;
    if (auto started = m_projection->start(std::move(job)); !started) {
        onProjected(started);
        return;
    }
    m_ok->setEnabled(false);
    m_message->setText(tr("Reading %1 and projecting its light…").arg(QFileInfo(m_probePath).fileName()));
}

void LightingDialog::onProjected(const core::Result<void>& result)
{
    if (m_reloadWanted) {
        m_reloadWanted = false;
        load();
        return;
    }
    if (result) {
        auto* job = m_projection->jobAs<core::lighting::ProbeProjectionJob>();
        m_probe = std::move(job->probe);
        m_light = job->light;
        m_exposure = core::lighting::previewExposure(*m_probe);
        m_message->clear();
    } else {
        const QString message = tr("%1 cannot be used as a light probe: %2")
                                    .arg(QFileInfo(m_probePath).fileName(), fromUtf8(result.error().message));
        if (m_fallbackPath) {
            m_probePath = *m_fallbackPath; // its probe and light are still loaded
            m_file->setText(m_probePath.isEmpty() ? tr("No file chosen.") : QDir::toNativeSeparators(m_probePath));
        } else {
            m_probe.reset();
        }
        m_message->setText(message);
    }
    m_fallbackPath.reset();
    m_ok->setEnabled(!m_probeChoice->isChecked() || m_probe.has_value());
    updatePictures();
    emit loaded(result.ok());
}

void LightingDialog::updatePictures()
{
    if (!m_probe || !m_probeChoice->isChecked()) {
        m_probePicture->setPixmap({});
        m_lightPicture->setPixmap({});
        m_probePicture->setText(m_probeChoice->isChecked() ? tr("Choose a probe file.") : tr("The default sky"));
        m_lightPicture->setText({});
        return;
    }
    const double degrees = m_rotation->value(), intensity = m_intensity->value();
    m_probePicture->setPixmap(
        toPixmap(core::lighting::previewProbe(*m_probe, kPictureWidth, degrees, intensity, m_exposure)));
    m_lightPicture->setPixmap(toPixmap(core::lighting::previewLight(
        core::lighting::turnedLight(m_light, degrees, intensity), kPictureWidth, m_exposure)));
}

core::scenario::LightingSpec LightingDialog::lighting() const
{
    core::scenario::LightingSpec spec;
    if (!m_probeChoice->isChecked() || m_probePath.isEmpty())
        return spec; // the default sky, as it is
    spec.probe = QDir::fromNativeSeparators(QDir(m_baseDir).relativeFilePath(m_probePath)).toStdString();
    spec.layout = m_layout->currentData().toString().toStdString();
    spec.rotation = m_rotation->value();
    spec.intensity = m_intensity->value();
    return spec;
}

} // namespace thespis::editor
