#include "editor/gaze_properties.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>

#include <algorithm>

#include "editor/qt_conversions.h"
#include "editor/target_choice.h"

namespace thespis::editor {

GazeProperties::GazeProperties(QWidget* parent) : QGroupBox(tr("Looks at"), parent)
{
    setObjectName(QStringLiteral("gazeProperties"));
    auto* form = new QFormLayout(this);
    m_target = new TargetChoice(this);
    m_target->setObjectName(QStringLiteral("gazeTarget"));
    m_influence = new QComboBox(this);
    m_influence->setObjectName(QStringLiteral("gazeInfluence"));
    m_influence->addItem(tr("The eyes alone"), QStringLiteral("EYES"));
    m_influence->addItem(tr("Eyes and head"), QStringLiteral("HEAD"));
    m_influence->addItem(tr("Eyes, head and shoulders"), QStringLiteral("SHOULDER"));
    m_influence->addItem(tr("Eyes, head, shoulders and waist"), QStringLiteral("WAIST"));
    m_offset = new QDoubleSpinBox(this);
    m_offset->setObjectName(QStringLiteral("gazeOffset"));
    m_offset->setRange(0, 90);
    m_offset->setSuffix(tr("°"));
    m_offset->setKeyboardTracking(false);
    m_direction = new QComboBox(this);
    m_direction->setObjectName(QStringLiteral("gazeDirection"));
    const std::pair<QString, const char*> directions[] = {
        {tr("right"), "RIGHT"}, {tr("left"), "LEFT"},          {tr("up"), "UP"},
        {tr("down"), "DOWN"},   {tr("up and right"), "UPRIGHT"}, {tr("up and left"), "UPLEFT"},
        {tr("down and right"), "DOWNRIGHT"}, {tr("down and left"), "DOWNLEFT"}};
    for (const auto& [text, bml] : directions)
        m_direction->addItem(text, QString::fromLatin1(bml));
    form->addRow(tr("Target:"), m_target);
    form->addRow(tr("Turns:"), m_influence);
    form->addRow(tr("Away by:"), m_offset);
    form->addRow(tr("Toward:"), m_direction);

    connect(m_target, &TargetChoice::targetChosen, this, &GazeProperties::emitEdit);
    connect(m_influence, &QComboBox::activated, this, &GazeProperties::emitEdit);
    connect(m_offset, &QDoubleSpinBox::valueChanged, this, &GazeProperties::emitEdit);
    connect(m_direction, &QComboBox::activated, this, &GazeProperties::emitEdit);
}

void GazeProperties::show(const core::scenario::Scenario& scenario, int character,
                          const std::optional<core::scenario::GazeSpec>& gaze, bool editable)
{
    setVisible(gaze.has_value());
    if (!gaze)
        return;
    m_refreshing = true;
    m_shown = *gaze;
    m_target->showTargets(scenario, character, gaze->target);
    m_influence->setCurrentIndex(std::max(0, m_influence->findData(fromUtf8(gaze->influence).toUpper())));
    m_offset->setValue(gaze->offsetAngle);
    m_direction->setCurrentIndex(std::max(0, m_direction->findData(fromUtf8(gaze->offsetDirection).toUpper())));
    m_direction->setEnabled(editable && gaze->offsetAngle > 0);
    for (QWidget* field : {static_cast<QWidget*>(m_target), static_cast<QWidget*>(m_influence),
                           static_cast<QWidget*>(m_offset)})
        field->setEnabled(editable);
    m_refreshing = false;
}

void GazeProperties::emitEdit()
{
    if (m_refreshing)
        return;
    core::scenario::GazeSpec gaze;
    gaze.target = m_target->target();
    gaze.influence = m_influence->currentData().toString().toStdString();
    gaze.offsetAngle = m_offset->value();
    if (gaze.offsetAngle > 0)
        gaze.offsetDirection = m_direction->currentData().toString().toStdString();
    if (gaze == m_shown)
        return;
    emit gazeEditRequested(gaze);
}

} // namespace thespis::editor
