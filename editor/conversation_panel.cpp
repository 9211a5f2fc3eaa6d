#include "editor/conversation_panel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFontDatabase>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalBlocker>
#include <QTabWidget>
#include <QTimer>
#include <QVBoxLayout>

#include <cmath>

#include "dialogue/bot_grammar.h"
#include "editor/character_choice.h"
#include "editor/conversation_jobs.h"
#include "editor/conversation_transcript.h"
#include "editor/document.h"
#include "editor/job_progress.h"
#include "editor/job_runner.h"
#include "editor/microphone.h"
#include "editor/playback_clock.h"
#include "editor/qt_conversions.h"
#include "editor/session.h"
#include "editor/stage_audio.h"
#include "runtime/clock.h"
#include "runtime/interaction_service.h"
#include "runtime/sound.h"
#include "speech/speak_job.h"
#include "util/file_io.h"

namespace thespis::editor {
namespace {

// Shorter than a tenth of a second: the button was tapped, not talked into.
constexpr std::size_t kShortestUtterance = 1600;

QString confidenceText(double confidence)
{
    return std::isfinite(confidence) ? QString::number(confidence, 'f', 2) : QStringLiteral("−∞");
}

} // namespace

ConversationPanel::ConversationPanel(QWidget* parent)
    : QWidget(parent), m_clock(std::make_shared<core::runtime::ExternalClock>()), m_prepare(new JobRunner(this)),
      m_turns(new JobRunner(this)), m_microphone(new Microphone(this)), m_talkTimer(new QTimer(this))
{
    auto* layout = new QVBoxLayout(this);

    // Who converses.
    auto* top = new QHBoxLayout;
    m_characters = addCharacterChoice(this, top, QStringLiteral("conversationCharacter"), tr("The character the visitor talks to"));
    m_converse = new QPushButton(tr("Converse"), this);
    m_converse->setObjectName(QStringLiteral("converse"));
    m_converse->setCheckable(true);
    m_converse->setToolTip(tr("Hand the character to the conversation from the playhead: it looks at the visitor and "
                              "answers. Hand Back gives it to the scenario again; nothing it plays stops."));
    m_speak = new QCheckBox(tr("Speak answers"), this);
    m_speak->setObjectName(QStringLiteral("speakAnswers"));
    m_speak->setChecked(true);
    m_speak->setToolTip(tr("Answers are spoken with face, gestures and gaze; off, they are only written in the "
                           "transcript. Chosen before Converse."));
    top->addWidget(m_converse);
    top->addWidget(m_speak);
    layout->addLayout(top);

    // The bot, and what its files had wrong.
    auto* botRow = new QHBoxLayout;
    m_botLabel = new QLabel(tr("No bot loaded."), this);
    m_botLabel->setObjectName(QStringLiteral("botSummary"));
    m_botLabel->setWordWrap(true);
    m_loadDemo = new QPushButton(this);
    m_loadDemo->setObjectName(QStringLiteral("loadDemoBot"));
    m_loadDemo->hide();
    m_loadFolder = new QPushButton(tr("Load Bot Folder…"), this);
    m_loadFolder->setObjectName(QStringLiteral("loadBotFolder"));
    m_loadFolder->setToolTip(tr("A folder of AIML, sets, maps, substitutions and properties (Rosie’s lib/ layout or flat)"));
    m_loadFiles = new QPushButton(tr("Load AIML Files…"), this);
    m_loadFiles->setObjectName(QStringLiteral("loadAimlFiles"));
    m_loadFiles->setToolTip(tr("One or more .aiml files (and .set, .map, … files, told by their extension)"));
    botRow->addWidget(m_botLabel, 1);
    botRow->addWidget(m_loadDemo);
    botRow->addWidget(m_loadFolder);
    botRow->addWidget(m_loadFiles);
    layout->addLayout(botRow);
    m_problems = new QListWidget(this);
    m_problems->setObjectName(QStringLiteral("botProblems"));
    m_problems->setMaximumHeight(6 * fontMetrics().height() + 8);
    m_problems->setIconSize(QSize(16, 16));
    m_problems->setWordWrap(true);
    m_problems->setToolTip(tr("What the bot’s files had wrong, by file:line:column; the rest loaded"));
    m_problems->hide();
    layout->addWidget(m_problems);

    // The transcript and the grammar the recogniser listens with.
    m_tabs = new QTabWidget(this);
    m_transcript = new ConversationTranscript(m_tabs);
    auto* grammarPage = new QWidget(m_tabs);
    auto* grammarLayout = new QVBoxLayout(grammarPage);
    grammarLayout->setContentsMargins(2, 2, 2, 2);
    m_grammarLabel = new QLabel(grammarPage);
    m_grammarLabel->setObjectName(QStringLiteral("grammarSummary"));
    m_grammarLabel->setWordWrap(true);
    m_grammar = new QPlainTextEdit(grammarPage);
    m_grammar->setObjectName(QStringLiteral("listeningGrammar"));
    m_grammar->setReadOnly(true);
    m_grammar->setLineWrapMode(QPlainTextEdit::NoWrap);
    m_grammar->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    m_grammar->setPlaceholderText(tr("The JSGF grammar the recogniser listens with — what the bot can answer — shows here "
                                     "once a bot is loaded."));
    grammarLayout->addWidget(m_grammarLabel);
    grammarLayout->addWidget(m_grammar, 1);
    m_tabs->addTab(m_transcript, tr("Transcript"));
    m_tabs->addTab(grammarPage, tr("Listening Grammar"));
    layout->addWidget(m_tabs, 1);

    // What the visitor says.
    m_heard = new QLabel(this);
    m_heard->setObjectName(QStringLiteral("heard"));
    m_heard->setWordWrap(true);
    m_heard->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(m_heard);
    auto* inputRow = new QHBoxLayout;
    m_input = new QLineEdit(this);
    m_input->setObjectName(QStringLiteral("visitorInput"));
    m_input->setPlaceholderText(tr("What the visitor says (Return sends)"));
    m_send = new QPushButton(tr("Send"), this);
    m_send->setObjectName(QStringLiteral("send"));
    inputRow->addWidget(m_input, 1);
    inputRow->addWidget(m_send);
    layout->addLayout(inputRow);
    auto* talkRow = new QHBoxLayout;
    m_talk = new QPushButton(tr("Hold to Talk"), this);
    m_talk->setObjectName(QStringLiteral("holdToTalk"));
    m_talk->setToolTip(tr("Hold while the visitor speaks into the microphone (or hold Space on the button); let go to "
                          "hear it"));
    m_hearRecording = new QPushButton(tr("Hear a Recording…"), this);
    m_hearRecording->setObjectName(QStringLiteral("hearRecording"));
    m_hearRecording->setToolTip(tr("What the visitor says, from a sound file (WAV, FLAC, OGG), recognised as the "
                                   "microphone would be"));
    m_saveState = new QPushButton(tr("Save State…"), this);
    m_saveState->setObjectName(QStringLiteral("saveConversationState"));
    m_saveState->setToolTip(tr("Keep what the visitor told the bot (its predicates, the history) in a JSON file"));
    m_loadState = new QPushButton(tr("Load State…"), this);
    m_loadState->setObjectName(QStringLiteral("loadConversationState"));
    m_loadState->setToolTip(tr("Converse from a saved state: the bot remembers what it was told"));
    talkRow->addWidget(m_talk);
    talkRow->addWidget(m_hearRecording);
    talkRow->addStretch(1);
    talkRow->addWidget(m_saveState);
    talkRow->addWidget(m_loadState);
    layout->addLayout(talkRow);
    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("conversationStatus"));
    m_status->setWordWrap(true);
    layout->addWidget(m_status);
    auto* progressRow = new QHBoxLayout;
    m_progress = new JobProgress(tr("No bot loaded yet"), this);
    m_cancel = new QPushButton(tr("Cancel"), this);
    m_cancel->setObjectName(QStringLiteral("cancelConversationJob"));
    progressRow->addWidget(m_progress, 1);
    progressRow->addWidget(m_cancel, 0, Qt::AlignTop);
    layout->addLayout(progressRow);

