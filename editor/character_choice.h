#pragma once
// The "Character:" chooser the per-character panels (gesticon, segments, bake) put on top: a
// combo box of the document's characters, named in the box and in its item data.

#include <QString>

class QBoxLayout;
class QComboBox;
class QWidget;

namespace thespis::editor {

class Document;

/// Adds "Character:" and a combo box (stretching) to `row`; the combo is returned.
QComboBox* addCharacterChoice(QWidget* parent, QBoxLayout* row, const QString& objectName, const QString& toolTip);

/// Fills `choice` with the document's characters, keeping the one chosen before when it is still
/// there (else the first, or none); emits nothing. Returns the chosen index.
int fillCharacterChoice(QComboBox* choice, const Document* document);

} // namespace thespis::editor
