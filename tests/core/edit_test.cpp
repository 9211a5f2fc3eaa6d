// Edits: apply / inverse round trips for every kind of change, refusal of edits that do not fit,
// merging of a drag's steps, and the document edits (move, trim, fade, split, ripple delete,
// markers, layer flags, masks, gestures, segment tags) checked against the evaluated motion.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "anim/quat.h"
#include "edit/document_edits.h"
#include "edit/scenario_edit.h"
#include "scenario/scenario_io.h"
#include "scenario/scenario_runtime.h"
#include "test_support.h"

using namespace thespis::core;
using namespace thespis::core::edit;
using namespace thespis::core::scenario;

namespace {

constexpr Tick Second = TicksPerSecond;

// One character whose right arm swings 0 → 90° over a 2 s clip ("swing", 10 frames per second,
// angle linear in time), played by actions on one body layer with a constant weight.
Scenario swingScenario(std::vector<Tick> starts = {0})
{
    Scenario s;
    s.name = "swing";
    Character c;
    c.name = "A";
    c.skeleton = "hanim-25";
    ClipAsset clip;
    clip.name = "swing";
    clip.frameRate = 10;
    clip.joints = {"r_shoulder"};
    for (int f = 0; f <= 20; ++f) {
        const double half = 0.5 * (f / 20.0) * std::numbers::pi / 2;
        clip.frames.insert(clip.frames.end(), {0.f, 0.f, float(std::sin(half)), float(std::cos(half))});
    }
    c.clips.push_back(clip);
    Layer body;
    body.name = "body";
    for (std::size_t i = 0; i < starts.size(); ++i) {
        ActionSpec a;
        a.name = "swing " + std::to_string(i + 1);
        a.clip = "swing";
        a.start = starts[i];
        body.actions.push_back(a);
    }
    c.layers.push_back(body);
    s.characters.push_back(c);
    NamedMask arm;
    arm.name = "arm";
    arm.mask = anim::JointMask({{"r_shoulder", 1.0f}});
    s.masks.push_back(arm);
    return s;
}

ScenarioRuntime runtimeOf(const Scenario& s)
{
    auto built = buildRuntime(s, thespis::test::testData());
    EXPECT_TRUE(built.ok()) << built.error().message;
    return built ? std::move(built).value() : ScenarioRuntime{};
}

// The right shoulder's angle (degrees) the layer plays at `seconds`.
double shoulderDegrees(const Scenario& s, double seconds)
{
    const ScenarioRuntime runtime = runtimeOf(s);
    const CharacterRuntime& c = runtime.characters.at(0);
    std::vector<float> frame(c.body->layout()->floatCount());
    c.body->evaluate(seconds, frame);
    const int joint = c.skeleton.find("r_shoulder");
    const anim::Quat& q = anim::rotationAt(std::span<const float>(frame), joint);
    return 2 * std::atan2(std::hypot(q.x, q.y, q.z), std::abs(q.w)) * 180 / std::numbers::pi;
}

Edit applied(Scenario& s, Result<Edit> edit)
{
    EXPECT_TRUE(edit.ok()) << (edit ? "" : edit.error().message);
    if (!edit)
        return {};
    auto ok = edit->apply(s);
    EXPECT_TRUE(ok.ok()) << (ok ? "" : ok.error().message);
    return *edit;
}

// Applies, checks the inverse restores the original exactly, and re-applies.
void expectRoundTrip(Scenario& s, const Edit& edit)
{
    const Scenario before = s;
    ASSERT_TRUE(edit.apply(s).ok());
    const Scenario after = s;
    ASSERT_TRUE(edit.inverse().apply(s).ok());
    EXPECT_EQ(s, before);
    ASSERT_TRUE(edit.apply(s).ok());
    EXPECT_EQ(s, after);
}

} // namespace

