#pragma once
// MessagesPanel: what the studio has to tell about the open scenario and did not stop for —
// motion files with joints that move nothing, bakes left out, models' joints without an H-Anim
// name — one line each with what it is about. Activating a line (double-click, Enter) asks to
// show that character or clip. A studio started from the desktop has no terminal: this is where
// load and import warnings go.

#include <QListWidget>

namespace thespis::editor {

class MessagesPanel : public QListWidget {
    Q_OBJECT
public:
    struct Entry {
        QString text;
        int character = -1; ///< the character it is about, or -1
        QString clip;       ///< the clip it is about, or empty
    };

    explicit MessagesPanel(QWidget* parent = nullptr);
    void setMessages(const QList<Entry>& messages);

signals:
    /// A message was activated: show its character (and clip, when it names one).
    void showRequested(int character, const QString& clip);
};

} // namespace thespis::editor
