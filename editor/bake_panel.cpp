#include "editor/bake_panel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QFileInfo>
#include <QFormLayout>
#include <QFrame>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QRandomGenerator>
#include <QSpinBox>
#include <QThread>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "edit/document_edits.h"
#include "editor/character_choice.h"
#include "editor/document.h"
#include "editor/job_runner.h"
#include "editor/qt_conversions.h"
#include "lighting/transfer_bake_job.h"
#include "scenario/scenario_character.h"

namespace thespis::editor {

namespace {

namespace lighting = core::lighting;

constexpr int kMaxOrder = 6;              // what the viewport's shaders draw
constexpr double kMaxEpsilonMetres = 0.1; // beyond this the relaxation hides real occluders
const QString kDefaultEpsilon = QStringLiteral("1.71e-4");
const QString kBakeFolder = QStringLiteral("bakes");
const QString kBakeExtension = QStringLiteral(".prt"); // as `thespis-cli bake --out` files are named
// Muted red for errors and amber for a bake that is not used: both read on light and dark palettes.
const QString kErrorStyle = QStringLiteral("color: #c0392b;");
const QString kWarningStyle = QStringLiteral("color: #b9770e;");

// 1234567 → "1 234 567" (narrow no-break spaces): readable whatever the locale.
QString grouped(qint64 n)
{
    QString digits = QString::number(n);
    for (qsizetype i = digits.size() - 3; i > 0; i -= 3)
        digits.insert(i, QChar(0x202F));
    return digits;
}

QString shortTransferName(lighting::TransferKind kind)
{
    return QString::fromLatin1(lighting::transferKindName(kind)).toUpper();
}

// A name fit for a file name on every system: letters, digits, '-' and '_' stay, the rest is '_'.
QString fileNamePart(const QString& name)
{
    QString part;
    for (QChar c : name)
        part += (c.isLetterOrNumber() || c == u'-' || c == u'_') ? c : QChar(u'_');
    return part.isEmpty() ? QStringLiteral("_") : part;
}

void removeFile(const QString& path)
{
    std::error_code ec;
    std::filesystem::remove(toFsPath(path), ec);
}

// The bakes folder when it is empty (a bake that wrote nothing leaves no trace).
void removeEmptyBakeFolder(const QString& file)
{
    const QDir folder = QFileInfo(file).absoluteDir();
    if (folder.dirName() == kBakeFolder && folder.isEmpty())
        QDir().rmdir(folder.absolutePath());
}

} // namespace

BakePanel::BakePanel(QWidget* parent) : QWidget(parent), m_job(new JobRunner(this))
{
    setObjectName(QStringLiteral("bakePanel"));
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(6, 6, 6, 6);
    layout->setSpacing(6);

    auto* top = new QFormLayout;
    top->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    m_character = new QComboBox(this);
    m_character->setObjectName(QStringLiteral("bakeCharacter"));
    m_character->setToolTip(tr("The character whose body is baked"));
    m_character->setMinimumContentsLength(14);
    top->addRow(tr("Character:"), m_character);
    m_currentBake = new QLabel(this);
    m_currentBake->setObjectName(QStringLiteral("currentBake"));
    m_currentBake->setWordWrap(true);
    m_currentBake->setTextInteractionFlags(Qt::TextSelectableByMouse);
    top->addRow(tr("Uses now:"), m_currentBake);
    layout->addLayout(top);

    auto* group = new QGroupBox(tr("Bake Settings"), this);
    auto* form = new QFormLayout(group);
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    m_transfer = new QComboBox(group);
    m_transfer->setObjectName(QStringLiteral("bakeTransfer"));
    m_transfer->addItem(tr("Diffuse unshadowed"), int(lighting::TransferKind::DiffuseUnshadowed));
    m_transfer->addItem(tr("Diffuse shadowed"), int(lighting::TransferKind::DiffuseShadowed));
    m_transfer->addItem(tr("Diffuse shadowed merged (paper)"), int(lighting::TransferKind::DiffuseShadowedMerged));
    m_transfer->setItemData(0, tr("DU: no shadows at all"), Qt::ToolTipRole);
    m_transfer->setItemData(1, tr("DS: each segment shadows only itself"), Qt::ToolTipRole);
    m_transfer->setItemData(2, tr("DSM: every segment shadows the others; receivers are transparent, occluders are not baked"),
                            Qt::ToolTipRole);
    form->addRow(tr("Transfer:"), m_transfer);

    m_order = new QSpinBox(group);
    m_order->setObjectName(QStringLiteral("bakeOrder"));
    m_order->setRange(1, kMaxOrder);
    m_order->setToolTip(tr("Spherical harmonics order: bands 0 … order − 1"));
    m_coefficients = new QLabel(group);
    m_coefficients->setForegroundRole(QPalette::PlaceholderText);
    auto* orderRow = new QHBoxLayout;
    orderRow->addWidget(m_order);
    orderRow->addWidget(m_coefficients, 1);
    form->addRow(tr("SH order:"), orderRow);

    m_rays = new QComboBox(group);
    m_rays->setObjectName(QStringLiteral("bakeRays"));
    for (int rays = 16; rays <= 4096; rays *= 2)
        m_rays->addItem(grouped(rays), rays);
    m_rays->setToolTip(tr("Stratified cosine-weighted directions traced from every vertex"));
    form->addRow(tr("Rays per vertex:"), m_rays);

    m_backend = new QComboBox(group);
    m_backend->setObjectName(QStringLiteral("bakeBackend"));
    m_backend->addItem(tr("Embree"), int(lighting::OcclusionBackendKind::Embree));
    m_backend->addItem(tr("Uniform grid"), int(lighting::OcclusionBackendKind::Grid));
    m_backend->setToolTip(tr("The ray tracer: Embree, or the paper's uniform grid (same results, slower)"));
    form->addRow(tr("Ray tracer:"), m_backend);

    m_epsilon = new QLineEdit(group);
    m_epsilon->setObjectName(QStringLiteral("bakeEpsilon"));
    m_epsilon->setPlaceholderText(kDefaultEpsilon);
    m_epsilon->setToolTip(tr("Relaxation ε in metres: hits nearer than this are ignored (default 1.71e-4, the H-Anim segment gap)"));
    form->addRow(tr("Relaxation ε (m):"), m_epsilon);

    m_threads = new QSpinBox(group);
    m_threads->setObjectName(QStringLiteral("bakeThreads"));
    m_threads->setRange(0, 1024);
    m_threads->setSpecialValueText(tr("All (%1)").arg(QThread::idealThreadCount()));
    m_threads->setToolTip(tr("Worker threads; the result does not depend on it"));
    form->addRow(tr("Threads:"), m_threads);
    layout->addWidget(group);
    m_settingsWidgets = {m_character, m_transfer, m_order, m_rays, m_backend, m_epsilon, m_threads};

    auto* buttons = new QHBoxLayout;
    m_start = new QPushButton(tr("Start Bake"), this);
    m_start->setObjectName(QStringLiteral("startBake"));
    m_start->setToolTip(tr("Bake the character in the background; the result is one undoable step"));
    m_cancel = new QPushButton(tr("Cancel"), this);
    m_cancel->setObjectName(QStringLiteral("cancelBake"));
    m_cancel->setToolTip(tr("Stop the bake; nothing changes"));
    buttons->addWidget(m_start, 1);
    buttons->addWidget(m_cancel);
    layout->addLayout(buttons);

    m_progress = new QProgressBar(this);
    m_progress->setObjectName(QStringLiteral("bakeProgress"));
    m_progress->setRange(0, 1);
    m_progress->setValue(0);
    m_progress->setFormat(tr("Not baking"));
    m_progress->setAlignment(Qt::AlignCenter);
    layout->addWidget(m_progress);
    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("bakeStatus"));
    m_status->setWordWrap(true);
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(m_status);

