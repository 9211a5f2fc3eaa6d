#pragma once
// SegmentPanel: the segment tag editor (paper §6.1.3). For one character of the document it
// lists the body's mesh segments (SegmentTableModel) with their joint, role (none / receiver /
// occluder) and size; rows can be filtered by name, many can be selected, and the tool bar's
// Receiver / Occluder / None buttons tag every selected segment at once as one undoable edit (a
// Role cell also edits on its own, through a combo box).
//
// Selection and the 3D view go together when a ScenePreview is set: the selected segments are
// highlighted in the viewport while the panel is visible, and a click on a character in the
// viewport selects the segment under the mouse (Ctrl toggles it, Shift adds it; a click on
// nothing clears the selection), switching the character shown when needed. Without a preview
// (no OpenGL) the panel works the same from the table alone.

#include <QPointer>
#include <QWidget>

#include <vector>

#include "scene/character_mesh.h"

class QComboBox;
class QLabel;
class QLineEdit;
class QTableView;
class QToolButton;

namespace thespis::editor {

class Document;
class ScenePreview;
class SegmentTableModel;

class SegmentPanel : public QWidget {
    Q_OBJECT
public:
    explicit SegmentPanel(QWidget* parent = nullptr);
    ~SegmentPanel() override;

    /// The document edited (null: none). Shows its first character.
    void setDocument(Document* document);
    /// The 3D view that highlights the selection and reports clicks (null: none).
    void setScenePreview(ScenePreview* preview);

    QTableView* table() const { return m_table; }
    SegmentTableModel* model() const { return m_model; }
    QComboBox* characterCombo() const { return m_characters; }
    QLineEdit* filterEdit() const { return m_filter; }
    /// The text of the message line (a body that did not load, a refused edit); empty when none.
    QString message() const;

    /// Index of the character shown (-1: none).
    int currentCharacter() const;
    void setCurrentCharacter(int character);
    /// The selected segments (rows, which are the body's segment indices), ascending.
    std::vector<int> selectedSegments() const;
    /// Replaces the selection (out-of-range indices are ignored) and scrolls to the first.
    void selectSegments(const std::vector<int>& segments);
    /// Tags every selected segment: one undoable edit. Refusals go to the message line.
    void applyRole(core::scene::SegmentRole role);

signals:
    /// The selected segments changed (by the table or by a click in the viewport).
    void selectionChanged();

protected:
    void showEvent(QShowEvent* event) override;
    void hideEvent(QHideEvent* event) override;

private:
    void refreshCharacters();
    void onSegmentsReloaded();
    void onSegmentClicked(int character, int segment, Qt::KeyboardModifiers modifiers);
    void onEmptySpaceClicked(Qt::KeyboardModifiers modifiers);
    void applyFilter();
    void updateActions();
    void updateHighlights();
    void showMessage(const QString& message);

    QPointer<Document> m_document;
    QPointer<ScenePreview> m_preview;
    SegmentTableModel* m_model = nullptr;
    QComboBox* m_characters = nullptr;
    QLineEdit* m_filter = nullptr;
    QTableView* m_table = nullptr;
    std::vector<QToolButton*> m_roleButtons;    // by SegmentRole
    QLabel* m_selectionCount = nullptr;
    QLabel* m_message = nullptr;
    QLabel* m_hint = nullptr;
};

} // namespace thespis::editor