    connect(m_characters, &QComboBox::currentIndexChanged, this, [this] {
        if (isConversing() && characterName() != m_conversing)
            handBack();
        updateEnabled();
    });
    connect(m_converse, &QPushButton::clicked, this, [this](bool on) {
        if (on)
            converse();
        else
            handBack();
        updateEnabled();
    });
    const auto startDir = [this] {
        return !m_defaultBot.isEmpty() ? QFileInfo(m_defaultBot).absolutePath() : m_document ? m_document->baseDir() : QString();
    };
    connect(m_loadFolder, &QPushButton::clicked, this, [this, startDir] {
        const QString folder = QFileDialog::getExistingDirectory(this, tr("Load Bot Folder"), startDir());
        if (!folder.isEmpty())
            loadBot({folder});
    });
    connect(m_loadFiles, &QPushButton::clicked, this, [this, startDir] {
        const QStringList files = QFileDialog::getOpenFileNames(
            this, tr("Load AIML Files"), startDir(),
            tr("AIML files (*.aiml);;Bot files (*.aiml *.set *.map *.substitution *.properties *.pdefaults);;All files (*)"));
        if (!files.isEmpty())
            loadBot(files);
    });
    connect(m_loadDemo, &QPushButton::clicked, this, [this] { loadBot({m_defaultBot}); });
    const auto send = [this] {
        const QString text = m_input->text();
        if (text.trimmed().isEmpty() || m_turns->isRunning())
            return;
        m_input->clear();
        say(text);
    };
    connect(m_input, &QLineEdit::returnPressed, this, send);
    connect(m_send, &QPushButton::clicked, this, send);
    connect(m_input, &QLineEdit::textChanged, this, &ConversationPanel::updateEnabled);
    connect(m_talk, &QPushButton::pressed, this, &ConversationPanel::startTalking);
    connect(m_talk, &QPushButton::released, this, &ConversationPanel::stopTalking);
    connect(m_talkTimer, &QTimer::timeout, this, [this] {
        if (m_microphone->seconds() >= Microphone::kMaxSeconds)
            stopTalking();
        updateStatus();
    });
    connect(m_hearRecording, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getOpenFileName(this, tr("Hear a Recording"), m_document ? m_document->baseDir() : QString(),
                                                          tr("Sound files (*.wav *.flac *.ogg)"));
        if (!path.isEmpty())
            hearRecording(path);
    });
    connect(m_saveState, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getSaveFileName(this, tr("Save Conversation State"), m_document ? m_document->baseDir() : QString(),
                                                          tr("Conversation state (*.json)"));
        if (!path.isEmpty())
            saveState(path);
    });
    connect(m_loadState, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getOpenFileName(this, tr("Load Conversation State"), m_document ? m_document->baseDir() : QString(),
                                                          tr("Conversation state (*.json)"));
        if (!path.isEmpty())
            loadState(path);
    });
    connect(m_cancel, &QPushButton::clicked, this, &ConversationPanel::cancel);
    connect(m_prepare, &JobRunner::progress, this, &ConversationPanel::showProgress);
    connect(m_prepare, &JobRunner::finished, this, &ConversationPanel::onPrepared);
    connect(m_turns, &JobRunner::progress, this, [this](const QString& stage) { m_heard->setText(stage + QStringLiteral("…")); });
    connect(m_turns, &JobRunner::finished, this, &ConversationPanel::onTurn);
    connect(m_microphone, &Microphone::availabilityChanged, this, [this] {
        updateEnabled();
        updateStatus();
    });
    updateEnabled();
    updateStatus();
}

