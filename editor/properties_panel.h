#pragma once
// PropertiesPanel: the fields of the action selected on the timeline — name, clip, start time,
// blend mode, joint mask, whether it renders outside its domain — each editable as one undoable
// command, plus what it is made of (length, fades, modifiers) for reading. With no action
// selected it describes the scenario (file, characters, length) and says how to select one.

#include <QWidget>

#include <optional>

#include "edit/scenario_edit.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QStackedWidget;

namespace thespis::editor {

class Document;

class PropertiesPanel : public QWidget {
    Q_OBJECT
public:
    explicit PropertiesPanel(QWidget* parent = nullptr);

    void setDocument(Document* document);
    /// The action whose properties are shown (the timeline's current one), or none.
    void setAction(std::optional<core::edit::ActionPath> action);
    std::optional<core::edit::ActionPath> action() const { return m_action; }

    QLineEdit* nameEdit() const { return m_name; }
    QComboBox* clipChoice() const { return m_clip; }
    QDoubleSpinBox* startEdit() const { return m_start; }
    QComboBox* modeChoice() const { return m_mode; }
    QComboBox* maskChoice() const { return m_mask; }
    QCheckBox* outsideDomainCheck() const { return m_outsideDomain; }

signals:
    /// An edit was refused; the message says why.
    void problem(const QString& message);

private:
    void refresh();
    void showScenario();
    void showAction();
    // Pushes the current action with `change` applied as one command named `text`.
    template <typename Change> void editAction(const QString& text, Change change);
    void onStartEdited();

    Document* m_document = nullptr;
    std::optional<core::edit::ActionPath> m_action;
    bool m_refreshing = false; // set while fields are filled from the document: not user edits

    QStackedWidget* m_pages = nullptr;
    QLabel* m_scenarioSummary = nullptr;
    QLabel* m_owner = nullptr;
    QLineEdit* m_name = nullptr;
    QComboBox* m_clip = nullptr;
    QDoubleSpinBox* m_start = nullptr;
    QComboBox* m_mode = nullptr;
    QComboBox* m_mask = nullptr;
    QCheckBox* m_outsideDomain = nullptr;
    QLabel* m_length = nullptr;
    QLabel* m_fades = nullptr;
    QLabel* m_modifiers = nullptr;
};

} // namespace thespis::editor
