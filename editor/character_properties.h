#pragma once
// CharacterProperties: the Properties page of a character selected in the scenario outline —
// its name, its body (a glTF model or the built-in humanoid) and the skeleton its motion plays
// on, where it stands and which way it faces, its layers and clips for reading. Every change is
// one undoable command (core/edit/content_edits.h); a refused one says why.

#include <QWidget>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QPushButton;

namespace thespis::editor {

class Document;

class CharacterProperties : public QWidget {
    Q_OBJECT
public:
    explicit CharacterProperties(QWidget* parent = nullptr);

    /// The character shown (index into the document's), or -1.
    void show(Document* document, int character);
    int character() const { return m_character; }
    /// Uses this glTF file as the character's body, playing on its own rig (Choose Model… after
    /// its file dialog).
    void setModel(const QString& path);

    QLineEdit* nameEdit() const { return m_name; }
    QComboBox* skeletonChoice() const { return m_skeleton; }
    QDoubleSpinBox* positionEdit(int axis) const { return m_position[axis]; }
    QDoubleSpinBox* headingEdit() const { return m_heading; }
    QPushButton* humanoidButton() const { return m_humanoid; }

signals:
    void problem(const QString& message);

private:
    void refresh();
    void push(const QString& text, const auto& made);
    void onPlacementEdited();

    Document* m_document = nullptr;
    int m_character = -1;
    bool m_refreshing = false;
    QLineEdit* m_name = nullptr;
    QLabel* m_body = nullptr;
    QPushButton* m_chooseModel = nullptr;
    QPushButton* m_humanoid = nullptr;
    QComboBox* m_skeleton = nullptr;
    QDoubleSpinBox* m_position[3] = {};
    QDoubleSpinBox* m_heading = nullptr;
    QLabel* m_contents = nullptr;
};

} // namespace thespis::editor
