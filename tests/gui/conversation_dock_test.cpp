// The Conversation dock on the real window and the built-in demo (issue 34, paper §5.3): with no
// microphone the talk button is off and the dock says what to do instead; the demo's bot, loaded
// from its button, answers a question typed and sent — the transcript shows the answer and the
// category's file:line, and Antigone says it on the Stage (her lips move, her voice is in what
// the studio plays, her eyes are on the visitor); real recordings (pocketsphinx's cards) are heard
// through the bot's own grammar with their confidence and answered, as are the samples let go of
// push-to-talk; speech the grammar does not cover is "not understood" and answered so; Hand Back
// gives her back, and a saved state brings back what she was told; a bad AIML file is named with
// its line while the rest loads.

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDockWidget>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QAudioDevice>
#include <QMediaDevices>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <functional>

#include "editor/conversation_panel.h"
#include "editor/conversation_transcript.h"
#include "editor/document.h"
#include "editor/playback_clock.h"
#include "editor/script_panel.h"
#include "editor/session.h"
#include "editor/stage_audio.h"
#include "editor/translations.h"
#include "gui_support.h"
#include "main_window.h"
#include "runtime/interaction_service.h"
#include "runtime/sound.h"
#include "scene/fap.h"
#include "speech/grammar_recogniser.h"
#include "studio_support.h"

using namespace thespis;
using editor::ConversationTranscript;
using test::characterIndex;
using test::raiseDock;
using test::saveScreenshot;
using test::whenModal;

namespace {

QString demoPath() { return QStringLiteral(THESPIS_RESOURCES "/demo.thespis"); }
QString antigoneAiml() { return QStringLiteral(THESPIS_RESOURCES "/dialogue/antigone/antigone.aiml"); }
QString cardsBot() { return QStringLiteral(THESPIS_TEST_DATA "/dialogue/cards"); }
QString cardsRecording(const char* name) { return QStringLiteral(THESPIS_SHARED_DATA "/speech/pocketsphinx/cards/") + QLatin1String(name); }

// "name:line" of the first line of `file` holding `text`, as the transcript names a category.
QString placeOf(const QString& file, const QString& text)
{
    QFile aiml(file);
    if (!aiml.open(QIODevice::ReadOnly))
        return QStringLiteral("(unreadable %1)").arg(file);
    const QStringList lines = QString::fromUtf8(aiml.readAll()).split(QLatin1Char('\n'));
    for (int i = 0; i < lines.size(); ++i)
        if (lines[i].contains(text))
            return QStringLiteral("%1:%2").arg(QFileInfo(file).fileName()).arg(i + 1);
    return QStringLiteral("(no %1 in %2)").arg(text, file);
}

// Answers the next file dialog with `names` (quoted when several) in the folder `folder`.
void answerFileDialog(const QString& folder, const QStringList& names)
{
    whenModal<QFileDialog>([folder, names](QFileDialog* files) {
        files->setDirectory(folder);
        QString typed = names.size() == 1 ? names.front() : QStringLiteral("\"%1\"").arg(names.join(QStringLiteral("\" \"")));
        files->findChild<QLineEdit*>(QStringLiteral("fileNameEdit"))->setText(typed);
        QMetaObject::invokeMethod(files, "accept");
    });
}

} // namespace

class ConversationDockTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void init();
    void noMicrophoneIsACleanState();
    void theDemosBotAnswersATypedQuestionWithVoiceLipsAndGaze();
    void aRecordingIsHeardWithItsConfidenceAndAnswered();
    void speechTheGrammarDoesNotCoverIsNotUnderstood();
    void handBackAndTheConversationsState();
    void aBadAimlFileIsNamedWithItsLine();
    void aScriptsHandOverGoesOnInTheDock();

private:
    editor::ConversationPanel* panel() { return m_window->conversation(); }
    // Loads the bot at `paths` and waits until its recogniser is open.
    void loadAndListen(const std::function<void()>& load);
    // The last exchange of Antigone's visit.
    core::runtime::Exchange lastExchange();
    // The widest Antigone's mouth opens (any viseme) at `seconds`.
    float mouthAt(double seconds);
    // Checks that the last answer was said on the stage: lips moving while it is spoken, not before.
    void checkSpokenOnTheStage();
    // The text of the transcript's last `back`-th line said (0: the last).
    QString lineText(int back, int column);

    std::unique_ptr<studio::MainWindow> m_window;
    int m_antigone = -1;
};

