#include "editor/document.h"

#include <QFile>
#include <QFileInfo>
#include <QUndoStack>

#include "editor/commands/edit_command.h"
#include "editor/qt_conversions.h"
#include "scenario/open_scenario.h"
#include "scenario/scenario_io.h"

namespace thespis::editor {

namespace {
constexpr core::Tick kOpenEndedPreview = 10 * core::TicksPerSecond;
} // namespace

Document::Document(core::scenario::Scenario scenario, core::scenario::ScenarioRuntime runtime, QString filePath,
                   QString baseDir)
    : m_scenario(std::move(scenario)), m_runtime(std::move(runtime)), m_filePath(std::move(filePath)),
      m_baseDir(std::move(baseDir)), m_assets(toFsPath(m_baseDir)), m_undoStack(new QUndoStack(this)),
      m_cache(std::make_unique<core::scenario::AssetCache>())
{
    connect(m_undoStack, &QUndoStack::cleanChanged, this, [this](bool clean) { emit modifiedChanged(!clean); });
}

Document::~Document() = default;

core::Result<std::unique_ptr<Document>> Document::open(const QString& path)
{
    return openReplacing(path, std::nullopt);
}

QString Document::firstCharacterName(const QString& path)
{
    auto opened = core::scenario::openScenario(toFsPath(QFileInfo(path).absoluteFilePath()));
    return opened && !opened->scenario.characters.empty() ? fromUtf8(opened->scenario.characters.front().name)
                                                          : QString();
}

core::Result<std::unique_ptr<Document>> Document::openReplacing(const QString& path,
                                                                std::optional<core::scenario::Scenario> replacement)
{
    const QFileInfo info(path);
    const std::filesystem::path file = toFsPath(info.absoluteFilePath());
    auto opened = core::scenario::openScenario(file);
    if (!opened)
        return opened.error();
    core::scenario::Scenario scenario = replacement ? std::move(*replacement) : std::move(opened->scenario);
    auto runtime = core::scenario::buildRuntime(scenario, opened->assets);
    if (!runtime) {
        core::Error error = runtime.error();
        error.detail = (error.detail.empty() ? std::string() : error.detail + "; ") + "in " + file.string();
        return error;
    }
    // A package's document has no file of its own until saved.
    const QString own = opened->package ? QString() : info.absoluteFilePath();
    std::unique_ptr<Document> document(new Document(std::move(scenario), std::move(*runtime), own, info.absolutePath()));
    if (opened->package) {
        document->m_assets = opened->assets;
        document->m_package = opened->package;
        document->m_packagePath = info.absoluteFilePath();
    }
    return document;
}

core::Result<std::unique_ptr<Document>> Document::recover(const QString& recoveryFile, const QString& originalPath,
                                                          const QString& baseDir, const QString& packagePath)
{
    core::Result<core::scenario::Scenario> scenario = core::scenario::loadScenario(toFsPath(recoveryFile));
    if (!scenario)
        return scenario.error();
    auto document = packagePath.isEmpty() ? fromScenario(std::move(scenario).value(), baseDir)
                                          : openReplacing(packagePath, std::move(scenario).value());
    if (!document)
        return document.error();
    (*document)->m_filePath = originalPath.isEmpty() ? QString() : QFileInfo(originalPath).absoluteFilePath();
    (*document)->setClean(false);
    return document;
}

core::Result<std::unique_ptr<Document>> Document::fromScenario(core::scenario::Scenario scenario, const QString& baseDir)
{
    core::Result<core::scenario::ScenarioRuntime> runtime = core::scenario::buildRuntime(scenario, toFsPath(baseDir));
    if (!runtime)
        return runtime.error();
    return std::unique_ptr<Document>(new Document(std::move(scenario), std::move(*runtime), QString(), baseDir));
}

QString Document::fileName() const
{
    const QString source = sourceFile();
    return source.isEmpty() ? tr("Untitled") : QFileInfo(source).fileName();
}

QString Document::scenarioName() const
{
    if (!m_scenario.name.empty())
        return QString::fromStdString(m_scenario.name);
    if (!sourceFile().isEmpty())
        return QFileInfo(sourceFile()).completeBaseName();
    return tr("Untitled");
}

QStringList Document::warnings() const
{
    QStringList list;
    for (const core::scenario::CharacterRuntime& character : m_runtime.characters)
        for (const std::string& warning : character.warnings)
            list << QStringLiteral("%1: %2").arg(QString::fromStdString(character.name), QString::fromStdString(warning));
    return list;
}

QList<Document::Message> Document::messages() const
{
    QList<Message> list;
    for (std::size_t c = 0; c < m_runtime.characters.size(); ++c) {
        const core::scenario::CharacterRuntime& character = m_runtime.characters[c];
        for (std::size_t w = 0; w < character.warnings.size(); ++w)
            list.push_back({fromUtf8(character.warnings[w]), int(c),
                            w < character.warningClips.size() ? fromUtf8(character.warningClips[w]) : QString()});
    }
    return list;
}

core::Tick Document::previewDuration() const
{
    return m_runtime.duration > 0 ? m_runtime.duration : kOpenEndedPreview;
}

bool Document::isModified() const
{
    return !m_undoStack->isClean();
}

core::Result<void> Document::edit(core::edit::Edit edit, const QString& text, Merge merge)
{
    if (edit.empty() || edit.changesNothing()) {
        // The last step of a drag may add nothing; it still ends the drag's command.
        if (merge.finished && m_undoStack->index() > 0)
            if (auto* top = dynamic_cast<const EditCommand*>(m_undoStack->command(m_undoStack->index() - 1));
                top && top->id() == merge.key && merge.key >= 0)
                const_cast<EditCommand*>(top)->finish();
        return {};
    }
    core::scenario::Scenario next = m_scenario;
    if (auto applied = edit.apply(next); !applied)
        return applied.error();
    auto runtime = runtimeAfter(edit, next);
    if (!runtime)
        return runtime.error();
    m_undoStack->push(new EditCommand(*this, std::move(edit), text, merge.key, merge.finished, std::move(next),
                                      std::move(runtime).value()));
    return {};
}

core::Result<void> Document::edit(core::Result<core::edit::Edit> edit, const QString& text, Merge merge)
{
    if (!edit)
        return edit.error();
    return this->edit(std::move(edit).value(), text, merge);
}

void Document::apply(const core::edit::Edit& edit)
{
    // Undo and redo replay edits that fitted this very state before: a failure is a bug.
    core::scenario::Scenario next = m_scenario;
    auto applied = edit.apply(next);
    Q_ASSERT(applied);
    auto runtime = runtimeAfter(edit, next);
    Q_ASSERT(runtime);
    if (!applied || !runtime)
        return;
    install(std::move(next), std::move(runtime).value(), edit);
}

core::Result<core::scenario::ScenarioRuntime> Document::runtimeAfter(const core::edit::Edit& edit,
                                                                     const core::scenario::Scenario& next)
{
    const core::edit::RuntimeScope scope = edit.runtimeScope();
    if (scope.everything)
        return core::scenario::buildRuntime(next, m_assets, m_cache.get());
    // Only what the edit touched is built again: a drag step on one action rebuilds one character.
    return core::scenario::rebuildRuntime(next, m_assets, m_runtime, scope.characters, m_cache.get());
}

void Document::install(core::scenario::Scenario scenario, core::scenario::ScenarioRuntime runtime,
                       const core::edit::Edit& edit)
{
    m_scenario = std::move(scenario);
    m_runtime = std::move(runtime);
    emit edited(edit);
}

core::Result<void> Document::saveAs(const QString& path)
{
    if (path.isEmpty())
        return core::makeError(core::ErrorCode::InvalidArgument, "The scenario has no file yet: choose where to save it.");
    const QFileInfo info(path);
    core::scenario::Scenario saved = m_scenario;
    const std::filesystem::path oldBase = toFsPath(m_baseDir), newBase = toFsPath(info.absolutePath());
    // A package's files are written beside the scenario first, under their names: those names
    // stay as they are, where the other relative paths are rebased.
    core::scenario::KeptNames inPackage;
    if (m_package) {
        if (auto written = m_package->extractTo(newBase, false); !written)
            return written.error();
        inPackage = [package = m_package](const std::string& name) { return package->manifest().find(name) != nullptr; };
    }
    // Relative paths (clips, models, bakes, the probe) must name the same files from the new folder.
    core::scenario::rebasePaths(saved, oldBase, newBase, inPackage);
    if (auto written = core::scenario::saveScenario(toFsPath(info.absoluteFilePath()), saved); !written) {
        core::Error error = written.error();
        error.detail = (error.detail.empty() ? std::string() : error.detail + "; ") + "file "
                       + info.absoluteFilePath().toStdString();
        return error;
    }
    m_scenario = std::move(saved);
    if (oldBase != newBase) // the undo history must still fit the document
        for (int i = 0; i < m_undoStack->count(); ++i)
            if (auto* command = dynamic_cast<const EditCommand*>(m_undoStack->command(i)))
                const_cast<EditCommand*>(command)->rebasePaths(oldBase, newBase, inPackage);
    m_package.reset();
    m_packagePath.clear();
    m_baseDir = info.absolutePath();
    m_assets = core::scenario::Assets(toFsPath(m_baseDir));
    setFilePath(info.absoluteFilePath());
    m_undoStack->setClean();
    return {};
}

void Document::setClean(bool clean)
{
    if (clean)
        m_undoStack->setClean();
    else
        m_undoStack->resetClean();
}

void Document::setFilePath(const QString& path)
{
    if (path == m_filePath)
        return;
    m_filePath = path;
    emit filePathChanged(path);
}

} // namespace thespis::editor