    auto* line = new QFrame(this);
    line->setFrameShape(QFrame::HLine);
    line->setFrameShadow(QFrame::Sunken);
    layout->addWidget(line);
    m_prtPreview = new QCheckBox(tr("Show PRT lighting (off: Phong)"), this);
    m_prtPreview->setObjectName(QStringLiteral("prtPreview"));
    m_prtPreview->setChecked(true);
    m_prtPreview->setToolTip(tr("Shade the viewport with the baked transfer, or with plain Phong to compare"));
    layout->addWidget(m_prtPreview);
    layout->addStretch(1);

    connect(m_order, &QSpinBox::valueChanged, this,
            [this](int order) { m_coefficients->setText(tr("%1 coefficients per vertex").arg(order * order)); });
    connect(m_character, &QComboBox::currentIndexChanged, this, [this] { refreshCurrentBake(); });
    connect(m_start, &QPushButton::clicked, this, &BakePanel::start);
    connect(m_cancel, &QPushButton::clicked, this, &BakePanel::cancel);
    connect(m_prtPreview, &QCheckBox::toggled, this, &BakePanel::prtPreviewToggled);
    connect(m_job, &JobRunner::progress, this, &BakePanel::onProgress);
    connect(m_job, &JobRunner::finished, this, &BakePanel::onFinished);