void ConversationDockTest::initTestCase()
{
    editor::installTranslators(*QCoreApplication::instance(), QLocale(QLocale::English)); // plural forms
    m_window = std::make_unique<studio::MainWindow>();
    m_window->resize(1600, 980);
    m_window->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
}

void ConversationDockTest::init()
{
    QVERIFY(m_window->openScenario(demoPath()));
    m_window->clock()->pause();
    m_window->clock()->seek(core::secondsToTicks(2.0));
    raiseDock(panel());
    m_antigone = characterIndex(*m_window->document(), "Antigone");
    QVERIFY(m_antigone >= 0);
    panel()->setCurrentCharacter(m_antigone);
    QVERIFY(!panel()->isConversing()); // a new scenario: nobody converses
}

void ConversationDockTest::loadAndListen(const std::function<void()>& load)
{
    load();
    QTRY_VERIFY_WITH_TIMEOUT(!panel()->isBusy(), 60000);
    QVERIFY2(panel()->hasBot(), qPrintable(panel()->message()));
    QVERIFY2(panel()->isListening(), qPrintable(panel()->message()));
}

core::runtime::Exchange ConversationDockTest::lastExchange()
{
    auto transcript = panel()->interactionService()->transcript("Antigone");
    if (!transcript || transcript->empty()) {
        qWarning("Antigone has no exchange");
        return {};
    }
    return transcript->back();
}

float ConversationDockTest::mouthAt(double seconds)
{
    m_window->clock()->seek(core::secondsToTicks(seconds));
    const auto& face = m_window->session()->poses().characters[std::size_t(m_antigone)].face;
    float open = 0;
    for (int v = 1; v <= 14; ++v)
        open = std::max(open, face[std::size_t(core::scene::visemeChannel(v))]);
    return open;
}

void ConversationDockTest::checkSpokenOnTheStage()
{
    const core::runtime::Exchange exchange = lastExchange();
    QVERIFY2(exchange.end > exchange.start + 1, qPrintable(QStringLiteral("spoken from %1 to %2 s").arg(exchange.start).arg(exchange.end)));
    // The answer plays from the playhead: the view plays.
    QVERIFY(m_window->clock()->isPlaying());
    m_window->clock()->pause();
    float before = 0, during = 0;
    for (double t = std::max(0.0, exchange.start - 0.6); t < exchange.start - 0.05; t += 0.05)
        before = std::max(before, mouthAt(t));
    for (double t = exchange.start; t < exchange.end; t += 0.04)
        during = std::max(during, mouthAt(t));
    QVERIFY2(during > 0.5f, qPrintable(QStringLiteral("her mouth opens %1 while she answers").arg(during)));
    QVERIFY2(before < 0.05f, qPrintable(QStringLiteral("her mouth opens %1 before she answers").arg(before)));
    // Her eyes are on the visitor.
    auto gaze = m_window->session()->stage()->gazeState("Antigone");
    QVERIFY(gaze && gaze->has_value());
    // Her voice is among what the studio plays aloud, where she answers.
    const auto sounds = panel()->soundService()->activations();
    QVERIFY(std::any_of(sounds.begin(), sounds.end(), [&](const auto& a) {
        return a.owner == "Antigone" && a.start == core::secondsToTicks(exchange.start);
    }));
}

QString ConversationDockTest::lineText(int back, int column)
{
    const QList<QTreeWidgetItem*> lines = panel()->transcript()->lines();
    return back < lines.size() ? lines[lines.size() - 1 - back]->text(column) : QStringLiteral("(no line %1)").arg(back);
}

void ConversationDockTest::noMicrophoneIsACleanState()
{
    if (!QMediaDevices::defaultAudioInput().isNull())
        QSKIP("This machine has a microphone: the no-microphone state cannot be seen here.");
    QVERIFY(!panel()->talkButton()->isEnabled());
    QVERIFY2(panel()->status().startsWith(QStringLiteral("No microphone found — type what the visitor says, or use “Hear a Recording…”")),
             qPrintable(panel()->status()));
    QVERIFY(QApplication::activeModalWidget() == nullptr); // a state, not an error dialog
    // Typing is always there: the input takes text (Send waits for a bot).
    QVERIFY(panel()->input()->isEnabled());
    saveScreenshot(panel(), QStringLiteral("conversation_no_microphone.png"));
}