TEST(Edit, EveryKindOfChangeRoundTrips)
{
    Scenario s = loadScenario(thespis::test::resources("demo.thespis")).value();
    const Scenario original = s;
    {
        auto e = moveActions(s, std::vector<ActionPath>{{0, 0, 1}, {0, 0, 2}}, Second / 2);
        ASSERT_TRUE(e.ok());
        expectRoundTrip(s, *e);
    }
    expectRoundTrip(s, *setLayerFlag(s, {0, 1}, LayerFlag::Mute, true));
    expectRoundTrip(s, *addMarker(s, Marker{"cue", 3 * Second, {}}));
    expectRoundTrip(s, *removeMarker(s, 0));
    expectRoundTrip(s, *setMaskWeights(s, 0, std::vector<std::string>{"vt1", "vl5"}, 0.5f));
    expectRoundTrip(s, *addMask(s, "legs", anim::JointMask::preset(anim::MaskPreset::LowerBody)));
    expectRoundTrip(s, *renameMask(s, 0, "neck and head"));
    expectRoundTrip(s, *addGesture(s, 1, Gesture{"wave hello", "wave", "leftArm", Second / 4, Second / 4, true}));
    expectRoundTrip(s, *removeGesture(s, {0, 0}));
    scene::SegmentTag tag{"l_hand", scene::SegmentRole::Receiver};
    expectRoundTrip(s, *setSegmentTags(s, 0, {tag}));
    expectRoundTrip(s, *setCharacterBake(s, 1, "bakes/demo-Antigone-dsm-o5-0123abcd.prt"));
    EXPECT_EQ(s.characters[1].bake, "bakes/demo-Antigone-dsm-o5-0123abcd.prt");
    {
        auto action = actionFromClip(s, {1, 0}, "nod", 2 * Second);
        ASSERT_TRUE(action.ok());
        expectRoundTrip(s, *insertActions(s, {1, 0}, {*action}));
    }
    expectRoundTrip(s, *removeActions(s, std::vector<ActionPath>{{1, 0, 1}}));
    // The inverse of everything done, in reverse order, gives the original back.
    EXPECT_NE(s, original);
}

TEST(Edit, RefusesWhatDoesNotFitAndLeavesTheDocumentAsItWas)
{
    Scenario s = swingScenario({0, 3 * Second});
    auto move = moveActions(s, std::vector<ActionPath>{{0, 0, 0}, {0, 0, 1}}, Second);
    ASSERT_TRUE(move.ok());
    // Someone changed the second action meanwhile: the whole edit is refused, nothing applied.
    Scenario changed = s;
    changed.characters[0].layers[0].actions[1].name = "renamed";
    const Scenario snapshot = changed;
    auto result = move->apply(changed);
    ASSERT_FALSE(result.ok());
    EXPECT_NE(result.error().message.find("not what the edit expects"), std::string::npos) << result.error().message;
    EXPECT_EQ(changed, snapshot);

    Edit outOfRange(ActionChange{{0, 0, 7}, s.characters[0].layers[0].actions[0], std::nullopt});
    EXPECT_FALSE(outOfRange.apply(s).ok());
    Edit noCharacter(LayerChange{{3, 0}, std::nullopt, Layer{}});
    EXPECT_FALSE(noCharacter.apply(s).ok());
    EXPECT_FALSE(moveActions(s, std::vector<ActionPath>{{0, 0, 5}}, 1).ok());
}

TEST(Edit, ADragsStepsMergeIntoOneEdit)
{
    Scenario s = swingScenario({Second});
    const Scenario original = s;
    const std::vector<ActionPath> one{{0, 0, 0}};
    Edit drag = applied(s, moveActions(s, one, Second / 10));
    Edit step = applied(s, moveActions(s, one, Second / 10));
    ASSERT_TRUE(drag.canMergeWith(step));
    drag.mergeWith(step);
    EXPECT_EQ(s.characters[0].layers[0].actions[0].start, Second + Second / 5);
    ASSERT_TRUE(drag.inverse().apply(s).ok());
    EXPECT_EQ(s, original);

    // Back to where it started: the merged edit changes nothing.
    Edit there = applied(s, moveActions(s, one, Second / 3));
    Edit back = applied(s, moveActions(s, one, -Second / 3));
    there.mergeWith(back);
    EXPECT_TRUE(there.changesNothing());

    // Inserts and removes never merge; nor do changes of other elements.
    auto insert = insertActions(s, {0, 0}, {*actionFromClip(s, {0, 0}, "swing", 0)});
    EXPECT_FALSE(insert->canMergeWith(*insert));
    Scenario two = swingScenario({0, Second});
    auto first = moveActions(two, std::vector<ActionPath>{{0, 0, 0}}, 1);
    auto second = moveActions(two, std::vector<ActionPath>{{0, 0, 1}}, 1);
    EXPECT_FALSE(first->canMergeWith(*second));
}

