#pragma once
// PropertiesPanel: the fields of the action selected on the timeline — name, clip, start time,
// where its motion starts, how often it plays, blend mode, joint mask, whether it renders outside
// its domain — each editable as one undoable command, plus what it is made of (length, fades,
// modifiers) for reading, and the settings of the idle motion it plays (IdleProperties). With a
// character selected in the outline instead, the character's (CharacterProperties); with nothing
// selected it describes the scenario and says how to select.

#include <QWidget>

#include <optional>

#include "edit/scenario_edit.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QLabel;
class QLineEdit;
class QSpinBox;
class QStackedWidget;

namespace thespis::editor {

class CharacterProperties;
class Document;
class BlinkProperties;
class GazeProperties;
class PointingProperties;
class IdleProperties;

class PropertiesPanel : public QWidget {
    Q_OBJECT
public:
    explicit PropertiesPanel(QWidget* parent = nullptr);

    void setDocument(Document* document);
    /// The action whose properties are shown (the timeline's current one), or none.
    void setAction(std::optional<core::edit::ActionPath> action);
    std::optional<core::edit::ActionPath> action() const { return m_action; }
    /// The character whose properties are shown when no action is, or none.
    void setCharacter(std::optional<int> character);
    CharacterProperties* characterPage() const { return m_characterPage; }
    /// The idle clip's settings, shown for an action playing idle motion.
    IdleProperties* idleProperties() const { return m_idle; }
    /// The blink clip's settings, shown for an action playing blinks.
    BlinkProperties* blinkProperties() const { return m_blinks; }
    /// What an action of a gaze layer looks at.
    GazeProperties* gazeProperties() const { return m_gaze; }
    PointingProperties* pointingProperties() const { return m_pointing; }

    QLineEdit* nameEdit() const { return m_name; }
    QComboBox* clipChoice() const { return m_clip; }
    QDoubleSpinBox* startEdit() const { return m_start; }
    QComboBox* modeChoice() const { return m_mode; }
    QComboBox* maskChoice() const { return m_mask; }
    QCheckBox* outsideDomainCheck() const { return m_outsideDomain; }
    QComboBox* placementChoice() const { return m_placement; }
    QSpinBox* repeatEdit() const { return m_repeat; }
    QCheckBox* rootMotionCheck() const { return m_rootMotion; }

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
    void onRepeatEdited();

    Document* m_document = nullptr;
    std::optional<core::edit::ActionPath> m_action;
    std::optional<int> m_character;
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
    QComboBox* m_placement = nullptr;
    QSpinBox* m_repeat = nullptr;
    QCheckBox* m_rootMotion = nullptr;
    CharacterProperties* m_characterPage = nullptr;
    QLabel* m_length = nullptr;
    QLabel* m_fades = nullptr;
    QLabel* m_modifiers = nullptr;
    IdleProperties* m_idle = nullptr;
    BlinkProperties* m_blinks = nullptr;
    GazeProperties* m_gaze = nullptr;
    PointingProperties* m_pointing = nullptr;
    QLabel* m_maskLabel = nullptr;
    QFormLayout* m_form = nullptr;
};

} // namespace thespis::editor
