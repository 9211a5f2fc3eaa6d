#pragma once
// BmlLexiconModel: the BML lexicon of one character of a Document (core::edit::bmlLexiconRows)
// as a table of lexeme → gesture, sorted by lexeme: BML's <gesture lexeme="BEAT"> plays the row's
// gesture. Editable in place: renaming a lexeme or picking another gesture is one undoable edit
// of the document (core/edit/lexicon_edits.h); an edit the document refuses changes nothing and
// is reported through editFailed(). The model follows the document's edits on its own.

#include <QAbstractTableModel>
#include <QPointer>
#include <QStringList>

#include <map>
#include <string>

#include "edit/scenario_edit.h"

namespace thespis::editor {

class Document;

class BmlLexiconModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { LexemeColumn, GestureColumn, ColumnCount };

    explicit BmlLexiconModel(QObject* parent = nullptr);

    /// The document whose character's lexicon is shown (null: none).
    void setDocument(Document* document);
    /// Shows another character's lexicon; out-of-range indices show none.
    void setCharacter(int character);
    int character() const { return m_character; }

    /// True when the character keeps its own table; false when it has the defaults.
    bool isOwnTable() const;
    /// The lexeme of `row` (upper case), empty when there is none.
    QString lexeme(int row) const;
    /// The row of `lexeme` (any case), or -1.
    int rowOf(const QString& lexeme) const;
    /// Names of the character's gestures (what the Gesture column can take).
    QStringList gestureNames() const;

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    /// One undoable edit of the document ("Rename BML Lexeme", "Set BML Lexeme"). Returns false
    /// (and emits editFailed) when the document refuses it; an equal value changes nothing.
    bool setData(const QModelIndex& index, const QVariant& value, int role = Qt::EditRole) override;

signals:
    void editFailed(const QString& message);
    void editSucceeded();

private:
    void onEdited(const core::edit::Edit& edit);
    void reset();

    QPointer<Document> m_document;
    int m_character = -1;
    std::map<std::string, std::string> m_rows; // as shown, until the next reset
};

} // namespace thespis::editor