namespace {

// swingScenario's character with more layers: "body" (actions at 0 and 3 s), "gestures" (body,
// one action at 1 s) and "face" (face, empty).
Scenario layeredScenario()
{
    Scenario s = swingScenario({0, 3 * Second});
    Layer gestures;
    gestures.name = "gestures";
    ActionSpec a;
    a.name = "nod";
    a.clip = "swing";
    a.start = Second;
    gestures.actions.push_back(a);
    Layer face;
    face.name = "face";
    face.kind = LayerKind::Face;
    s.characters[0].layers.push_back(gestures);
    s.characters[0].layers.push_back(face);
    return s;
}

const std::vector<ActionSpec>& actionsOf(const Scenario& s, int layer)
{
    return s.characters[0].layers[std::size_t(layer)].actions;
}

} // namespace

TEST(DocumentEdits, MovesActionsToAnotherLayerAndBack)
{
    Scenario s = layeredScenario();
    const Scenario original = s;
    const std::vector<ActionPath> second{{0, 0, 1}};
    auto down = moveActions(s, second, Second, 1);
    ASSERT_TRUE(down.ok()) << down.error().message;
    EXPECT_EQ(movedActionPaths(s, second, 1), (std::vector<ActionPath>{{0, 1, 1}}));
    expectRoundTrip(s, *down); // applied; undone restores the original exactly; applied again
    ASSERT_EQ(actionsOf(s, 0).size(), 1u);
    ASSERT_EQ(actionsOf(s, 1).size(), 2u);
    EXPECT_EQ(actionsOf(s, 1)[1].name, "swing 2"); // no clash: keeps its name
    EXPECT_EQ(actionsOf(s, 1)[1].start, 4 * Second);
    EXPECT_EQ(actionsOf(s, 1)[0].name, "nod"); // the layer's own action stays first
    EXPECT_TRUE(validateScenario(s, thespis::test::testData()).empty());
    EXPECT_NEAR(shoulderDegrees(s, 5.0), 45.0, 0.5); // the gestures layer plays it 1 s into the swing

    // And back up, 1 s earlier: the original document.
    applied(s, moveActions(s, std::vector<ActionPath>{{0, 1, 1}}, -Second, -1));
    EXPECT_EQ(s, original);

    // Several actions of several layers at once: each lands at the end of the layer below its own.
    auto both = moveActions(s, std::vector<ActionPath>{{0, 1, 0}, {0, 0, 0}}, 0, -1);
    EXPECT_FALSE(both.ok()); // layer 0 has no layer above it
    const std::vector<ActionPath> two{{0, 1, 0}, {0, 0, 0}};
    EXPECT_EQ(movedActionPaths(s, two, 1), std::vector<ActionPath>{}); // "nod" would go to the face layer
    const std::vector<ActionPath> twoBody{{0, 0, 0}, {0, 0, 1}};
    EXPECT_EQ(movedActionPaths(s, twoBody, 1), (std::vector<ActionPath>{{0, 1, 1}, {0, 1, 2}}));
    expectRoundTrip(s, *moveActions(s, twoBody, 0, 1));
    EXPECT_TRUE(actionsOf(s, 0).empty());
    EXPECT_EQ(actionsOf(s, 1)[1].name, "swing 1");
    EXPECT_EQ(actionsOf(s, 1)[2].name, "swing 2");
}

TEST(DocumentEdits, MovedActionsGetAUniqueNameInTheirNewLayer)
{
    Scenario s = layeredScenario();
    s.characters[0].layers[1].actions[0].name = "swing 1"; // the gestures layer has one already
    s.characters[0].layers[1].actions.push_back(s.characters[0].layers[1].actions[0]);
    s.characters[0].layers[1].actions[1].name = "swing 1 2";
    applied(s, moveActions(s, std::vector<ActionPath>{{0, 0, 0}}, 0, 1));
    ASSERT_EQ(actionsOf(s, 1).size(), 3u);
    EXPECT_EQ(actionsOf(s, 1)[2].name, "swing 1 3");
    EXPECT_EQ(actionsOf(s, 1)[2].start, 0);
    // Back to the body layer: no clash there, the name stays.
    applied(s, moveActions(s, std::vector<ActionPath>{{0, 1, 2}}, 0, -1));
    EXPECT_EQ(actionsOf(s, 0).back().name, "swing 1 3");
}

