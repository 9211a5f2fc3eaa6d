#include "editor/export_motion_dialog.h"

#include <QBoxLayout>
#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>

#include "editor/document.h"
#include "editor/job_progress.h"
#include "editor/job_runner.h"
#include "editor/qt_conversions.h"
#include "runtime/motion_bake_job.h"

namespace thespis::editor {

ExportMotionDialog::ExportMotionDialog(const Document& document, int character, QWidget* parent)
    : QDialog(parent), m_document(document), m_job(new JobRunner(this))
{
    setWindowTitle(tr("Export Motion"));
    setObjectName(QStringLiteral("exportMotionDialog"));
    auto* layout = new QVBoxLayout(this);
    auto* intro = new QLabel(tr("A character's motion over the whole scenario, as the studio plays it, for Blender, "
                                "three.js and game engines: a glTF file (.glb) with the character and its motion, or "
                                "a BVH clip."),
                             this);
    intro->setWordWrap(true);
    layout->addWidget(intro);

    auto* form = new QFormLayout;
    m_character = new QComboBox(this);
    m_character->setObjectName(QStringLiteral("motionCharacter"));
    for (const auto& c : document.scenario().characters)
        m_character->addItem(c.model.empty() ? tr("%1 (built-in humanoid)").arg(fromUtf8(c.name))
                                             : tr("%1 (%2)").arg(fromUtf8(c.name), QFileInfo(fromUtf8(c.model)).fileName()));
    form->addRow(tr("Character:"), m_character);
    m_fps = new QDoubleSpinBox(this);
    m_fps->setObjectName(QStringLiteral("motionFps"));
    m_fps->setRange(1, 240);
    m_fps->setDecimals(2);
    m_fps->setValue(30);
    m_fps->setSuffix(tr(" fps"));
    form->addRow(tr("Frame rate:"), m_fps);
    m_output = new QLineEdit(this);
    m_output->setObjectName(QStringLiteral("motionOutput"));
    auto* choose = new QPushButton(tr("Choose…"), this);
    auto* outputRow = new QHBoxLayout;
    outputRow->addWidget(m_output, 1);
    outputRow->addWidget(choose);
    form->addRow(tr("Write to:"), outputRow);
    layout->addLayout(form);
    m_animationOnly = new QCheckBox(tr("Animation only (.glb): the joints and the motion without meshes and "
                                       "materials, to play onto a model already in the other tool"),
                                    this);
    m_animationOnly->setObjectName(QStringLiteral("motionAnimationOnly"));
    layout->addWidget(m_animationOnly);

    m_progress = new JobProgress(tr("Not exported yet"), this);
    layout->addWidget(m_progress);

    auto* buttons = new QDialogButtonBox(this);
    m_export = buttons->addButton(tr("Export"), QDialogButtonBox::AcceptRole);
    m_export->setObjectName(QStringLiteral("exportMotionButton"));
    m_cancel = buttons->addButton(QDialogButtonBox::Cancel);
    buttons->addButton(QDialogButtonBox::Close);
    layout->addWidget(buttons);
    connect(m_export, &QPushButton::clicked, this, [this] { (void)exportMotion(); });
    connect(m_cancel, &QPushButton::clicked, this, &ExportMotionDialog::cancel);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(choose, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getSaveFileName(this, tr("Export Motion"), m_output->text(),
                                                          tr("glTF 2.0 (*.glb);;BVH motion (*.bvh)"));
        if (!path.isEmpty())
            setOutput(path);
    });
    connect(m_output, &QLineEdit::textChanged, this, &ExportMotionDialog::updateEnabled);
    connect(m_character, &QComboBox::currentIndexChanged, this, [this](int index) {
        // The file is named after the character until the user names it otherwise.
        const QFileInfo file(QDir::fromNativeSeparators(m_output->text()));
        if (index < 0 || file.completeBaseName() != m_namedAfter)
            return;
        m_namedAfter = fromUtf8(m_document.scenario().characters[std::size_t(index)].name);
        setOutput(file.dir().filePath(m_namedAfter + QLatin1Char('.') + file.suffix()));
    });
    connect(m_job, &JobRunner::progress, m_progress, &JobProgress::setProgress);
    connect(m_job, &JobRunner::finished, this, &ExportMotionDialog::onFinished);

