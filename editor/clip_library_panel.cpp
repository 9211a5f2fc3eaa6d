#include "editor/clip_library_panel.h"

#include <QDropEvent>

#include "editor/document.h"
#include "widgets/dropped_files.h"
#include "widgets/timeline_view.h"

namespace thespis::editor {

ClipLibraryPanel::ClipLibraryPanel(QWidget* parent) : QTreeWidget(parent)
{
    setObjectName(QStringLiteral("clipLibrary"));
    setColumnCount(2);
    setHeaderLabels({tr("Clip"), tr("Source")});
    setDragEnabled(true);
    setAcceptDrops(true);
    setDragDropMode(QAbstractItemView::DragDrop);
    setSelectionMode(QAbstractItemView::SingleSelection);
    setRootIsDecorated(true);
    setToolTip(tr("Drag a clip onto a track of its character to add an action; drop BVH or glTF files here to import them"));
}

void ClipLibraryPanel::setDocument(Document* document)
{
    if (m_document)
        disconnect(m_document, nullptr, this, nullptr);
    m_document = document;
    if (m_document)
        connect(m_document, &Document::edited, this, [this] { refresh(); });
    refresh();
}

void ClipLibraryPanel::refresh()
{
    clear();
    if (!m_document)
        return;
    for (const auto& character : m_document->scenario().characters) {
        auto* group = new QTreeWidgetItem(this, {QString::fromStdString(character.name)});
        group->setData(0, Qt::UserRole, topLevelItemCount() - 1);
        group->setFlags(Qt::ItemIsEnabled);
        for (const auto& clip : character.clips) {
            const QString source = clip.idle ? tr("idle motion from %1").arg(QString::fromStdString(clip.idle->database))
                                   : clip.file.empty() ? tr("keyframes in the scenario")
                                                       : QString::fromStdString(clip.file);
            auto* item = new QTreeWidgetItem(group, {QString::fromStdString(clip.name), source});
            item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemIsDragEnabled);
            item->setToolTip(0, tr("Drag onto a track of %1").arg(QString::fromStdString(character.name)));
        }
    }
    expandAll();
    resizeColumnToContents(0);
}

QTreeWidgetItem* ClipLibraryPanel::clipItem(const QString& character, const QString& clip) const
{
    for (int i = 0; i < topLevelItemCount(); ++i) {
        QTreeWidgetItem* group = topLevelItem(i);
        if (group->text(0) != character)
            continue;
        for (int k = 0; k < group->childCount(); ++k)
            if (group->child(k)->text(0) == clip)
                return group->child(k);
    }
    return nullptr;
}

void ClipLibraryPanel::dragEnterEvent(QDragEnterEvent* event)
{
    if (!widgets::droppedFiles(event->mimeData()).isEmpty())
        event->acceptProposedAction();
    else
        QTreeWidget::dragEnterEvent(event);
}

void ClipLibraryPanel::dragMoveEvent(QDragMoveEvent* event)
{
    if (!widgets::droppedFiles(event->mimeData()).isEmpty())
        event->acceptProposedAction();
    else
        QTreeWidget::dragMoveEvent(event);
}

void ClipLibraryPanel::dropEvent(QDropEvent* event)
{
    const QStringList files = widgets::droppedFiles(event->mimeData());
    if (files.isEmpty()) {
        event->ignore(); // a clip dragged within the library goes nowhere
        return;
    }
    event->acceptProposedAction();
    const QTreeWidgetItem* item = itemAt(event->position().toPoint());
    if (item && item->parent())
        item = item->parent();
    emit filesDropped(files, item ? item->data(0, Qt::UserRole).toInt() : -1);
}

QStringList ClipLibraryPanel::mimeTypes() const
{
    return {QString::fromLatin1(widgets::TimelineView::ClipMimeType)};
}

QMimeData* ClipLibraryPanel::mimeData(const QList<QTreeWidgetItem*>& items) const
{
    if (items.isEmpty() || !items.front()->parent())
        return nullptr;
    auto* mime = new QMimeData;
    mime->setData(QString::fromLatin1(widgets::TimelineView::ClipMimeType), items.front()->text(0).toUtf8());
    return mime;
}

} // namespace thespis::editor
