#include "editor/messages_panel.h"

#include <QStyle>

namespace thespis::editor {

namespace {
constexpr int kCharacterRole = Qt::UserRole + 1;
constexpr int kClipRole = Qt::UserRole + 2;
} // namespace

MessagesPanel::MessagesPanel(QWidget* parent) : QListWidget(parent)
{
    setObjectName(QStringLiteral("messagesPanel"));
    setWordWrap(true);
    setAlternatingRowColors(true);
    setToolTip(tr("Double-click a message to show what it is about"));
    connect(this, &QListWidget::itemActivated, this, [this](QListWidgetItem* item) {
        emit showRequested(item->data(kCharacterRole).toInt(), item->data(kClipRole).toString());
    });
}

void MessagesPanel::setMessages(const QList<Entry>& messages)
{
    clear();
    const QIcon warning = style()->standardIcon(QStyle::SP_MessageBoxWarning);
    for (const Entry& message : messages) {
        auto* item = new QListWidgetItem(warning, message.text, this);
        item->setData(kCharacterRole, message.character);
        item->setData(kClipRole, message.clip);
        item->setToolTip(message.text);
    }
    if (messages.isEmpty()) {
        auto* item = new QListWidgetItem(tr("Nothing to report."), this);
        item->setFlags(Qt::NoItemFlags);
    }
}

} // namespace thespis::editor
