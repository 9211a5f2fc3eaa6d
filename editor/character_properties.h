#pragma once
// CharacterProperties: the Properties page of a character selected in the scenario outline —
// its name, its body (a glTF model or the built-in humanoid) and the skeleton its motion plays
// on, where it stands and which way it faces, its layers and clips for reading; for a glTF model,
// the face mapping table its face follows (the one its names are recognised as, or a file chosen,
// or one edited in the Face Mapping dialog). Every change is one undoable command
// (core/edit/content_edits.h); a refused one says why.

#include <QWidget>

class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
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
    /// Makes this table file the character's face mapping (Choose… after its file dialog);
    /// empty: the table recognised from the model's names (Automatic).
    void setFaceMappingFile(const QString& path);
    /// Edit…: the Face Mapping dialog on the character's table (or the recognised one). Accepted,
    /// the table is saved to the character's file (asked for when it has none yet) and the
    /// character set to follow it, in one undo step.
    void editFaceMapping();

    QLineEdit* nameEdit() const { return m_name; }
    QComboBox* skeletonChoice() const { return m_skeleton; }
    QDoubleSpinBox* positionEdit(int axis) const { return m_position[axis]; }
    QDoubleSpinBox* headingEdit() const { return m_heading; }
    QPushButton* humanoidButton() const { return m_humanoid; }
    QLabel* faceMappingLabel() const { return m_faceMapping; }
    QPushButton* chooseFaceMappingButton() const { return m_chooseFaceMapping; }
    QPushButton* automaticFaceButton() const { return m_automaticFace; }
    QPushButton* editFaceMappingButton() const { return m_editFaceMapping; }

signals:
    void problem(const QString& message);

private:
    void refresh();
    void push(const QString& text, const auto& made);
    void onPlacementEdited();
    void setFaceMapping(const QString& path, const QString& text);

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
    QFormLayout* m_form = nullptr;
    QLabel* m_faceMapping = nullptr;
    QPushButton* m_chooseFaceMapping = nullptr;
    QPushButton* m_automaticFace = nullptr;
    QPushButton* m_editFaceMapping = nullptr;
    QWidget* m_faceButtons = nullptr; // the row of the face mapping's buttons
};

} // namespace thespis::editor
