#pragma once
// ClipLibraryPanel: the clips each character can play, grouped by character. Dragging a clip onto
// a timeline track of that character creates an action playing it (widgets::TimelineView takes
// the drop as widgets::TimelineView::ClipMimeType with the clip's name). Under "Motion synthesis",
// "Idle" is dragged as widgets::TimelineView::SynthesizerMimeType: dropped on a body track it
// plays the character's idle motion (its clip made on the way when it has none). Motion files
// dropped on it from the file manager are to be imported into the character they land on.

#include <QTreeWidget>

namespace thespis::editor {

class Document;

class ClipLibraryPanel : public QTreeWidget {
    Q_OBJECT
public:
    explicit ClipLibraryPanel(QWidget* parent = nullptr);
    void setDocument(Document* document);
    /// The idle motion database a dragged "Idle" plays (the shipped one), shown beside it.
    void setIdleDatabase(const QString& path);
    /// The "Idle" item under "Motion synthesis" (tests start drags from it).
    QTreeWidgetItem* idleItem() const { return m_idle; }
    /// The item of a character's clip, or null (tests start drags from it).
    QTreeWidgetItem* clipItem(const QString& character, const QString& clip) const;

signals:
    /// Files dropped from the file manager, on a character's group or clip (its index), or
    /// elsewhere (-1).
    void filesDropped(const QStringList& files, int character);

protected:
    QMimeData* mimeData(const QList<QTreeWidgetItem*>& items) const override;
    QStringList mimeTypes() const override;
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dragMoveEvent(QDragMoveEvent* event) override;
    void dropEvent(QDropEvent* event) override;

private:
    void refresh();
    Document* m_document = nullptr;
    QString m_idleDatabase;
    QTreeWidgetItem* m_idle = nullptr;
};

} // namespace thespis::editor
