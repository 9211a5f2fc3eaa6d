#pragma once
// GesticonModel: the gesture database (gesticon, paper §5) of one character of a Document as a
// table: name, clip, body part (the mask; "Whole body" without one), fade in and fade out in
// seconds, the dependent-joint filter as a check box and its band of PCs ("20–30"), and how speech
// fits it to its words: whether it holds its stroke, and where the stroke is. Editable in
// place: each setData() is one undoable edit of the document (core::edit::replaceGesture); an
// edit the document refuses (a duplicate name, a clip the character does not have, a band out of
// order, …) changes nothing and is reported through editFailed(). The model follows the document's edits (do, undo, redo) on its own.

#include <QAbstractTableModel>
#include <QPointer>
#include <QStringList>

#include "edit/scenario_edit.h"
#include "scenario/scenario.h"

namespace thespis::editor {

class Document;

class GesticonModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column {
        NameColumn, ClipColumn, MaskColumn, FadeInColumn, FadeOutColumn, FilterColumn, BandColumn,
        HoldColumn,   ///< check box: speech holds the stroke rather than stretching the gesture
        StrokeColumn, ///< seconds into the clip of the stroke; EditRole −1 for none
        ColumnCount
    };
    /// The columns toggled as check boxes.
    static bool isCheckColumn(int column) { return column == FilterColumn || column == HoldColumn; }

    explicit GesticonModel(QObject* parent = nullptr);

    /// The document whose gestures are shown (null: none); shows its first character.
    void setDocument(Document* document);
    Document* document() const { return m_document; }
    /// Index of the character whose gesticon is shown (-1 when there is none).
    int character() const { return m_character; }
    /// Shows another character's gestures; out-of-range indices show none.
    void setCharacter(int character);

    /// The gesture shown in `row`, or null.
    const core::scenario::Gesture* gesture(int row) const;
    /// The row of the gesture named `name`, or -1.
    int rowOf(const QString& name) const;
    /// Names of the character's clips (what the Clip column can take).
    QStringList clipNames() const;
    /// Names of the scenario's masks (what the Body part column can take besides the whole body,
    /// which is the empty string).
    QStringList maskNames() const;

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    /// DisplayRole: text as shown (fades in the locale's notation, "Whole body"); EditRole: the
    /// value an editor takes (name, clip name, mask name or "" for the whole body, fades in
    /// seconds as double); CheckStateRole on the filter column.
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    /// One undoable edit of the document. Returns false (and emits editFailed) when the document
    /// refuses the change; setting a value equal to the current one changes nothing.
    bool setData(const QModelIndex& index, const QVariant& value, int role = Qt::EditRole) override;

signals:
    /// An edit the document refused; the message says why (for the panel's message line).
    void editFailed(const QString& message);
    /// An edit that went through (the panel clears its message line).
    void editSucceeded();

private:
    const core::scenario::Character* currentCharacter() const;
    int liveRowCount() const;
    void onEdited(const core::edit::Edit& edit);
    void reset();

    QPointer<Document> m_document;
    int m_character = -1;
    int m_rows = 0; // rows the views know about, updated on reset
};

} // namespace thespis::editor