void ConversationDockTest::theDemosBotAnswersATypedQuestionWithVoiceLipsAndGaze()
{
    // The demo's bot, from its button; its grammar shows in the inspector.
    auto* demoButton = panel()->findChild<QPushButton*>(QStringLiteral("loadDemoBot"));
    QVERIFY(demoButton && demoButton->isVisible());
    loadAndListen([&] { QTest::mouseClick(demoButton, Qt::LeftButton); });
    if (QTest::currentTestFailed())
        return;
    QVERIFY2(panel()->botSummary().startsWith(QStringLiteral("“antigone”: ")) && panel()->botSummary().contains(QStringLiteral("categories")),
             qPrintable(panel()->botSummary()));
    QVERIFY(panel()->problems()->isHidden());
    QVERIFY(panel()->grammarView()->toPlainText().contains(QStringLiteral("public <utterance>")));
    const QString jsgf = panel()->grammarView()->toPlainText();
    QVERIFY2(jsgf.contains(QStringLiteral("bury")) && jsgf.contains(QStringLiteral("creon")), qPrintable(jsgf.left(2000)));
    QVERIFY2(panel()->grammarSummary().contains(QStringLiteral("pattern")), qPrintable(panel()->grammarSummary()));
    QVERIFY(panel()->grammarView()->isReadOnly());
    auto* tabs = panel()->findChild<QTabWidget*>();
    tabs->setCurrentIndex(1);
    saveScreenshot(panel(), QStringLiteral("conversation_grammar.png"));
    tabs->setCurrentIndex(0);
    // No microphone here, but she can hear recordings now; the talk button stays off.
    QCOMPARE(panel()->talkButton()->isEnabled(), !QMediaDevices::defaultAudioInput().isNull());

    // Typed and sent as a user would: she is handed over, answers, and the transcript says who
    // answered with which category.
    QSignalSpy mixed(m_window->audio(), &editor::StageAudio::mixed);
    QTest::keyClicks(panel()->input(), QStringLiteral("Why did you bury him?"));
    QVERIFY(panel()->sendButton()->isEnabled());
    QTest::mouseClick(panel()->sendButton(), Qt::LeftButton);
    QVERIFY(panel()->input()->text().isEmpty());
    QTRY_VERIFY_WITH_TIMEOUT(!panel()->isAnswering(), 20000);
    QVERIFY2(panel()->isConversing(), qPrintable(panel()->message()));
    QCOMPARE(panel()->converseButton()->text(), QStringLiteral("Hand Back"));
    QCOMPARE(lineText(1, ConversationTranscript::WhoColumn), QStringLiteral("Visitor"));
    QCOMPARE(lineText(1, ConversationTranscript::SaidColumn), QStringLiteral("Why did you bury him?"));
    QCOMPARE(lineText(1, ConversationTranscript::DetailColumn), QStringLiteral("typed"));
    QCOMPARE(lineText(0, ConversationTranscript::WhoColumn), QStringLiteral("Antigone"));
    QCOMPARE(lineText(0, ConversationTranscript::SaidColumn), QStringLiteral("Because the laws of the gods are older than any king's edict."));
    QCOMPARE(lineText(0, ConversationTranscript::DetailColumn), placeOf(antigoneAiml(), QStringLiteral("<pattern>WHY DID YOU BURY HIM</pattern>")));
    QVERIFY(lineText(0, ConversationTranscript::WhenColumn).startsWith(QStringLiteral("2.00 – ")));
    QCOMPARE(panel()->heard(), QStringLiteral("Typed: “Why did you bury him?”"));

    // While it plays, the studio's mix carries her voice (the demo's timeline is silent there).
    const core::runtime::Exchange exchange = lastExchange();
    for (const auto& sound : m_window->audio()->timelineSounds()->activations()) {
        const double from = core::ticksToSeconds(sound.start), to = from + double(sound.clip->samples.size()) / sound.clip->rate;
        QVERIFY(from >= exchange.end || to <= exchange.start);
    }
    QTRY_VERIFY_WITH_TIMEOUT(std::any_of(mixed.begin(), mixed.end(), [](const QList<QVariant>& block) { return block.at(2).toFloat() > 0.05f; }),
                             5000);
    checkSpokenOnTheStage();
    if (QTest::currentTestFailed())
        return;
}

