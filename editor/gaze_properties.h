#pragma once
// GazeProperties: on the Properties page of an action of a gaze layer (format 10), what the
// character looks at — the camera (in AR the visitor), another character's eyes or hand, or a
// point typed as "x y z" — how much of the body turns (BML's influence: the eyes; the head; the
// shoulders; the waist) and an offset away from the target. Each change asks for one edit.

#include <QGroupBox>

#include <optional>

#include "scenario/scenario.h"

class QComboBox;
class QDoubleSpinBox;

namespace thespis::editor {

class TargetChoice;

class GazeProperties : public QGroupBox {
    Q_OBJECT
public:
    explicit GazeProperties(QWidget* parent = nullptr);

    /// Shows `gaze`, an action's of `character` in `scenario`; hidden when it has none.
    void show(const core::scenario::Scenario& scenario, int character,
              const std::optional<core::scenario::GazeSpec>& gaze, bool editable);

    TargetChoice* targetChoice() const { return m_target; }
    QComboBox* influenceChoice() const { return m_influence; }
    QDoubleSpinBox* offsetEdit() const { return m_offset; }
    QComboBox* directionChoice() const { return m_direction; }

signals:
    /// The fields as the user left them.
    void gazeEditRequested(const core::scenario::GazeSpec& gaze);

private:
    void emitEdit();

    TargetChoice* m_target = nullptr;
    QComboBox* m_influence = nullptr;
    QDoubleSpinBox* m_offset = nullptr;
    QComboBox* m_direction = nullptr;
    core::scenario::GazeSpec m_shown; ///< what show() put in the fields: leaving them unchanged edits nothing
    bool m_refreshing = false;
};

} // namespace thespis::editor
