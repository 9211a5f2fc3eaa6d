#pragma once
// TargetChoice: what a gaze or a pointing arm aims at, as BML writes it — the camera (in AR the
// visitor), another character's eyes or hands picked from a list, or a joint ("Creon:l_wrist")
// or a point in metres ("0.5 1.6 2") typed in.

#include <QComboBox>

#include <string>

#include "scenario/scenario.h"

namespace thespis::editor {

class TargetChoice : public QComboBox {
    Q_OBJECT
public:
    explicit TargetChoice(QWidget* parent = nullptr);

    /// Lists the camera and the characters of `scenario` other than `character`, and shows `target`.
    void showTargets(const core::scenario::Scenario& scenario, int character, const std::string& target);
    /// A target picked from the list is its data; one typed is what was typed.
    std::string target() const;

signals:
    /// A target picked, or one typed and confirmed.
    void targetChosen();
};

} // namespace thespis::editor
