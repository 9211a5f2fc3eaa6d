#pragma once
// ConversationTranscript: the Conversation dock's transcript (issue 34). One row per line said —
// the visitor's (typed, or heard with the recogniser's confidence) and the character's answer
// with the category that gave each of its sentences (file:line; the full path and the pattern in
// its tooltip) and when, on the stage's time, it is spoken — and greyed rows for what happened
// (a bot loaded, the character handed over or back).

#include <QTreeWidget>

namespace thespis::core::runtime {
struct Exchange;
}

namespace thespis::editor {

class ConversationTranscript : public QTreeWidget {
    Q_OBJECT
public:
    enum Column { WhoColumn, SaidColumn, DetailColumn, WhenColumn };

    explicit ConversationTranscript(QWidget* parent = nullptr);

    /// The visitor's line (`how`: "typed", "heard, confidence …") and `character`'s answer.
    void addExchange(const QString& character, const core::runtime::Exchange& exchange, const QString& how);
    /// What happened, greyed.
    void addEvent(const QString& text);
    /// Rows that are lines said (not events), oldest first.
    QList<QTreeWidgetItem*> lines() const;

private:
    QTreeWidgetItem* addRow(const QStringList& columns, bool event);
    void fitHeight(QTreeWidgetItem* item);
};

} // namespace thespis::editor
