#include "widgets/python_highlighter.h"

#include <QGuiApplication>
#include <QPalette>
#include <QTextDocument>

namespace thespis::widgets {
namespace {

// Block states: inside a triple-quoted string opened with ''' or """ on an earlier line.
enum State { Normal = 0, InSingleTriple = 1, InDoubleTriple = 2 };

QTextCharFormat coloured(const QColor& colour, bool bold = false, bool italic = false)
{
    QTextCharFormat format;
    format.setForeground(colour);
    if (bold)
        format.setFontWeight(QFont::Bold);
    format.setFontItalic(italic);
    return format;
}

} // namespace

PythonHighlighter::PythonHighlighter(QTextDocument* document) : QSyntaxHighlighter(document)
{
    const bool dark = QGuiApplication::palette().color(QPalette::Base).lightness() < 128;
    const QColor keyword = dark ? QColor(0xc6, 0x78, 0xdd) : QColor(0x80, 0x00, 0x80);
    const QColor builtin = dark ? QColor(0x61, 0xaf, 0xef) : QColor(0x00, 0x50, 0xa0);
    const QColor service = dark ? QColor(0xe5, 0xc0, 0x7b) : QColor(0x8a, 0x5a, 0x00);
    const QColor number = dark ? QColor(0xd1, 0x9a, 0x66) : QColor(0xa0, 0x30, 0x00);
    m_string = coloured(dark ? QColor(0x98, 0xc3, 0x79) : QColor(0x00, 0x80, 0x00));
    m_comment = coloured(dark ? QColor(0x7f, 0x84, 0x8e) : QColor(0x70, 0x70, 0x70), false, true);

    const QString keywords = QStringLiteral(
        "and|as|assert|async|await|break|class|continue|def|del|elif|else|except|finally|for|from|global|if|"
        "import|in|is|lambda|nonlocal|not|or|pass|raise|return|try|while|with|yield|None|True|False");
    const QString builtins = QStringLiteral(
        "print|range|len|round|min|max|abs|sum|list|dict|set|tuple|str|int|float|bool|enumerate|zip|sorted");
    m_rules.push_back({QRegularExpression(QStringLiteral("\\b(%1)\\b").arg(keywords)), coloured(keyword, true)});
    m_rules.push_back({QRegularExpression(QStringLiteral("\\b(%1)(?=\\()").arg(builtins)), coloured(builtin)});
    m_rules.push_back({QRegularExpression(QStringLiteral("\\b(animService|anim|voiceService|thespis)\\b")),
                       coloured(service, true)});
    m_rules.push_back({QRegularExpression(QStringLiteral("\\.([A-Za-z_]+_(body|face)|start_player|stop_player|wait)\\b")),
                       coloured(service)});
    m_rules.push_back({QRegularExpression(QStringLiteral("\\b[0-9]+(\\.[0-9]*)?([eE][-+]?[0-9]+)?\\b")), coloured(number)});
}

void PythonHighlighter::highlightBlock(const QString& text)
{
    for (const Rule& rule : m_rules)
        for (auto it = rule.pattern.globalMatch(text); it.hasNext();) {
            const QRegularExpressionMatch match = it.next();
            const int group = match.lastCapturedIndex() >= 1 && rule.pattern.pattern().startsWith(QLatin1String("\\.")) ? 1 : 0;
            setFormat(match.capturedStart(group), match.capturedLength(group), rule.format);
        }

    // Strings and comments, scanned left to right so that a # inside a string is not a comment
    // and quotes inside a comment open nothing.
    int i = 0;
    setCurrentBlockState(Normal);
    if (previousBlockState() == InSingleTriple || previousBlockState() == InDoubleTriple) {
        const QString close = previousBlockState() == InSingleTriple ? QStringLiteral("'''") : QStringLiteral("\"\"\"");
        const int end = text.indexOf(close);
        if (end < 0) {
            setFormat(0, int(text.size()), m_string);
            setCurrentBlockState(previousBlockState());
            return;
        }
        setFormat(0, end + 3, m_string);
        i = end + 3;
    }
    while (i < text.size()) {
        const QChar c = text.at(i);
        if (c == QLatin1Char('#')) {
            setFormat(i, int(text.size()) - i, m_comment);
            return;
        }
        if (c != QLatin1Char('\'') && c != QLatin1Char('"')) {
            ++i;
            continue;
        }
        const QString triple(3, c);
        if (text.mid(i, 3) == triple) {
            const int end = text.indexOf(triple, i + 3);
            if (end < 0) {
                setFormat(i, int(text.size()) - i, m_string);
                setCurrentBlockState(c == QLatin1Char('\'') ? InSingleTriple : InDoubleTriple);
                return;
            }
            setFormat(i, end + 3 - i, m_string);
            i = end + 3;
            continue;
        }
        int end = i + 1;
        while (end < text.size() && text.at(end) != c)
            end += text.at(end) == QLatin1Char('\\') ? 2 : 1;
        setFormat(i, std::min(end + 1, int(text.size())) - i, m_string);
        i = end + 1;
    }
}

} // namespace thespis::widgets