TEST(DocumentEdits, LayerMovesRefuseLockedLayersOtherKindsAndOtherCharacters)
{
    Scenario s = layeredScenario();
    const std::vector<ActionPath> first{{0, 0, 0}};
    // A face layer takes no body action.
    auto face = moveActions(s, std::vector<ActionPath>{{0, 1, 0}}, 0, 1);
    ASSERT_FALSE(face.ok());
    EXPECT_NE(face.error().message.find("body action"), std::string::npos) << face.error().message;
    EXPECT_NE(face.error().message.find("face layer \"face\""), std::string::npos) << face.error().message;
    // No layer above the first, none three below: the character ends there.
    auto above = moveActions(s, first, 0, -1);
    ASSERT_FALSE(above.ok());
    EXPECT_NE(above.error().message.find("1 layer up"), std::string::npos) << above.error().message;
    EXPECT_FALSE(moveActions(s, first, 0, 3).ok());
    // Locked target, then locked source.
    applied(s, setLayerFlag(s, {0, 1}, LayerFlag::Lock, true));
    auto locked = moveActions(s, first, 0, 1);
    ASSERT_FALSE(locked.ok());
    EXPECT_NE(locked.error().message.find("\"gestures\" is locked"), std::string::npos) << locked.error().message;
    EXPECT_FALSE(moveActions(s, std::vector<ActionPath>{{0, 1, 0}}, 0, -1).ok());
    // Listed twice.
    EXPECT_FALSE(moveActions(s, std::vector<ActionPath>{{0, 0, 0}, {0, 0, 0}}, Second).ok());
}

TEST(Edit, ADragAcrossLayersMergesIntoOneEditThatUndoes)
{
    // A drag re-made from its start at each mouse move (as the timeline does), merged step by step.
    const Scenario start = layeredScenario();
    Scenario s = start;
    const std::vector<ActionPath> one{{0, 0, 1}};
    Edit drag = applied(s, moveActions(start, one, Second / 10, 0));
    auto stepTo = [&](Tick delta, int layers) {
        Edit wanted = *moveActions(start, one, delta, layers);
        Edit step = drag.stepTo(wanted);
        applied(s, step);
        Scenario expected = start;
        EXPECT_TRUE(wanted.apply(expected).ok());
        EXPECT_EQ(s, expected);
        ASSERT_TRUE(drag.canMergeWith(step));
        drag.mergeWith(step);
        EXPECT_EQ(drag, wanted);
    };
    stepTo(Second / 5, 0);
    EXPECT_EQ(drag.stepTo(*moveActions(start, one, Second / 2, 0)).changes().size(), 1u); // in place: one replace
    stepTo(Second / 5, 1); // down to the gestures layer
    EXPECT_EQ(actionsOf(s, 1).size(), 2u);
    stepTo(Second / 2, 1);
    stepTo(Second, 0); // back up
    stepTo(Second, 1);
    const Scenario moved = s;
    ASSERT_TRUE(drag.inverse().apply(s).ok()); // undo: the drag's start, exactly
    EXPECT_EQ(s, start);
    ASSERT_TRUE(drag.apply(s).ok()); // redo
    EXPECT_EQ(s, moved);
    // Back to where it started (Escape): nothing left to do.
    stepTo(0, 0);
    EXPECT_TRUE(drag.changesNothing());
    EXPECT_EQ(s, start);
}

TEST(DocumentEdits, MoveStopsAtTheStartOfTheTimeline)
{
    Scenario s = swingScenario({Second, 3 * Second});
    applied(s, moveActions(s, std::vector<ActionPath>{{0, 0, 0}, {0, 0, 1}}, -5 * Second));
    EXPECT_EQ(s.characters[0].layers[0].actions[0].start, 0);
    EXPECT_EQ(s.characters[0].layers[0].actions[1].start, 2 * Second); // the group keeps its spacing
}

TEST(DocumentEdits, TrimmingTheStartKeepsTheMotionInPlace)
{
    Scenario s = swingScenario({Second});
    EXPECT_NEAR(shoulderDegrees(s, 2.0), 45.0, 0.5); // 1 s into the 2 s swing
    const auto span = actionSpan(s, runtimeOf(s), {0, 0, 0});
    ASSERT_TRUE(span);
    EXPECT_EQ(span->end, 3 * Second);
    applied(s, trimAction(s, {0, 0, 0}, *span, Edge::Start, Second + Second / 2, Second / 30));
    const ActionSpec& trimmed = s.characters[0].layers[0].actions[0];
    EXPECT_EQ(trimmed.start, Second + Second / 2);
    ASSERT_EQ(trimmed.modifiers.size(), 1u);
    EXPECT_EQ(trimmed.modifiers[0].kind, ModifierKind::Trim);
    EXPECT_NEAR(shoulderDegrees(s, 2.0), 45.0, 0.5);  // same pose at the same time
    EXPECT_NEAR(shoulderDegrees(s, 1.25), 0.0, 1e-3); // before the new start: rest pose

    // The start cannot go before the clip's first frame.
    const auto again = actionSpan(s, runtimeOf(s), {0, 0, 0});
    ASSERT_TRUE(again);
    EXPECT_EQ(again->untrimmed.start, 0.0);
    applied(s, trimAction(s, {0, 0, 0}, *again, Edge::Start, 0, Second / 30));
    EXPECT_EQ(s.characters[0].layers[0].actions[0].start, Second);
    EXPECT_NEAR(shoulderDegrees(s, 2.0), 45.0, 0.5);
}