ConversationPanel::~ConversationPanel() = default;

void ConversationPanel::setSession(Session* session, StageAudio* audio)
{
    m_session = session;
    m_audio = audio;
    session->addPanel(this);
    connect(session, &Session::edited, this, &ConversationPanel::followStage);
    // The answers are spoken from the playhead.
    connect(session, &Session::aboutToTick, this, [this](core::Tick time) { m_clock->setTime(time); });
}

void ConversationPanel::setDocument(Document* document)
{
    // The old stage, and what its characters were told, go with the old document.
    if (isConversing())
        addEvent(tr("%1 left the conversation: the scenario was closed.").arg(fromUtf8(m_conversing)));
    m_conversing.clear();
    m_document = document;
    if (m_audio && m_sound)
        m_audio->removeSource(m_sound);
    m_sound = document ? std::make_shared<core::runtime::SoundService>(document->assets(), m_clock) : nullptr;
    if (m_audio && m_sound)
        m_audio->addSource(m_sound);
    syncClock();
    makeService();
    if (document)
        connect(document, &Document::edited, this, [this] {
            fillCharacterChoice(m_characters, m_document);
            updateEnabled();
        });
    fillCharacterChoice(m_characters, document);
    updateEnabled();
    updateStatus();
}

void ConversationPanel::setDefaultBot(const QString& folder)
{
    m_defaultBot = folder;
    m_loadDemo->setVisible(!folder.isEmpty());
    m_loadDemo->setText(tr("Load “%1”").arg(QFileInfo(folder).fileName()));
    m_loadDemo->setToolTip(tr("Load the bot shipped with the demo: %1").arg(QDir::toNativeSeparators(folder)));
}

