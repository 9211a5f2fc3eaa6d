#pragma once
// ClipLibraryPanel: the clips each character can play, grouped by character. Dragging a clip onto
// a timeline track of that character creates an action playing it (widgets::TimelineView takes
// the drop as widgets::TimelineView::ClipMimeType with the clip's name).

#include <QTreeWidget>

namespace thespis::editor {

class Document;

class ClipLibraryPanel : public QTreeWidget {
    Q_OBJECT
public:
    explicit ClipLibraryPanel(QWidget* parent = nullptr);
    void setDocument(Document* document);
    /// The item of a character's clip, or null (tests start drags from it).
    QTreeWidgetItem* clipItem(const QString& character, const QString& clip) const;

protected:
    QMimeData* mimeData(const QList<QTreeWidgetItem*>& items) const override;
    QStringList mimeTypes() const override;

private:
    void refresh();
    Document* m_document = nullptr;
};

} // namespace thespis::editor