void ConversationDockTest::aRecordingIsHeardWithItsConfidenceAndAnswered()
{
    // The cards bot, from Load Bot Folder… as a user picks it.
    answerFileDialog(QFileInfo(cardsBot()).absolutePath(), {QStringLiteral("cards")});
    loadAndListen([&] { QTest::mouseClick(panel()->findChild<QPushButton*>(QStringLiteral("loadBotFolder")), Qt::LeftButton); });
    if (QTest::currentTestFailed())
        return;
    QVERIFY2(panel()->botSummary().startsWith(QStringLiteral("“cards”: 3 categories, 2 sets")), qPrintable(panel()->botSummary()));

    // Hear a Recording…: pocketsphinx's own "ten of clubs", through the bot's grammar.
    answerFileDialog(QFileInfo(cardsRecording("001.wav")).absolutePath(), {QStringLiteral("001.wav")});
    QTest::mouseClick(panel()->findChild<QPushButton*>(QStringLiteral("hearRecording")), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(!panel()->isAnswering() && panel()->transcript()->lines().size() >= 2, 30000);
    QVERIFY2(panel()->heard().startsWith(QStringLiteral("Heard: “ten of clubs” — confidence ")), qPrintable(panel()->heard()));
    const double confidence = panel()->heard().section(QStringLiteral("confidence "), 1).toDouble();
    QVERIFY(std::abs(confidence - lastExchange().confidence) < 0.0051); // as the recogniser gave it, to two places
    QVERIFY2(confidence > -1.5 && confidence < 0.5, qPrintable(panel()->heard()));
    QCOMPARE(lineText(1, ConversationTranscript::SaidColumn), QStringLiteral("ten of clubs"));
    QVERIFY(lineText(1, ConversationTranscript::DetailColumn).startsWith(QStringLiteral("heard, confidence ")));
    QCOMPARE(lineText(0, ConversationTranscript::SaidColumn), QStringLiteral("The ten of clubs: a fine card."));
    QCOMPARE(lineText(0, ConversationTranscript::DetailColumn),
             placeOf(cardsBot() + QStringLiteral("/cards.aiml"), QStringLiteral("<set>rank</set> OF <set>suit</set>")));
    checkSpokenOnTheStage();
    if (QTest::currentTestFailed())
        return;

    // Push-to-talk lets go of 16 kHz samples: the same path (here from a recording, for there is
    // no microphone).
    auto samples = core::speech::readRecording(cardsRecording("003.wav").toStdString());
    QVERIFY(samples.ok());
    m_window->clock()->seek(core::secondsToTicks(6.0));
    panel()->hearSamples(std::move(samples).value());
    QTRY_VERIFY_WITH_TIMEOUT(!panel()->isAnswering(), 30000);
    QVERIFY2(panel()->heard().startsWith(QStringLiteral("Heard: “seven of clubs” — confidence ")), qPrintable(panel()->heard()));
    QCOMPARE(lineText(0, ConversationTranscript::SaidColumn), QStringLiteral("The seven of clubs: a fine card."));

    // The screen a person sees: the 3D view with Antigone answering, the dock beside it.
    m_window->clock()->seek(core::secondsToTicks(lastExchange().start + 0.6));
    QTest::qWait(300);
    saveScreenshot(m_window.get(), QStringLiteral("studio_conversation.png"));
    saveScreenshot(panel(), QStringLiteral("conversation_dock.png"));
}

void ConversationDockTest::speechTheGrammarDoesNotCoverIsNotUnderstood()
{
    // A card called to the demo's bot: nothing of hers sounds like it.
    loadAndListen([&] { panel()->loadBot({QFileInfo(antigoneAiml()).absolutePath()}); });
    if (QTest::currentTestFailed())
        return;
    panel()->hearRecording(cardsRecording("001.wav"));
    QTRY_VERIFY_WITH_TIMEOUT(!panel()->isAnswering(), 30000);
    QVERIFY2(panel()->heard().startsWith(QStringLiteral("Not understood — confidence ")), qPrintable(panel()->heard()));
    QCOMPARE(lineText(1, ConversationTranscript::SaidColumn), QStringLiteral("(not understood)"));
    QCOMPARE(lineText(0, ConversationTranscript::DetailColumn), placeOf(antigoneAiml(), QStringLiteral("<pattern>XNOTUNDERSTOOD</pattern>")));
    QVERIFY(!lastExchange().understood);
}

void ConversationDockTest::handBackAndTheConversationsState()
{
    loadAndListen([&] { panel()->loadBot({QFileInfo(antigoneAiml()).absolutePath()}); });
    if (QTest::currentTestFailed())
        return;
    QTemporaryDir folder;
    QVERIFY(folder.isValid());

    // Converse, from its button; she is told a name; the state is saved.
    QTest::mouseClick(panel()->converseButton(), Qt::LeftButton);
    QVERIFY(panel()->isConversing());
    QVERIFY(panel()->interactionService()->conversing("Antigone"));
    QVERIFY(!panel()->findChild<QCheckBox*>(QStringLiteral("speakAnswers"))->isEnabled()); // chosen before
    QTest::keyClicks(panel()->input(), QStringLiteral("My name is Ada"));
    QTest::keyClick(panel()->input(), Qt::Key_Return);
    QTRY_VERIFY_WITH_TIMEOUT(!panel()->isAnswering(), 20000);
    QCOMPARE(lineText(0, ConversationTranscript::SaidColumn), QStringLiteral("Welcome to Thebes, Ada."));
    answerFileDialog(folder.path(), {QStringLiteral("visitor.json")});
    QTest::mouseClick(panel()->findChild<QPushButton*>(QStringLiteral("saveConversationState")), Qt::LeftButton);
    QTRY_VERIFY(QFileInfo::exists(folder.filePath(QStringLiteral("visitor.json"))));

    // Hand Back: she is the scenario's again and lets go of the visitor's eyes.
    m_window->clock()->pause();
    QTest::mouseClick(panel()->converseButton(), Qt::LeftButton);
    QVERIFY(!panel()->isConversing());
    QVERIFY(!panel()->interactionService()->conversing("Antigone"));
    QCOMPARE(panel()->converseButton()->text(), QStringLiteral("Converse"));
    m_window->clock()->seek(m_window->clock()->time() + core::secondsToTicks(3.0));
    QVERIFY(!*m_window->session()->stage()->gazeState("Antigone"));

    // A new visit forgets; one from the saved state remembers.
    panel()->say(QStringLiteral("What is my name?"));
    QTRY_VERIFY_WITH_TIMEOUT(!panel()->isAnswering(), 20000);
    QCOMPARE(lineText(0, ConversationTranscript::SaidColumn), QStringLiteral("You have not told me yet."));
    answerFileDialog(folder.path(), {QStringLiteral("visitor.json")});
    QTest::mouseClick(panel()->findChild<QPushButton*>(QStringLiteral("loadConversationState")), Qt::LeftButton);
    QTRY_VERIFY(panel()->message().contains(QStringLiteral("visitor.json")));
    panel()->say(QStringLiteral("What is my name?"));
    QTRY_VERIFY_WITH_TIMEOUT(!panel()->isAnswering(), 20000);
    QCOMPARE(lineText(0, ConversationTranscript::SaidColumn), QStringLiteral("You are Ada."));

    // A file that is no conversation's state is refused, naming why.
    QFile junk(folder.filePath(QStringLiteral("junk.json")));
    QVERIFY(junk.open(QIODevice::WriteOnly));
    junk.write("{\"format\": \"something else\"}");
    junk.close();
    QVERIFY(!panel()->loadState(junk.fileName()));
    QVERIFY2(!panel()->message().isEmpty(), "the refusal is said");
}

void ConversationDockTest::aBadAimlFileIsNamedWithItsLine()
{
    QTemporaryDir folder;
    QVERIFY(folder.isValid());
    QFile bad(folder.filePath(QStringLiteral("bad.aiml")));
    QVERIFY(bad.open(QIODevice::WriteOnly));
    bad.write("<aiml>\n<category><pattern>HOWDY</pattern><template>Hi there.</template></category>\n"
              "<category><pattern>BYE<pattern><template>x</template></category>\n</aiml>\n");
    bad.close();
    QFile::copy(antigoneAiml(), folder.filePath(QStringLiteral("antigone.aiml")));

    // Load AIML Files…, both picked: the bad one is named by file and line, the rest loads.
    answerFileDialog(folder.path(), {QStringLiteral("antigone.aiml"), QStringLiteral("bad.aiml")});
    QTest::mouseClick(panel()->findChild<QPushButton*>(QStringLiteral("loadAimlFiles")), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(!panel()->isBusy() && panel()->problems()->count() > 0, 30000);
    QVERIFY(panel()->problems()->isVisible());
    const QString problem = panel()->problems()->item(0)->text();
    QVERIFY2(problem.startsWith(QStringLiteral("bad.aiml:3:23: ")), qPrintable(problem));
    QVERIFY(panel()->problems()->item(0)->toolTip().startsWith(bad.fileName() + QStringLiteral(":3:23: "))); // the whole path
    QCOMPARE(panel()->problems()->count(), 3); // two elements a pattern cannot hold, then the XML breaks
    QVERIFY2(panel()->problems()->item(2)->text().contains(QStringLiteral("malformed")), qPrintable(panel()->problems()->item(2)->text()));
    QVERIFY2(panel()->message().contains(QStringLiteral("3 problems in its files")), qPrintable(panel()->message()));
    QVERIFY2(panel()->botSummary().startsWith(QStringLiteral("“antigone.aiml and 1 more”: ")), qPrintable(panel()->botSummary()));
    // What loaded answers.
    panel()->say(QStringLiteral("howdy"));
    QTRY_VERIFY_WITH_TIMEOUT(!panel()->isAnswering(), 20000);
    QCOMPARE(lineText(0, ConversationTranscript::DetailColumn), QStringLiteral("bad.aiml:2"));
    saveScreenshot(panel(), QStringLiteral("conversation_bad_aiml.png"));
}

void ConversationDockTest::aScriptsHandOverGoesOnInTheDock()
{
    // The demo's script ends so: Antigone is handed to a conversation with her bot. The script
    // tells her its name first; the dock takes her over with what she was told.
    auto* script = m_window->findChild<editor::ScriptPanel*>();
    QVERIFY(script);
    script->setSource(QStringLiteral(
        "bot = interactionService.load_bot('dialogue/antigone/antigone.aiml')\n"
        "interactionService.converse('Antigone', bot)\n"
        "print(interactionService.hear('Antigone', 'My name is Haemon')['answer']['text'])\n"));
    script->run();
    QTRY_VERIFY_WITH_TIMEOUT(!script->isRunning(), 30000);
    QVERIFY2(script->output().indexOf(QStringLiteral("Error")) < 0, qPrintable(script->output()));
    QTRY_VERIFY_WITH_TIMEOUT(panel()->isConversing(), 5000);
    QCOMPARE(panel()->currentCharacter(), m_antigone);
    QVERIFY(!script->interactionService()->conversing("Antigone"));
    QVERIFY(panel()->interactionService()->conversing("Antigone"));
    QCOMPARE(panel()->converseButton()->text(), QStringLiteral("Hand Back"));
    QVERIFY(panel()->isVisible());
    // Its grammar is made and the recogniser opened, as for a bot loaded in the dock.
    QTRY_VERIFY_WITH_TIMEOUT(!panel()->isBusy(), 60000);
    QVERIFY2(panel()->isListening(), qPrintable(panel()->message()));
    QVERIFY(panel()->grammarView()->toPlainText().contains(QStringLiteral("public <utterance>")));
    // The transcript says so, among its events.
    QCOMPARE(panel()->transcript()->findItems(QStringLiteral("Antigone takes questions: the script handed the conversation over."),
                                              Qt::MatchExactly, ConversationTranscript::SaidColumn).size(),
             qsizetype(1));

    // The visitor asks on in the dock: she answers, and remembers what the script's visitor said.
    QTest::keyClicks(panel()->input(), QStringLiteral("What is my name?"));
    QTest::mouseClick(panel()->sendButton(), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(!panel()->isAnswering(), 20000);
    QCOMPARE(lineText(1, ConversationTranscript::SaidColumn), QStringLiteral("What is my name?"));
    QVERIFY2(lineText(0, ConversationTranscript::SaidColumn).contains(QStringLiteral("Haemon")),
             qPrintable(lineText(0, ConversationTranscript::SaidColumn)));
    saveScreenshot(m_window.get(), QStringLiteral("studio_conversation_after_script.png"));
    panel()->handBack();
}

QTEST_MAIN(ConversationDockTest)
#include "conversation_dock_test.moc"