    const QString folder = document.sourceFile().isEmpty() ? QDir::homePath() : QFileInfo(document.sourceFile()).absolutePath();
    const int chosen = character >= 0 && character < m_character->count() ? character : 0;
    m_namedAfter = chosen < int(document.scenario().characters.size())
                       ? fromUtf8(document.scenario().characters[std::size_t(chosen)].name)
                       : QStringLiteral("motion");
    setOutput(QDir(folder).filePath(m_namedAfter + QStringLiteral(".glb")));
    m_character->setCurrentIndex(chosen);
    updateEnabled();
    resize(560, 300);
}

ExportMotionDialog::~ExportMotionDialog() = default;

void ExportMotionDialog::setOutput(const QString& path)
{
    m_output->setText(QDir::toNativeSeparators(path));
}

void ExportMotionDialog::setCharacter(int character)
{
    m_character->setCurrentIndex(character);
}

void ExportMotionDialog::setAnimationOnly(bool animationOnly)
{
    m_animationOnly->setChecked(animationOnly);
}

void ExportMotionDialog::setFrameRate(double framesPerSecond)
{
    m_fps->setValue(framesPerSecond);
}

bool ExportMotionDialog::isExporting() const
{
    return m_job->isRunning();
}

bool ExportMotionDialog::exportMotion()
{
    if (m_job->isRunning() || m_character->currentIndex() < 0)
        return false;
    auto job = std::make_unique<core::runtime::MotionBakeJob>();
    job->scenario = m_document.scenario();
    job->assets = m_document.assets();
    job->character = m_document.scenario().characters[std::size_t(m_character->currentIndex())].name;
    job->output = toFsPath(QDir::fromNativeSeparators(m_output->text().trimmed()));
    job->fps = m_fps->value();
    job->animationOnly = m_animationOnly->isChecked() && job->output.extension() == ".glb";
    if (m_animationOnly->isChecked() && job->output.extension() != ".glb") {
        m_progress->refused(tr("“Animation only” goes with a .glb file; a BVH file is always the motion alone."));
        return false;
    }
    if (auto started = m_job->start(std::move(job)); !started) {
        m_progress->refused(fromUtf8(started.error().message));
        return false;
    }
    m_progress->started();
    updateEnabled();
    return true;
}

void ExportMotionDialog::cancel()
{
    if (m_job->isRunning())
        m_job->cancel();
    else
        reject();
}

void ExportMotionDialog::onFinished(const core::Result<void>& result)
{
    updateEnabled();
    if (!result) {
        m_progress->failed(result.error());
        return;
    }
    const auto* job = m_job->jobAs<core::runtime::MotionBakeJob>();
    const QString path = fromFsPath(job->output);
    QString text = tr("Wrote %1: %n frame(s) at %2 fps.", nullptr, int(job->frameCount))
                       .arg(QDir::toNativeSeparators(path))
                       .arg(job->fps);
    for (const std::string& warning : job->warnings)
        text += QLatin1Char('\n') + fromUtf8(warning);
    m_progress->finished(tr("Exported"), text);
    emit exported(path);
}

QLabel* ExportMotionDialog::messageLabel() const
{
    return m_progress->message();
}

QProgressBar* ExportMotionDialog::progressBar() const
{
    return m_progress->bar();
}

void ExportMotionDialog::updateEnabled()
{
    const bool running = m_job->isRunning();
    m_export->setEnabled(!running && m_character->count() > 0 && !m_output->text().trimmed().isEmpty());
    m_cancel->setEnabled(running);
    m_output->setEnabled(!running);
    m_character->setEnabled(!running);
    m_fps->setEnabled(!running);
    m_animationOnly->setEnabled(!running);
}

} // namespace thespis::editor
