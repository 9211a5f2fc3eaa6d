#include "editor/document.h"

#include <QFile>
#include <QFileInfo>
#include <QUndoStack>

#include "editor/qt_conversions.h"
#include "scenario/scenario_io.h"

namespace thespis::editor {

namespace {
constexpr double kOpenEndedPreviewSeconds = 10.0;
} // namespace

Document::Document(core::scenario::Scenario scenario, core::scenario::ScenarioRuntime runtime, QString filePath,
                   QString baseDir)
    : m_scenario(std::move(scenario)), m_runtime(std::move(runtime)), m_filePath(std::move(filePath)),
      m_baseDir(std::move(baseDir)), m_undoStack(new QUndoStack(this))
{
    connect(m_undoStack, &QUndoStack::cleanChanged, this, [this](bool clean) { emit modifiedChanged(!clean); });
}

Document::~Document() = default;

core::Result<std::unique_ptr<Document>> Document::open(const QString& path)
{
    const QFileInfo info(path);
    const std::filesystem::path file = toFsPath(info.absoluteFilePath());
    core::Result<core::scenario::Scenario> scenario = core::scenario::loadScenario(file);
    if (!scenario)
        return scenario.error();
    core::Result<core::scenario::ScenarioRuntime> runtime = core::scenario::buildRuntime(*scenario, file.parent_path());
    if (!runtime) {
        core::Error error = runtime.error();
        error.detail = (error.detail.empty() ? std::string() : error.detail + "; ") + "in " + file.string();
        return error;
    }
    return std::unique_ptr<Document>(
        new Document(std::move(*scenario), std::move(*runtime), info.absoluteFilePath(), info.absolutePath()));
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
    return m_filePath.isEmpty() ? tr("Untitled") : QFileInfo(m_filePath).fileName();
}

QString Document::scenarioName() const
{
    if (!m_scenario.name.empty())
        return QString::fromStdString(m_scenario.name);
    if (!m_filePath.isEmpty())
        return QFileInfo(m_filePath).completeBaseName();
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

double Document::previewDuration() const
{
    return m_runtime.duration > 0 ? m_runtime.duration : kOpenEndedPreviewSeconds;
}

bool Document::isModified() const
{
    return !m_undoStack->isClean();
}

} // namespace thespis::editor
