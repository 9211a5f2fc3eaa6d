#pragma once
// Files dragged from the file manager onto a view: their local paths (what they hold is told
// apart by the editor, which knows what it reads).

#include <QMimeData>
#include <QStringList>
#include <QUrl>

namespace thespis::widgets {

inline QStringList droppedFiles(const QMimeData* mime)
{
    QStringList files;
    if (mime && mime->hasUrls())
        for (const QUrl& url : mime->urls())
            if (url.isLocalFile())
                files << url.toLocalFile();
    return files;
}

} // namespace thespis::widgets