    setSettings(lighting::BakeSettings{});
    m_coefficients->setText(tr("%1 coefficients per vertex").arg(m_order->value() * m_order->value()));
    setDocument(nullptr);
}

BakePanel::~BakePanel()
{
    // Cancel and wait for a running bake before the widgets go; it reports nothing more.
    disconnect(m_job, nullptr, this, nullptr);
    delete m_job;
}

void BakePanel::setDocument(Document* document)
{
    if (document == m_document && document)
        return;
    if (isRunning())
        cancel();
    if (m_document)
        disconnect(m_document, nullptr, this, nullptr);
    m_document = document;
    if (m_document)
        connect(m_document, &Document::edited, this, [this] { refreshCharacters(); });
    m_currentBakeKey.clear();
    refreshCharacters();
}

bool BakePanel::isRunning() const
{
    return m_job->isRunning();
}

core::Result<lighting::BakeSettings> BakePanel::settings() const
{
    lighting::BakeSettings s;
    s.order = m_order->value();
    s.raysPerVertex = m_rays->currentData().toInt();
    s.transfer = lighting::TransferKind(m_transfer->currentData().toInt());
    s.backend = lighting::OcclusionBackendKind(m_backend->currentData().toInt());
    s.threads = m_threads->value();
    const QString text = m_epsilon->text().trimmed();
    bool ok = false;
    double epsilon = text.isEmpty() ? kDefaultEpsilon.toDouble(&ok) : text.toDouble(&ok);
    if (!ok)
        epsilon = locale().toDouble(text, &ok);
    if (!ok || !std::isfinite(epsilon) || epsilon < 0 || epsilon > kMaxEpsilonMetres)
        return core::makeError(core::ErrorCode::InvalidArgument,
                               tr("Relaxation ε must be a distance in metres from 0 to %1 (for example 1.71e-4), not “%2”.")
                                   .arg(kMaxEpsilonMetres)
                                   .arg(text)
                                   .toStdString());
    s.epsilon = float(epsilon);
    if (auto valid = lighting::validateBakeSettings(s); !valid)
        return valid.error();
    return s;
}

