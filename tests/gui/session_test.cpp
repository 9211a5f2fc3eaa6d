// editor::Session: views registered once follow every document (detached from the old one before
// it goes), and the session's stage follows edits — the same stage, with a live action playing
// on, when an action moves; a stage of the new cast when a character is added. On the demo.

#include <QSignalSpy>
#include <QTest>
#include <QUndoStack>

#include <memory>
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

QTEST_MAIN(SessionTest)
#include "session_test.moc"
