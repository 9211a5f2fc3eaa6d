#include "editor/conversation_transcript.h"

#include <QFileInfo>
#include <QFontMetrics>
#include <QHeaderView>
#include <QStyle>

#include "editor/qt_conversions.h"
#include "runtime/interaction_service.h"
#include "speech/speak_job.h"

namespace thespis::editor {
namespace {

constexpr int kEventRole = Qt::UserRole + 1;

} // namespace

ConversationTranscript::ConversationTranscript(QWidget* parent) : QTreeWidget(parent)
{
    setObjectName(QStringLiteral("conversationTranscript"));
    setHeaderLabels({tr("Who"), tr("Said"), tr("Source"), tr("Spoken (s)")});
    setRootIsDecorated(false);
    setWordWrap(true);
    setUniformRowHeights(false);
    setAlternatingRowColors(true);
    setSelectionMode(QAbstractItemView::ExtendedSelection);
    header()->setStretchLastSection(false);
    header()->setSectionResizeMode(WhoColumn, QHeaderView::ResizeToContents);
    header()->setSectionResizeMode(SaidColumn, QHeaderView::Stretch);
    header()->setSectionResizeMode(DetailColumn, QHeaderView::Interactive);
    header()->setSectionResizeMode(WhenColumn, QHeaderView::ResizeToContents);
    setColumnWidth(DetailColumn, 150);
    // A tree view elides what does not fit; answers are sentences, so their rows grow instead.
    connect(header(), &QHeaderView::sectionResized, this, [this](int column) {
        if (column == SaidColumn)
        {
            for (int i = 0; i < topLevelItemCount(); ++i)
                fitHeight(topLevelItem(i));
            doItemsLayout();
        }
    });
}

void ConversationTranscript::fitHeight(QTreeWidgetItem* item)
{
    const int width = columnWidth(SaidColumn) - 2 * style()->pixelMetric(QStyle::PM_FocusFrameHMargin, nullptr, this) - 6;
    if (width <= 0)
        return;
    const QFontMetrics metrics(item->font(SaidColumn));
    const QRect bounds = metrics.boundingRect(QRect(0, 0, width, 100000), Qt::TextWordWrap, item->text(SaidColumn));
    item->setSizeHint(SaidColumn, QSize(width, bounds.height() + 4));
}

void ConversationTranscript::addExchange(const QString& character, const core::runtime::Exchange& exchange, const QString& how)
{
    QTreeWidgetItem* visitor = addRow({tr("Visitor"), exchange.understood ? fromUtf8(exchange.heard) : tr("(not understood)"), how, QString()}, false);
    QFont bold = visitor->font(WhoColumn);
    bold.setBold(true);
    visitor->setFont(WhoColumn, bold);

    // The answer, with the category (file:line) that gave each of its sentences.
    QStringList places, patterns;
    for (const core::dialogue::MatchedCategory& matched : exchange.answer.matched) {
        const QString file = fromUtf8(matched.source.file);
        places << (matched.learned ? tr("learned") : QStringLiteral("%1:%2").arg(QFileInfo(file).fileName()).arg(matched.source.line));
        patterns << QStringLiteral("%1:%2  %3").arg(file).arg(matched.source.line).arg(fromUtf8(matched.pattern));
    }
    const QString words = fromUtf8(core::speech::spokenWords(exchange.answer.text));
    const QString when = exchange.end > exchange.start
                             ? QStringLiteral("%1 – %2").arg(exchange.start, 0, 'f', 2).arg(exchange.end, 0, 'f', 2)
                             : tr("not spoken");
    QTreeWidgetItem* answer =
        addRow({character, words.isEmpty() ? tr("(no answer: no category matched)") : words, places.join(QStringLiteral("; ")), when}, false);
    answer->setToolTip(SaidColumn, fromUtf8(exchange.answer.text)); // with its speech tags
    answer->setToolTip(DetailColumn, patterns.join(QLatin1Char('\n')));
}

void ConversationTranscript::addEvent(const QString& text)
{
    addRow({QString(), text, QString(), QString()}, true);
}

QList<QTreeWidgetItem*> ConversationTranscript::lines() const
{
    QList<QTreeWidgetItem*> said;
    for (int i = 0; i < topLevelItemCount(); ++i)
        if (!topLevelItem(i)->data(WhoColumn, kEventRole).toBool())
            said << topLevelItem(i);
    return said;
}

QTreeWidgetItem* ConversationTranscript::addRow(const QStringList& columns, bool event)
{
    auto* item = new QTreeWidgetItem(this, columns);
    item->setData(WhoColumn, kEventRole, event);
    if (event) {
        QFont italic = item->font(SaidColumn);
        italic.setItalic(true);
        item->setFont(SaidColumn, italic);
        item->setForeground(SaidColumn, palette().color(QPalette::Disabled, QPalette::Text));
    }
    item->setToolTip(SaidColumn, columns.at(SaidColumn));
    fitHeight(item);
    doItemsLayout();
    scrollToItem(item);
    return item;
}

} // namespace thespis::editor
