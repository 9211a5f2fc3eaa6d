#pragma once
// PythonHighlighter: colours Python source in a text document — keywords, built-ins, strings
// (single, double and triple-quoted across lines), comments, numbers, and the names of the
// animation service's calls, in the palette's colours (readable in light and dark themes).

#include <QRegularExpression>
#include <QSyntaxHighlighter>
#include <QTextCharFormat>
#include <vector>

namespace thespis::widgets {

class PythonHighlighter : public QSyntaxHighlighter {
    Q_OBJECT
public:
    explicit PythonHighlighter(QTextDocument* document);

protected:
    void highlightBlock(const QString& text) override;

private:
    struct Rule {
        QRegularExpression pattern;
        QTextCharFormat format;
    };
    std::vector<Rule> m_rules;
    QTextCharFormat m_string, m_comment;
};

} // namespace thespis::widgets
