#include "editor/clip_library_panel.h"

#include <QDropEvent>
#include <QFileInfo>

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

void ClipLibraryPanel::setIdleDatabase(const QString& path)
{
    m_idleDatabase = path;
    refresh();
}

void ClipLibraryPanel::refresh()
{
    clear();
    m_idle = nullptr;
    if (!m_document)
        return;
    // What any character can play without a file of its own.
    auto* synthesis = new QTreeWidgetItem(this, {tr("Motion synthesis")});
    synthesis->setData(0, Qt::UserRole, -1);
    synthesis->setFlags(Qt::ItemIsEnabled);
    m_idle = new QTreeWidgetItem(synthesis, {tr("Idle"), m_idleDatabase.isEmpty()
                                                            ? tr("no idle database found")
                                                            : tr("standing idle from %1").arg(QFileInfo(m_idleDatabase).fileName())});
    m_idle->setFlags(m_idleDatabase.isEmpty() ? Qt::ItemIsEnabled
                                              : Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemIsDragEnabled);
    m_idle->setToolTip(0, tr("Drag onto a body track: the character stands, shifting its weight and moving a little, "
                             "for as long as the scenario plays"));
    m_idle->setToolTip(1, m_idleDatabase);
    for (const auto& character : m_document->scenario().characters) {
        auto* group = new QTreeWidgetItem(this, {QString::fromStdString(character.name)});
        group->setData(0, Qt::UserRole, topLevelItemCount() - 2); // after "Motion synthesis"
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
    return {QString::fromLatin1(widgets::TimelineView::ClipMimeType),
            QString::fromLatin1(widgets::TimelineView::SynthesizerMimeType)};
}

QMimeData* ClipLibraryPanel::mimeData(const QList<QTreeWidgetItem*>& items) const
{
    if (items.isEmpty() || !items.front()->parent())
        return nullptr;
    auto* mime = new QMimeData;
    if (items.front() == m_idle)
        mime->setData(QString::fromLatin1(widgets::TimelineView::SynthesizerMimeType), QByteArrayLiteral("idle"));
    else
        mime->setData(QString::fromLatin1(widgets::TimelineView::ClipMimeType), items.front()->text(0).toUtf8());
    return mime;
}

} // namespace thespis::editor
