#include "editor/commands/edit_command.h"

#include "editor/document.h"

namespace thespis::editor {

EditCommand::EditCommand(Document& document, core::edit::Edit edit, const QString& text, int mergeKey, bool finished,
                         core::scenario::Scenario prepared, core::scenario::ScenarioRuntime preparedRuntime)
    : QUndoCommand(text), m_document(document), m_edit(std::move(edit)), m_mergeKey(mergeKey), m_finished(finished),
      m_prepared(std::in_place, std::move(prepared), std::move(preparedRuntime))
{
}

void EditCommand::redo()
{
    if (m_prepared) {
        m_document.install(std::move(m_prepared->first), std::move(m_prepared->second), m_edit);
        m_prepared.reset();
        return;
    }
    m_document.apply(m_edit);
}

void EditCommand::undo()
{
    m_document.apply(m_edit.inverse());
}

bool EditCommand::mergeWith(const QUndoCommand* other)
{
    const auto* next = static_cast<const EditCommand*>(other); // same id(): only EditCommands have ids
    if (m_finished || m_mergeKey < 0 || !m_edit.canMergeWith(next->m_edit))
        return false;
    m_edit.mergeWith(next->m_edit);
    m_finished = next->m_finished;
    setObsolete(m_edit.changesNothing());
    return true;
}

} // namespace thespis::editor
