#pragma once
// BmlLexiconBox: the "BML lexemes" section of the Gesticon dock — which gesture of the character
// a BML <gesture lexeme="BEAT"> plays (BmlLexiconModel), with the gesture picked from the
// character's gesticon; Add / Remove a row and Reset to defaults, each one undoable edit. A line
// above the table says whether the character keeps its own table or has the defaults.

#include <QPointer>
#include <QWidget>

class QLabel;
class QTableView;
class QToolButton;

namespace thespis::editor {

class BmlLexiconModel;
class Document;

class BmlLexiconBox : public QWidget {
    Q_OBJECT
public:
    explicit BmlLexiconBox(QWidget* parent = nullptr);

    void setDocument(Document* document);
    void setCharacter(int character);

    BmlLexiconModel* model() const { return m_model; }
    QTableView* table() const { return m_table; }
    QToolButton* addButton() const { return m_add; }
    QToolButton* removeButton() const { return m_remove; }
    QToolButton* resetButton() const { return m_reset; }

    /// Adds a row "LEXEME" (or "LEXEME_2", …) playing the character's first gesture and starts
    /// editing its lexeme. One undoable edit.
    void addRow();
    /// Removes the current row: one undoable edit.
    void removeCurrent();
    /// Gives the character the defaults again (its own table goes): one undoable edit.
    void resetToDefaults();

signals:
    /// An edit the document refused, or that went through (an empty message), for the dock's
    /// message line.
    void message(const QString& text);

private:
    void updateActions();

    QPointer<Document> m_document;
    BmlLexiconModel* m_model = nullptr;
    QLabel* m_state = nullptr;
    QTableView* m_table = nullptr;
    QToolButton* m_add = nullptr;
    QToolButton* m_remove = nullptr;
    QToolButton* m_reset = nullptr;
};

} // namespace thespis::editor