int ConversationPanel::currentCharacter() const { return m_characters->currentIndex(); }
void ConversationPanel::setCurrentCharacter(int character) { m_characters->setCurrentIndex(character); }
bool ConversationPanel::isBusy() const { return m_prepare->isRunning() || m_turns->isRunning(); }
bool ConversationPanel::isAnswering() const { return m_turns->isRunning(); }
QString ConversationPanel::grammarSummary() const { return m_grammarLabel->text(); }
QString ConversationPanel::botSummary() const { return m_botLabel->text(); }
QString ConversationPanel::heard() const { return m_heard->text(); }
QString ConversationPanel::status() const { return m_status->text(); }
QString ConversationPanel::message() const { return m_progress->message()->text(); }

std::string ConversationPanel::characterName() const
{
    return m_characters->currentIndex() >= 0 ? m_characters->currentData().toString().toStdString() : std::string();
}

void ConversationPanel::makeService()
{
    m_service.reset();
    m_serviceStage = m_session ? m_session->stage() : nullptr;
    if (m_serviceStage && m_sound)
        m_service = std::make_shared<core::runtime::InteractionService>(m_serviceStage, m_sound);
}

void ConversationPanel::followStage()
{
    if (!m_session)
        return;
    const std::shared_ptr<core::runtime::Stage>& stage = m_session->stage();
    const std::string who = m_conversing;
    if (stage == m_serviceStage) {
        if (!who.empty() && (!stage || stage->findCharacter(who) < 0))
            handBack();
        return;
    }
    // A stage made anew (characters added or removed): the conversation goes on there, with what
    // the visitor told the bot.
    std::string state;
    if (!who.empty())
        if (auto saved = m_service->saveState(who))
            state = std::move(saved).value();
    m_conversing.clear();
    makeService();
    if (!who.empty()) {
        if (stage && stage->findCharacter(who) >= 0)
            startConversing(state, tr("%1 converses on, in the rebuilt scenario.").arg(fromUtf8(who)));
        else
            addEvent(tr("%1 left the conversation: the character is gone.").arg(fromUtf8(who)));
    }
    updateEnabled();
}

void ConversationPanel::syncClock()
{
    if (m_session)
        m_clock->setTime(m_session->clock()->time());
}

// ---- The bot ----

void ConversationPanel::loadBot(const QStringList& paths)
{
    if (m_prepare->isRunning()) {
        m_progress->refused(tr("The bot is still being prepared: wait, or cancel it first."));
        return;
    }
    auto job = std::make_unique<LoadBotJob>();
    for (const QString& path : paths)
        job->paths.push_back(toFsPath(path));
    m_botName = paths.isEmpty() ? QString() : QFileInfo(paths.front()).fileName();
    if (paths.size() > 1)
        m_botName = tr("%1 and %n more", nullptr, int(paths.size() - 1)).arg(m_botName);
    m_preparing = Preparing::Bot;
    if (auto started = m_prepare->start(std::move(job)); !started) {
        m_progress->failed(started.error());
        return;
    }
    m_progress->started();
    updateEnabled();
}

bool ConversationPanel::takeOver(const std::shared_ptr<core::runtime::InteractionService>& from)
{
    if (!from || from == m_service || !m_document || !m_service || m_prepare->isRunning())
        return false;
    const auto& characters = m_document->scenario().characters;
    for (int c = 0; c < int(characters.size()); ++c) {
        const std::string& name = characters[std::size_t(c)].name;
        std::shared_ptr<const core::dialogue::Bot> bot = from->bot(name);
        auto state = from->saveState(name);
        if (!bot || !state)
            continue;
        // The script's service lets go first: both turn the same character's gaze.
        syncClock();
        from->handBack(name);
        if (isConversing())
            handBack();
        m_bot = std::move(bot);
        m_recogniser.reset();
        m_botName = tr("the script's bot");
        setCurrentCharacter(c);
        if (!startConversing(*state, tr("%1 takes questions: the script handed the conversation over.").arg(fromUtf8(name))))
            return false;
        // Its listening grammar and recogniser, as for a bot loaded here.
        auto job = std::make_unique<LoadBotJob>();
        job->given = m_bot;
        m_preparing = Preparing::Bot;
        if (auto started = m_prepare->start(std::move(job)); !started)
            m_progress->failed(started.error());
        else
            m_progress->started();
        updateEnabled();
        return true;
    }
    return false;
}

