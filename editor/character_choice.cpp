#include "editor/character_choice.h"

#include <QBoxLayout>
#include <QComboBox>
#include <QCoreApplication>
#include <QLabel>
#include <QSignalBlocker>

#include "editor/document.h"
#include "editor/qt_conversions.h"

namespace thespis::editor {

QComboBox* addCharacterChoice(QWidget* parent, QBoxLayout* row, const QString& objectName, const QString& toolTip)
{
    auto* label = new QLabel(QCoreApplication::translate("CharacterChoice", "Character:"), parent);
    auto* choice = new QComboBox(parent);
    choice->setObjectName(objectName);
    choice->setToolTip(toolTip);
    choice->setMinimumContentsLength(12);
    label->setBuddy(choice);
    row->addWidget(label);
    row->addWidget(choice, 1);
    return choice;
}

int fillCharacterChoice(QComboBox* choice, const Document* document)
{
    const QString current = choice->currentData().toString();
    const QSignalBlocker blocker(choice);
    choice->clear();
    if (document)
        for (const core::scenario::Character& character : document->scenario().characters)
            choice->addItem(fromUtf8(character.name), fromUtf8(character.name));
    const int kept = choice->findData(current);
    choice->setCurrentIndex(kept >= 0 ? kept : (choice->count() > 0 ? 0 : -1));
    return choice->currentIndex();
}

} // namespace thespis::editor
