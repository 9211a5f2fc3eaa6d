// editor::Session: views registered once follow every document (detached from the old one before
// it goes), the session's stage follows edits — the same stage, with a live action playing on,
// when an action moves; a stage of the new cast when a character is added — and every tick
// evaluates the stage exactly once and publishes those poses to the views and the mailbox. On
// the demo.

#include <QSignalSpy>
#include <QTest>
#include <QUndoStack>

#include <memory>
#include <string>
#include <vector>

#include "edit/content_edits.h"
#include "edit/document_edits.h"
#include "editor/document.h"
#include "editor/playback_clock.h"
#include "editor/session.h"

using namespace thespis;

namespace {

std::unique_ptr<editor::Document> demo()
{
    auto document = editor::Document::open(QStringLiteral(THESPIS_RESOURCES "/demo.thespis"));
    return document ? std::move(document).value() : nullptr;
}

} // namespace

class SessionTest : public QObject {
    Q_OBJECT
private slots:
    void viewsFollowEveryDocument();
    void aLiveActionPlaysOnThroughAnEdit();
    void anotherCastGetsANewStage();
    void aTickEvaluatesOnceAndPublishesTheStagesPoses();
    void anEditSetsTheRuntimeOnceAndShowsItAtOnce();
};

void SessionTest::viewsFollowEveryDocument()
{
    editor::PlaybackClock clock;
    editor::Session session(&clock);
    std::vector<editor::Document*> seen;
    session.addView([&](editor::Document* d) { seen.push_back(d); });
    QCOMPARE(seen, std::vector<editor::Document*>{nullptr}); // told at once: nothing open
    QVERIFY(!session.stage());

    QSignalSpy changed(&session, &editor::Session::documentChanged);
    auto first = demo();
    QVERIFY(first);
    editor::Document* firstPointer = first.get();
    session.setDocument(std::move(first));
    QCOMPARE(seen.back(), firstPointer);
    QVERIFY(session.stage());
    QCOMPARE(session.stage()->runtime().characters.size(), firstPointer->runtime().characters.size());

    auto second = demo();
    editor::Document* secondPointer = second.get();
    seen.clear();
    session.setDocument(std::move(second));
    // Detached from the first before it went, then shown the second.
    QCOMPARE(seen, (std::vector<editor::Document*>{nullptr, secondPointer}));
    QCOMPARE(changed.count(), 2);
    session.setDocument(nullptr);
    QVERIFY(!session.stage());
}

void SessionTest::aLiveActionPlaysOnThroughAnEdit()
{
    editor::PlaybackClock clock;
    editor::Session session(&clock);
    session.setDocument(demo());
    editor::Document& document = *session.document();
    const auto stage = session.stage();
    const std::string character = document.scenario().characters[0].name;
    const std::string action = document.scenario().characters[0].layers[0].actions[0].name;
    const core::Tick now = core::secondsToTicks(1.0);
    QVERIFY(stage->activateAction(character, core::runtime::Track::Body, action, now).ok());
    QVERIFY(*stage->isPlaying(character, core::runtime::Track::Body, action, now + 1));

    QSignalSpy edited(&session, &editor::Session::edited);
    const std::vector<core::edit::ActionPath> moved{{1, 0, 0}};
    QVERIFY(document.edit(core::edit::moveActions(document.scenario(), moved, core::TicksPerSecond / 2),
                          QStringLiteral("Move")).ok());
    QCOMPARE(edited.count(), 1);
    QCOMPARE(edited.first().at(0).toBool(), false); // the same stage
    QCOMPARE(session.stage(), stage);
    // The stage plays the edited schedules, and the live action still plays.
    const auto& runtime = session.stage()->runtime();
    QCOMPARE(runtime.characters[1].body, document.runtime().characters[1].body);
    QVERIFY(*stage->isPlaying(character, core::runtime::Track::Body, action, now + 1));
}

void SessionTest::anotherCastGetsANewStage()
{
    editor::PlaybackClock clock;
    editor::Session session(&clock);
    session.setDocument(demo());
    editor::Document& document = *session.document();
    const auto before = session.stage();
    QSignalSpy edited(&session, &editor::Session::edited);
    QVERIFY(document.edit(core::edit::duplicateCharacter(document.scenario(), 0), QStringLiteral("Duplicate")).ok());
    QCOMPARE(edited.count(), 1);
    QCOMPARE(edited.first().at(0).toBool(), true);
    QVERIFY(session.stage() != before);
    QCOMPARE(session.stage()->runtime().characters.size(), document.scenario().characters.size());
    document.undoStack()->undo();
    QCOMPARE(session.stage()->runtime().characters.size(), document.scenario().characters.size());
}

