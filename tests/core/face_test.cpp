// The built-in humanoid's MPEG-4 face (issue 31; core/scene/face_rig.h, humanoid_face.h): FAP
// semantics on the modelled face — open_jaw of N lowers the chin by N MNS units, closing an upper
// lid by 1024 IRISD units meets the lower lid, each low-level FAP moves its feature point by its
// value in its unit along its direction — the lips never pass through each other, zero FAPs give
// the neutral mesh bit for bit, and visemes and expressions expand into their FAPs. Face layers are
// weighted per FAP region by face masks (scene/face_mask.h).

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "anim/frame.h"
#include "scene/default_humanoid.h"
#include "scene/face_rig.h"
#include "scene/face_tables.h"
#include "scene/face_mask.h"
#include "scene/fap.h"
#include "scenario/scenario_runtime.h"

namespace thespis::core::scene {
namespace {

using anim::Vec3;
using anim::Vec3d;

const Character& humanoid()
{
    static const Character character = *makeDefaultHumanoid({});
    return character;
}

// The face's rest mesh deformed by `face` (a face frame).
struct Deformed {
    std::vector<Vec3> positions, normals;
};

Deformed deform(FaceDeformer& deformer, const std::vector<float>& face)
{
    Deformed out{humanoid().mesh.positions, humanoid().mesh.normals};
    deformer.deform(face, out.positions, out.normals);
    return out;
}

std::vector<float> faceFrame(std::initializer_list<std::pair<int, float>> channels)
{
    std::vector<float> face(std::size_t(kFaceChannelCount), 0.0f);
    for (const auto& [channel, value] : channels)
        face[std::size_t(channel)] = value;
    return face;
}

Vec3d at(const Deformed& d, const std::string& point)
{
    const FeaturePoint* fp = humanoid().face.findFeaturePoint(point);
    EXPECT_NE(fp, nullptr) << point;
    const Vec3& p = d.positions[fp ? fp->vertex : 0];
    return {p.x, p.y, p.z};
}

Vec3d restAt(const std::string& point) { return at(Deformed{humanoid().mesh.positions, {}}, point); }

TEST(HumanoidFace, HasFeaturePointsAndFapUnitsOfAnAdultFace)
{
    const FaceRig& face = humanoid().face;
    for (const char* point : {"2.1", "2.2", "2.3", "2.4", "2.5", "3.1", "3.3", "3.5", "3.6", "4.1", "4.6", "5.3", "6.1",
                              "8.1", "8.4", "9.3", "9.15", "10.1"})
        EXPECT_NE(face.findFeaturePoint(point), nullptr) << point;
    // Measured between the feature points, as Figure C-2 defines them (metres per 1024 units).
    EXPECT_NEAR(face.units.es * 1024, 0.064, 0.004);    // pupils 64 mm apart
    EXPECT_NEAR(face.units.irisd * 1024, 0.0098, 0.0015); // the eye's opening
    EXPECT_NEAR(face.units.mw * 1024, 0.053, 0.005);    // the mouth's width
    EXPECT_GT(face.units.ens * 1024, 0.035);
    EXPECT_GT(face.units.mns * 1024, 0.012);
    EXPECT_LT(face.units.mns * 1024, 0.030);
    EXPECT_TRUE(humanoid().validate().ok());
}

TEST(HumanoidFace, ZeroFapsGiveTheNeutralMeshBitForBit)
{
    FaceDeformer deformer(humanoid());
    EXPECT_GT(deformer.vertices().size(), 3000u);
    const Deformed neutral = deform(deformer, faceFrame({}));
    EXPECT_EQ(neutral.positions, humanoid().mesh.positions);
    EXPECT_EQ(neutral.normals, humanoid().mesh.normals);
    // After a moving face, zero again is the neutral face again, exactly; an empty frame too.
    Deformed moved{humanoid().mesh.positions, humanoid().mesh.normals};
    deformer.deform(faceFrame({{fapChannel(3), 400}, {expressionChannel(1), 1}}), moved.positions, moved.normals);
    EXPECT_NE(moved.positions, humanoid().mesh.positions);
    deformer.deform(faceFrame({}), moved.positions, moved.normals);
    EXPECT_EQ(moved.positions, humanoid().mesh.positions);
    EXPECT_EQ(moved.normals, humanoid().mesh.normals);
    deformer.deform({}, moved.positions, moved.normals);
    EXPECT_EQ(moved.positions, humanoid().mesh.positions);
}

TEST(HumanoidFace, OpenJawLowersTheChinByItsValueInMns)
{
    FaceDeformer deformer(humanoid());
    const double mns = humanoid().face.units.mns;
    const Vec3d chin = restAt("2.1");
    for (const float n : {50.0f, 300.0f, 600.0f, 1000.0f}) {
        const Deformed open = deform(deformer, faceFrame({{fapChannel(3), n}}));
        const double drop = chin.y - at(open, "2.1").y;
        EXPECT_NEAR(drop, n * mns, 0.01 * n * mns) << n << " MNS units";
        // The tongue goes down with the jaw (its tip about as far as the chin); the upper lip stays.
        const double tongue = restAt("6.1").y - at(open, "6.1").y;
        EXPECT_GT(tongue, 0.5 * drop);
        EXPECT_LT(tongue, 1.5 * drop);
        EXPECT_NEAR(at(open, "2.2").y, restAt("2.2").y, 1e-7);
        // The lips part: the lower inner lip is now below the upper by about the drop.
        EXPECT_GT(at(open, "2.2").y - at(open, "2.3").y, 0.5 * n * mns);
    }
}

TEST(HumanoidFace, ClosingAnUpperLidByTheIrisDiameterMeetsTheLowerLid)
{
    FaceDeformer deformer(humanoid());
    const double irisd = humanoid().face.units.irisd;
    for (const auto& [fap, upper, lower] : {std::tuple{19, "3.1", "3.3"}, std::tuple{20, "3.2", "3.4"}}) {
        const Deformed shut = deform(deformer, faceFrame({{fapChannel(fap), 1024}}));
        EXPECT_NEAR(at(shut, upper).y, at(shut, lower).y, 0.01 * 1024 * irisd) << upper;
        EXPECT_NEAR(at(shut, lower).y, restAt(lower).y, 1e-7) << "the lower lid did not move";
        // Half way: half the opening.
        const Deformed half = deform(deformer, faceFrame({{fapChannel(fap), 512}}));
        EXPECT_NEAR(restAt(upper).y - at(half, upper).y, 512 * irisd, 0.01 * 512 * irisd);
    }
    // The lower lid's FAP (21, up) meets the upper lid from below.
    const Deformed raised = deform(deformer, faceFrame({{fapChannel(21), 1024}}));
    EXPECT_NEAR(at(raised, "3.3").y, restAt("3.1").y, 0.01 * 1024 * irisd);
}

// Every low-level FAP with a feature point and a linear influence moves that point by exactly its
// value in its unit, along the direction the standard gives it.
TEST(HumanoidFace, EachFapMovesItsFeaturePointByItsValueInItsUnit)
{
    FaceDeformer deformer(humanoid());
    const FapUnits& units = humanoid().face.units;
    const auto directionOf = [](const FapInfo& fap) -> Vec3d {
        const std::string_view d = fap.direction;
        if (d == "up")
            return {0, 1, 0};
        if (d == "down")
            return {0, -1, 0};
        if (d == "forward")
            return {0, 0, 1};
        if (d == "left")
            return {1, 0, 0};
        if (d == "right")
            return {-1, 0, 0};
        return {};
    };
    int checked = 0;
    for (int number = 4; number <= kFapCount; ++number) {
        const FapInfo& fap = fapInfo(number);
        // Rigid (jaw, eyes, lids), rolls and angles are checked elsewhere; the tongue's tip and
        // body, the pupils and the head have no linear point of their own here.
        if (fap.unit == FapUnit::AU || fap.featurePoint.empty() || number == 14 || number == 15 ||
            (number >= 19 && number <= 30) || number == 47)
            continue;
        const Vec3d direction = directionOf(fap);
        ASSERT_NE(direction, Vec3d{}) << fap.name;
        // The inner lip contour's FAPs open the mouth with negative values (positive ones press
        // the lips together, where they stop at each other: TheLipsNeverPassThroughEachOther).
        const std::string_view fp = fap.featurePoint;
        const bool inner = fp == "2.2" || fp == "2.3" || (fp >= "2.6" && fp <= "2.9");
        const float value = inner ? -200 : 200;
        const Deformed moved = deform(deformer, faceFrame({{fapChannel(number), value}}));
        const std::string point(fap.featurePoint);
        const Vec3d shift = at(moved, point) - restAt(point);
        const Vec3d expected = direction * (value * units.of(fap.unit));
        const double error = std::sqrt(anim::dot(shift - expected, shift - expected));
        EXPECT_LT(error, 0.02 * std::abs(value) * units.of(fap.unit)) << fap.name << " at " << point;
        ++checked;
    }
    EXPECT_GE(checked, 40);
}

TEST(HumanoidFace, EyeballsTurnByTheirFapsInAngleUnits)
{
    FaceDeformer deformer(humanoid());
    const double angle = 20 * std::numbers::pi / 180;
    const float units = float(angle / FapUnits::au);
    const Deformed looking = deform(deformer, faceFrame({{fapChannel(23), units}, {fapChannel(25), units}}));
    // The left pupil turns left (+x) and down about the eye's centre; the right one stays.
    const Vec3d before = restAt("3.5"), after = at(looking, "3.5");
    EXPECT_GT(after.x, before.x + 0.002);
    EXPECT_LT(after.y, before.y - 0.002);
    EXPECT_NEAR(at(looking, "3.6").x, restAt("3.6").x, 1e-7);
    const RigidFacePart* ball = nullptr;
    for (const RigidFacePart& part : humanoid().face.parts)
        if (part.name == "l_eyeball")
            ball = &part;
    ASSERT_NE(ball, nullptr);
    const Vec3d a = before - ball->pivot, b = after - ball->pivot;
    const double turned = std::acos(anim::dot(a, b) / std::sqrt(anim::dot(a, a) * anim::dot(b, b)));
    const double expected = std::acos(std::cos(angle) * std::cos(angle)); // yaw then pitch, both 20°
    EXPECT_NEAR(turned, expected, 1e-4);
}

TEST(HumanoidFace, TheLipsNeverPassThroughEachOther)
{
    FaceDeformer deformer(humanoid());
    const FaceRig& face = humanoid().face;
    ASSERT_GT(face.lipContacts.size(), 10u);
    std::mt19937 random(7);
    std::uniform_real_distribution<float> value(-700, 700);
    const int lipFaps[] = {3, 4, 5, 8, 9, 10, 11, 12, 13, 16, 17, 18, 51, 52, 55, 56, 57, 58, 59, 60};
    int crossingsPrevented = 0;
    for (int trial = 0; trial < 300; ++trial) {
        std::vector<float> frame = faceFrame({});
        for (const int fap : lipFaps)
            if (random() % 3 == 0)
                frame[std::size_t(fapChannel(fap))] = fap == 3 ? std::abs(value(random)) : value(random);
        if (trial % 4 == 0)
            frame[std::size_t(visemeChannel(1 + trial % kVisemeCount))] = 1;
        const Deformed d = deform(deformer, frame);
        for (const auto& [upper, lower] : face.lipContacts) {
            ASSERT_LE(d.positions[lower].y, d.positions[upper].y) << "trial " << trial;
            crossingsPrevented += d.positions[lower].y == d.positions[upper].y;
        }
    }
    EXPECT_GT(crossingsPrevented, 0) << "some combinations pressed the lips together";
}

TEST(HumanoidFace, VisemesAndExpressionsAreTheirFaps)
{
    FaceDeformer deformer(humanoid());
    for (int e = 1; e <= kExpressionCount; ++e) {
        std::vector<float> expanded = faceFrame({});
        for (const FapValue& v : expressionFaps(e))
            expanded[std::size_t(fapChannel(v.fap))] += 0.5f * v.value;
        const Deformed byWeight = deform(deformer, faceFrame({{expressionChannel(e), 0.5f}}));
        const Deformed byFaps = deform(deformer, expanded);
        EXPECT_EQ(byWeight.positions, byFaps.positions) << expressionName(e);
        EXPECT_NE(byWeight.positions, humanoid().mesh.positions) << expressionName(e);
    }
    const Deformed bilabial = deform(deformer, faceFrame({{visemeChannel(1), 1}}));
    EXPECT_NEAR(at(bilabial, "2.2").y, at(bilabial, "2.3").y, 1e-7) << "p, b, m press the lips together";
    const Deformed open = deform(deformer, faceFrame({{visemeChannel(10), 1}}));
    EXPECT_GT(at(open, "2.2").y - at(open, "2.3").y, 0.005) << "A: opens the mouth";
}

TEST(HumanoidFace, HeadFapsTurnTheSkull)
{
    FaceDeformer deformer(humanoid());
    const anim::Skeleton& skeleton = humanoid().skeleton;
    std::vector<float> body = anim::neutralFrame(*skeleton.frameLayout());
    const int skull = skeleton.find("skullbase");
    deformer.turnJoints(faceFrame({{fapChannel(49), float(0.3 / FapUnits::au)}}), body);
    const anim::Quat& q = anim::rotationAt(std::span<const float>(body), skull);
    EXPECT_NEAR(2 * std::asin(q.y), 0.3, 1e-5) << "head_yaw turns the head left";
    EXPECT_NEAR(q.x, 0, 1e-7);
}

// A face layer's clip: one frame of the given face channels, held for a second.
scenario::ClipAsset faceClip(std::string name, std::vector<std::pair<std::string, float>> values)
{
    scenario::ClipAsset clip;
    clip.name = std::move(name);
    clip.frameRate = 1;
    for (int frame = 0; frame < 2; ++frame)
        for (const auto& [channel, value] : values) {
            if (frame == 0)
                clip.scalars.push_back(channel);
            clip.frames.push_back(value);
        }
    return clip;
}

scenario::Layer faceLayer(std::string name, std::string clip, std::string mask)
{
    scenario::Layer layer;
    layer.name = std::move(name);
    layer.kind = scenario::LayerKind::Face;
    scenario::ActionSpec action;
    action.name = layer.name;
    action.clip = std::move(clip);
    action.mask = std::move(mask);
    layer.actions.push_back(std::move(action));
    return layer;
}

TEST(FaceMask, ARegionWeighsItsChannelsAndANamedChannelOverridesIt)
{
    const auto layout = anim::FrameLayout::mpeg4Face();
    const auto channel = [&](std::string_view name) { return std::size_t(*findFaceChannel(name)); };
    anim::JointMask speech = faceMaskPreset(FaceMaskPreset::Speech);
    ASSERT_TRUE(isFaceMask(speech));
    EXPECT_FALSE(isFaceMask(anim::JointMask::preset(anim::MaskPreset::UpperBody)));
    std::vector<float> w = speech.resolve(*layout);
    EXPECT_EQ(w[channel("open_jaw")], 1.0f);
    EXPECT_EQ(w[channel("raise_b_midlip_o")], 1.0f); // outer lips: the mouth too
    EXPECT_EQ(w[channel("viseme1")], 1.0f);          // the visemes' weights are on the mouth
    EXPECT_EQ(w[channel("raise_tongue_tip")], 1.0f);
    EXPECT_EQ(w[channel("lift_l_cheek")], 0.5f);
    EXPECT_EQ(w[channel("raise_l_i_eyebrow")], 0.0f);
    EXPECT_EQ(w[channel("close_t_l_eyelid")], 0.0f);
    EXPECT_EQ(w[channel("joy")], 0.0f);

    speech.setWeight("fap31", 0.7f); // raise_l_i_eyebrow alone
    w = speech.resolve(*layout);
    EXPECT_EQ(w[channel("raise_l_i_eyebrow")], 0.7f);
    EXPECT_EQ(w[channel("raise_r_i_eyebrow")], 0.0f);
    const std::vector<float> mirrored = mirroredFaceMask(speech).resolve(*layout);
    EXPECT_EQ(mirrored[channel("raise_r_i_eyebrow")], 0.7f);
    EXPECT_EQ(mirrored[channel("raise_l_i_eyebrow")], 0.0f);
    EXPECT_EQ(mirroredFap(12), 13);  // raise_l_cornerlip ↔ raise_r_cornerlip
    EXPECT_EQ(mirroredFap(9), 8);    // lower_t_lip_rm ↔ lower_t_lip_lm
    EXPECT_EQ(mirroredFap(3), 3);    // open_jaw: the middle
}

// The paper's case (§5.2): a speech layer over an expression layer — the mouth speaks, the brows
// keep the expression. Layers blend normalized by weight: on the mouth the speech's 1 against the
// expression's ⅓ gives speech ¾ of it; on the brows the speech's 0 leaves them the expression's.
// Without the speech mask its neutral brows would take half of them away.
TEST(FaceMask, SpeechOnTheMouthOverAnExpressionOnTheBrows)
{
    scenario::Scenario s;
    s.masks.push_back({"speech", faceMaskPreset(FaceMaskPreset::Speech), {}});
    s.masks.push_back({"expression", faceMaskPreset(FaceMaskPreset::Expression), {}});
    scenario::Character c;
    c.name = "A";
    c.clips.push_back(faceClip("frown", {{"fap3", 300}, {"fap31", -200}}));
    c.clips.push_back(faceClip("speak", {{"fap3", 100}, {"viseme1", 1}}));
    c.layers.push_back(faceLayer("expression", "frown", "expression"));
    c.layers.push_back(faceLayer("speech", "speak", "speech"));
    s.characters.push_back(c);

    const auto evaluate = [](const scenario::Scenario& scenario) {
        auto built = scenario::buildRuntime(scenario, std::filesystem::temp_directory_path());
        EXPECT_TRUE(built.ok()) << describe(built.error());
        std::vector<float> face(std::size_t{kFaceChannelCount}, 0.0f);
        if (built.ok())
            built->characters[0].face->evaluate(0.5, face);
        return face;
    };
    std::vector<float> face = evaluate(s);
    EXPECT_FLOAT_EQ(face[std::size_t(fapChannel(3))], 0.75f * 100.0f + 0.25f * 300.0f) << "speech has ¾ of the mouth";
    EXPECT_FLOAT_EQ(face[std::size_t(fapChannel(31))], -200.0f) << "the expression keeps the brows";
    EXPECT_FLOAT_EQ(face[std::size_t(visemeChannel(1))], 0.75f);

    s.characters[0].layers[1].mute = true; // the expression alone: a third of it on the mouth
    face = evaluate(s);
    EXPECT_NEAR(face[std::size_t(fapChannel(3))], 100.0f, 1e-3);
    EXPECT_FLOAT_EQ(face[std::size_t(fapChannel(31))], -200.0f);

    s.characters[0].layers[1].mute = false; // unmasked, the speech layer's brows halve them
    s.characters[0].layers[1].actions[0].mask.clear();
    face = evaluate(s);
    EXPECT_FLOAT_EQ(face[std::size_t(fapChannel(31))], -100.0f);
}

TEST(FaceMask, EveryChannelIsShownOnceUnderItsRegionOnTheFace)
{
    const std::vector<FaceMaskElement>& elements = faceMaskElements();
    ASSERT_EQ(elements.size(), kFaceRegions.size() + std::size_t(kFaceChannelCount));
    const auto layout = anim::FrameLayout::mpeg4Face();
    std::set<std::string> keys;
    for (const FaceMaskElement& element : elements) {
        EXPECT_TRUE(keys.insert(element.key).second) << element.key;
        if (element.parent < 0)
            continue;
        const int e = layout->find(element.key, anim::ElementKind::Scalar);
        ASSERT_GE(e, 0) << element.key;
        EXPECT_EQ(layout->group(e), elements[std::size_t(element.parent)].key);
        // On the head: within 15 cm of the face's middle, the face's size.
        EXPECT_NEAR(element.position.y, 1.66, 0.15) << element.label;
        EXPECT_NEAR(element.position.x, 0.0, 0.15) << element.label;
    }
    const auto find = [&](std::string_view key) {
        return *std::find_if(elements.begin(), elements.end(), [&](const FaceMaskElement& e) { return e.key == key; });
    };
    EXPECT_EQ(find("fap3").label, "open_jaw");
    EXPECT_GT(find("fap31").position.y, find("fap3").position.y + 0.05) << "the brows above the jaw";
    EXPECT_GT(find("fap31").position.x, 0.0f) << "the left brow on the character's left (+x)";
}

} // namespace
} // namespace thespis::core::scene
