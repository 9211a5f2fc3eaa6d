#pragma once
// A tool button that shows its text only (the panels' Add / Remove / … rows).

#include <QString>
#include <QToolButton>

namespace thespis::editor {

inline QToolButton* textButton(const QString& text, const QString& tip, const QString& objectName, QWidget* parent)
{
    auto* button = new QToolButton(parent);
    button->setText(text);
    button->setToolTip(tip);
    button->setObjectName(objectName);
    button->setToolButtonStyle(Qt::ToolButtonTextOnly);
    return button;
}

} // namespace thespis::editor