void ConversationPanel::onPrepared(const core::Result<void>& result)
{
    const bool cancelled = !result && result.error().code == core::ErrorCode::Cancelled;
    if (m_preparing == Preparing::Recogniser) {
        const auto* job = m_prepare->jobAs<ListenJob>();
        if (cancelled)
            m_progress->finished(tr("Not listening"), tr("Cancelled: the recogniser was not opened. Type what the visitor says."));
        else if (!result)
            m_progress->failed(result.error());
        else if (job && job->bot == m_bot) {
            m_recogniser = job->recogniser;
            showPronounced(m_recogniser->espeakPronounced());
            // What loading said stays: the problems of the bot's files are still worth reading.
            m_progress->finished(tr("Ready to listen"), m_loadMessage + QLatin1Char(' ') +
                                                      tr("The recogniser listens for what the bot can answer (opened in %1 s).")
                                                          .arg(job->seconds, 0, 'f', 1));
        }
        updateEnabled();
        updateStatus();
        return;
    }

    auto* job = m_prepare->jobAs<LoadBotJob>();
    if (cancelled || !result || !job) {
        if (cancelled)
            m_progress->finished(tr("Cancelled"), tr("Cancelled: the bot was not changed."));
        else if (!result)
            m_progress->failed(result.error());
        updateEnabled();
        return;
    }
    // A new bot restarts the conversation; the bot a script handed over goes on with it.
    const bool newBot = job->loaded.bot != m_bot;
    const std::string who = newBot ? m_conversing : std::string();
    if (!who.empty()) {
        m_service->handBack(who);
        m_conversing.clear();
    }
    m_bot = job->loaded.bot;
    m_recogniser.reset();

    showBot(*job);
    const std::size_t categories = m_bot->categories().size();
    QString loaded = tr("Loaded %n categories in %1 s.", nullptr, int(categories)).arg(job->loadSeconds, 0, 'f', 2);
    if (!job->loaded.problems.empty())
        loaded += QLatin1Char(' ') + tr("%n problem(s) in its files: the rest loaded.", nullptr, int(job->loaded.problems.size()));
    m_progress->finished(tr("Bot loaded"), loaded);
    m_loadMessage = loaded;
    addEvent(tr("Bot “%1” loaded: %n categories.", nullptr, int(categories)).arg(m_botName));
    if (!who.empty())
        startConversing({}, tr("%1 converses with the new bot.").arg(fromUtf8(who)));

    // Then, off the GUI thread too, the recogniser (seconds on a big grammar).
    if (job->grammar) {
        auto listen = std::make_unique<ListenJob>();
        listen->bot = m_bot;
        m_preparing = Preparing::Recogniser;
        if (auto started = m_prepare->start(std::move(listen)); !started)
            m_progress->failed(started.error());
    }
    updateEnabled();
    updateStatus();
}

void ConversationPanel::showProgress(const QString& stage, qint64 done, qint64 total)
{
    if (total > 0) {
        m_progress->setProgress(stage, done, total);
        return;
    }
    // The core's steps say nothing of how far they are: a busy bar with what is done.
    QProgressBar* bar = m_progress->bar();
    bar->setRange(0, 0);
    bar->setFormat(stage);
}

// ---- The conversation ----

bool ConversationPanel::converse()
{
    const std::string name = characterName();
    if (isConversing() && m_conversing == name)
        return true;
    if (isConversing())
        handBack();
    return startConversing();
}

bool ConversationPanel::startConversing(const std::string& state, const QString& note)
{
    const std::string name = characterName();
    if (!m_service || !m_bot || name.empty()) {
        m_progress->refused(!m_bot ? tr("Load a bot first: it is what the character answers with.")
                                   : tr("Open a scenario and choose the character who converses."));
        updateEnabled();
        return false;
    }
    syncClock();
    core::runtime::InteractionOptions options;
    options.speak = m_speak->isChecked();
    if (auto conversing = m_service->converse(name, m_bot, options, state); !conversing) {
        m_progress->failed(conversing.error());
        updateEnabled();
        return false;
    }
    m_conversing = name;
    addEvent(!note.isEmpty() ? note : tr("%1 converses with the visitor (%2).").arg(fromUtf8(name), m_botName));
    if (m_session)
        m_session->tick(); // she turns to the visitor also while paused
    updateEnabled();
    updateStatus();
    return true;
}