TEST(DocumentEdits, TrimmingTheEndShortensWithinTheClip)
{
    Scenario s = swingScenario({0});
    auto span = actionSpan(s, runtimeOf(s), {0, 0, 0});
    applied(s, trimAction(s, {0, 0, 0}, *span, Edge::End, Second, Second / 30));
    auto shorter = actionSpan(s, runtimeOf(s), {0, 0, 0});
    ASSERT_TRUE(shorter);
    EXPECT_EQ(shorter->end, Second);
    EXPECT_NEAR(shoulderDegrees(s, 0.5), 22.5, 0.5);
    // Dragging past the clip's last frame stops there; below the minimum length stops there.
    applied(s, trimAction(s, {0, 0, 0}, *shorter, Edge::End, 10 * Second, Second / 30));
    EXPECT_EQ(actionSpan(s, runtimeOf(s), {0, 0, 0})->end, 2 * Second);
    shorter = actionSpan(s, runtimeOf(s), {0, 0, 0});
    applied(s, trimAction(s, {0, 0, 0}, *shorter, Edge::End, -Second, Second / 30));
    EXPECT_EQ(actionSpan(s, runtimeOf(s), {0, 0, 0})->end, Second / 30);
}

TEST(DocumentEdits, TrimmingTheEndOfAnEndlessLoopMakesItFinite)
{
    Scenario s = swingScenario({0});
    ModifierSpec loop;
    loop.kind = ModifierKind::Loop;
    loop.count = 0;
    s.characters[0].layers[0].actions[0].modifiers.push_back(loop);
    auto span = actionSpan(s, runtimeOf(s), {0, 0, 0});
    ASSERT_TRUE(span && span->openEnded);
    EXPECT_FALSE(trimAction(s, {0, 0, 0}, *span, Edge::Start, Second, 1).ok());
    applied(s, trimAction(s, {0, 0, 0}, *span, Edge::End, 5 * Second, 1));
    span = actionSpan(s, runtimeOf(s), {0, 0, 0});
    ASSERT_TRUE(span);
    EXPECT_FALSE(span->openEnded);
    EXPECT_EQ(span->end, 5 * Second);
}

TEST(DocumentEdits, SplitGivesTheSameMotionInTwoActions)
{
    Scenario s = swingScenario({Second});
    const double before[] = {1.2, 1.9, 2.1, 2.8};
    std::vector<double> angles;
    for (double t : before)
        angles.push_back(shoulderDegrees(s, t));
    const auto span = actionSpan(s, runtimeOf(s), {0, 0, 0});
    applied(s, splitAction(s, {0, 0, 0}, *span, 2 * Second));
    ASSERT_EQ(s.characters[0].layers[0].actions.size(), 2u);
    EXPECT_EQ(s.characters[0].layers[0].actions[1].start, 2 * Second);
    EXPECT_EQ(s.characters[0].layers[0].actions[1].name, "swing 1 2");
    for (std::size_t i = 0; i < angles.size(); ++i)
        EXPECT_NEAR(shoulderDegrees(s, before[i]), angles[i], 1e-3) << before[i];
    EXPECT_EQ(actionSpan(s, runtimeOf(s), {0, 0, 0})->end, 2 * Second);
    EXPECT_FALSE(splitAction(s, {0, 0, 0}, *actionSpan(s, runtimeOf(s), {0, 0, 0}), 5 * Second).ok());
}

TEST(DocumentEdits, RippleDeleteClosesTheGap)
{
    Scenario s = swingScenario({0, 2 * Second, 5 * Second});
    const ScenarioRuntime runtime = runtimeOf(s);
    Scenario plain = s;
    applied(plain, removeActions(plain, std::vector<ActionPath>{{0, 0, 1}}));
    ASSERT_EQ(plain.characters[0].layers[0].actions.size(), 2u);
    EXPECT_EQ(plain.characters[0].layers[0].actions[1].start, 5 * Second);

    applied(s, removeActions(s, std::vector<ActionPath>{{0, 0, 1}}, &runtime));
    ASSERT_EQ(s.characters[0].layers[0].actions.size(), 2u);
    EXPECT_EQ(s.characters[0].layers[0].actions[0].start, 0);
    EXPECT_EQ(s.characters[0].layers[0].actions[1].start, 3 * Second); // 2 s earlier
}