void BakePanel::setSettings(const lighting::BakeSettings& s)
{
    m_order->setValue(std::clamp(s.order, 1, kMaxOrder));
    const int rays = std::clamp(s.raysPerVertex, 16, 4096);
    int index = m_rays->findData(rays);
    if (index < 0) {
        // Not a power of two: keep it, in order.
        index = 0;
        while (index < m_rays->count() && m_rays->itemData(index).toInt() < rays)
            ++index;
        m_rays->insertItem(index, grouped(rays), rays);
    }
    m_rays->setCurrentIndex(index);
    m_transfer->setCurrentIndex(std::max(0, m_transfer->findData(int(s.transfer))));
    m_backend->setCurrentIndex(std::max(0, m_backend->findData(int(s.backend))));
    m_epsilon->setText(s.epsilon == 1.71e-4f ? kDefaultEpsilon : QString::number(double(s.epsilon), 'g', 6));
    m_threads->setValue(s.threads);
}

int BakePanel::currentCharacter() const
{
    if (!m_document)
        return -1;
    const std::string name = m_character->currentData().toString().toStdString();
    const auto& characters = m_document->scenario().characters;
    for (std::size_t i = 0; i < characters.size(); ++i)
        if (characters[i].name == name)
            return int(i);
    return -1;
}

void BakePanel::setCurrentCharacter(int index)
{
    if (index >= 0 && index < m_character->count())
        m_character->setCurrentIndex(index);
}

core::Result<QString> BakePanel::outputPathFor(int index, const lighting::BakeSettings& s) const
{
    if (!m_document || index < 0 || std::size_t(index) >= m_document->scenario().characters.size())
        return core::makeError(core::ErrorCode::InvalidArgument, tr("There is no character to bake.").toStdString());
    const QString base = m_document->baseDir();
    const QString folder = base.isEmpty() ? QString() : QDir(base).absoluteFilePath(kBakeFolder);
    // mkpath fails inside a folder that cannot be written to (or where a file has the name).
    if (folder.isEmpty() || !QDir().mkpath(folder) || !QFileInfo(folder).isWritable())
        return core::makeError(core::ErrorCode::IoError,
                               tr("Save the scenario in a folder you can write to first: the bake goes to %1, which "
                                  "cannot be written.")
                                   .arg(QDir::toNativeSeparators(folder.isEmpty() ? tr("its folder") : folder))
                                   .toStdString());
    const QString stem = m_document->filePath().isEmpty() ? QStringLiteral("untitled")
                                                          : fileNamePart(QFileInfo(m_document->filePath()).completeBaseName());
    const QString character = fileNamePart(fromUtf8(m_document->scenario().characters[std::size_t(index)].name));
    const QString prefix = QStringLiteral("%1-%2-%3-o%4-")
                               .arg(stem, character, QString::fromLatin1(lighting::transferKindName(s.transfer)))
                               .arg(s.order);
    for (;;) {
        const QString unique = QStringLiteral("%1").arg(QRandomGenerator::global()->generate(), 8, 16, QChar(u'0'));
        const QString path = QDir(folder).filePath(prefix + unique + kBakeExtension);
        if (!QFileInfo::exists(path))
            return path;
    }
}

void BakePanel::start()
{
    if (isRunning() || !m_document)
        return;
    auto s = settings();
    if (!s) {
        setStatus(fromUtf8(s.error().message), true);
        return;
    }
    const int index = currentCharacter();
    auto path = outputPathFor(index, *s);
    if (!path) {
        setStatus(fromUtf8(path.error().message), true);
        return;
    }
    const core::scenario::Scenario& scenario = m_document->scenario();
    auto body = core::scenario::loadCharacterBody(scenario, std::size_t(index), m_document->assets());
    if (!body) {
        removeEmptyBakeFolder(*path);
        setStatus(tr("The body of the character could not be loaded: %1").arg(fromUtf8(body.error().message)), true);
        return;
    }
    const core::scenario::Character& character = scenario.characters[std::size_t(index)];
    Running running{character.name, character.skeleton, character.model, character.segmentTags, *s, *path};
    const auto vertices = qint64(body->mesh.vertexCount());
    auto job = std::make_unique<lighting::TransferBakeJob>();
    job->mesh = std::move(body->mesh);
    job->settings = *s;
    job->output = toFsPath(*path);
    if (auto started = m_job->start(std::move(job)); !started) {
        removeEmptyBakeFolder(*path);
        setStatus(fromUtf8(started.error().message), true);
        return;
    }
    m_running = std::move(running);
    onProgress({}, 0, vertices);
    setStatus(tr("Baking %1: %2, order %3, %4 rays per vertex…")
                  .arg(fromUtf8(character.name), shortTransferName(s->transfer))
                  .arg(s->order)
                  .arg(grouped(s->raysPerVertex)),
              false);
    updateEnabled();
}