void ConversationPanel::handBack()
{
    if (!isConversing())
        return;
    syncClock();
    if (m_service)
        m_service->handBack(m_conversing);
    addEvent(tr("%1 is handed back to the scenario.").arg(fromUtf8(m_conversing)));
    m_conversing.clear();
    if (m_session)
        m_session->tick();
    updateEnabled();
    updateStatus();
}

void ConversationPanel::say(const QString& text)
{
    if (text.trimmed().isEmpty() || (!isConversing() && !startConversing()))
        return;
    auto job = std::make_unique<TurnJob>();
    job->text = text.trimmed().toStdString();
    startTurn(std::move(job));
}

void ConversationPanel::hearSamples(std::vector<std::int16_t> samples)
{
    if (!isConversing() && !startConversing())
        return;
    auto job = std::make_unique<TurnJob>();
    job->samples = std::move(samples);
    startTurn(std::move(job));
}

void ConversationPanel::hearRecording(const QString& path)
{
    if (!isConversing() && !startConversing())
        return;
    auto job = std::make_unique<TurnJob>();
    job->recording = toFsPath(path);
    startTurn(std::move(job));
}

void ConversationPanel::startTurn(std::unique_ptr<TurnJob> job)
{
    job->service = m_service;
    job->character = m_conversing;
    job->recogniser = m_recogniser;
    syncClock();
    if (auto started = m_turns->start(std::move(job)); !started) {
        m_progress->failed(started.error());
        return;
    }
    m_heard->setStyleSheet(QString());
    m_heard->setText(tr("Answering…"));
    updateEnabled();
}

void ConversationPanel::cancel()
{
    m_prepare->cancel();
    m_turns->cancel();
}

void ConversationPanel::onTurn(const core::Result<void>& result)
{
    if (const TurnJob* job = m_turns->jobAs<TurnJob>())
        showTurn(*job); // also when a cancel came after the answer was given
    if (!result) {
        const TurnJob* job = m_turns->jobAs<TurnJob>();
        if (result.error().code != core::ErrorCode::Cancelled)
            m_progress->failed(result.error());
        else if (!job || !job->exchange)
            m_heard->setText(tr("Cancelled: the character was told nothing."));
    }
    updateEnabled();
}

void ConversationPanel::showTurn(const TurnJob& job)
{
    QString detail;
    if (job.heard) {
        const core::speech::Recognition& heard = *job.heard;
        const QString confidence = confidenceText(heard.confidence);
        if (heard.understood()) {
            m_heard->setStyleSheet(QString());
            m_heard->setText(tr("Heard: “%1” — confidence %2").arg(fromUtf8(heard.text), confidence));
        } else {
            m_heard->setStyleSheet(QStringLiteral("color: #c0392b;"));
            m_heard->setText(heard.text.empty() ? tr("Not understood — confidence %1; nothing of the grammar fits.").arg(confidence)
                                                : tr("Not understood — confidence %1; nearest: “%2”.")
                                                      .arg(confidence, fromUtf8(heard.text)));
        }
        detail = tr("heard, confidence %1").arg(confidence);
    } else if (job.text) {
        m_heard->setStyleSheet(QString());
        m_heard->setText(tr("Typed: “%1”").arg(fromUtf8(*job.text)));
        detail = tr("typed");
    }
    if (!job.exchange)
        return;
    const core::runtime::Exchange& exchange = *job.exchange;
    m_transcript->addExchange(fromUtf8(job.character), exchange, detail);
    QStringList warnings;
    if (!exchange.answer.problem.empty())
        warnings << fromUtf8(exchange.answer.problem);
    for (const std::string& warning : exchange.warnings)
        warnings << fromUtf8(warning);
    if (!warnings.isEmpty())
        m_progress->refused(warnings.join(QLatin1Char('\n')));
    if (exchange.end > exchange.start) {
        if (m_session)
            m_session->tick();
        emit playRequested(); // heard and seen from the playhead
    }
}

void ConversationPanel::addEvent(const QString& text) { m_transcript->addEvent(text); }

// ---- Push to talk ----