TEST(DocumentEdits, FadesSetEnvelopesAndRefuseKeyframedAndDominanceCurves)
{
    Scenario s = swingScenario({0});
    applied(s, setActionFades(s, {0, 0, 0}, 0.4, std::nullopt));
    const anim::Curve& weight = s.characters[0].layers[0].actions[0].weight;
    EXPECT_EQ(weight.kind(), anim::CurveKind::CubicFade);
    EXPECT_DOUBLE_EQ(weight.envelope().attack, 0.4);
    EXPECT_DOUBLE_EQ(weight.envelope().release, 0.0);
    applied(s, setActionFades(s, {0, 0, 0}, std::nullopt, 0.7));
    EXPECT_DOUBLE_EQ(s.characters[0].layers[0].actions[0].weight.envelope().attack, 0.4);
    EXPECT_DOUBLE_EQ(s.characters[0].layers[0].actions[0].weight.envelope().release, 0.7);
    EXPECT_FALSE(setActionFades(s, {0, 0, 0}, -1.0, std::nullopt).ok());

    auto keyed = anim::Curve::keyframed({{0, 0}, {1, 1}});
    applied(s, setActionCurves(s, {0, 0, 0}, *keyed, std::nullopt));
    auto refused = setActionFades(s, {0, 0, 0}, 0.2, std::nullopt);
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().message.find("keyframed"), std::string::npos);

    // A dominance curve rises and falls over the whole action: no fades either, and its α > 0.
    applied(s, setActionCurves(s, {0, 0, 0}, anim::Curve::dominance(5), std::nullopt));
    refused = setActionFades(s, {0, 0, 0}, 0.2, std::nullopt);
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().message.find("dominance"), std::string::npos);
    EXPECT_FALSE(setActionCurves(s, {0, 0, 0}, anim::Curve::dominance(0), std::nullopt).ok());
}

TEST(DocumentEdits, LockedLayersRefuseEdits)
{
    Scenario s = swingScenario({0});
    applied(s, setLayerFlag(s, {0, 0}, LayerFlag::Lock, true));
    EXPECT_FALSE(moveActions(s, std::vector<ActionPath>{{0, 0, 0}}, 1).ok());
    EXPECT_FALSE(removeActions(s, std::vector<ActionPath>{{0, 0, 0}}).ok());
    EXPECT_FALSE(setActionFades(s, {0, 0, 0}, 0.1, 0.1).ok());
    auto refused = insertActions(s, {0, 0}, {*actionFromClip(s, {0, 0}, "swing", 0)});
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().message.find("locked"), std::string::npos);
}

TEST(DocumentEdits, InsertedActionsGetUniqueNames)
{
    Scenario s = swingScenario({0});
    s.characters[0].layers[0].actions[0].name = "swing";
    auto action = actionFromClip(s, {0, 0}, "swing", 3 * Second);
    ASSERT_TRUE(action.ok());
    EXPECT_EQ(action->weight, anim::Curve::cubicFade(0.3, 0.3));
    applied(s, insertActions(s, {0, 0}, {*action, *action}));
    ASSERT_EQ(s.characters[0].layers[0].actions.size(), 3u);
    EXPECT_EQ(s.characters[0].layers[0].actions[1].name, "swing 2");
    EXPECT_EQ(s.characters[0].layers[0].actions[2].name, "swing 3");
    EXPECT_FALSE(actionFromClip(s, {0, 0}, "no such clip", 0).ok());
}

TEST(DocumentEdits, MarkersStayOrderedByTime)
{
    Scenario s = swingScenario();
    applied(s, addMarker(s, {"b", 2 * Second, {}}));
    applied(s, addMarker(s, {"a", Second, {}}));
    applied(s, addMarker(s, {"c", 3 * Second, {}}));
    ASSERT_EQ(s.markers.size(), 3u);
    EXPECT_EQ(s.markers[0].name, "a");
    EXPECT_EQ(s.markers[2].name, "c");
    applied(s, moveMarker(s, 0, -Second));
    EXPECT_EQ(s.markers[0].time, 0);
    EXPECT_FALSE(removeMarker(s, 5).ok());
}

