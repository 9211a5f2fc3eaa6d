// What the Conversation dock shows of a loaded bot: its size, what its files had wrong, the
// grammar the recogniser listens with and the words espeak-ng pronounces for it.
#include "editor/conversation_panel.h"

#include <QFileInfo>
#include <QLabel>
#include <QListWidget>
#include <QPlainTextEdit>
#include <QStyle>

#include "editor/conversation_jobs.h"
#include "editor/qt_conversions.h"

namespace thespis::editor {

void ConversationPanel::showBot(const LoadBotJob& job)
{
    // Its size and what its files had wrong.
    m_botLabel->setText(tr("“%1”: %n categories", nullptr, int(m_bot->categories().size())).arg(m_botName) +
                        tr(", %n set(s)", nullptr, int(m_bot->sets().size())) +
                        tr(", %n map(s)", nullptr, int(m_bot->maps().size())));
    m_botLabel->setToolTip(tr("Loaded in %1 s").arg(job.loadSeconds, 0, 'f', 2));
    m_problems->clear();
    for (const core::dialogue::LoadProblem& problem : job.loaded.problems) {
        // By the file's name (its path in the tooltip): file:line:column: what was wrong.
        const QString described = fromUtf8(core::dialogue::describe(problem));
        const QString path = fromUtf8(problem.file);
        auto* item = new QListWidgetItem(style()->standardIcon(QStyle::SP_MessageBoxWarning),
                                         described.startsWith(path) ? QFileInfo(path).fileName() + described.mid(path.size()) : described,
                                         m_problems);
        item->setToolTip(described);
        item->setData(Qt::UserRole, fromUtf8(problem.file));
        item->setData(Qt::UserRole + 1, problem.line);
    }
    m_problems->setVisible(m_problems->count() > 0);

    // The grammar it will listen with.
    if (job.grammar) {
        const core::dialogue::ListeningGrammar& grammar = *job.grammar;
        m_grammarLabel->setText(tr("%n pattern(s) to listen for", nullptr, int(grammar.patternsUsed)) +
                                tr(" (%n left out)", nullptr, int(grammar.patternsSkipped)) +
                                tr(", %n word(s); wildcards stand for %1 of them.", nullptr, int(grammar.words.size()))
                                    .arg(grammar.wildcardWords.size()));
        m_grammarLabel->setToolTip(tr("The recogniser listens with the same language as a graph of %1 states and %2 word arcs.")
                                       .arg(grammar.graph.states)
                                       .arg(grammar.graph.wordArcs()));
        QString notes;
        for (const std::string& note : grammar.notes)
            notes += QStringLiteral("// ") + fromUtf8(note) + QLatin1Char('\n');
        m_grammar->setPlainText(notes + (notes.isEmpty() ? QString() : QStringLiteral("\n")) + fromUtf8(grammar.jsgf));
    } else {
        m_grammarLabel->setText(tr("Nothing to listen for: %1 Type what the visitor says.").arg(fromUtf8(job.grammarError)));
        m_grammarLabel->setToolTip(QString());
        m_grammar->clear();
    }
}

void ConversationPanel::showPronounced(const std::vector<std::string>& guessed)
{
    if (guessed.empty())
        return;
    m_grammarLabel->setText(m_grammarLabel->text() + QLatin1Char(' ') +
                            tr("%n word(s) not in the dictionary, pronounced by espeak-ng.", nullptr, int(guessed.size())));
    QString pronounced;
    for (const std::string& word : guessed)
        pronounced += QStringLiteral("\n") + fromUtf8(word);
    // Below what the tooltip says of the grammar.
    m_grammarLabel->setToolTip(m_grammarLabel->toolTip() + QStringLiteral("\n\n") + tr("Pronounced by espeak-ng:") + pronounced);
}

} // namespace thespis::editor
