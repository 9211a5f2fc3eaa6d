#include "editor/pointing_properties.h"

#include <QComboBox>
#include <QFormLayout>

#include <algorithm>

#include "editor/qt_conversions.h"
#include "editor/target_choice.h"

namespace thespis::editor {

PointingProperties::PointingProperties(QWidget* parent) : QGroupBox(tr("Points at"), parent)
{
    setObjectName(QStringLiteral("pointingProperties"));
    setCheckable(true);
    setToolTip(tr("Aims the gesture's arm at a target while the action plays (BML's <pointing>)"));
    auto* form = new QFormLayout(this);
    m_target = new TargetChoice(this);
    m_target->setObjectName(QStringLiteral("pointingTarget"));
    m_hand = new QComboBox(this);
    m_hand->setObjectName(QStringLiteral("pointingHand"));
    m_hand->addItem(tr("Right hand"), QStringLiteral("RIGHT_HAND"));
    m_hand->addItem(tr("Left hand"), QStringLiteral("LEFT_HAND"));
    m_hand->addItem(tr("Both hands"), QStringLiteral("BOTH_HANDS"));
    form->addRow(tr("Target:"), m_target);
    form->addRow(tr("With:"), m_hand);

    connect(this, &QGroupBox::toggled, this, &PointingProperties::emitEdit);
    connect(m_target, &TargetChoice::targetChosen, this, &PointingProperties::emitEdit);
    connect(m_hand, &QComboBox::activated, this, &PointingProperties::emitEdit);
}

void PointingProperties::show(const core::scenario::Scenario& scenario, int character,
                              const std::optional<core::scenario::PointingSpec>& pointing, bool bodyAction,
                              bool editable)
{
    setVisible(bodyAction);
    if (!bodyAction)
        return;
    m_refreshing = true;
    m_shown = pointing;
    const core::scenario::PointingSpec shown = pointing.value_or(core::scenario::PointingSpec{});
    setChecked(pointing.has_value());
    m_target->showTargets(scenario, character, shown.target);
    m_hand->setCurrentIndex(std::max(0, m_hand->findData(fromUtf8(shown.hand).toUpper())));
    setEnabled(editable);
    m_refreshing = false;
}

void PointingProperties::emitEdit()
{
    if (m_refreshing)
        return;
    std::optional<core::scenario::PointingSpec> pointing;
    if (isChecked())
        pointing = core::scenario::PointingSpec{m_target->target(), m_hand->currentData().toString().toStdString()};
    if (pointing == m_shown)
        return;
    emit pointingEditRequested(pointing);
}

} // namespace thespis::editor