void BakePanel::cancel()
{
    m_job->cancel();
}

void BakePanel::onProgress(const QString&, qint64 done, qint64 total)
{
    m_progress->setRange(0, int(std::max<qint64>(total, 1)));
    m_progress->setValue(int(std::min(done, total)));
    m_progress->setFormat(tr("%p% — %1 / %2 vertices").arg(grouped(done), grouped(total)));
}

void BakePanel::onFinished(const core::Result<void>& result)
{
    const std::optional<Running> running = std::move(m_running);
    m_running.reset();
    updateEnabled();
    if (!running)
        return;
    const QString* path = &running->path;
    if (!result) {
        removeEmptyBakeFolder(*path);
        m_progress->setRange(0, 1);
        m_progress->setValue(0);
        if (result.error().code == core::ErrorCode::Cancelled) {
            m_progress->setFormat(tr("Cancelled"));
            setStatus(tr("Cancelled — nothing changed."), false);
        } else {
            m_progress->setFormat(tr("Failed"));
            setStatus(tr("The bake failed: %1").arg(fromUtf8(result.error().message)), true);
        }
        return;
    }
    // Apply to the character baked, if it is still the one that was baked.
    auto refuse = [&](const QString& why) {
        removeFile(*path);
        removeEmptyBakeFolder(*path);
        setStatus(why, true);
    };
    if (!m_document)
        return refuse(tr("The scenario was closed while baking; nothing changed."));
    const auto& characters = m_document->scenario().characters;
    const auto it = std::find_if(characters.begin(), characters.end(),
                                 [&](const core::scenario::Character& c) { return c.name == running->character; });
    if (it == characters.end())
        return refuse(tr("The character “%1” is gone; the bake was thrown away.").arg(fromUtf8(running->character)));
    if (it->skeleton != running->skeleton || it->model != running->model || it->segmentTags != running->segmentTags)
        return refuse(tr("%1 changed while baking (body or segment tags); nothing changed: bake again.")
                          .arg(fromUtf8(running->character)));
    const int index = int(it - characters.begin());
    const lighting::BakeSettings& s = running->settings;
    const QString text = tr("Bake %1 (%2, order %3)").arg(fromUtf8(running->character), shortTransferName(s.transfer)).arg(s.order);
    // Relative to the document's folder now ("bakes/…"; it may have been saved elsewhere meanwhile).
    const QString relative = QDir(m_document->baseDir()).relativeFilePath(*path);
    if (auto edited = m_document->edit(core::edit::setCharacterBake(m_document->scenario(), index, relative.toStdString()),
                                       text);
        !edited)
        return refuse(tr("The bake could not be applied: %1").arg(fromUtf8(edited.error().message)));

    const lighting::BakeStatistics& statistics = m_job->jobAs<lighting::TransferBakeJob>()->statistics;
    const double mrays = statistics.seconds > 0 ? double(statistics.rays) / statistics.seconds / 1e6 : 0.0;
    setStatus(tr("Last bake: %1, order %2, %3 rays per vertex — %4 s, %5 Mrays/s.")
                  .arg(shortTransferName(s.transfer))
                  .arg(s.order)
                  .arg(grouped(s.raysPerVertex))
                  .arg(statistics.seconds, 0, 'f', statistics.seconds < 10 ? 2 : 1)
                  .arg(mrays, 0, 'f', 1),
              false);
    refreshCurrentBake();
}