void ConversationPanel::startTalking()
{
    if (m_microphone->isRecording() || (!isConversing() && !startConversing()))
        return;
    QString error;
    if (!m_microphone->start(&error)) {
        m_progress->refused(error);
        updateStatus();
        return;
    }
    // She listens visibly while the visitor speaks.
    syncClock();
    if (auto listening = m_service->visitorSpeaks(m_conversing); !listening)
        m_progress->failed(listening.error());
    if (m_session)
        m_session->tick();
    m_talkTimer->start(100);
    updateStatus();
}

void ConversationPanel::stopTalking()
{
    if (!m_microphone->isRecording())
        return;
    m_talkTimer->stop();
    std::vector<std::int16_t> samples = m_microphone->stop();
    updateStatus();
    if (samples.size() < kShortestUtterance) {
        m_heard->setText(tr("Nothing was heard: hold the button while the visitor speaks."));
        return;
    }
    hearSamples(std::move(samples));
}

// ---- State ----

bool ConversationPanel::saveState(const QString& path)
{
    if (!isConversing()) {
        m_progress->refused(tr("Nothing to save: no character converses."));
        return false;
    }
    auto saved = m_service->saveState(m_conversing);
    auto written = saved ? core::writeFileAtomically(toFsPath(path), *saved) : core::Result<void>(saved.error());
    if (!written) {
        m_progress->failed(written.error());
        return false;
    }
    m_progress->finished(tr("Saved"), tr("What the visitor told the bot is in “%1”.").arg(QFileInfo(path).fileName()));
    return true;
}

bool ConversationPanel::loadState(const QString& path)
{
    auto read = core::readTextFile(toFsPath(path));
    if (!read) {
        m_progress->failed(read.error());
        return false;
    }
    const std::string before = m_conversing;
    if (isConversing()) {
        m_service->handBack(m_conversing);
        m_conversing.clear();
    }
    if (!startConversing(*read, tr("%1 converses on from “%2”.").arg(fromUtf8(characterName()), QFileInfo(path).fileName()))) {
        if (!before.empty()) // as it was before: conversing, from where it was not saved
            addEvent(tr("%1 is handed back to the scenario.").arg(fromUtf8(before)));
        return false;
    }
    m_progress->finished(tr("Loaded"), tr("The conversation goes on from “%1”.").arg(QFileInfo(path).fileName()));
    return true;
}

// ---- What can be done now ----

void ConversationPanel::updateEnabled()
{
    const bool preparing = m_prepare->isRunning(), answering = m_turns->isRunning();
    const bool ready = m_service && m_bot && currentCharacter() >= 0;
    m_converse->setEnabled(ready || isConversing());
    {
        const QSignalBlocker blocker(m_converse);
        m_converse->setChecked(isConversing());
    }
    m_converse->setText(isConversing() ? tr("Hand Back") : tr("Converse"));
    m_speak->setEnabled(!isConversing());
    m_loadFolder->setEnabled(!preparing);
    m_loadFiles->setEnabled(!preparing);
    m_loadDemo->setEnabled(!preparing);
    m_send->setEnabled(ready && !answering && !m_input->text().trimmed().isEmpty());
    const bool canHear = ready && m_recogniser && !answering;
    m_talk->setEnabled(m_microphone->isRecording() || (canHear && m_microphone->isAvailable()));
    m_hearRecording->setEnabled(canHear);
    m_saveState->setEnabled(isConversing());
    m_loadState->setEnabled(ready);
    m_cancel->setEnabled(preparing || answering);
}

void ConversationPanel::updateStatus()
{
    if (m_microphone->isRecording())
        m_status->setText(tr("Listening… %1 s — let go when the visitor is done.").arg(m_microphone->seconds(), 0, 'f', 1));
    else if (!m_microphone->isAvailable())
        m_status->setText(tr("No microphone found — type what the visitor says, or use “Hear a Recording…”."));
    else if (!m_bot)
        m_status->setText(tr("Microphone: %1. Load a bot to talk to.").arg(m_microphone->deviceName()));
    else if (!m_recogniser)
        m_status->setText(tr("Microphone: %1. Hold to Talk works once the recogniser is open.").arg(m_microphone->deviceName()));
    else
        m_status->setText(tr("Microphone: %1. Hold “Hold to Talk” while the visitor speaks.").arg(m_microphone->deviceName()));
}

} // namespace thespis::editor
