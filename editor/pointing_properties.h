#pragma once
// PointingProperties: on the Properties page of a body action (format 11), whether its gesture
// points — BML's <pointing> put on the timeline — and at what, with which hand. Checked, the
// Stage turns the arm at the shoulder so that the index finger points at the target while the
// action plays. Each change asks for one edit.

#include <QGroupBox>

#include <optional>

#include "scenario/scenario.h"

class QComboBox;

namespace thespis::editor {

class TargetChoice;

class PointingProperties : public QGroupBox {
    Q_OBJECT
public:
    explicit PointingProperties(QWidget* parent = nullptr);

    /// Shows the pointing of an action of `character` in `scenario` (unchecked when it has none);
    /// hidden when `bodyAction` is false.
    void show(const core::scenario::Scenario& scenario, int character,
              const std::optional<core::scenario::PointingSpec>& pointing, bool bodyAction, bool editable);

    TargetChoice* targetChoice() const { return m_target; }
    QComboBox* handChoice() const { return m_hand; }

signals:
    /// The fields as the user left them: none when the action no longer points.
    void pointingEditRequested(const std::optional<core::scenario::PointingSpec>& pointing);

private:
    void emitEdit();

    TargetChoice* m_target = nullptr;
    QComboBox* m_hand = nullptr;
    std::optional<core::scenario::PointingSpec> m_shown; ///< leaving the fields as shown edits nothing
    bool m_refreshing = false;
};

} // namespace thespis::editor