TEST(DocumentEdits, MasksRenameEverywhereAndRefuseRemovalWhileUsed)
{
    Scenario s = swingScenario({0});
    s.characters[0].layers[0].actions[0].mask = "arm";
    s.characters[0].gestures.push_back(Gesture{"g", "swing", "arm", 0, 0, false});
    auto removal = removeMask(s, 0);
    ASSERT_FALSE(removal.ok());
    EXPECT_NE(removal.error().message.find("action \"swing 1\""), std::string::npos) << removal.error().message;
    EXPECT_NE(removal.error().message.find("gesture \"g\""), std::string::npos);

    applied(s, renameMask(s, 0, "right arm"));
    EXPECT_EQ(s.masks[0].name, "right arm");
    EXPECT_EQ(s.characters[0].layers[0].actions[0].mask, "right arm");
    EXPECT_EQ(s.characters[0].gestures[0].mask, "right arm");
    EXPECT_TRUE(validateScenario(s, thespis::test::testData()).empty());
    EXPECT_FALSE(addMask(s, "right arm", {}).ok());
    EXPECT_FALSE(setMaskWeights(s, 0, std::vector<std::string>{"r_elbow"}, 1.5f).ok());
}

TEST(DocumentEdits, CharacterBakesAreCheckedAndNeverMerge)
{
    Scenario s = swingScenario();
    EXPECT_FALSE(setCharacterBake(s, 3, "bakes/a.prt").ok());
    EXPECT_FALSE(setCharacterBake(s, -1, "bakes/a.prt").ok());
    const Scenario original = s;
    Edit first = applied(s, setCharacterBake(s, 0, "bakes/a.prt"));
    EXPECT_EQ(s.characters[0].bake, "bakes/a.prt");
    Edit second = applied(s, setCharacterBake(s, 0, "bakes/b.prt"));
    EXPECT_FALSE(first.canMergeWith(second)); // each bake is an undo step of its own
    // The inverse of the first no longer fits (the bake is b now): refused, nothing changed.
    const Scenario now = s;
    EXPECT_FALSE(first.inverse().apply(s).ok());
    EXPECT_EQ(s, now);
    ASSERT_TRUE(second.inverse().apply(s).ok());
    ASSERT_TRUE(first.inverse().apply(s).ok());
    EXPECT_EQ(s, original);
    EXPECT_TRUE(setCharacterBake(s, 0, "").value().changesNothing());
}

TEST(DocumentEdits, PathsRebaseWithTheDocument)
{
    // Saved to another folder, the document's relative paths are rewritten; the undo history's
    // edits must be rewritten the same way, or their inverses no longer fit.
    EXPECT_EQ(rebasedPath("bakes/a.prt", "/work/show", "/work/show/sub"), "../bakes/a.prt");
    EXPECT_EQ(rebasedPath("../clips/walk.bvh", "/work/show/sub", "/work/show"), "clips/walk.bvh");
    EXPECT_EQ(rebasedPath("/data/walk.bvh", "/work/show", "/elsewhere"), "/data/walk.bvh");
    EXPECT_EQ(rebasedPath("", "/work/show", "/elsewhere"), "");

    Scenario s = swingScenario();
    s.lighting.probe = "probes/sky.hdr";
    const Scenario original = s;
    Edit bake = applied(s, setCharacterBake(s, 0, "bakes/a.prt"));
    Scenario saved = s;
    rebasePaths(saved, "/work/show", "/work/show/sub");
    EXPECT_EQ(saved.characters[0].bake, "../bakes/a.prt");
    EXPECT_EQ(saved.lighting.probe, "../probes/sky.hdr");
    for (std::size_t c = 0; c < saved.characters.size(); ++c)
        for (std::size_t k = 0; k < saved.characters[c].clips.size(); ++k)
            EXPECT_EQ(saved.characters[c].clips[k].file, rebasedPath(s.characters[c].clips[k].file, "/work/show", "/work/show/sub"));
    EXPECT_FALSE(bake.inverse().apply(saved).ok()); // made for the old folder
    bake.rebasePaths("/work/show", "/work/show/sub");
    ASSERT_TRUE(bake.inverse().apply(saved).ok());
    Scenario expected = original;
    rebasePaths(expected, "/work/show", "/work/show/sub");
    EXPECT_EQ(saved, expected);
    EXPECT_EQ(saved.characters[0].bake, "");
}

