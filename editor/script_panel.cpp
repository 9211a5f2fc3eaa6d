#include "editor/script_panel.h"

#include <QFile>
#include <QFontDatabase>
#include <QHBoxLayout>
#include <QLabel>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QScrollBar>
#include <QShortcut>
#include <QSplitter>
#include <QTextBlock>
#include <QVBoxLayout>

#include "runtime/animation_service.h"
#include "script_runner.h"
#include "widgets/python_highlighter.h"

namespace thespis::editor {
namespace {

/// The paper's §4.5 example, shipped in resources/scripts.
QString exampleScript()
{
    QFile file(QStringLiteral(":/scripts/antigone_creon.py"));
    return file.open(QIODevice::ReadOnly) ? QString::fromUtf8(file.readAll()) : QString();
}

} // namespace

ScriptPanel::ScriptPanel(QWidget* parent) : QWidget(parent), m_clock(std::make_shared<core::runtime::ExternalClock>())
{
    const QFont fixed = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    m_editor = new QPlainTextEdit(this);
    m_editor->setObjectName(QStringLiteral("scriptEditor"));
    m_editor->setFont(fixed);
    m_editor->setLineWrapMode(QPlainTextEdit::NoWrap);
    m_editor->setTabStopDistance(4 * QFontMetricsF(fixed).horizontalAdvance(QLatin1Char(' ')));
    new widgets::PythonHighlighter(m_editor->document());
    m_editor->setPlainText(exampleScript());

    m_console = new QPlainTextEdit(this);
    m_console->setObjectName(QStringLiteral("scriptConsole"));
    m_console->setFont(fixed);
    m_console->setReadOnly(true);
    m_console->setPlaceholderText(tr("What the script prints, and its errors, show here."));

    m_run = new QPushButton(tr("Run"), this);
    m_run->setObjectName(QStringLiteral("runScript"));
    m_run->setToolTip(tr("Run the script on the scenario shown, while it plays (Ctrl+Return)"));
    m_stop = new QPushButton(tr("Stop"), this);
    m_stop->setObjectName(QStringLiteral("stopScript"));
    m_stop->setToolTip(tr("Stop the script now, even in a wait"));
    auto* clear = new QPushButton(tr("Clear Output"), this);
    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("scriptStatus"));
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);
    connect(m_run, &QPushButton::clicked, this, &ScriptPanel::run);
    connect(m_stop, &QPushButton::clicked, this, &ScriptPanel::stop);
    connect(clear, &QPushButton::clicked, m_console, &QPlainTextEdit::clear);
    auto* shortcut = new QShortcut(QKeySequence(Qt::CTRL | Qt::Key_Return), m_editor);
    shortcut->setContext(Qt::WidgetShortcut);
    connect(shortcut, &QShortcut::activated, this, &ScriptPanel::run);

    auto* buttons = new QHBoxLayout;
    buttons->addWidget(m_run);
    buttons->addWidget(m_stop);
    buttons->addWidget(m_status, 1);
    buttons->addWidget(clear);
    auto* splitter = new QSplitter(Qt::Horizontal, this);
    splitter->addWidget(m_editor);
    splitter->addWidget(m_console);
    splitter->setStretchFactor(0, 3);
    splitter->setStretchFactor(1, 2);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addLayout(buttons);
    layout->addWidget(splitter, 1);
    updateButtons();
}

ScriptPanel::~ScriptPanel()
{
    if (m_runner)
        m_runner->stop();
    if (m_worker.joinable())
        m_worker.join();
}

void ScriptPanel::setStage(std::shared_ptr<core::runtime::Stage> stage)
{
    if (stage == m_stage)
        return;
    if (isRunning()) {
        stop();
        append(tr("The scenario was rebuilt, so the script was stopped.") + QLatin1Char('\n'), true);
    }
    m_stage = std::move(stage);
    updateButtons();
}

void ScriptPanel::setTime(double seconds) { m_clock->setTime(core::secondsToTicks(seconds)); }

QString ScriptPanel::source() const { return m_editor->toPlainText(); }

void ScriptPanel::setSource(const QString& source) { m_editor->setPlainText(source); }

QString ScriptPanel::output() const { return m_console->toPlainText(); }

void ScriptPanel::run()
{
    if (isRunning() || !m_stage)
        return;
    if (!m_runner)
        m_runner = std::make_unique<script::ScriptRunner>();
    // A script starts over: what an earlier one left playing goes.
    m_stage->resetLive();
    auto service = std::make_shared<core::runtime::AnimationService>(m_stage, m_clock);
    m_status->setText(tr("Running…"));
    append(tr("— Run at %1 s —").arg(core::ticksToSeconds(m_clock->now()), 0, 'f', 2) + QLatin1Char('\n'), false);
    const std::string source = m_editor->toPlainText().toStdString();
    m_worker = std::thread([this, source, service] {
        const auto sink = [this](script::Stream stream, std::string_view text) {
            const QString line = QString::fromUtf8(text.data(), qsizetype(text.size()));
            QMetaObject::invokeMethod(this, [this, line, stream] { append(line, stream == script::Stream::Err); },
                                      Qt::QueuedConnection);
        };
        const core::Result<void> result = m_runner->run(source, "script.py", service, sink);
        QMetaObject::invokeMethod(this, [this, result] { onFinished(result); }, Qt::QueuedConnection);
    });
    updateButtons();
    emit runningChanged(true);
    emit playRequested();
}

void ScriptPanel::stop()
{
    if (m_runner && isRunning()) {
        m_status->setText(tr("Stopping…"));
        m_runner->stop();
    }
}

void ScriptPanel::append(const QString& text, bool error)
{
    QTextCharFormat format;
    format.setForeground(error ? QColor(0xc0, 0x20, 0x20) : palette().color(QPalette::Text));
    QTextCursor cursor(m_console->document());
    cursor.movePosition(QTextCursor::End);
    cursor.insertText(text, format);
    m_console->verticalScrollBar()->setValue(m_console->verticalScrollBar()->maximum());
}

void ScriptPanel::onFinished(const core::Result<void>& result)
{
    if (m_worker.joinable())
        m_worker.join();
    QString message;
    if (result) {
        m_status->setText(tr("Finished."));
    } else if (result.error().code == core::ErrorCode::Cancelled) {
        message = tr("Stopped.");
        m_status->setText(message);
    } else {
        message = QString::fromStdString(result.error().message);
        m_status->setText(message);
        // Put the cursor on the line the error names.
        static const QRegularExpression lineNumber(QStringLiteral("^script\\.py, line (\\d+):"));
        if (const auto match = lineNumber.match(message); match.hasMatch()) {
            const QTextBlock block = m_editor->document()->findBlockByNumber(match.captured(1).toInt() - 1);
            if (block.isValid()) {
                QTextCursor cursor(block);
                cursor.select(QTextCursor::LineUnderCursor);
                m_editor->setTextCursor(cursor);
            }
        }
    }
    updateButtons();
    emit runningChanged(false);
    emit finished(message);
}

void ScriptPanel::updateButtons()
{
    m_run->setEnabled(m_stage && !isRunning());
    m_stop->setEnabled(isRunning());
    if (!m_stage && !isRunning())
        m_status->setText(tr("Open a scenario to run scripts on it."));
    else if (m_status->text() == tr("Open a scenario to run scripts on it."))
        m_status->clear();
}

} // namespace thespis::editor