void SessionTest::aTickEvaluatesOnceAndPublishesTheStagesPoses()
{
    editor::PlaybackClock clock;
    editor::Session session(&clock);
    session.setDocument(demo());
    const auto stage = session.stage();
    // Scripts see the time before the evaluation, views get the poses after it.
    std::vector<std::string> order;
    connect(&session, &editor::Session::aboutToTick, &session, [&](core::Tick) { order.push_back("script"); });
    connect(&session, &editor::Session::posesChanged, &session, [&](const core::runtime::PoseSet&) { order.push_back("view"); });
    connect(&session, &editor::Session::posesChanged, &session, [&](const core::runtime::PoseSet&) { order.push_back("view"); });
    QVERIFY(stage->activateAction("Antigone", core::runtime::Track::Body, "nod", core::secondsToTicks(0.5)).ok());

    core::runtime::PoseSet expected = stage->makePoseSet(), mailed;
    std::uint64_t mailSeen = 0;
    for (const double t : {1.0, 1.5, 0.25, 3.0}) {
        order.clear();
        const std::uint64_t before = stage->ticks(), evaluations = session.evaluations();
        clock.seek(core::secondsToTicks(t));
        QCOMPARE(stage->ticks(), before + 1); // the stage evaluated once, by the session
        QCOMPARE(session.evaluations(), evaluations + 1);
        QCOMPARE(order, (std::vector<std::string>{"script", "view", "view"}));
        const core::runtime::PoseSet& shown = session.poses();
        QCOMPARE(shown.time, core::secondsToTicks(t));
        // Those are the stage's poses at that tick, the live action included ...
        core::runtime::Stage reference(stage->runtimeCopy());
        QVERIFY(reference.activateAction("Antigone", core::runtime::Track::Body, "nod", core::secondsToTicks(0.5)).ok());
        reference.evaluate(core::secondsToTicks(t), expected);
        for (std::size_t c = 0; c < expected.characters.size(); ++c)
            QCOMPARE(shown.characters[c].body, expected.characters[c].body);
        // ... and the mailbox holds the same for the AR renderer.
        mailSeen = session.mailbox()->takeNewer(mailed, mailSeen);
        QVERIFY(mailSeen > 0);
        QCOMPARE(mailed.time, shown.time);
        QCOMPARE(mailed.characters[1].body, shown.characters[1].body);
        if (t == 1.0) { // the nod shows: Antigone's pose differs from her authored one
            core::runtime::Stage authored(stage->runtimeCopy());
            authored.evaluate(core::secondsToTicks(t), expected);
            QVERIFY(shown.characters[1].body != expected.characters[1].body);
        }
    }
}

void SessionTest::anEditSetsTheRuntimeOnceAndShowsItAtOnce()
{
    editor::PlaybackClock clock;
    editor::Session session(&clock);
    session.setDocument(demo());
    editor::Document& document = *session.document();
    clock.seek(core::secondsToTicks(2.0));
    const auto stage = session.stage();
    const core::runtime::PoseSet before = session.poses();
    const std::uint64_t runtimes = session.runtimesSet(), evaluations = session.evaluations();
    QSignalSpy shown(&session, &editor::Session::posesChanged);
    // Creon's first action moved 1 s later: at 2 s he is somewhere else in it.
    const std::vector<core::edit::ActionPath> moved{{0, 0, 0}};
    QVERIFY(document.edit(core::edit::moveActions(document.scenario(), moved, core::TicksPerSecond), QStringLiteral("Move")).ok());
    QCOMPARE(session.runtimesSet(), runtimes + 1);
    QCOMPARE(session.evaluations(), evaluations + 1);
    QCOMPARE(shown.count(), 1);
    QCOMPARE(session.stage(), stage);
    QVERIFY(session.poses().characters[0].body != before.characters[0].body);
}

QTEST_MAIN(SessionTest)
#include "session_test.moc"