void BakePanel::refreshCharacters()
{
    fillCharacterChoice(m_character, m_document);
    refreshCurrentBake();
    updateEnabled();
}

void BakePanel::refreshCurrentBake()
{
    const int index = currentCharacter();
    if (index < 0) {
        m_currentBakeKey.clear();
        m_currentBake->setText(tr("—"));
        m_currentBake->setToolTip({});
        return;
    }
    const core::scenario::Scenario& scenario = m_document->scenario();
    const core::scenario::Character& character = scenario.characters[std::size_t(index)];
    // Reading the bake and building the body again only when something they depend on changed.
    QString key = m_document->baseDir() + u'\n' + fromUtf8(character.name) + u'\n' + fromUtf8(character.bake) + u'\n'
                  + fromUtf8(character.model) + u'\n' + fromUtf8(character.skeleton);
    for (const core::scene::SegmentTag& tag : character.segmentTags)
        key += u'\n' + fromUtf8(tag.segment) + u':' + QString::number(int(tag.role));
    if (key == m_currentBakeKey)
        return;
    m_currentBakeKey = key;
    m_currentBake->setStyleSheet(QString());

    if (character.bake.empty()) {
        m_currentBake->setText(tr("none — unshadowed (DU)"));
        m_currentBake->setToolTip(tr("Bake the character to light it with shadows"));
        return;
    }
    const QString file = QFileInfo(fromUtf8(character.bake)).fileName();
    auto bake = lighting::readBakeFile(m_document->assets().path(character.bake));
    if (!bake) {
        m_currentBake->setText(tr("%1\nmissing or unreadable — lit unshadowed (DU)").arg(file));
        m_currentBake->setToolTip(fromUtf8(bake.error().message));
        m_currentBake->setStyleSheet(kWarningStyle);
        return;
    }
    auto body = core::scenario::loadCharacterBody(scenario, std::size_t(index), m_document->assets());
    auto fits = body ? lighting::checkBakeMatchesMesh(*bake, body->mesh) : core::Result<void>(body.error());
    if (!fits) {
        m_currentBake->setText(tr("%1\nstale: it no longer fits the body or its segment tags — lit unshadowed (DU) "
                                  "until baked again")
                                   .arg(file));
        m_currentBake->setToolTip(fromUtf8(fits.error().message));
        m_currentBake->setStyleSheet(kWarningStyle);
        return;
    }
    m_currentBake->setText(tr("%1\n%2, order %3, %4 rays per vertex")
                               .arg(file, shortTransferName(bake->transferKind))
                               .arg(bake->order)
                               .arg(grouped(bake->raysPerVertex)));
    m_currentBake->setToolTip(QDir::toNativeSeparators(fromFsPath(m_document->assets().path(character.bake))));
}

void BakePanel::updateEnabled()
{
    const bool running = isRunning();
    const bool ready = m_document && m_character->count() > 0;
    for (QWidget* widget : m_settingsWidgets)
        widget->setEnabled(ready && !running);
    m_start->setEnabled(ready && !running);
    m_cancel->setEnabled(running);
}

void BakePanel::setStatus(const QString& text, bool error)
{
    m_status->setText(text);
    m_status->setStyleSheet(error ? kErrorStyle : QString());
}

QString BakePanel::statusText() const
{
    return m_status->text();
}

QString BakePanel::currentBakeText() const
{
    return m_currentBake->text();
}

void BakePanel::setPrtPreview(bool prt)
{
    const QSignalBlocker blocker(m_prtPreview);
    m_prtPreview->setChecked(prt);
}

bool BakePanel::prtPreview() const
{
    return m_prtPreview->isChecked();
}

} // namespace thespis::editor