TEST(DocumentEdits, GesturesAreChecked)
{
    Scenario s = swingScenario();
    EXPECT_TRUE(addGesture(s, 0, Gesture{"g", "swing", "arm", 0, 0, false}).ok());
    EXPECT_FALSE(addGesture(s, 0, Gesture{"", "swing", "", 0, 0, false}).ok());
    EXPECT_FALSE(addGesture(s, 0, Gesture{"g", "nope", "", 0, 0, false}).ok());
    EXPECT_FALSE(addGesture(s, 0, Gesture{"g", "swing", "nope", 0, 0, false}).ok());
    EXPECT_FALSE(addGesture(s, 3, Gesture{"g", "swing", "", 0, 0, false}).ok());
    applied(s, addGesture(s, 0, Gesture{"g", "swing", "arm", 0, 0, false}));
    EXPECT_FALSE(addGesture(s, 0, Gesture{"g", "swing", "", 0, 0, false}).ok()); // taken
    EXPECT_TRUE(replaceGesture(s, {0, 0}, Gesture{"g", "swing", "", Second, 0, true}).ok()); // its own name
}

TEST(Edit, RuntimeScopeNamesWhatAnEditRebuilds)
{
    const Scenario s = loadScenario(thespis::test::resources("demo.thespis")).value();
    ASSERT_GE(s.characters.size(), 2u);
    const RuntimeScope move = moveActions(s, std::vector<ActionPath>{{1, 0, 0}}, Second / 2)->runtimeScope();
    EXPECT_FALSE(move.everything);
    EXPECT_EQ(move.characters, std::vector<int>{1});
    EXPECT_TRUE(addMarker(s, Marker{"cue", Second, {}})->runtimeScope().empty());
    EXPECT_TRUE(addMask(s, "legs", anim::JointMask::preset(anim::MaskPreset::LowerBody))->runtimeScope().everything);
    Edit both = *moveActions(s, std::vector<ActionPath>{{1, 0, 0}}, Second);
    both.append(*setLayerFlag(s, {0, 1}, LayerFlag::Mute, true));
    both.append(*moveActions(s, std::vector<ActionPath>{{1, 0, 1}}, Second));
    EXPECT_EQ(both.runtimeScope().characters, (std::vector<int>{0, 1}));
}

TEST(Edit, RebuildingTheTouchedCharacterGivesTheSameMotionAsBuildingAll)
{
    const Scenario s = loadScenario(thespis::test::resources("demo.thespis")).value();
    const auto before = buildRuntime(s, thespis::test::resources());
    ASSERT_TRUE(before.ok()) << before.error().message;
    const Edit edit = *moveActions(s, std::vector<ActionPath>{{1, 0, 1}}, Second / 3);
    Scenario after = s;
    ASSERT_TRUE(edit.apply(after).ok());
    const RuntimeScope scope = edit.runtimeScope();
    const auto rebuilt = rebuildRuntime(after, thespis::test::resources(), *before, scope.characters);
    ASSERT_TRUE(rebuilt.ok()) << rebuilt.error().message;
    const auto built = buildRuntime(after, thespis::test::resources());
    ASSERT_TRUE(built.ok());
    EXPECT_EQ(rebuilt->duration, built->duration);
    // The untouched character keeps its schedules; the moved action plays where it was moved.
    EXPECT_EQ(rebuilt->characters[0].body, before->characters[0].body);
    EXPECT_NE(rebuilt->characters[1].body, before->characters[1].body);
    for (std::size_t c = 0; c < s.characters.size(); ++c) {
        std::vector<float> a = built->characters[c].skeleton.restFrame(), b = a;
        for (double t = 0; t <= ticksToSeconds(built->duration); t += 0.25) {
            built->characters[c].evaluateBody(t, a);
            rebuilt->characters[c].evaluateBody(t, b);
            ASSERT_EQ(a, b) << "character " << c << " at " << t << " s";
        }
    }
    // The motion did change for the touched character.
    std::vector<float> old = before->characters[1].skeleton.restFrame(), moved = old;
    bool differs = false;
    for (double t = 0; t <= ticksToSeconds(built->duration) && !differs; t += 0.25) {
        before->characters[1].evaluateBody(t, old);
        rebuilt->characters[1].evaluateBody(t, moved);
        differs = old != moved;
    }
    EXPECT_TRUE(differs);

    Scenario fewer = after;
    fewer.characters.pop_back();
    EXPECT_FALSE(rebuildRuntime(fewer, thespis::test::resources(), *before, std::vector<int>{0}).ok());
}
