// The edits that bring content into a scenario (core/edit/content_edits.h): each change applies,
// builds, and its inverse gives the document back exactly; refusals say why and change nothing.

#include <gtest/gtest.h>

#include "edit/content_edits.h"
#include "edit/document_edits.h"
#include "scenario/scenario_runtime.h"
#include "test_support.h"

namespace thespis::core::edit {
namespace {

using namespace scenario;

// Applies `made` to a copy of `s`, checks that the result builds and that the inverse gives `s`
// back exactly.
void expectRoundTrip(const Scenario& s, const Result<Edit>& made)
{
    ASSERT_TRUE(made.ok()) << describe(made.error());
    Scenario changed = s;
    ASSERT_TRUE(made->apply(changed).ok());
    EXPECT_NE(changed, s);
    auto built = buildRuntime(changed, test::sharedData());
    EXPECT_TRUE(built.ok()) << describe(built.error());
    ASSERT_TRUE(made->inverse().apply(changed).ok());
    EXPECT_EQ(changed, s);
}

Scenario withWalker()
{
    Scenario s;
    s.name = "content";
    EXPECT_TRUE(addCharacter(s, newCharacter("", "", "hanim-loa1"))->apply(s).ok());
    ClipAsset walk;
    walk.name = "walk";
    walk.file = "mocap/cmu/02_01.bvh";
    EXPECT_TRUE(addClips(s, 0, {walk})->apply(s).ok());
    auto action = actionFromClip(s, {0, 0}, "walk", 0);
    EXPECT_TRUE(insertActions(s, {0, 0}, {*action})->apply(s).ok());
    return s;
}

TEST(ContentEdits, CharactersComeAndGo)
{
    Scenario s = withWalker();
    EXPECT_EQ(s.characters[0].name, "Actor");
    EXPECT_EQ(s.characters[0].layers[0].actions[0].placement, Placement::Continue);
    expectRoundTrip(s, addCharacter(s, newCharacter("Actor", "characters/CesiumMan/CesiumMan.glb", "model")));
    ASSERT_TRUE(addCharacter(s, newCharacter("Actor", "", "hanim-25"))->apply(s).ok());
    EXPECT_EQ(s.characters[1].name, "Actor 2");
    expectRoundTrip(s, renameCharacter(s, 1, "Ismene"));
    expectRoundTrip(s, duplicateCharacter(s, 0));
    auto copy = duplicateCharacter(s, 0);
    ASSERT_TRUE(copy->apply(s).ok());
    EXPECT_EQ(s.characters.back().name, "Actor 3");
    EXPECT_EQ(s.characters.back().position.x, 1.0f); // a metre to its right
    expectRoundTrip(s, setCharacterPlacement(s, 0, {1.0f, 0.0f, 2.0f}, 45.0));
    expectRoundTrip(s, removeCharacter(s, 1));
    EXPECT_FALSE(renameCharacter(s, 1, "Actor").ok());
    EXPECT_FALSE(renameCharacter(s, 7, "Nobody").ok());
}

TEST(ContentEdits, ANewModelDropsTheOldOnesTagsAndBake)
{
    Scenario s = withWalker();
    s.characters[0].segmentTags = {{"hair", scene::SegmentRole::Receiver}};
    s.characters[0].bake = "bakes/old.prt";
    auto body = setCharacterBody(s, 0, "characters/CesiumMan/CesiumMan.glb", "model");
    ASSERT_TRUE(body.ok());
    ASSERT_TRUE(body->apply(s).ok());
    EXPECT_TRUE(s.characters[0].segmentTags.empty());
    EXPECT_TRUE(s.characters[0].bake.empty());
    EXPECT_TRUE(buildRuntime(s, test::sharedData()).ok());
    EXPECT_FALSE(setCharacterBody(s, 0, "", "model").ok());
    EXPECT_FALSE(setCharacterBody(s, 0, "", "hanim-loa9").ok());
}

TEST(ContentEdits, LayersAddRenameMoveRemove)
{
    Scenario s = withWalker();
    expectRoundTrip(s, addLayer(s, 0, "body", LayerKind::Body));
    ASSERT_TRUE(addLayer(s, 0, "body", LayerKind::Body)->apply(s).ok());
    EXPECT_EQ(s.characters[0].layers.back().name, "body 2");
    expectRoundTrip(s, renameLayer(s, {0, 2}, "gestures"));
    EXPECT_FALSE(renameLayer(s, {0, 2}, "face").ok());
    auto moved = moveLayer(s, {0, 2}, -1);
    expectRoundTrip(s, moved);
    ASSERT_TRUE(moved->apply(s).ok());
    EXPECT_EQ(s.characters[0].layers[1].name, "body 2");
    EXPECT_FALSE(moveLayer(s, {0, 0}, -1).ok());
    s.characters[0].layers[1].lock = true;
    EXPECT_FALSE(removeLayer(s, {0, 1}).ok());
    expectRoundTrip(s, removeLayer(s, {0, 2}));
}

TEST(ContentEdits, ClipsRenameWithTheirUsersAndAreNotRemovedWhileUsed)
{
    Scenario s = withWalker();
    ClipAsset renamed = s.characters[0].clips[0];
    renamed.name = "stroll";
    renamed.unit = 0.0564;
    auto rename = replaceClip(s, {0, 0}, renamed);
    expectRoundTrip(s, rename);
    ASSERT_TRUE(rename->apply(s).ok());
    EXPECT_EQ(s.characters[0].layers[0].actions[0].clip, "stroll");
    auto refused = removeClip(s, {0, 0});
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().message.find("still used by action \"walk\""), std::string::npos) << refused.error().message;
    ASSERT_TRUE(removeActions(s, std::vector<ActionPath>{{0, 0, 0}})->apply(s).ok());
    expectRoundTrip(s, removeClip(s, {0, 0}));
}

TEST(ContentEdits, IdleGoesOnABodyLayerWithTheCharactersOwnClip)
{
    Scenario s = withWalker();
    const std::string database = std::string(THESPIS_RESOURCES) + "/motion/cmu_standing.idle";
    // The first drop adds the clip and the action in one edit; it builds and undoes exactly.
    auto first = addIdleAction(s, {0, 0}, database, 3 * TicksPerSecond);
    expectRoundTrip(s, first);
    ASSERT_TRUE(first->apply(s).ok());
    const ClipAsset& clip = s.characters[0].clips.back();
    ASSERT_TRUE(clip.idle);
    EXPECT_EQ(clip.name, "idle");
    EXPECT_EQ(clip.idle->database, database);
    EXPECT_EQ(s.characters[0].layers[0].actions.back().clip, "idle");
    EXPECT_EQ(s.characters[0].layers[0].actions.back().start, 3 * TicksPerSecond);
    const auto runtime = buildRuntime(s, test::sharedData());
    ASSERT_TRUE(runtime.ok()) << describe(runtime.error());
    const auto span = actionSpan(s, *runtime, {0, 0, 1});
    ASSERT_TRUE(span.has_value());
    EXPECT_TRUE(span->openEnded);
    // The next drop plays the same clip: no second "idle 2".
    const std::size_t clips = s.characters[0].clips.size();
    ASSERT_TRUE(addIdleAction(s, {0, 0}, database, 20 * TicksPerSecond)->apply(s).ok());
    EXPECT_EQ(s.characters[0].clips.size(), clips);
    EXPECT_EQ(s.characters[0].layers[0].actions.back().clip, "idle");
    // Refused: a face layer, no database.
    auto face = addIdleAction(s, {0, 1}, database, 0);
    ASSERT_FALSE(face.ok());
    EXPECT_NE(face.error().message.find("body layer"), std::string::npos) << face.error().message;
    EXPECT_FALSE(addIdleAction(s, {0, 0}, "", 0).ok());
}

TEST(ContentEdits, TheLight)
{
    Scenario s = withWalker();
    LightingSpec light;
    light.probe = "probes/polyhaven_1k/venice_sunset_1k.hdr";
    light.rotation = 120;
    light.intensity = 0.8;
    expectRoundTrip(s, setLighting(s, light));
    light.layout = "fisheye";
    EXPECT_FALSE(setLighting(s, light).ok());
    light.layout = "latlong";
    light.intensity = -1;
    EXPECT_FALSE(setLighting(s, light).ok());
}

TEST(ContentEdits, ScriptsAddReplaceRemove)
{
    Scenario s;
    expectRoundTrip(s, setScript(s, "greet", "print('hello')\n"));
    ASSERT_TRUE(setScript(s, "greet", "print('hello')\n")->apply(s).ok());
    ASSERT_EQ(s.scripts.size(), 1u);
    expectRoundTrip(s, setScript(s, "greet", "print('bye')\n")); // replaces the source
    ASSERT_TRUE(setScript(s, "greet", "print('bye')\n")->apply(s).ok());
    EXPECT_EQ(s.scripts.size(), 1u);
    EXPECT_EQ(s.findScript("greet")->source, "print('bye')\n");
    expectRoundTrip(s, removeScript(s, "greet"));
    EXPECT_FALSE(setScript(s, "", "pass").ok());
    auto missing = removeScript(s, "other");
    ASSERT_FALSE(missing.ok());
    EXPECT_EQ(missing.error().code, ErrorCode::NotFound);
}

} // namespace
} // namespace thespis::core::edit
