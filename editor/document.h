#pragma once
// Document: one open scenario. Owns the scenario document (core::scenario::Scenario), the file
// it came from, the runnable schedules built from it (ScenarioRuntime) and its undo history.
// Views read it; every change is a core::edit::Edit pushed through edit() as one undoable
// command (STYLE.md §4, §5). After each change the runtime is rebuilt and edited() is emitted.

#include <QObject>
#include <QString>
#include <QStringList>

#include <memory>
#include <optional>

#include "edit/scenario_edit.h"
#include "scenario/package.h"
#include "scenario/scenario.h"
#include "scenario/scenario_runtime.h"
#include "util/error.h"
#include "util/tick.h"

class QUndoStack;

namespace thespis::editor {

/// How a change joins the undo history. Steps of one drag carry the same `key` (a CommandId)
/// and merge into one command; the last step (`finished`) closes it.
struct Merge {
    int key = -1;
    bool finished = true;
};

class Document : public QObject {
    Q_OBJECT
public:
    ~Document() override;

    /// Reads a .thespis file and builds its schedules (clip files resolve next to it). Errors
    /// are the reader's or the builder's, with the file name added to the detail. A package
    /// (.thespkg, core/scenario/package.h) opens the same way, checked first: its scenario plays
    /// from it; the document has no file of its own until saved, when the package's files are
    /// written beside it.
    static core::Result<std::unique_ptr<Document>> open(const QString& path);
    /// Reads an autosaved copy (Autosaver) back: the document takes the original file's path
    /// (empty for a never-saved one) and folder, and starts modified, so that saving writes the
    /// recovered work where it belongs. A document that played from a package plays from it again.
    static core::Result<std::unique_ptr<Document>> recover(const QString& recoveryFile, const QString& originalPath,
                                                           const QString& baseDir, const QString& packagePath = {});
    /// A document over a scenario held in memory and never saved; clip files resolve in
    /// `baseDir`.
    static core::Result<std::unique_ptr<Document>> fromScenario(core::scenario::Scenario scenario,
                                                                const QString& baseDir);
    /// The first character's name in the scenario or package at `path`, read without building
    /// anything (for help texts); empty when it cannot be read or has no character.
    static QString firstCharacterName(const QString& path);

    const core::scenario::Scenario& scenario() const { return m_scenario; }
    const core::scenario::ScenarioRuntime& runtime() const { return m_runtime; }

    /// Absolute path of the file, empty when the document was never saved.
    QString filePath() const { return m_filePath; }
    /// The file the document was read from: its own, else the package it was opened from.
    QString sourceFile() const { return m_filePath.isEmpty() ? m_packagePath : m_filePath; }
    /// The package the document plays from until it is saved (empty: none).
    QString packagePath() const { return m_packagePath; }
    /// The folder the scenario's relative paths (clips, models, probe) resolve in.
    QString baseDir() const { return m_baseDir; }
    /// Where the scenario's files are found (the resolver every reader asks).
    const core::scenario::Assets& assets() const { return m_assets; }
    /// The file's name ("demo.thespis"), or "Untitled".
    QString fileName() const;
    /// The scenario's own name, else the file's base name, else "Untitled".
    QString scenarioName() const;
    /// Problems that did not stop loading (e.g. BVH joints with no H-Anim counterpart).
    QStringList warnings() const;
    /// The same with what each is about, for the Messages panel.
    struct Message {
        QString text;
        int character = -1; ///< index of the character it is about, or -1
        QString clip;       ///< the clip it is about, or empty
    };
    QList<Message> messages() const;

    /// Length of the timeline (the runtime's duration).
    core::Tick duration() const { return m_runtime.duration; }
    /// What a preview plays: the duration, or 10 s when the scenario has no finite length
    /// (only open-ended actions), so that there is always something to scrub.
    core::Tick previewDuration() const;

    QUndoStack* undoStack() const { return m_undoStack; }
    bool isModified() const;

    /// Pushes `edit` as one undoable command named `text` ("Move 2 Actions"). The edit is tried
    /// on a copy first: when it does not fit, or the scenario it makes does not build, nothing
    /// changes and the error says why. An edit that changes nothing pushes nothing.
    core::Result<void> edit(core::edit::Edit edit, const QString& text, Merge merge = {});
    /// As edit(), for the Result the document edits return.
    core::Result<void> edit(core::Result<core::edit::Edit> edit, const QString& text, Merge merge = {});

    /// Writes the scenario to `path` atomically; on success the document takes that path (and its
    /// folder as base: relative clip, model, bake and probe paths are rewritten to still name the same
    /// files) and is clean. Errors name the file.
    core::Result<void> saveAs(const QString& path);
    core::Result<void> save() { return saveAs(m_filePath); }
    /// A file the scenario names was written again under the same name (a face mapping table
    /// saved from the studio): emits edited() with an empty edit, so that views read it anew.
    /// Nothing to undo: the document itself is unchanged.
    void fileRewritten() { emit edited(core::edit::Edit()); }
    /// Marks the current state as saved (or, false, as changed: a recovered document).
    void setClean(bool clean);
    /// The path a recovered document came from (it keeps its original file path).
    void setFilePath(const QString& path);

signals:
    void modifiedChanged(bool modified);
    /// After every change (do, undo, redo), once the runtime is rebuilt.
    void edited(const core::edit::Edit& edit);
    void filePathChanged(const QString& path);

private:
    friend class EditCommand;
    /// The scenario of the file or package at `path` (core::scenario::openScenario), or
    /// `replacement` (recovered work) with the file's or package's assets.
    static core::Result<std::unique_ptr<Document>> openReplacing(const QString& path,
                                                                 std::optional<core::scenario::Scenario> replacement);
    Document(core::scenario::Scenario scenario, core::scenario::ScenarioRuntime runtime, QString filePath,
             QString baseDir);
    // Applies an edit that is known to fit and rebuilds the runtime (undo / redo).
    void apply(const core::edit::Edit& edit);
    // The runtime of `next`, the scenario `edit` made from the current one.
    core::Result<core::scenario::ScenarioRuntime> runtimeAfter(const core::edit::Edit& edit,
                                                               const core::scenario::Scenario& next);
    void install(core::scenario::Scenario scenario, core::scenario::ScenarioRuntime runtime,
                 const core::edit::Edit& edit);

    core::scenario::Scenario m_scenario;
    core::scenario::ScenarioRuntime m_runtime;
    QString m_filePath;
    QString m_baseDir;
    core::scenario::Assets m_assets; // m_baseDir's
    QUndoStack* m_undoStack = nullptr; // child QObject
    std::unique_ptr<core::scenario::AssetCache> m_cache; // files the runtime reads, kept between edits
    // The package opened, until the first save writes its files out (names it holds are its
    // entries; other relative names are the user's, beside the package).
    std::shared_ptr<const core::scenario::Package> m_package;
    QString m_packagePath;
};

} // namespace thespis::editor
