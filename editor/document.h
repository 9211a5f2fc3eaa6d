#pragma once
// Document: one open scenario. Owns the scenario document (core::scenario::Scenario), the file
// it came from, the runnable schedules built from it (ScenarioRuntime) and its undo history.
// Views read it; edits will go through its operations and the undo stack (STYLE.md §4, §5).

#include <QObject>
#include <QString>
#include <QStringList>

#include <memory>

#include "scenario/scenario.h"
#include "scenario/scenario_runtime.h"
#include "util/error.h"

class QUndoStack;

namespace thespis::editor {

class Document : public QObject {
    Q_OBJECT
public:
    ~Document() override;

    /// Reads a .thespis file and builds its schedules (clip files resolve next to it). Errors
    /// are the reader's or the builder's, with the file name added to the detail.
    static core::Result<std::unique_ptr<Document>> open(const QString& path);
    /// A document over a scenario held in memory and never saved; clip files resolve in
    /// `baseDir`.
    static core::Result<std::unique_ptr<Document>> fromScenario(core::scenario::Scenario scenario,
                                                                const QString& baseDir);

    const core::scenario::Scenario& scenario() const { return m_scenario; }
    const core::scenario::ScenarioRuntime& runtime() const { return m_runtime; }

    /// Absolute path of the file, empty when the document was never saved.
    QString filePath() const { return m_filePath; }
    /// The folder the scenario's relative paths (clips, models, probe) resolve in.
    QString baseDir() const { return m_baseDir; }
    /// The file's name ("demo.thespis"), or "Untitled".
    QString fileName() const;
    /// The scenario's own name, else the file's base name, else "Untitled".
    QString scenarioName() const;
    /// Problems that did not stop loading (e.g. BVH joints with no H-Anim counterpart).
    QStringList warnings() const;

    /// Length of the timeline in seconds (the runtime's duration).
    double duration() const { return m_runtime.duration; }
    /// What a preview plays: the duration, or 10 s when the scenario has no finite length
    /// (only open-ended actions), so that there is always something to scrub.
    double previewDuration() const;

    QUndoStack* undoStack() const { return m_undoStack; }
    bool isModified() const;

signals:
    void modifiedChanged(bool modified);

private:
    Document(core::scenario::Scenario scenario, core::scenario::ScenarioRuntime runtime, QString filePath,
             QString baseDir);

    core::scenario::Scenario m_scenario;
    core::scenario::ScenarioRuntime m_runtime;
    QString m_filePath;
    QString m_baseDir;
    QUndoStack* m_undoStack = nullptr; // child QObject
};

} // namespace thespis::editor
