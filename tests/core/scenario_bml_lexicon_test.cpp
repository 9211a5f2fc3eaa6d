// A character's own BML lexicon (format 12, Character::bmlLexicon): the golden file, the upgrade
// from version 11 (no table: the defaults), the reader naming what is wrong, the runtime's warning
// about a row naming no gesture, the edits that set a table or a row and take it back — and, on
// the demo, a row that makes Creon's <gesture lexeme="BEAT"> play his "greet" instead of "agree",
// both live (runtime::BmlRealizer) and put on the timeline (edit::insertBml).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "edit/bml_edits.h"
#include "edit/document_edits.h"
#include "edit/lexicon_edits.h"
#include "runtime/bml_performance.h"
#include "runtime/stage.h"
#include "scenario/scenario_io.h"
#include "scenario/scenario_runtime.h"
#include "scenario_formats.h"
#include "test_support.h"
#include "util/file_io.h"

namespace thespis::test {
namespace {

using namespace core::scenario;
using core::secondsToTicks;
using json = nlohmann::json;
using Rows = std::map<std::string, std::string>;
namespace edit = core::edit;
namespace runtime = core::runtime;
namespace speech = core::speech;

Scenario demo()
{
    auto loaded = loadScenario(resources("demo.thespis"));
    EXPECT_TRUE(loaded) << core::describe(loaded.error());
    return loaded ? std::move(loaded).value() : Scenario{};
}

// The demo with Creon's (character 0) BML lexicon row BEAT → greet, set by the edit the studio makes.
Scenario beatGreets()
{
    Scenario s = demo();
    auto set = edit::setBmlLexeme(s, 0, "beat", "greet");
    EXPECT_TRUE(set) << set.error().message;
    EXPECT_TRUE(set && set->apply(s));
    return s;
}

speech::BmlBlock block(const std::string& behaviours)
{
    auto parsed = speech::parseBml("<bml id=\"b\">" + behaviours + "</bml>");
    EXPECT_TRUE(parsed) << parsed.error().message;
    return parsed ? std::move(parsed).value() : speech::BmlBlock{};
}

// The gesture action insertBml puts on Creon's timeline for `behaviours` (one gesture), by name.
std::string insertedGesture(const Scenario& document, const std::string& behaviours,
                            edit::BmlInsertOptions options = edit::BmlInsertOptions())
{
    auto built = buildRuntime(document, resources());
    EXPECT_TRUE(built) << core::describe(built.error());
    if (!built)
        return {};
    auto inserted = edit::insertBml(document, *built, 0, block(behaviours), {}, options, secondsToTicks(1.0));
    if (!inserted)
        return std::string("error: ").append(inserted.error().message);
    Scenario after = document;
    EXPECT_TRUE(inserted->edit.apply(after));
    const ActionSpec& action = after.characters[0].layers.back().actions.back();
    return action.name + " (" + action.clip + ")";
}

// Creon's body, live, half way through `behaviours` played from 1 s by the realizer on a Stage of
// `document`, and when the block ends.
struct Played {
    std::vector<float> body;
    double end = 0;
};
Played playedLive(const Scenario& document, const std::string& behaviours, const runtime::BmlOptions& options = {})
{
    auto built = buildRuntime(document, resources());
    EXPECT_TRUE(built) << core::describe(built.error());
    auto stage = std::make_shared<runtime::Stage>(std::move(built).value());
    runtime::BmlRealizer realizer(stage, nullptr);
    auto performed = realizer.perform("Creon", block(behaviours), options, secondsToTicks(1.0));
    EXPECT_TRUE(performed) << performed.error().message;
    if (!performed)
        return {};
    runtime::PoseSet poses = stage->makePoseSet();
    stage->evaluate(secondsToTicks(0.5 * (performed->start + performed->end)), poses);
    return {poses.characters[0].body, performed->end};
}

constexpr const char* kBeat = "<gesture id=\"g1\" lexeme=\"BEAT\"/>";

} // namespace

TEST(ScenarioBmlLexicon, TheGoldenFileKeepsOwnTablesAndVersion11HasTheDefaults)
{
    const Scenario v12 = goldenScenario(12);
    ASSERT_EQ(v12.characters.size(), 2u);
    EXPECT_EQ(v12.characters[0].bmlLexicon, (Rows{{"BEAT", "stroll"}, {"WAVE", "greet"}}));
    ASSERT_TRUE(v12.characters[1].bmlLexicon) << "an empty table is a table: no rows, not the defaults";
    EXPECT_TRUE(v12.characters[1].bmlLexicon->empty());
    // Version 11 is version 12 without the tables: every character has the defaults.
    Scenario v11 = goldenScenario(11);
    Scenario stripped = v12;
    for (Character& c : stripped.characters)
        c.bmlLexicon.reset();
    EXPECT_EQ(v11, stripped);
    // As the runtime keeps them: the own ones (upper case), the defaults without one, none for an empty one.
    EXPECT_EQ(speech::BmlLexicon::of(v12.characters[0].bmlLexicon).entryFor("beat", {"greet", "stroll"}), "stroll");
    EXPECT_EQ(speech::BmlLexicon::of(v12.characters[1].bmlLexicon).entryFor("BEAT", {"agree"}), "");
    EXPECT_EQ(speech::BmlLexicon::of(v11.characters[0].bmlLexicon).gestures, speech::BmlLexicon::defaults().gestures);
}

TEST(ScenarioBmlLexicon, TheReaderNamesTheFieldThatIsWrong)
{
    const json doc = json::parse(core::readTextFile(testData("formats/v12/scenario.thespis")).value());
    json notObject = doc;
    notObject["characters"][0]["bmlLexicon"] = json::array({"BEAT"});
    EXPECT_NE(refusedScenario(notObject).find("characters[0].bmlLexicon: expected an object of BML lexemes and gesture names"),
              std::string::npos)
        << refusedScenario(notObject);
    json number = doc;
    number["characters"][0]["bmlLexicon"]["BEAT"] = 3;
    EXPECT_NE(refusedScenario(number).find("characters[0].bmlLexicon.BEAT: expected the name of a gesture"), std::string::npos)
        << refusedScenario(number);
    json emptyEntry = doc;
    emptyEntry["characters"][1]["bmlLexicon"]["NOD"] = "";
    EXPECT_NE(refusedScenario(emptyEntry).find("characters[1].bmlLexicon.NOD: expected the name of a gesture"),
              std::string::npos)
        << refusedScenario(emptyEntry);
    json emptyLexeme = doc;
    emptyLexeme["characters"][0]["bmlLexicon"][""] = "greet";
    EXPECT_NE(refusedScenario(emptyLexeme).find("characters[0].bmlLexicon: a lexeme must not be empty"), std::string::npos)
        << refusedScenario(emptyLexeme);
    json twice = doc;
    twice["characters"][0]["bmlLexicon"]["beat"] = "greet";
    EXPECT_NE(refusedScenario(twice).find("characters[0].bmlLexicon.beat: the lexeme \"BEAT\" is the same in another case"),
              std::string::npos)
        << refusedScenario(twice);
}

TEST(ScenarioBmlLexicon, ARowNamingNoGestureIsAWarningNotAnError)
{
    Scenario s = demo();
    s.characters[0].bmlLexicon = Rows{{"BEAT", "juggle"}, {"WAVE", "greet"}};
    auto built = buildRuntime(s, resources());
    ASSERT_TRUE(built) << core::describe(built.error());
    const auto& warnings = built->characters[0].warnings;
    EXPECT_NE(std::find(warnings.begin(), warnings.end(),
                        "Character \"Creon\", BML lexicon, BEAT: the character has no gesture named \"juggle\" to "
                        "play it."),
              warnings.end());
    EXPECT_EQ(std::count_if(warnings.begin(), warnings.end(),
                            [](const std::string& w) { return w.find("BML lexicon") != std::string::npos; }),
              1);
    // BML then says that nothing plays BEAT, with the behaviour's place.
    const std::string error = insertedGesture(s, kBeat);
    EXPECT_EQ(error.rfind("error: line 1, column ", 0), 0u) << error;
    EXPECT_NE(error.find("no gesture for \"BEAT\""), std::string::npos) << error;
}

TEST(ScenarioBmlLexicon, TheEditsSetARowOrTheTableAndTheirInverseTakesItBack)
{
    const Scenario original = demo();
    ASSERT_FALSE(original.characters[0].bmlLexicon);
    EXPECT_EQ(edit::bmlLexiconRows(original.characters[1]), (Rows{{"AGREE", "agree"}, {"BEAT", "agree"}, {"NOD", "agree"}}))
        << "Antigone has only 'agree': the defaults' other rows could not play";

    // One row: the character gets its own table (the defaults it can play, with the row).
    auto row = edit::setBmlLexeme(original, 0, "beat", "greet");
    ASSERT_TRUE(row) << row.error().message;
    EXPECT_EQ(row->runtimeScope().characters, std::vector<int>{0});
    Scenario s = original;
    ASSERT_TRUE(row->apply(s));
    EXPECT_EQ(s.characters[0].bmlLexicon, (Rows{{"AGREE", "agree"}, {"BEAT", "greet"}, {"GREET", "greet"},
                                               {"NOD", "agree"}, {"POINT", "point"}, {"WAVE", "greet"}}));
    ASSERT_TRUE(row->inverse().apply(s));
    EXPECT_EQ(s, original);

    // Refused: a gesture the character lacks, two lexemes the same, an empty lexeme, no row to remove.
    EXPECT_FALSE(edit::setBmlLexeme(original, 0, "BEAT", "juggle"));
    EXPECT_FALSE(edit::setBmlLexicon(original, 0, Rows{{"beat", "greet"}, {"BEAT", "agree"}}));
    EXPECT_FALSE(edit::setBmlLexicon(original, 0, Rows{{"", "greet"}}));
    EXPECT_FALSE(edit::setBmlLexeme(original, 0, "SHRUG", std::nullopt));
    EXPECT_FALSE(edit::setBmlLexicon(original, 7, std::nullopt));

    // A whole table, then back to the defaults; a rename of a row; each undoes.
    auto table = edit::setBmlLexicon(original, 0, Rows{{"shrug", "agree"}});
    ASSERT_TRUE(table) << table.error().message;
    ASSERT_TRUE(table->apply(s));
    EXPECT_EQ(s.characters[0].bmlLexicon, (Rows{{"SHRUG", "agree"}}));
    auto rename = edit::renameBmlLexeme(s, 0, "shrug", "Beat");
    ASSERT_TRUE(rename) << rename.error().message;
    Scenario renamed = s;
    ASSERT_TRUE(rename->apply(renamed));
    EXPECT_EQ(renamed.characters[0].bmlLexicon, (Rows{{"BEAT", "agree"}}));
    ASSERT_TRUE(rename->inverse().apply(renamed));
    EXPECT_EQ(renamed, s);
    auto reset = edit::setBmlLexicon(s, 0, std::nullopt);
    ASSERT_TRUE(reset);
    ASSERT_TRUE(reset->apply(s));
    EXPECT_EQ(s, original);

    // A row whose gesture went keeps it through other changes; a renamed gesture takes its rows along.
    Scenario kept = beatGreets();
    (*kept.characters[0].bmlLexicon)["WAVE"] = "gone";
    EXPECT_TRUE(edit::setBmlLexeme(kept, 0, "NOD", "point")) << "WAVE → gone was there already";
    Gesture greet = *kept.characters[0].findGesture("greet");
    greet.name = "hail";
    auto renamedGesture = edit::replaceGesture(kept, {0, 0}, greet);
    ASSERT_TRUE(renamedGesture) << renamedGesture.error().message;
    ASSERT_TRUE(renamedGesture->apply(kept));
    EXPECT_EQ(kept.characters[0].bmlLexicon->at("BEAT"), "hail");
    EXPECT_EQ(kept.characters[0].bmlLexicon->at("GREET"), "hail");
    EXPECT_EQ(kept.characters[0].bmlLexicon->at("WAVE"), "gone");

    // On the defaults, a renamed gesture keeps its lexemes too: BEAT still nods.
    Scenario defaults = demo();
    Gesture agree = *defaults.characters[0].findGesture("agree");
    const int index = int(defaults.characters[0].findGesture("agree") - defaults.characters[0].gestures.data());
    agree.name = "assent";
    auto renamedDefault = edit::replaceGesture(defaults, {0, index}, agree);
    ASSERT_TRUE(renamedDefault) << renamedDefault.error().message;
    ASSERT_TRUE(renamedDefault->apply(defaults));
    ASSERT_TRUE(defaults.characters[0].bmlLexicon);
    EXPECT_EQ(defaults.characters[0].bmlLexicon->at("BEAT"), "assent");
    EXPECT_EQ(defaults.characters[0].bmlLexicon->at("WAVE"), "greet");
    EXPECT_EQ(insertedGesture(defaults, kBeat), "g1 assent (nod)");
    ASSERT_TRUE(renamedDefault->inverse().apply(defaults));
    EXPECT_EQ(defaults, demo());
}

TEST(ScenarioBmlLexicon, ARowChangesTheGestureInsertBmlPutsOnTheTimeline)
{
    EXPECT_EQ(insertedGesture(demo(), kBeat), "g1 agree (nod)") << "the defaults: BEAT plays agree";
    const Scenario own = beatGreets();
    EXPECT_EQ(insertedGesture(own, kBeat), "g1 greet (wave)");
    // Saved and read back, the row still holds.
    auto read = parseScenario(serializeScenario(own));
    ASSERT_TRUE(read) << core::describe(read.error());
    EXPECT_EQ(insertedGesture(*read, kBeat), "g1 greet (wave)");
    // A row redirects even a lexeme that names a gesture; a lexicon given to insertBml wins.
    Scenario pointGreets = demo();
    ASSERT_TRUE(edit::setBmlLexeme(pointGreets, 0, "POINT", "greet")->apply(pointGreets));
    EXPECT_EQ(insertedGesture(pointGreets, "<gesture id=\"g1\" lexeme=\"POINT\"/>"), "g1 greet (wave)");
    edit::BmlInsertOptions given;
    given.lexicon = speech::BmlLexicon::defaults();
    EXPECT_EQ(insertedGesture(own, kBeat, given), "g1 agree (nod)");
    // Without its row (removed), BEAT names no gesture of Creon.
    Scenario removed = own;
    ASSERT_TRUE(edit::setBmlLexeme(removed, 0, "BEAT", std::nullopt)->apply(removed));
    EXPECT_EQ(insertedGesture(removed, kBeat).rfind("error:", 0), 0u) << insertedGesture(removed, kBeat);
}

TEST(ScenarioBmlLexicon, ARowChangesTheGestureTheLiveRealizerPlays)
{
    const Played agree = playedLive(demo(), kBeat);
    const Played greet = playedLive(demo(), "<gesture id=\"g1\" lexeme=\"GREET\"/>");
    ASSERT_NE(agree.body, greet.body) << "the two entries must look different for this test to tell them apart";
    const Played own = playedLive(beatGreets(), kBeat);
    EXPECT_EQ(own.end, greet.end);
    EXPECT_EQ(own.body, greet.body) << "Creon's BEAT → greet plays greet";
    EXPECT_NE(own.body, agree.body);
    // A lexicon given to the realizer wins over the character's.
    runtime::BmlOptions given;
    given.lexicon = speech::BmlLexicon::defaults();
    EXPECT_EQ(playedLive(beatGreets(), kBeat, given).body, agree.body);
}

} // namespace thespis::test
