// Gaze layers in the scenario (format 10, scenario.h's GazeSpec): the golden file, the upgrade from
// version 9, the reader and the runtime naming what is wrong, the edits that add and change a
// gaze, and the Stage turning the head from the action's start and letting go at its end.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "edit/document_edits.h"
#include "edit/gaze_edits.h"
#include "runtime/stage.h"
#include "scenario/scenario_io.h"
#include "scenario/scenario_runtime.h"
#include "scenario_formats.h"
#include "test_support.h"
#include "util/file_io.h"

namespace thespis::test {
namespace {

using namespace core::scenario;
using core::ErrorCode;
using json = nlohmann::json;

json goldenJson()
{
    return json::parse(core::readTextFile(testData("formats/v10/scenario.thespis")).value());
}

// The demo with Creon looking at Antigone from 1 s for 2.5 s (edit::addGaze, as the studio's
// Add Gaze at Playhead does).
Scenario demoWithGaze()
{
    Scenario demo = loadScenario(resources("demo.thespis")).value();
    auto added = core::edit::addGaze(demo, 0, GazeSpec{"Antigone", "SHOULDER", 5, "LEFT"}, core::secondsToTicks(1), 2.5);
    EXPECT_TRUE(added) << added.error().message;
    EXPECT_TRUE(added->apply(demo));
    return demo;
}

ActionSpec& lookOf(Scenario& demo) { return demo.characters[0].layers.back().actions[0]; }

// The problem buildRuntime() finds in `scenario`.
std::string runtimeProblem(const Scenario& scenario)
{
    auto built = buildRuntime(scenario, resources());
    EXPECT_FALSE(built);
    return built ? std::string() : built.error().message;
}

} // namespace

TEST(ScenarioGaze, TheGoldenFileHasAGazeLayerLookingAtTheOtherCharacter)
{
    const Scenario s = goldenScenario(10);
    ASSERT_EQ(s.characters.size(), 2u);
    const Layer& layer = s.characters[1].layers.back();
    EXPECT_EQ(layer.kind, LayerKind::Gaze);
    ASSERT_EQ(layer.actions.size(), 1u);
    const ActionSpec& look = layer.actions[0];
    ASSERT_TRUE(look.gaze);
    EXPECT_EQ(look.gaze->target, "Mocap");
    EXPECT_EQ(look.gaze->influence, "SHOULDER");
    EXPECT_EQ(look.gaze->offsetAngle, 5.0);
    EXPECT_EQ(look.gaze->offsetDirection, "LEFT");
    EXPECT_TRUE(look.clip.empty());
    // Version 9 reads as before: nothing in it looks anywhere.
    for (const Character& c : goldenScenario(9).characters)
        for (const Layer& l : c.layers) {
            EXPECT_NE(l.kind, LayerKind::Gaze);
            for (const ActionSpec& a : l.actions)
                EXPECT_FALSE(a.gaze);
        }
}

TEST(ScenarioGaze, TheReaderNamesTheFieldThatIsWrong)
{
    json doc = goldenJson();
    json& action = doc["characters"][1]["layers"][2]["actions"][0];
    json noTarget = doc;
    noTarget["characters"][1]["layers"][2]["actions"][0]["gaze"].erase("target");
    EXPECT_NE(refusedScenario(noTarget).find("characters[1].layers[2].actions[0].gaze.target: this field is required"),
              std::string::npos)
        << refusedScenario(noTarget);
    json unknown = doc;
    unknown["characters"][1]["layers"][2]["actions"][0]["gaze"]["blink"] = true;
    EXPECT_NE(refusedScenario(unknown).find("gaze.blink: unknown member of a gaze"), std::string::npos);
    json noClip = doc;
    noClip["characters"][1]["layers"][2]["actions"][0].erase("gaze");
    EXPECT_NE(refusedScenario(noClip).find("actions[0].clip: this field is required"), std::string::npos);
    EXPECT_TRUE(action.contains("gaze"));
}

TEST(ScenarioGaze, TheRuntimeNamesAGazeThatCannotPlay)
{
    const Scenario s = demoWithGaze();
    Scenario nobody = s;
    lookOf(nobody).gaze->target = "Ismene";
    EXPECT_NE(runtimeProblem(nobody).find("action \"look at Antigone\", gaze.target: the scenario has no character "
                                          "named \"Ismene\""),
              std::string::npos)
        << runtimeProblem(nobody);
    Scenario influence = s;
    lookOf(influence).gaze->influence = "KNEES";
    EXPECT_NE(runtimeProblem(influence).find("gaze.influence"), std::string::npos);
    Scenario direction = s;
    lookOf(direction).gaze->offsetDirection = "SIDEWAYS";
    EXPECT_NE(runtimeProblem(direction).find("gaze.offsetDirection"), std::string::npos);
    Scenario onBody = s;
    onBody.characters[0].layers[0].actions[0].gaze = GazeSpec{};
    EXPECT_NE(runtimeProblem(onBody).find("gaze: only an action of a gaze layer looks at something"), std::string::npos);
}

TEST(ScenarioGaze, TheStageLooksFromTheActionsStartAndLetsGoAtItsEnd)
{
    Scenario s = demoWithGaze();
    auto built = buildRuntime(s, resources());
    ASSERT_TRUE(built) << core::describe(built.error());
    ASSERT_EQ(built->characters[0].gaze.size(), 1u);
    const GazeCue& cue = built->characters[0].gaze[0];
    EXPECT_DOUBLE_EQ(cue.start, 1.0);
    EXPECT_NEAR(cue.end, 3.5, 1e-9);
    EXPECT_EQ(cue.target.kind, core::motion::GazeTarget::Kind::Joint);
    EXPECT_EQ(cue.target.character, "Antigone");
    EXPECT_EQ(cue.settings.influence, core::motion::GazeInfluence::Shoulder);
    EXPECT_NE(cue.settings.offsetHeading, 0.0);

    core::runtime::Stage stage(*built);
    core::runtime::PoseSet poses = stage.makePoseSet();
    const auto lookingAt = [&](double t) {
        stage.evaluate(core::secondsToTicks(t), poses);
        auto state = stage.gazeState("Creon").value();
        return state && !state->released;
    };
    EXPECT_FALSE(lookingAt(0.9));
    EXPECT_TRUE(lookingAt(1.1));
    EXPECT_TRUE(lookingAt(3.4));
    EXPECT_FALSE(lookingAt(3.6));
    // Scrubbing back into it looks again; a new runtime with the layer muted does not.
    EXPECT_TRUE(lookingAt(2.0));
    s.characters[0].layers.back().mute = true;
    auto muted = buildRuntime(s, resources());
    ASSERT_TRUE(muted);
    EXPECT_TRUE(muted->characters[0].gaze.empty());
    ASSERT_TRUE(stage.setRuntime(*muted));
    EXPECT_FALSE(lookingAt(2.1));
}

TEST(ScenarioGaze, AddingAndChangingAGazeAreUndoableEdits)
{
    Scenario s = goldenScenario(9);
    auto added = core::edit::addGaze(s, 0, GazeSpec{"camera"}, core::secondsToTicks(1), 2.5);
    ASSERT_TRUE(added) << added.error().message;
    Scenario after = s;
    ASSERT_TRUE(added->apply(after));
    const Layer& layer = after.characters[0].layers.back();
    EXPECT_EQ(layer.name, "Gaze");
    EXPECT_EQ(layer.kind, LayerKind::Gaze);
    ASSERT_EQ(layer.actions.size(), 1u);
    EXPECT_EQ(layer.actions[0].gaze->target, "camera");
    const core::edit::ActionPath path{0, int(after.characters[0].layers.size()) - 1, 0};
    ActionSpec changed = layer.actions[0];
    changed.gaze->target = "Inline:l_radiocarpal";
    auto replaced = core::edit::replaceAction(after, path, changed);
    ASSERT_TRUE(replaced) << replaced.error().message;
    Scenario changedScenario = after;
    ASSERT_TRUE(replaced->apply(changedScenario));
    EXPECT_EQ(changedScenario.characters[0].layers.back().actions[0].gaze->target, "Inline:l_radiocarpal");
    changed.gaze.reset();
    EXPECT_FALSE(core::edit::replaceAction(after, path, changed));

    Scenario undone = after;
    ASSERT_TRUE(added->inverse().apply(undone));
    EXPECT_EQ(undone, s);
    EXPECT_FALSE(core::edit::addGaze(s, 5, GazeSpec{}, 0, 1));
    EXPECT_FALSE(core::edit::addGaze(s, 0, GazeSpec{}, 0, 0));
}

} // namespace thespis::test
