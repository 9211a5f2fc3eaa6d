// File ▸ Export Package… (export_package_dialog.h).

#include "editor/export_package_dialog.h"

#include <QBoxLayout>
#include <QCheckBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QProgressBar>
#include <QRegularExpression>
#include <QPushButton>
#include <QTableWidget>

#include "editor/document.h"
#include "editor/job_progress.h"
#include "editor/job_runner.h"
#include "editor/qt_conversions.h"
#include "scenario/package.h"
#include "scenario/package_export_job.h"
#include "scenario/scenario_io.h"

namespace thespis::editor {

namespace {

const QString kErrorStyle = QStringLiteral("color: #c0392b;");

/// The scenario's own name in the package: its file's, else its name's.
QString scenarioEntry(const Document& document)
{
    QString base = QFileInfo(document.sourceFile()).completeBaseName();
    if (base.isEmpty())
        base = document.scenarioName();
    base.replace(QRegularExpression(QStringLiteral("[/\\\\:]")), QStringLiteral("_"));
    return base + QStringLiteral(".thespis");
}

QString sizeText(qint64 bytes)
{
    return QLocale().formattedDataSize(bytes, 1, QLocale::DataSizeSIFormat);
}

} // namespace

ExportPackageDialog::ExportPackageDialog(const Document& document, QWidget* parent)
    : QDialog(parent), m_document(document), m_job(new JobRunner(this))
{
    setWindowTitle(tr("Export Package"));
    setObjectName(QStringLiteral("exportPackageDialog"));
    auto* layout = new QVBoxLayout(this);
    auto* intro = new QLabel(tr("One file with the scenario and every file it names, which Thespis opens anywhere "
                                "(File ▸ Open) and thespis-cli plays or imports."),
                             this);
    intro->setWordWrap(true);
    layout->addWidget(intro);

    m_contents = new QTableWidget(0, 3, this);
    m_contents->setObjectName(QStringLiteral("packageContents"));
    m_contents->setHorizontalHeaderLabels({tr("In the package"), tr("Size"), tr("Named by")});
    m_contents->horizontalHeader()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    m_contents->horizontalHeader()->setSectionResizeMode(1, QHeaderView::ResizeToContents);
    m_contents->horizontalHeader()->setStretchLastSection(true);
    m_contents->verticalHeader()->hide();
    m_contents->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_contents->setSelectionMode(QAbstractItemView::NoSelection);
    layout->addWidget(m_contents, 1);
    m_summary = new QLabel(this);
    m_summary->setObjectName(QStringLiteral("packageSummary"));
    layout->addWidget(m_summary);

    m_output = new QLineEdit(this);
    m_output->setObjectName(QStringLiteral("packageOutput"));
    auto* choose = new QPushButton(tr("Choose…"), this);
    auto* outputRow = new QHBoxLayout;
    outputRow->addWidget(new QLabel(tr("Write to:"), this));
    outputRow->addWidget(m_output, 1);
    outputRow->addWidget(choose);
    layout->addLayout(outputRow);
    m_bake = new QCheckBox(tr("Bake the lighting first where a character has no bake or an out-of-date one "
                              "(the new bakes go into the package only)"),
                           this);
    m_bake->setObjectName(QStringLiteral("packageBake"));
    layout->addWidget(m_bake);

    m_progress = new JobProgress(tr("Not exported yet"), this);
    layout->addWidget(m_progress);

    auto* buttons = new QDialogButtonBox(this);
    m_export = buttons->addButton(tr("Export"), QDialogButtonBox::AcceptRole);
    m_export->setObjectName(QStringLiteral("exportPackageButton"));
    m_cancel = buttons->addButton(QDialogButtonBox::Cancel);
    buttons->addButton(QDialogButtonBox::Close);
    layout->addWidget(buttons);
    connect(m_export, &QPushButton::clicked, this, [this] { (void)exportPackage(); });
    connect(m_cancel, &QPushButton::clicked, this, &ExportPackageDialog::cancel);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(choose, &QPushButton::clicked, this, [this] {
        QString path = QFileDialog::getSaveFileName(this, tr("Export Package"), m_output->text(),
                                                    tr("Thespis packages (*.thespkg)"));
        if (!path.isEmpty())
            setOutput(path);
    });
    connect(m_output, &QLineEdit::textChanged, this, &ExportPackageDialog::updateEnabled);
    connect(m_job, &JobRunner::progress, m_progress, &JobProgress::setProgress);
    connect(m_job, &JobRunner::finished, this, &ExportPackageDialog::onFinished);

    auto planned = core::scenario::planPackage(document.scenario(), document.assets(), scenarioEntry(document).toStdString());
    if (planned)
        m_plan = std::move(planned).value();
    else
        m_planError = fromUtf8(planned.error().message);
    const QString folder = document.sourceFile().isEmpty() ? QDir::homePath() : QFileInfo(document.sourceFile()).absolutePath();
    setOutput(QDir(folder).filePath(QFileInfo(scenarioEntry(document)).completeBaseName() + QStringLiteral(".thespkg")));
    showPlan();
    resize(640, 420);
}

ExportPackageDialog::~ExportPackageDialog() = default;

void ExportPackageDialog::showPlan()
{
    m_contents->setRowCount(0);
    if (!m_plan) {
        m_summary->setText(m_planError);
        m_summary->setStyleSheet(kErrorStyle);
        updateEnabled();
        return;
    }
    qint64 total = 0;
    const auto addRow = [&](const QString& name, qint64 size, const QString& namedBy) {
        const int row = m_contents->rowCount();
        m_contents->insertRow(row);
        m_contents->setItem(row, 0, new QTableWidgetItem(name));
        auto* sizeItem = new QTableWidgetItem(size >= 0 ? sizeText(size) : QString());
        sizeItem->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        m_contents->setItem(row, 1, sizeItem);
        m_contents->setItem(row, 2, new QTableWidgetItem(namedBy));
        total += std::max<qint64>(0, size);
    };
    addRow(fromUtf8(m_plan->scenarioEntry), qint64(core::scenario::serializeScenario(m_plan->scenario).size()),
           tr("the scenario itself, with its scripts and gestures"));
    for (const core::scenario::PackageFile& file : m_plan->files) {
        std::error_code error;
        const auto size = std::filesystem::file_size(file.source, error);
        addRow(fromUtf8(file.name), error ? -1 : qint64(size), fromUtf8(file.usedBy));
    }
    m_summary->setText(tr("The scenario and %n file(s), %1 before compression.", "", int(m_plan->files.size())).arg(sizeText(total)));
    m_summary->setStyleSheet(QString());
    updateEnabled();
}

void ExportPackageDialog::setOutput(const QString& path)
{
    QString file = path;
    if (!file.endsWith(QLatin1String(core::scenario::kPackageExtension.data())))
        file += QLatin1String(core::scenario::kPackageExtension.data());
    m_output->setText(QDir::toNativeSeparators(file));
}

bool ExportPackageDialog::isExporting() const
{
    return m_job->isRunning();
}

bool ExportPackageDialog::exportPackage()
{
    if (!m_plan || m_job->isRunning())
        return false;
    auto job = std::make_unique<core::scenario::ExportPackageJob>();
    job->scenario = m_document.scenario();
    job->assets = m_document.assets();
    job->scenarioEntry = m_plan->scenarioEntry;
    job->output = toFsPath(QDir::fromNativeSeparators(m_output->text().trimmed()));
    job->bakeLighting = m_bake->isChecked();
    if (auto started = m_job->start(std::move(job)); !started) {
        m_progress->refused(fromUtf8(started.error().message));
        return false;
    }
    m_progress->started();
    updateEnabled();
    return true;
}

void ExportPackageDialog::cancel()
{
    if (m_job->isRunning())
        m_job->cancel();
    else
        reject();
}

void ExportPackageDialog::onFinished(const core::Result<void>& result)
{
    updateEnabled();
    if (!result) {
        m_progress->failed(result.error());
        return;
    }
    const auto* job = m_job->jobAs<core::scenario::ExportPackageJob>();
    const QString path = fromFsPath(job->output);
    QString text = tr("Wrote %1: %2 (%3 before compression).")
                       .arg(QDir::toNativeSeparators(path), sizeText(qint64(job->packageBytes)), sizeText(qint64(job->contentBytes)));
    for (const std::string& baked : job->baked)
        text += QLatin1Char('\n') + tr("Baked the lighting of %1.").arg(fromUtf8(baked));
    m_progress->finished(tr("Exported"), text);
    emit exported(path);
}

QLabel* ExportPackageDialog::messageLabel() const
{
    return m_progress->message();
}

QProgressBar* ExportPackageDialog::progressBar() const
{
    return m_progress->bar();
}

void ExportPackageDialog::updateEnabled()
{
    const bool running = m_job->isRunning();
    m_export->setEnabled(m_plan && !running && !m_output->text().trimmed().isEmpty());
    m_cancel->setEnabled(running);
    m_output->setEnabled(!running);
    m_bake->setEnabled(!running);
}

} // namespace thespis::editor
