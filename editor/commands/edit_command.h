#pragma once
// EditCommand: the one undo command of the studio. It wraps a core::edit::Edit and applies it to
// its Document on redo, its inverse on undo (STYLE.md §5). Steps of a drag carry the same merge
// key and merge into one command until the step that finishes the drag; a merged command that
// comes back to where it started marks itself obsolete, so the stack drops it.

#include <QUndoCommand>

#include "edit/scenario_edit.h"
#include "scenario/scenario.h"
#include "scenario/scenario_runtime.h"

namespace thespis::editor {

class Document;

class EditCommand final : public QUndoCommand {
public:
    /// `prepared` is the document's next state and runtime, already built by Document::edit():
    /// the first redo installs it instead of building it again.
    EditCommand(Document& document, core::edit::Edit edit, const QString& text, int mergeKey, bool finished,
                core::scenario::Scenario prepared, core::scenario::ScenarioRuntime preparedRuntime);

    void redo() override;
    void undo() override;
    int id() const override { return m_mergeKey; }
    bool mergeWith(const QUndoCommand* other) override;

    const core::edit::Edit& edit() const { return m_edit; }
    /// See core::edit::Edit::rebasePaths (Document::saveAs to another folder).
    void rebasePaths(const std::filesystem::path& from, const std::filesystem::path& to, const core::scenario::KeptNames& keep = {})
    {
        m_edit.rebasePaths(from, to, keep);
    }
    /// Ends merging: a drag finished with a step that changed nothing more.
    void finish() { m_finished = true; }

private:
    Document& m_document;
    core::edit::Edit m_edit;
    int m_mergeKey;
    bool m_finished;
    std::optional<std::pair<core::scenario::Scenario, core::scenario::ScenarioRuntime>> m_prepared;
};

} // namespace thespis::editor
