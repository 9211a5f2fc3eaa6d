#include "editor/script_panel.h"

#include <QComboBox>
#include <QUrl>
#include <QDir>
#include <QFile>
#include <QInputDialog>
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

#include "edit/content_edits.h"
#include "editor/document.h"
#include "editor/session.h"
#include "editor/stage_audio.h"
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
    m_choice = new QComboBox(this);
    m_choice->setObjectName(QStringLiteral("scriptChoice"));
    m_choice->setToolTip(tr("Scratch, or a script kept in the scenario"));
    m_choice->addItem(tr("Scratch"));
    m_choice->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    connect(m_choice, &QComboBox::currentIndexChanged, this, &ScriptPanel::onChoice);
    m_save = new QPushButton(tr("Save to Scenario…"), this);
    m_save->setObjectName(QStringLiteral("saveScript"));
    m_save->setToolTip(tr("Keep this script in the scenario (saved with it, one undo step)"));
    connect(m_save, &QPushButton::clicked, this, &ScriptPanel::onSave);
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
    buttons->addWidget(m_choice);
    buttons->addWidget(m_save);
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

void ScriptPanel::setSession(Session* session)
{
    m_session = session;
    session->addView([this](Document*) { followSession(); }, this);
    connect(session, &Session::edited, this, &ScriptPanel::followSession);
    // A waiting script sees each new time before the stage is evaluated at it.
    connect(session, &Session::aboutToTick, this, [this](core::Tick time) { setTime(time); });
}

void ScriptPanel::followSession()
{
    const Document* document = m_session->document();
    setStage(m_session->stage());
    setAssets(document ? document->assets() : core::scenario::Assets("."));
    QStringList names, sources;
    if (document)
        for (const core::scenario::ScriptSpec& script : document->scenario().scripts) {
            names.push_back(QString::fromStdString(script.name));
            sources.push_back(QString::fromStdString(script.source));
        }
    setScenarioScripts(names, sources);
    setSaveEnabled(document != nullptr);
}

void ScriptPanel::setAssets(const core::scenario::Assets& assets) { m_assets = assets; }

void ScriptPanel::setAudio(StageAudio* audio) { m_audio = audio; }

void ScriptPanel::setTime(core::Tick now)
{
    m_clock->setTime(now);
}

QString ScriptPanel::source() const { return m_editor->toPlainText(); }

void ScriptPanel::setSource(const QString& source)
{
    m_editor->setPlainText(source);
    m_editor->document()->setModified(true); // the user's text, not the scenario's
}

QString ScriptPanel::output() const { return m_console->toPlainText(); }

void ScriptPanel::setScenarioScripts(const QStringList& names, const QStringList& sources)
{
    const QString shown = m_shown > 0 ? m_choice->itemText(m_shown) : QString();
    const QSignalBlocker blocker(m_choice);
    while (m_choice->count() > 1)
        m_choice->removeItem(1);
    m_choice->addItems(names);
    m_sources = sources;
    const int again = shown.isEmpty() ? -1 : int(names.indexOf(shown));
    if (again >= 0) {
        m_shown = again + 1;
        m_choice->setCurrentIndex(m_shown);
        if (!m_editor->document()->isModified())
            m_editor->setPlainText(m_sources.at(again)); // the scenario's text, e.g. after undo
    } else if (m_shown > 0) {
        m_shown = 0; // its script went: back to Scratch, keeping the text shown as it is
        m_choice->setCurrentIndex(0);
    }
}

void ScriptPanel::setSaveEnabled(bool enabled) { m_save->setEnabled(enabled); }

bool ScriptPanel::showScenarioScript(const QString& name)
{
    const int index = m_choice->findText(name);
    if (index < 1)
        return false;
    m_choice->setCurrentIndex(index);
    return true;
}

void ScriptPanel::onChoice(int index)
{
    if (index == m_shown || index < 0)
        return;
    if (m_shown == 0)
        m_scratch = m_editor->toPlainText();
    m_shown = index;
    m_editor->setPlainText(index == 0 ? m_scratch : m_sources.at(index - 1));
    m_editor->document()->setModified(false);
}

void ScriptPanel::onSave()
{
    QString name = m_shown > 0 ? m_choice->itemText(m_shown) : QString();
    if (name.isEmpty()) {
        bool ok = false;
        name = QInputDialog::getText(this, tr("Save Script to Scenario"), tr("Name of the script:"), QLineEdit::Normal,
                                     tr("script"), &ok)
                   .trimmed();
        if (!ok || name.isEmpty())
            return;
    }
    if (Document* document = m_session ? m_session->document() : nullptr)
        (void)document->edit(core::edit::setScript(document->scenario(), name.toStdString(),
                                                   m_editor->toPlainText().toStdString()),
                             tr("Save Script “%1”").arg(name));
    if (showScenarioScript(name))
        m_editor->document()->setModified(false);
}

void ScriptPanel::run()
{
    if (isRunning() || !m_stage)
        return;
    // A script as the scenario file holds it runs only once the user trusts that file.
    if (m_shown > 0 && !m_editor->document()->isModified() && m_trustCheck && !m_trustCheck()) {
        m_status->setText(tr("Not run: the scenario's scripts are not trusted."));
        return;
    }
    if (!m_runner)
        m_runner = std::make_unique<script::ScriptRunner>();
    // A script starts over: what an earlier one left playing goes.
    m_stage->resetLive();
    auto service = std::make_shared<core::runtime::AnimationService>(m_stage, m_clock);
    // The paper's start_player / stop_player play and pause the studio's transport (asked from
    // the script's thread, done on the GUI's).
    service->setPlayerControl([this](bool play) {
        QMetaObject::invokeMethod(this, [this, play] { play ? emit playRequested() : emit pauseRequested(); },
                                  Qt::QueuedConnection);
    });
    if (m_audio)
        m_audio->removeSource(m_sound);
    m_sound = std::make_shared<core::runtime::SoundService>(m_assets, m_clock);
    if (m_audio)
        m_audio->addSource(m_sound);
    auto sound = m_sound;
    m_interaction = std::make_shared<core::runtime::InteractionService>(m_stage, m_sound);
    auto interaction = m_interaction;
    emit interactionServiceChanged();
    m_status->setText(tr("Running…"));
    append(tr("— Run at %1 s —").arg(core::ticksToSeconds(m_clock->now()), 0, 'f', 2) + QLatin1Char('\n'), false);
    const std::string source = m_editor->toPlainText().toStdString();
    const std::string fileName = (m_shown > 0 ? m_choice->itemText(m_shown) : QStringLiteral("script")).toStdString() + ".py";
    m_fileName = QString::fromStdString(fileName);
    m_worker = std::thread([this, source, fileName, service, sound, interaction] {
        const auto sink = [this](script::Stream stream, std::string_view text) {
            const QString line = QString::fromUtf8(text.data(), qsizetype(text.size()));
            QMetaObject::invokeMethod(this, [this, line, stream] { append(line, stream == script::Stream::Err); },
                                      Qt::QueuedConnection);
        };
        const core::Result<void> result = m_runner->run(source, fileName, service, sink, sound, interaction);
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
        if (m_audio) // a stopped script's voices stop with it
            m_audio->removeSource(m_sound);
        message = tr("Stopped.");
        m_status->setText(message);
    } else {
        message = QString::fromStdString(result.error().message);
        m_status->setText(message);
        // Put the cursor on the line the error names.
        static const QRegularExpression lineNumber(QStringLiteral("^[^,]*\\.py, line (\\d+):"));
        if (const auto match = lineNumber.match(message); match.hasMatch() && message.startsWith(m_fileName)) {
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
