#include "editor/target_choice.h"

#include <QLineEdit>

#include "editor/qt_conversions.h"

namespace thespis::editor {

TargetChoice::TargetChoice(QWidget* parent) : QComboBox(parent)
{
    setEditable(true);
    setInsertPolicy(QComboBox::NoInsert);
    setToolTip(tr("The camera, a character (its eyes), a joint of one (\"Creon:r_radiocarpal\") or a point in "
                  "metres (\"0.5 1.6 2\")"));
    connect(this, &QComboBox::activated, this, &TargetChoice::targetChosen);
    connect(lineEdit(), &QLineEdit::editingFinished, this, &TargetChoice::targetChosen);
}

void TargetChoice::showTargets(const core::scenario::Scenario& scenario, int character, const std::string& target)
{
    const QSignalBlocker quiet(this);
    clear();
    addItem(tr("The camera (the viewer)"), QStringLiteral("camera"));
    for (int c = 0; c < int(scenario.characters.size()); ++c) {
        if (c == character)
            continue;
        const QString name = fromUtf8(scenario.characters[std::size_t(c)].name);
        addItem(tr("%1's eyes").arg(name), name);
        addItem(tr("%1's right hand").arg(name), name + QStringLiteral(":r_radiocarpal"));
        addItem(tr("%1's left hand").arg(name), name + QStringLiteral(":l_radiocarpal"));
    }
    const QString shown = fromUtf8(target);
    if (const int known = findData(shown); known >= 0)
        setCurrentIndex(known);
    else
        setEditText(shown);
}

std::string TargetChoice::target() const
{
    const int picked = findText(currentText());
    return (picked >= 0 ? itemData(picked).toString() : currentText().trimmed()).toStdString();
}

} // namespace thespis::editor
