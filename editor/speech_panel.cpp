#include "editor/speech_panel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QSplitter>
#include <QVBoxLayout>

#include "edit/bml_edits.h"
#include "edit/speech_edits.h"
#include "editor/character_choice.h"
#include "editor/document.h"
#include "editor/job_progress.h"
#include "editor/job_runner.h"
#include "editor/playback_clock.h"
#include "editor/qt_conversions.h"
#include "editor/session.h"
#include "editor/stage_audio.h"
#include "editor/viseme_table.h"
#include "runtime/bml_performance.h"
#include "runtime/clock.h"
#include "runtime/sound.h"
#include "runtime/speech_performance.h"
#include "speech/lip_sync.h"
#include "speech/speak_job.h"

namespace thespis::editor {
namespace {

constexpr const char* kPreviewLine = "preview";

} // namespace

SpeechPanel::SpeechPanel(QWidget* parent) : QWidget(parent), m_runner(new JobRunner(this))
{
    auto* layout = new QVBoxLayout(this);
    auto* top = new QHBoxLayout;
    m_characters = addCharacterChoice(this, top, QStringLiteral("speechCharacter"), tr("The character who speaks"));
    layout->addLayout(top);

    auto* voiceRow = new QHBoxLayout;
    m_voices = new QComboBox(this);
    m_voices->setObjectName(QStringLiteral("speechVoice"));
    m_voices->setToolTip(tr("The espeak-ng voices installed"));
    if (auto voices = core::speech::listVoices()) {
        // English first: the rest follow by language.
        std::stable_sort(voices->begin(), voices->end(), [](const auto& a, const auto& b) {
            return a.language.starts_with("en") > b.language.starts_with("en");
        });
        for (const core::speech::VoiceInfo& v : *voices)
            m_voices->addItem(QStringLiteral("%1 (%2)").arg(fromUtf8(v.name), fromUtf8(v.language)), fromUtf8(v.identifier));
    }
    m_rate = new QSpinBox(this);
    m_rate->setObjectName(QStringLiteral("speechRate"));
    m_rate->setRange(80, 450);
    m_rate->setValue(175);
    m_rate->setSuffix(tr(" words/min"));
    m_pitch = new QSpinBox(this);
    m_pitch->setObjectName(QStringLiteral("speechPitch"));
    m_pitch->setRange(0, 100);
    m_pitch->setValue(50);
    voiceRow->addWidget(new QLabel(tr("Voice:"), this));
    voiceRow->addWidget(m_voices, 1);
    voiceRow->addWidget(new QLabel(tr("Rate:"), this));
    voiceRow->addWidget(m_rate);
    voiceRow->addWidget(new QLabel(tr("Pitch:"), this));
    voiceRow->addWidget(m_pitch);
    layout->addLayout(voiceRow);

    auto* split = new QSplitter(Qt::Vertical, this);
    m_text = new QPlainTextEdit(split);
    m_text->setObjectName(QStringLiteral("speechText"));
    m_text->setPlaceholderText(tr("What the character says. Gestures go around the words they span:\n"
                                  "Are you <begin_gesture id=\"g1\" anim=\"raise_eyebrows\"/>really sure<end_gesture id=\"g1\"/>?\n"
                                  "Or a BML block:\n"
                                  "<bml id=\"b1\"><speech id=\"s1\"><text>Hello <sync id=\"t1\"/>there.</text></speech>\n"
                                  "<gesture id=\"g1\" lexeme=\"BEAT\" stroke=\"s1:t1\"/><gaze id=\"z1\" target=\"camera\"/></bml>"));
    auto* visemeBox = new QGroupBox(tr("Visemes and their coarticulation"), split);
    auto* visemeLayout = new QVBoxLayout(visemeBox);
    m_visemes = new VisemeTable(visemeBox);
    visemeLayout->addWidget(m_visemes);
    split->setStretchFactor(0, 1);
    split->setStretchFactor(1, 2);
    layout->addWidget(split, 1);

    auto* buttons = new QHBoxLayout;
    m_preview = new QPushButton(tr("Preview"), this);
    m_preview->setObjectName(QStringLiteral("speechPreview"));
    m_preview->setToolTip(tr("Say it from the playhead, face and voice, without changing the scenario"));
    m_insert = new QPushButton(tr("Insert at Playhead"), this);
    m_insert->setObjectName(QStringLiteral("speechInsert"));
    m_insert->setToolTip(tr("Put the line, its visemes and its gestures (or the BML block's speech, gestures, head, face and gaze) on the timeline at the playhead (one undo step)"));
    m_lipSync = new QPushButton(tr("Lip Sync a Recording…"), this);
    m_lipSync->setObjectName(QStringLiteral("speechLipSync"));
    m_lipSync->setToolTip(tr("Align a WAV with the text above as its transcript (empty: the words are recognised) and insert it"));
    m_cancel = new QPushButton(tr("Cancel"), this);
    m_closeUp = new QCheckBox(tr("Close-up"), this);
    m_closeUp->setToolTip(tr("Turn the 3D view to the speaker's face when previewing"));
    buttons->addWidget(m_preview);
    buttons->addWidget(m_insert);
    buttons->addWidget(m_lipSync);
    buttons->addWidget(m_cancel);
    buttons->addStretch(1);
    buttons->addWidget(m_closeUp);
    layout->addLayout(buttons);
    m_progress = new JobProgress(tr("Nothing spoken yet"), this);
    layout->addWidget(m_progress);

    connect(m_preview, &QPushButton::clicked, this, &SpeechPanel::preview);
    connect(m_insert, &QPushButton::clicked, this, &SpeechPanel::insert);
    connect(m_lipSync, &QPushButton::clicked, this, [this] {
        const QString wav = QFileDialog::getOpenFileName(this, tr("Lip Sync a Recording"), m_document ? m_document->baseDir() : QString(),
                                                         tr("Sound files (*.wav *.flac *.ogg)"));
        if (!wav.isEmpty())
            lipSync(wav);
    });
    connect(m_cancel, &QPushButton::clicked, this, &SpeechPanel::cancel);
    connect(m_runner, &JobRunner::progress, m_progress, &JobProgress::setProgress);
    connect(m_runner, &JobRunner::finished, this, [this](const core::Result<void>& result) {
        if (!result)
            m_progress->failed(result.error());
        onFinished(result.ok());
    });
    updateEnabled();
}

SpeechPanel::~SpeechPanel() = default;

void SpeechPanel::setSession(Session* session, StageAudio* audio)
{
    m_session = session;
    m_audio = audio;
    session->addPanel(this);
}

void SpeechPanel::setDocument(Document* document)
{
    m_document = document;
    m_previewSound = document ? std::make_shared<core::runtime::SoundService>(
                                    document->assets(), std::make_shared<core::runtime::ExternalClock>())
                              : nullptr;
    if (document)
        connect(document, &Document::edited, this, [this] { fillCharacterChoice(m_characters, m_document); });
    fillCharacterChoice(m_characters, document);
    updateEnabled();
}

int SpeechPanel::currentCharacter() const { return m_characters->currentIndex(); }
void SpeechPanel::setCurrentCharacter(int character) { m_characters->setCurrentIndex(character); }
QString SpeechPanel::text() const { return m_text->toPlainText(); }
void SpeechPanel::setText(const QString& text) { m_text->setPlainText(text); }
void SpeechPanel::setRate(int wordsPerMinute) { m_rate->setValue(wordsPerMinute); }
void SpeechPanel::setPitch(int pitch) { m_pitch->setValue(pitch); }
void SpeechPanel::setCloseUp(bool closeUp) { m_closeUp->setChecked(closeUp); }
bool SpeechPanel::isBusy() const { return m_runner->isRunning(); }
QString SpeechPanel::message() const { return m_progress->message()->text(); }
void SpeechPanel::cancel() { m_runner->cancel(); }

core::speech::VoiceSettings SpeechPanel::voice() const
{
    core::speech::VoiceSettings voice;
    if (m_voices->currentIndex() >= 0)
        voice.voice = m_voices->currentData().toString().toStdString();
    voice.wordsPerMinute = m_rate->value();
    voice.pitch = m_pitch->value();
    return voice;
}

bool SpeechPanel::setVoice(const QString& voice)
{
    int index = m_voices->findData(voice);
    for (int i = 0; index < 0 && i < m_voices->count(); ++i)
        if (m_voices->itemText(i).startsWith(voice + QLatin1String(" (")) || m_voices->itemText(i).endsWith(QStringLiteral("(%1)").arg(voice)))
            index = i;
    if (index >= 0)
        m_voices->setCurrentIndex(index);
    return index >= 0;
}

void SpeechPanel::preview() { start(Then::Preview); }
void SpeechPanel::insert() { start(Then::Insert); }

void SpeechPanel::lipSync(const QString& wav)
{
    m_recording = wav;
    start(Then::LipSync);
}

void SpeechPanel::start(Then then)
{
    if (!m_document || currentCharacter() < 0 || m_runner->isRunning())
        return;
    m_then = then;
    const std::string text = m_text->toPlainText().toStdString();
    std::unique_ptr<core::Job> job;
    if (then == Then::LipSync) {
        auto tagged = core::speech::parseTaggedText(text);
        if (!tagged) {
            m_progress->failed(tagged.error());
            return;
        }
        auto lipSync = std::make_unique<core::speech::LipSyncJob>();
        lipSync->audio = toFsPath(m_recording);
        lipSync->transcript = tagged->text;
        job = std::move(lipSync);
    } else {
        auto speak = std::make_unique<core::speech::SpeakJob>();
        speak->text = text;
        speak->voice = voice();
        speak->visemes = m_visemes->visemes();
        job = std::move(speak);
    }
    if (auto started = m_runner->start(std::move(job)); !started) {
        m_progress->failed(started.error());
        return;
    }
    m_progress->started();
    updateEnabled();
}

void SpeechPanel::onFinished(bool ok)
{
    updateEnabled();
    if (!ok || !m_document || !m_session)
        return;
    switch (m_then) {
    case Then::Preview: playPreview(); break;
    case Then::Insert: insertSpoken(); break;
    case Then::LipSync: insertLipSync(); break;
    }
}

void SpeechPanel::playPreview()
{
    const auto* job = m_runner->jobAs<core::speech::SpeakJob>();
    const int c = currentCharacter();
    if (!job || c < 0 || !m_session->stage())
        return;
    const std::string& name = m_document->scenario().characters[std::size_t(c)].name;
    const core::Tick at = m_session->clock()->time();
    if (job->bml) {
        previewBml(*job, name, at);
        return;
    }
    auto performed = core::runtime::performSpeech(*m_session->stage(), name, kPreviewLine, job->visemeCues, job->gestureBml, at);
    if (!performed) {
        m_progress->failed(performed.error());
        return;
    }
    m_previewSound->clear();
    m_previewSound->playClip(core::runtime::speechSoundName(name, kPreviewLine),
                             std::make_shared<const core::runtime::SoundClip>(
                                 core::runtime::SoundClip{job->utterance.rate, job->utterance.samples}),
                             at);
    if (m_audio)
        m_audio->addSource(m_previewSound);
    QString text = tr("Previewing %1 s of speech from %2 s: %n viseme(s)", nullptr, performed->visemes)
                       .arg(job->utterance.duration(), 0, 'f', 2)
                       .arg(core::ticksToSeconds(at), 0, 'f', 2);
    if (!performed->unknownGestures.empty())
        text += tr("; not in the gesticon: %1").arg(fromUtf8(performed->unknownGestures.front()));
    m_progress->finished(tr("Previewing"), text);
    if (m_closeUp->isChecked())
        emit closeUpRequested(c);
    m_session->tick();
    emit playRequested();
}

void SpeechPanel::previewBml(const core::speech::SpeakJob& job, const std::string& character, core::Tick at)
{
    m_previewSound->clear();
    core::runtime::BmlRealizer realizer(m_session->stage(), m_previewSound);
    core::runtime::BmlOptions options;
    options.voice = job.voice;
    options.spoken = std::make_shared<const std::map<std::string, core::speech::Utterance>>(job.bmlSpeech);
    auto performed = realizer.perform(character, *job.bml, options, at);
    if (!performed) {
        m_progress->failed(performed.error());
        return;
    }
    if (m_audio)
        m_audio->addSource(m_previewSound);
    m_progress->finished(tr("Previewing"), tr("Previewing BML block “%1” from %2 s to %3 s: %n behaviour(s)", nullptr,
                                              int(performed->times.size()))
                                               .arg(fromUtf8(performed->block))
                                               .arg(performed->start, 0, 'f', 2)
                                               .arg(performed->end, 0, 'f', 2));
    if (m_closeUp->isChecked())
        emit closeUpRequested(currentCharacter());
    m_session->tick();
    emit playRequested();
}

void SpeechPanel::insertBml(const core::speech::SpeakJob& job)
{
    core::edit::BmlInsertOptions options;
    options.voice = job.voice;
    options.visemes = m_visemes->visemes();
    const core::Tick at = m_session->clock()->time();
    auto inserted = core::edit::insertBml(m_document->scenario(), m_document->runtime(), currentCharacter(), *job.bml,
                                          job.bmlSpeech, options, at);
    if (!inserted) {
        m_progress->failed(inserted.error());
        return;
    }
    if (auto done = m_document->edit(std::move(inserted->edit), tr("Insert BML")); !done) {
        m_progress->failed(done.error());
        return;
    }
    m_progress->finished(tr("Inserted"),
                         tr("Inserted BML from %1 s to %2 s: %n speech(es), %3 gesture(s), %4 head gesture(s), "
                            "%5 face lexeme(s), %6 gaze(s).",
                            nullptr, inserted->speeches)
                             .arg(core::ticksToSeconds(at), 0, 'f', 2)
                             .arg(core::ticksToSeconds(at) + inserted->seconds, 0, 'f', 2)
                             .arg(inserted->gestures)
                             .arg(inserted->headGestures)
                             .arg(inserted->faceLexemes)
                             .arg(inserted->gazes));
}

void SpeechPanel::insertSpoken()
{
    const auto* job = m_runner->jobAs<core::speech::SpeakJob>();
    if (!job)
        return;
    if (job->bml) {
        insertBml(*job);
        return;
    }
    // The line keeps its text, not a file: espeak-ng says it again the same way when it plays.
    auto line = core::edit::speechLine(job->text, job->voice, job->utterance.timing, {}, m_session->clock()->time());
    auto inserted = core::edit::insertSpeech(m_document->scenario(), currentCharacter(), std::move(line),
                                             job->visemeCues, job->gestureBml, &m_document->runtime());
    if (!inserted) {
        m_progress->failed(inserted.error());
        return;
    }
    if (auto done = m_document->edit(std::move(inserted->edit), tr("Insert Speech")); !done) {
        m_progress->failed(done.error());
        return;
    }
    m_progress->finished(tr("Inserted"), tr("Inserted at %1 s: %n viseme(s), %2 face and %3 body gesture(s).", nullptr,
                                             inserted->visemeActions)
                                              .arg(core::ticksToSeconds(*m_document->scenario()
                                                                             .characters[std::size_t(currentCharacter())]
                                                                             .speech.back()
                                                                             .start),
                                                   0, 'f', 2)
                                              .arg(inserted->faceGestures)
                                              .arg(inserted->bodyGestures));
}

void SpeechPanel::insertLipSync()
{
    const auto* job = m_runner->jobAs<core::speech::LipSyncJob>();
    auto tagged = core::speech::parseTaggedText(m_text->toPlainText().toStdString());
    if (!job || !tagged)
        return;
    // Gestures are timed by the words of the transcript; a recognised one has no tags.
    if (tagged->text != job->result.transcript)
        tagged = core::speech::TaggedText{job->result.transcript, {}};
    const core::speech::SpeechTiming& timing = job->result.timing;
    // The recording stays where it is: named relative to the scenario when it is in its folder.
    QString audio = QDir(m_document->baseDir()).relativeFilePath(m_recording);
    if (audio.startsWith(QLatin1String("..")))
        audio = QFileInfo(m_recording).absoluteFilePath();
    auto line = core::edit::speechLine(core::speech::taggedTextString(*tagged), voice(), timing, audio.toStdString(),
                                       m_session->clock()->time());
    auto inserted = core::edit::insertSpeech(m_document->scenario(), currentCharacter(), std::move(line),
                                             core::speech::visemeCues(timing, m_visemes->visemes()),
                                             core::speech::taggedBml(*tagged, timing), &m_document->runtime());
    if (!inserted) {
        m_progress->failed(inserted.error());
        return;
    }
    if (auto done = m_document->edit(std::move(inserted->edit), tr("Lip Sync Recording")); !done) {
        m_progress->failed(done.error());
        return;
    }
    QString text = tr("Lip-synced “%1”: %n word(s), %2 viseme(s).", nullptr, int(timing.words.size()))
                       .arg(QFileInfo(m_recording).fileName())
                       .arg(inserted->visemeActions);
    for (const std::string& warning : job->result.warnings)
        text += QLatin1Char('\n') + fromUtf8(warning);
    m_progress->finished(tr("Inserted"), text);
}

void SpeechPanel::updateEnabled()
{
    const bool ready = m_document && currentCharacter() >= 0 && !m_runner->isRunning();
    m_preview->setEnabled(ready);
    m_insert->setEnabled(ready);
    m_lipSync->setEnabled(ready);
    m_cancel->setEnabled(m_runner->isRunning());
}

} // namespace thespis::editor
