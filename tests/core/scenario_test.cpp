// Tests of the scenario document (core/scenario): the version 1 format and its golden files,
// round trips, unknown fields, version handling, malformed input, atomic saves, upgrade steps,
// and building runnable schedules from the demo and from fixtures.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numbers>
#include <set>
#include <sstream>
#include <unistd.h>

#include "anim/hanim.h"
#include "scenario/scenario_io.h"
#include "scenario/scenario_runtime.h"
#include "scenario/scenario_upgrade.h"
#include "test_support.h"
#include "util/file_io.h"

namespace fs = std::filesystem;
using namespace thespis::core;
using namespace thespis::core::scenario;
using nlohmann::json;

namespace {

std::string readFile(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// A fresh, empty folder for one test, removed afterwards.
class TempDir {
public:
    TempDir()
    {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        m_path = fs::temp_directory_path()
                 / ("thespis_scenario_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
        fs::remove_all(m_path);
        fs::create_directories(m_path);
    }
    ~TempDir()
    {
        std::error_code ec;
        fs::permissions(m_path, fs::perms::owner_all, fs::perm_options::add, ec);
        fs::remove_all(m_path, ec);
    }
    const fs::path& path() const { return m_path; }

private:
    fs::path m_path;
};

std::vector<std::string> filesIn(const fs::path& folder)
{
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(folder))
        names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

fs::path goldenV1() { return thespis::test::testData("formats/v1/scenario.thespis"); }
fs::path goldenV2() { return thespis::test::testData("formats/v2/scenario.thespis"); }
fs::path goldenV3() { return thespis::test::testData("formats/v3/scenario.thespis"); }
fs::path goldenV4() { return thespis::test::testData("formats/v4/scenario.thespis"); }
fs::path goldenV5() { return thespis::test::testData("formats/v5/scenario.thespis"); }
fs::path demoPath() { return thespis::test::resources("demo.thespis"); }

Scenario loadOrFail(const fs::path& path)
{
    auto scenario = loadScenario(path);
    if (!scenario) {
        ADD_FAILURE() << describe(scenario.error());
        return {};
    }
    return std::move(scenario).value();
}

// A small valid document, the base of the malformed-input table.
json minimalDocument()
{
    return json::parse(R"({
      "format": "thespis-scenario", "version": 1, "schema": "Scenario.1", "name": "t", "duration": 0,
      "masks": [{"schema": "Mask.1", "name": "arm", "defaultWeight": 0.0, "weights": {"r_shoulder": 1.0}}],
      "characters": [{
        "schema": "Character.1", "name": "A", "skeleton": "hanim-loa1",
        "clips": [{"schema": "Clip.1", "name": "c", "frameRate": 30.0, "joints": ["humanoid_root", "r_shoulder"],
                   "rootTranslation": true,
                   "frames": [[0, 0, 0, 1, 0, 0, 0, 1, 0, 0.98, 0], [0, 0, 0, 1, 0, 0, -0.5, 0.866, 0, 0.98, 0]]}],
        "layers": [{"schema": "Layer.1", "name": "body", "kind": "body", "mode": "normalized", "actions": [{
          "schema": "Action.1", "name": "a", "clip": "c", "start": 0,
          "modifiers": [{"schema": "Modifier.1", "kind": "loop", "count": 2}],
          "weight": {"schema": "Curve.1", "kind": "cubicFade", "fadeIn": 0.1, "fadeOut": 0.1, "peak": 1.0},
          "scale": {"schema": "Curve.1", "kind": "constant", "value": 1.0},
          "mask": "arm", "mode": "normalized", "renderOutsideDomain": false}]}]
      }]
    })");
}

Result<Scenario> parseJson(const json& document) { return parseScenario(document.dump()); }

float quatLength(std::span<const float> frame, int rotation)
{
    const anim::Quat& q = anim::rotationAt(frame, rotation);
    return std::sqrt(anim::dot(q, q));
}

} // namespace

// ---------------------------------------------------------------------------------------------
// Golden files

TEST(ScenarioGolden, LoadsVersion1WithEveryField)
{
    const Scenario s = loadOrFail(goldenV1());
    EXPECT_EQ(s.name, "Golden scenario, format 1");
    EXPECT_EQ(s.duration, 10 * TicksPerSecond);
    EXPECT_EQ(s.extra["studio"]["camera"], "wide");
    EXPECT_EQ(s.extra["studio"]["notes"], json::parse(R"(["first", 2, null])"));

    ASSERT_EQ(s.masks.size(), 2u);
    EXPECT_EQ(s.masks[0].name, "upper");
    EXPECT_FLOAT_EQ(s.masks[0].mask.defaultWeight(), 0.25f);
    EXPECT_FLOAT_EQ(s.masks[0].mask.weight("vl5"), 0.5f);
    EXPECT_FLOAT_EQ(s.masks[0].mask.weight("vt1"), 1.0f);
    EXPECT_EQ(s.masks[0].extra["color"], "#ff8800");
    EXPECT_TRUE(s.masks[1].mask.weights().empty());

    ASSERT_EQ(s.characters.size(), 2u);
    const Character& mocap = s.characters[0];
    EXPECT_EQ(mocap.skeleton, "clip:walk");
    ASSERT_EQ(mocap.clips.size(), 2u);
    EXPECT_EQ(mocap.clips[0].file, "../../scenarios/tiny_body.bvh");
    EXPECT_EQ(mocap.clips[0].frameRateOverride, 0.0);
    EXPECT_EQ(mocap.clips[1].frameRateOverride, 5.0);
    EXPECT_EQ(mocap.clips[1].extra["source"], "made for the tests");

    ASSERT_EQ(mocap.layers.size(), 2u);
    const Layer& base = mocap.layers[0];
    EXPECT_EQ(base.kind, LayerKind::Body);
    EXPECT_EQ(base.mode, anim::BlendMode::Normalized);
    ASSERT_EQ(base.actions.size(), 2u);
    const ActionSpec& walk = base.actions[0];
    ASSERT_EQ(walk.modifiers.size(), 2u);
    EXPECT_EQ(walk.modifiers[0].kind, ModifierKind::TimeStretch);
    EXPECT_EQ(walk.modifiers[0].factor, 1.5);
    EXPECT_EQ(walk.modifiers[1].kind, ModifierKind::Loop);
    EXPECT_EQ(walk.modifiers[1].count, 3);
    EXPECT_TRUE(walk.renderOutsideDomain);
    EXPECT_TRUE(walk.weight.isIdentity());

    const ActionSpec& wave = base.actions[1];
    EXPECT_EQ(wave.start, 1058400000); // 1.5 s, exactly
    EXPECT_EQ(wave.modifiers[0].kind, ModifierKind::Trim);
    EXPECT_EQ(wave.modifiers[0].start, 0.125);
    EXPECT_EQ(wave.modifiers[0].end, 0.75);
    EXPECT_EQ(wave.modifiers[1].kind, ModifierKind::TimeOffset);
    EXPECT_EQ(wave.modifiers[1].offset, -0.5);
    EXPECT_EQ(wave.weight, anim::Curve::linearFade(0.25, 0.5, 0.8));
    EXPECT_EQ(wave.scale, anim::Curve::cubicFade(0.1, 0.1, 1.0));
    EXPECT_EQ(wave.mask, "upper");
    EXPECT_EQ(wave.mode, anim::BlendMode::Override);

    const Layer& gestures = mocap.layers[1];
    EXPECT_EQ(gestures.mode, anim::BlendMode::Additive);
    const ActionSpec& mirrored = gestures.actions[0];
    EXPECT_EQ(mirrored.start, 5 * TicksPerSecond);
    EXPECT_EQ(mirrored.modifiers[0].kind, ModifierKind::Mirror);
    EXPECT_EQ(mirrored.modifiers[0].axis, 0);
    EXPECT_EQ(mirrored.modifiers[1].kind, ModifierKind::GlobalTransform);
    EXPECT_EQ(mirrored.modifiers[1].rotation, (anim::Quat{0.0f, 0.6f, 0.0f, 0.8f}));
    EXPECT_EQ(mirrored.modifiers[1].translation, (anim::Vec3{1.5f, 0.0f, -2.0f}));
    EXPECT_EQ(mirrored.weight, anim::Curve::linearAdsr(0.2, 0.3, 0.5, 0.4, 1.0));
    EXPECT_EQ(mirrored.scale, anim::Curve::cubicAdsr(0.1, 0.2, 0.75, 0.3, 1.25));
    EXPECT_EQ(mirrored.mode, anim::BlendMode::Additive);

    const Character& inl = s.characters[1];
    EXPECT_EQ(inl.skeleton, "hanim-loa1");
    EXPECT_EQ(inl.extra["color"], "blue");
    const ClipAsset& sway = inl.clips[0];
    EXPECT_TRUE(sway.file.empty());
    EXPECT_EQ(sway.frameRate, 2.0);
    EXPECT_EQ(sway.joints, (std::vector<std::string>{"humanoid_root", "l_shoulder"}));
    EXPECT_TRUE(sway.rootTranslation);
    ASSERT_EQ(sway.frames.size(), 33u);
    EXPECT_EQ(sway.frames[9], 0.98f);
    EXPECT_EQ(sway.frames[11 + 6], 0.258819f);
    const ClipAsset& smile = inl.clips[1];
    EXPECT_EQ(smile.scalars, (std::vector<std::string>{"fap12", "fap13"}));
    EXPECT_EQ(smile.frames, (std::vector<float>{0.0f, 0.0f, 120.5f, 118.0f}));

    const ActionSpec& swayAction = inl.layers[0].actions[0];
    ASSERT_EQ(swayAction.modifiers.size(), 1u);
    EXPECT_EQ(swayAction.modifiers[0].kind, ModifierKind::TimeWarp);
    EXPECT_EQ(swayAction.modifiers[0].duration, 2.0);
    EXPECT_DOUBLE_EQ(swayAction.modifiers[0].warp.evaluate(1.0), 0.5);
    ASSERT_EQ(swayAction.weight.kind(), anim::CurveKind::Keyframed);
    const auto& keys = swayAction.weight.keys();
    ASSERT_EQ(keys.size(), 5u);
    EXPECT_EQ(keys[0].mode, anim::TangentMode::AutoClamped);
    EXPECT_EQ(keys[1].mode, anim::TangentMode::Linear);
    EXPECT_EQ(keys[2].mode, anim::TangentMode::Constant);
    EXPECT_EQ(keys[3].mode, anim::TangentMode::Free);
    EXPECT_EQ(keys[3].inSlope, -0.25);
    EXPECT_EQ(keys[4].mode, anim::TangentMode::Broken);
    EXPECT_EQ(keys[4].inSlope, -1.5);
    EXPECT_EQ(keys[4].outSlope, 0.5);
    EXPECT_EQ(swayAction.weightExtra["label"], "custom");
    EXPECT_EQ(swayAction.weightExtra["keys"][4]["selected"], true);
    EXPECT_EQ(swayAction.extra["comment"], "written by hand");

    const Layer& face = inl.layers[1];
    EXPECT_EQ(face.kind, LayerKind::Face);
    EXPECT_EQ(face.mode, anim::BlendMode::Override);
    EXPECT_EQ(face.extra["muted"], false);
    EXPECT_EQ(face.actions[0].scale, anim::Curve::constant(1.5));
    EXPECT_EQ(face.actions[0].start, TicksPerSecond);
}

TEST(ScenarioGolden, EveryGoldenFileLoadsAndRewritesByteForByte)
{
    // One folder per format version (STYLE.md §7); each file in it must still load, and the
    // current version's files must be exactly what the writer produces.
    int files = 0;
    for (const auto& folder : fs::directory_iterator(thespis::test::testData("formats"))) {
        for (const auto& entry : fs::directory_iterator(folder.path())) {
            if (entry.path().extension() != FileExtension)
                continue;
            SCOPED_TRACE(entry.path().string());
            ++files;
            const Scenario s = loadOrFail(entry.path());
            if (folder.path().filename() == "v" + std::to_string(int(format::Current))) {
                EXPECT_EQ(serializeScenario(s), readFile(entry.path()));
            }
            auto again = parseScenario(serializeScenario(s));
            ASSERT_TRUE(again.ok()) << describe(again.error());
            EXPECT_EQ(*again, s);
        }
    }
    EXPECT_GE(files, 1);
}

TEST(ScenarioGolden, LoadsVersion2TimelineStateGesticonAndMarkers)
{
    const Scenario s = loadOrFail(goldenV2());
    ASSERT_EQ(s.characters.size(), 2u);
    const Character& mocap = s.characters[0];
    const Character& inl = s.characters[1];
    EXPECT_TRUE(mocap.layers[0].lock);
    EXPECT_FALSE(mocap.layers[0].mute || mocap.layers[0].solo);
    EXPECT_TRUE(mocap.layers[1].solo);
    EXPECT_TRUE(inl.layers[1].mute);
    // "muted" was never a field of the format: it stays an unknown field, as in version 1.
    EXPECT_EQ(inl.layers[1].extra["muted"], false);

    ASSERT_EQ(mocap.gestures.size(), 2u);
    const Gesture& greet = mocap.gestures[0];
    EXPECT_EQ(greet.name, "greet");
    EXPECT_EQ(greet.clip, "wave");
    EXPECT_EQ(greet.mask, "upper");
    EXPECT_EQ(greet.fadeIn, TicksPerSecond / 4);
    EXPECT_EQ(greet.fadeOut, TicksPerSecond / 2);
    EXPECT_TRUE(greet.dependentJointFilter);
    EXPECT_TRUE(mocap.gestures[1].mask.empty());
    EXPECT_EQ(mocap.gestures[1].extra["note"], "kept as written");
    EXPECT_EQ(mocap.findGesture("stroll"), &mocap.gestures[1]);
    EXPECT_EQ(mocap.findGesture("nope"), nullptr);
    ASSERT_EQ(inl.gestures.size(), 1u);

    ASSERT_EQ(s.markers.size(), 2u);
    EXPECT_EQ(s.markers[0].name, "start of wave");
    EXPECT_EQ(s.markers[0].time, TicksPerSecond);
    EXPECT_TRUE(s.markers[1].name.empty());
    EXPECT_EQ(s.markers[1].time, 5 * TicksPerSecond + TicksPerSecond / 30);
    for (const Error& e : validateScenario(s, goldenV2().parent_path()))
        ADD_FAILURE() << describe(e);
}

TEST(ScenarioGolden, LoadsVersion3ImportOptionsAndPlacement)
{
    const Scenario s = loadOrFail(goldenV3());
    const Character& mocap = s.characters.at(0);
    EXPECT_EQ(mocap.position, (anim::Vec3{1.5f, 0.0f, -0.25f}));
    EXPECT_EQ(mocap.heading, 30.0);
    const ClipAsset& clip = mocap.clips.at(0);
    EXPECT_EQ(clip.unit, 0.01);
    EXPECT_FALSE(clip.fitGround);
    EXPECT_TRUE(clip.keepCalibrationFrame);
    EXPECT_EQ(clip.mapping.at("Hips"), "humanoid_root");
    EXPECT_EQ(mocap.layers.at(0).actions.at(0).placement, Placement::Continue);
    EXPECT_EQ(s.characters.at(1).layers.at(0).actions.at(0).placement, Placement::Character);
    EXPECT_EQ(s.lighting.rotation, 45.0);
    EXPECT_EQ(s.lighting.intensity, 1.5);
    bool rootMotion = false;
    for (const Layer& layer : mocap.layers)
        for (const ActionSpec& action : layer.actions)
            for (const ModifierSpec& m : action.modifiers)
                rootMotion = rootMotion || (m.kind == ModifierKind::Loop && m.rootMotion);
    EXPECT_TRUE(rootMotion);
    // Written back in the current format, it reads back the same.
    auto back = parseScenario(serializeScenario(s));
    ASSERT_TRUE(back) << describe(back.error());
    EXPECT_EQ(*back, s);
}

TEST(ScenarioGolden, LoadsVersion4Scripts)
{
    const Scenario s = loadOrFail(goldenV4());
    ASSERT_EQ(s.scripts.size(), 1u);
    EXPECT_EQ(s.scripts[0].name, "greet");
    EXPECT_NE(s.scripts[0].source.find("animService.waitUntilActionFinished_body(\"Creon\", \"creon_nod\", -0.5)\n"),
              std::string::npos);
    EXPECT_NE(s.findScript("greet"), nullptr);
    EXPECT_EQ(s.findScript("other"), nullptr);
    // Written back in the current format, it reads back the same.
    auto back = parseScenario(serializeScenario(s));
    ASSERT_TRUE(back) << describe(back.error());
    EXPECT_EQ(*back, s);
}

TEST(ScenarioGolden, LoadsVersion5IdleClips)
{
    const Scenario s = loadOrFail(goldenV5());
    const ClipAsset* idle = s.characters.at(1).findClip("idle");
    ASSERT_NE(idle, nullptr);
    ASSERT_TRUE(idle->idle.has_value());
    EXPECT_EQ(idle->idle->database, "idle/cmu_standing.idle");
    EXPECT_EQ(idle->idle->seed, 7u);
    EXPECT_EQ(idle->idle->amplitude, 0.5);
    EXPECT_EQ(idle->idle->extra["style"], "calm");
    EXPECT_TRUE(idle->file.empty());
    // The writer's bytes are checked on the current version's golden file (v8).
}

TEST(ScenarioGolden, Version4UpgradesToVersion5WithoutIdleClips)
{
    Scenario v5 = loadOrFail(goldenV5());
    auto& clips = v5.characters.at(1).clips;
    clips.erase(std::remove_if(clips.begin(), clips.end(), [](const ClipAsset& c) { return c.idle.has_value(); }),
                clips.end());
    Scenario v4 = loadOrFail(goldenV4());
    v4.name = v5.name;
    EXPECT_EQ(v4, v5);
}

TEST(ScenarioIo, IdleClipsHaveNoFileAndSaneParameters)
{
    json doc = minimalDocument();
    const auto withClip = [&](json clip) {
        json d = doc;
        d["characters"][0]["clips"][0] = std::move(clip);
        return parseJson(d);
    };
    auto both = withClip({{"name", "c"}, {"file", "x.bvh"}, {"idle", {{"database", "i.idle"}}}});
    ASSERT_FALSE(both);
    EXPECT_NE(both.error().message.find("characters[0].clips[0].file"), std::string::npos) << both.error().message;
    auto noDatabase = withClip({{"name", "c"}, {"idle", {{"seed", 3}}}});
    ASSERT_FALSE(noDatabase);
    EXPECT_NE(noDatabase.error().message.find("clips[0].idle.database"), std::string::npos) << noDatabase.error().message;
    auto loud = withClip({{"name", "c"}, {"idle", {{"database", "i.idle"}, {"amplitude", 50}}}});
    ASSERT_FALSE(loud);
    EXPECT_NE(loud.error().message.find("idle.amplitude"), std::string::npos) << loud.error().message;
    auto negativeSeed = withClip({{"name", "c"}, {"idle", {{"database", "i.idle"}, {"seed", -1}}}});
    ASSERT_FALSE(negativeSeed);
    EXPECT_NE(negativeSeed.error().message.find("idle.seed"), std::string::npos) << negativeSeed.error().message;
}

TEST(ScenarioGolden, Version3UpgradesToVersion4WithoutScripts)
{
    Scenario v4 = loadOrFail(goldenV4());
    v4.scripts.clear();
    Scenario v3 = loadOrFail(goldenV3());
    v3.name = v4.name;
    EXPECT_EQ(v3, v4);
}

TEST(ScenarioIo, ScriptsNeedUniqueNamesAndASource)
{
    json doc = minimalDocument();
    doc["scripts"] = json::array({{{"schema", "Script.1"}, {"name", "a"}, {"source", "pass"}},
                                  {{"schema", "Script.1"}, {"name", "a"}, {"source", "pass"}}});
    auto twice = parseJson(doc);
    ASSERT_FALSE(twice);
    EXPECT_NE(twice.error().message.find("scripts[1].name"), std::string::npos) << twice.error().message;
    doc["scripts"] = json::array({{{"schema", "Script.1"}, {"name", "a"}}});
    auto noSource = parseJson(doc);
    ASSERT_FALSE(noSource);
    EXPECT_NE(noSource.error().message.find("scripts[0].source"), std::string::npos) << noSource.error().message;
}

TEST(ScenarioGolden, Version2UpgradesToVersion3WithoutTheNewFields)
{
    Scenario v3 = loadOrFail(goldenV3());
    v3.characters[0].position = {};
    v3.characters[0].heading = 0;
    v3.characters[0].clips[0].unit = 0;
    v3.characters[0].clips[0].fitGround = true;
    v3.characters[0].clips[0].keepCalibrationFrame = false;
    v3.characters[0].clips[0].mapping.clear();
    for (Character& character : v3.characters)
        for (Layer& layer : character.layers)
            for (ActionSpec& action : layer.actions) {
                action.placement = Placement::World;
                for (ModifierSpec& m : action.modifiers)
                    m.rootMotion = false;
            }
    v3.lighting.rotation = 0;
    v3.lighting.intensity = 1;
    Scenario v2 = loadOrFail(goldenV2());
    v2.name = v3.name;
    EXPECT_EQ(v2, v3);
}

TEST(ScenarioGolden, Version1UpgradesToVersion2WithoutTheNewFields)
{
    // The version 2 golden file is the version 1 one plus the new fields: taking those away
    // again must give exactly what the upgraded version 1 file reads as.
    Scenario v2 = loadOrFail(goldenV2());
    for (Character& character : v2.characters) {
        character.gestures.clear();
        for (Layer& layer : character.layers)
            layer.mute = layer.solo = layer.lock = false;
    }
    v2.markers.clear();
    Scenario v1 = loadOrFail(goldenV1());
    v1.name = v2.name;
    EXPECT_EQ(v1, v2);
}

TEST(ScenarioGolden, Version1GoldenValidatesAndBuilds)
{
    const Scenario s = loadOrFail(goldenV1());
    const auto problems = validateScenario(s, goldenV1().parent_path());
    for (const Error& e : problems)
        ADD_FAILURE() << describe(e);
    auto runtime = buildRuntime(s, goldenV1().parent_path());
    ASSERT_TRUE(runtime.ok()) << describe(runtime.error());
    EXPECT_EQ(runtime->duration, 10 * TicksPerSecond);
}

// ---------------------------------------------------------------------------------------------
// Round trips and unknown fields

TEST(ScenarioIo, SaveLoadRoundTripIsExact)
{
    TempDir dir;
    const Scenario original = loadOrFail(goldenV1());
    const fs::path path = dir.path() / "copy.thespis";
    ASSERT_TRUE(saveScenario(path, original).ok());
    const Scenario loaded = loadOrFail(path);
    EXPECT_EQ(loaded, original);
    EXPECT_EQ(serializeScenario(loaded), readFile(path));
    EXPECT_EQ(filesIn(dir.path()), (std::vector<std::string>{"copy.thespis"}));
}

TEST(ScenarioIo, RoundTripKeepsExactTicksAndFloats)
{
    Scenario s;
    s.name = "ticks";
    s.duration = std::numeric_limits<Tick>::max();
    Character c;
    c.name = "C";
    ClipAsset clip;
    clip.name = "k";
    clip.joints = {"skullbase"};
    clip.frames = {0.1f, 0.2f, 0.3f, 0.9f, 1e-7f, -3.4028235e38f, 0.333333343f, 0.7f};
    c.clips.push_back(clip);
    Layer layer;
    layer.name = "l";
    ActionSpec a;
    a.name = "a";
    a.clip = "k";
    a.start = 1; // one tick
    a.weight = anim::Curve::cubicAdsr(1.0 / 3.0, 0.1, 0.2, 1e-9, 0.7);
    layer.actions.push_back(a);
    c.layers.push_back(layer);
    s.characters.push_back(c);
    auto again = parseScenario(serializeScenario(s));
    ASSERT_TRUE(again.ok()) << describe(again.error());
    EXPECT_EQ(*again, s);
    // Floats are written in their shortest form, not as their double expansion.
    EXPECT_NE(serializeScenario(s).find("[0.1, 0.2, 0.3, 0.9]"), std::string::npos);
}

TEST(ScenarioIo, ADominanceWeightCurveRoundTrips)
{
    auto s = parseJson(minimalDocument());
    ASSERT_TRUE(s.ok()) << describe(s.error());
    s->characters[0].layers[0].actions[0].weight = anim::Curve::dominance(3.5, 0.75);
    const std::string text = serializeScenario(*s);
    EXPECT_EQ(json::parse(text)["characters"][0]["layers"][0]["actions"][0]["weight"],
              json::parse(R"({"schema": "Curve.1", "kind": "dominance", "alpha": 3.5, "peak": 0.75})"));
    auto again = parseScenario(text);
    ASSERT_TRUE(again.ok()) << describe(again.error());
    EXPECT_EQ(*again, *s);
    EXPECT_EQ(again->characters[0].layers[0].actions[0].weight.kind(), anim::CurveKind::Dominance);
}

TEST(ScenarioIo, ModelSegmentTagsAndLightingRoundTrip)
{
    Scenario s;
    s.name = "lit";
    Character c;
    c.name = "Robot";
    c.model = "robot.glb";
    c.segmentTags = {{"hair", scene::SegmentRole::Receiver}, {"coat", scene::SegmentRole::Occluder}};
    c.bake = "bakes/lit-Robot-dsm-o5-0badc0de.prt";
    s.characters.push_back(c);
    s.lighting.probe = "probes/sunset.hdr";
    s.lighting.layout = "angular";
    const std::string text = serializeScenario(s);
    EXPECT_NE(text.find("\"role\": \"receiver\""), std::string::npos) << text;
    EXPECT_NE(text.find("\"bake\": \"bakes/lit-Robot-dsm-o5-0badc0de.prt\""), std::string::npos) << text;
    auto again = parseScenario(text);
    ASSERT_TRUE(again.ok()) << describe(again.error());
    EXPECT_EQ(*again, s);

    // Without a model, tags, bake or probe nothing new is written: older scenarios stay byte-identical.
    Scenario plain;
    plain.characters.push_back(Character{.name = "Plain"});
    const std::string plainText = serializeScenario(plain);
    for (const char* member : {"\"model\"", "\"segments\"", "\"bake\"", "\"lighting\""})
        EXPECT_EQ(plainText.find(member), std::string::npos) << member;
}

TEST(ScenarioIo, TheArPlacementAndPhantomOccludersRoundTrip)
{
    Scenario s;
    s.characters.push_back(Character{.name = "Hero"});
    s.ar.offset = {0.02, -0.015};
    s.ar.heading = 90;
    s.ar.scale = 0.1;
    s.ar.shadowCatcher = false;
    s.ar.occluders.push_back({"cup", PhantomOccluder::Shape::Model, {0.3, 0, 0.1}, {1, 1, 1}, 15, "props/cup.glb"});
    s.ar.occluders.push_back({"", PhantomOccluder::Shape::Box, {0, 0, 0.5}, {1.2, 0.8, 0.3}, 0, ""});
    const std::string text = serializeScenario(s);
    EXPECT_NE(text.find("\"schema\": \"PhantomOccluder.1\""), std::string::npos) << text;
    auto again = parseScenario(text);
    ASSERT_TRUE(again.ok()) << describe(again.error());
    EXPECT_EQ(*again, s);
    // Rebased with the rest of the scenario's files.
    rebasePaths(s, "/a/scenes", "/a");
    EXPECT_EQ(s.ar.occluders[0].model, "scenes/props/cup.glb");
    // The defaults write nothing: scenarios without AR stay as they were.
    Scenario plain;
    plain.characters.push_back(Character{.name = "Plain"});
    EXPECT_EQ(serializeScenario(plain).find("\"ar\""), std::string::npos);
}

TEST(ScenarioIo, UnknownFieldsSurviveAtEveryLevel)
{
    json doc = minimalDocument();
    doc["future"] = {{"a", 1}};
    doc["masks"][0]["tint"] = "red";
    doc["characters"][0]["portrait"] = "creon.png";
    doc["characters"][0]["clips"][0]["license"] = "CC0";
    doc["characters"][0]["layers"][0]["locked"] = true;
    json& action = doc["characters"][0]["layers"][0]["actions"][0];
    action["note"] = json::array({1, 2.5, "x"});
    action["weight"]["handle"] = 3;
    action["modifiers"][0]["ui"] = {{"collapsed", true}};
    action["scale"] = json::parse(R"({"schema": "Curve.1", "kind": "keyframed", "keys": [
        {"time": 0.0, "value": 1.0, "tangent": "free", "inSlope": 2.0, "color": "blue"},
        {"time": 1.0, "value": 2.0}]})");

    auto first = parseJson(doc);
    ASSERT_TRUE(first.ok()) << describe(first.error());
    const std::string written = serializeScenario(*first);
    auto second = parseScenario(written);
    ASSERT_TRUE(second.ok()) << describe(second.error());
    EXPECT_EQ(*second, *first);

    const json out = json::parse(written);
    EXPECT_EQ(out["future"], doc["future"]);
    EXPECT_EQ(out["masks"][0]["tint"], "red");
    EXPECT_EQ(out["characters"][0]["portrait"], "creon.png");
    EXPECT_EQ(out["characters"][0]["clips"][0]["license"], "CC0");
    EXPECT_EQ(out["characters"][0]["layers"][0]["locked"], true);
    const json& a = out["characters"][0]["layers"][0]["actions"][0];
    EXPECT_EQ(a["note"], action["note"]);
    EXPECT_EQ(a["weight"]["handle"], 3);
    EXPECT_EQ(a["modifiers"][0]["ui"]["collapsed"], true);
    EXPECT_EQ(a["scale"]["keys"][0]["color"], "blue");
    EXPECT_FALSE(a["scale"]["keys"][1].contains("color"));
    EXPECT_EQ(a["scale"]["keys"][1]["tangent"], "autoClamped");
}

TEST(ScenarioIo, UnknownFieldWithAnEmptyNameSurvives)
{
    // Found by fuzz_scenario: a member named "" was taken for "nothing to skip" and dropped.
    json doc = minimalDocument();
    doc[""] = 1;
    doc["characters"][0]["layers"][0][""] = "body";
    doc["characters"][0]["layers"][0]["actions"][0]["scale"] = json::parse(R"({"schema": "Curve.1", "kind": "keyframed",
        "keys": [{"time": 0.0, "value": 1.0, "": 7}]})");
    auto first = parseJson(doc);
    ASSERT_TRUE(first.ok()) << describe(first.error());
    const json out = json::parse(serializeScenario(*first));
    EXPECT_EQ(out[""], 1);
    EXPECT_EQ(out["characters"][0]["layers"][0][""], "body");
    EXPECT_EQ(out["characters"][0]["layers"][0]["actions"][0]["scale"]["keys"][0][""], 7);
    auto second = parseScenario(out.dump());
    ASSERT_TRUE(second.ok());
    EXPECT_EQ(*second, *first);
}

TEST(ScenarioIo, WriterPutsFormatAndVersionFirst)
{
    const std::string text = serializeScenario(Scenario{});
    EXPECT_EQ(text.rfind("{\n  \"format\": \"thespis-scenario\",\n  \"version\": 12,\n  \"schema\": \"Scenario.12\"", 0), 0u)
        << text;
    auto back = parseScenario(text);
    ASSERT_TRUE(back.ok());
    EXPECT_EQ(*back, Scenario{});
}

// ---------------------------------------------------------------------------------------------
// Versions and formats

TEST(ScenarioIo, RefusesNewerVersion)
{
    json doc = minimalDocument();
    doc["version"] = 13;
    auto result = parseJson(doc);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.error().code, ErrorCode::NewerVersion);
    EXPECT_EQ(result.error().message,
              "This scenario was saved by a newer Thespis (format 13). Update Thespis to open it.");

    doc["version"] = 18446744073709551615ull;
    result = parseJson(doc);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.error().code, ErrorCode::NewerVersion);
}

TEST(ScenarioIo, RefusesWhatIsNotAScenario)
{
    const char* cases[] = {
        "",
        "   ",
        "HIERARCHY\nROOT Hips\n",
        "[1, 2, 3]",
        "\"thespis-scenario\"",
        R"({"version": 1})",
        R"({"format": "otio", "version": 1})",
        R"({"format": 7, "version": 1})",
        "\x89PNG\r\n\x1a\n",
    };
    for (const char* text : cases) {
        SCOPED_TRACE(text);
        auto result = parseScenario(text);
        ASSERT_FALSE(result.ok());
        EXPECT_EQ(result.error().code, ErrorCode::NotOurFormat) << result.error().message;
    }
}

TEST(ScenarioIo, BadVersionsAreCorrupt)
{
    for (const json& version : {json(0), json(-2), json(1.5), json("1"), json(nullptr), json::array()}) {
        json doc = minimalDocument();
        doc["version"] = version;
        SCOPED_TRACE(version.dump());
        auto result = parseJson(doc);
        ASSERT_FALSE(result.ok());
        EXPECT_EQ(result.error().code, ErrorCode::CorruptData);
        EXPECT_EQ(result.error().message.rfind("version: ", 0), 0u) << result.error().message;
    }
    json doc = minimalDocument();
    doc.erase("version");
    auto result = parseJson(doc);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.error().code, ErrorCode::CorruptData);
    EXPECT_EQ(result.error().message, "version: this field is required but missing.");
}

TEST(ScenarioIo, SyntaxErrorsGiveLineAndColumn)
{
    const std::string text = "{\n  \"format\": \"thespis-scenario\",\n  \"version\": 1,\n  oops\n}\n";
    auto result = parseScenario(text);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.error().code, ErrorCode::CorruptData);
    EXPECT_EQ(result.error().message.rfind("line 4, column 3: ", 0), 0u) << result.error().message;

    auto truncated = parseScenario(R"({"format": "thespis-scenario", "version": 1, "characters": [)");
    ASSERT_FALSE(truncated.ok());
    EXPECT_EQ(truncated.error().code, ErrorCode::CorruptData);
    EXPECT_EQ(truncated.error().message.rfind("line 1, column ", 0), 0u) << truncated.error().message;

    auto invalidUtf8 = parseScenario("{\"format\": \"thespis-scenario\", \"version\": 1, \"name\": \"\xff\"}");
    ASSERT_FALSE(invalidUtf8.ok());
    EXPECT_EQ(invalidUtf8.error().code, ErrorCode::CorruptData);
}

TEST(ScenarioIo, NumbersBeyondDoubleArePointedAt)
{
    auto result = parseScenario("{\"format\": \"thespis-scenario\",\n \"version\": 1,\n \"duration\": 1e999}");
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.error().code, ErrorCode::CorruptData);
    EXPECT_EQ(result.error().message, "line 3, column 14: the scenario holds a number too large to read.");
}

TEST(ScenarioIo, RefusesDeepNestingWithoutRecursing)
{
    std::string text = R"({"format": "thespis-scenario", "version": 1, "x": )";
    text += std::string(100000, '[') + std::string(100000, ']') + "}";
    auto result = parseScenario(text);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.error().code, ErrorCode::CorruptData);
    EXPECT_NE(result.error().message.find("nests deeper"), std::string::npos) << result.error().message;

    // Brackets inside strings do not count.
    json doc = minimalDocument();
    doc["text"] = std::string(1000, '[');
    EXPECT_TRUE(parseJson(doc).ok());
}

// Each malformed document names the field that is wrong.
struct MalformedCase {
    const char* what;
    std::function<void(json&)> mutate;
    const char* expectedStart; // the message must start with this
};

TEST(ScenarioIo, MalformedFieldsAreNamed)
{
    auto action = [](json& d) -> json& { return d["characters"][0]["layers"][0]["actions"][0]; };
    auto clip = [](json& d) -> json& { return d["characters"][0]["clips"][0]; };
    const std::vector<MalformedCase> cases = {
        {"fractional ticks", [&](json& d) { action(d)["start"] = 1.5; },
         "characters[0].layers[0].actions[0].start: expected an integer number of ticks"},
        {"ticks as text", [&](json& d) { action(d)["start"] = "0"; },
         "characters[0].layers[0].actions[0].start: expected an integer number of ticks"},
        {"negative ticks", [&](json& d) { action(d)["start"] = -5; },
         "characters[0].layers[0].actions[0].start: must not be negative"},
        {"missing start", [&](json& d) { action(d).erase("start"); },
         "characters[0].layers[0].actions[0].start: this field is required but missing"},
        {"duration too large", [&](json& d) { d["duration"] = 18446744073709551615ull; },
         "duration: expected an integer number of ticks"},
        {"duration as float", [&](json& d) { d["duration"] = 1e30; }, "duration: expected an integer number of ticks"},
        {"missing name", [&](json& d) { d["characters"][0].erase("name"); },
         "characters[0].name: this field is required but missing"},
        {"empty name", [&](json& d) { d["characters"][0]["name"] = ""; }, "characters[0].name: must not be empty"},
        {"name not text", [&](json& d) { d["characters"][0]["name"] = 5; }, "characters[0].name: expected a text"},
        {"duplicate character", [&](json& d) { d["characters"].push_back(d["characters"][0]); },
         "characters[1].name: another character is already named \"A\""},
        {"characters not a list", [&](json& d) { d["characters"] = json::object(); }, "characters: expected a list"},
        {"unknown segment role", [&](json& d) { d["characters"][0]["segments"] = json::parse(R"([{"name": "hair", "role": "shiny"}])"); },
         "characters[0].segments[0].role: "},
        {"segment tagged twice", [&](json& d) { d["characters"][0]["segments"] = json::parse(R"([{"name": "hair"}, {"name": "hair"}])"); },
         "characters[0].segments[1].name: segment \"hair\" is tagged twice"},
        {"bake not text", [&](json& d) { d["characters"][0]["bake"] = 5; }, "characters[0].bake: expected a text"},
        {"unknown member of a tag", [&](json& d) { d["characters"][0]["segments"] = json::parse(R"([{"name": "hair", "colour": 1}])"); },
         "characters[0].segments[0].colour: unknown member of a segment tag"},
        {"ar scale zero", [&](json& d) { d["ar"] = json::parse(R"({"scale": 0})"); }, "ar.scale: must be greater than 0"},
        {"ar offset short", [&](json& d) { d["ar"] = json::parse(R"({"offset": [0.1]})"); },
         "ar.offset: expected 2 numbers"},
        {"occluder shape", [&](json& d) { d["ar"] = json::parse(R"({"occluders": [{"shape": "sphere"}]})"); },
         "ar.occluders[0].shape: "},
        {"occluder size", [&](json& d) { d["ar"] = json::parse(R"({"occluders": [{"shape": "box", "size": [1, -2, 1]}]})"); },
         "ar.occluders[0].size[1]: must be greater than 0"},
        {"occluder model missing", [&](json& d) { d["ar"] = json::parse(R"({"occluders": [{"shape": "model"}]})"); },
         "ar.occluders[0].model: this field is required but missing"},
        {"unknown probe layout", [&](json& d) { d["lighting"] = json::parse(R"({"probe": "p.hdr", "layout": "fisheye"})"); },
         "lighting.layout: "},
        {"layer not an object", [&](json& d) { d["characters"][0]["layers"][0] = 7; },
         "characters[0].layers[0]: expected an object"},
        {"wrong schema", [&](json& d) { action(d)["schema"] = "Action.7"; },
         "characters[0].layers[0].actions[0].schema: expected \"Action.4\""},
        {"unknown placement", [&](json& d) { action(d)["placement"] = "elsewhere"; },
         "characters[0].layers[0].actions[0].placement: expected \"world\", \"character\" or \"continue\""},
        {"root motion not a flag", [&](json& d) { action(d)["modifiers"][0]["rootMotion"] = 1; },
         "characters[0].layers[0].actions[0].modifiers[0].rootMotion: expected true or false"},
        {"import option on an inline clip", [&](json& d) { clip(d)["unit"] = 0.01; },
         "characters[0].clips[0].unit: only a clip read from a file has this"},
        {"negative unit", [&](json& d) { clip(d) = json::parse(R"({"name": "c", "file": "w.bvh", "unit": -1})"); },
         "characters[0].clips[0].unit: must not be negative"},
        {"mapping to a number", [&](json& d) { clip(d) = json::parse(R"({"name": "c", "file": "w.bvh", "mapping": {"Hips": 3}})"); },
         "characters[0].clips[0].mapping.Hips: expected a joint name"},
        {"position of two numbers", [&](json& d) { d["characters"][0]["position"] = json::array({1, 2}); },
         "characters[0].position: expected a position [x, y, z] in metres"},
        {"model rig without a model", [&](json& d) { d["characters"][0]["skeleton"] = "model"; },
         "characters[0].skeleton: \"model\" plays on the model's own rig, and the character has no model"},
        {"negative light intensity", [&](json& d) { d["lighting"] = json::parse(R"({"probe": "p.hdr", "intensity": -2})"); },
         "lighting.intensity: must not be negative"},
        {"filter band out of order",
         [&](json& d) {
             d["characters"][0]["gestures"] = json::parse(
                 R"([{"name": "g", "clip": "c", "dependentJointFilter": true, "filterFadeFrom": 35, "filterMuteAbove": 25}])");
         },
         "characters[0].gestures[0].filterMuteAbove: must not be below filterFadeFrom (35), found 25"},
        {"filter band past the posture", [&](json& d) {
             d["characters"][0]["gestures"] = json::parse(R"([{"name": "g", "clip": "c", "filterFadeFrom": 90}])");
         },
         "characters[0].gestures[0].filterFadeFrom: "},
        {"mask weight above 1", [&](json& d) { d["masks"][0]["weights"]["r_shoulder"] = 1.5; },
         "masks[0].weights.r_shoulder: must be between 0 and 1"},
        {"mask weight text", [&](json& d) { d["masks"][0]["weights"]["r_shoulder"] = "full"; },
         "masks[0].weights.r_shoulder: expected a number"},
        {"mask default negative", [&](json& d) { d["masks"][0]["defaultWeight"] = -0.1; },
         "masks[0].defaultWeight: must be between 0 and 1"},
        {"mask weights a list", [&](json& d) { d["masks"][0]["weights"] = json::array(); },
         "masks[0].weights: expected an object"},
        {"duplicate mask", [&](json& d) { d["masks"].push_back(d["masks"][0]); },
         "masks[1].name: another mask is already named \"arm\""},
        {"unknown curve kind", [&](json& d) { action(d)["weight"]["kind"] = "cubic"; },
         "characters[0].layers[0].actions[0].weight.kind: expected \"constant\", \"linearFade\""},
        {"negative fade", [&](json& d) { action(d)["weight"]["fadeIn"] = -1; },
         "characters[0].layers[0].actions[0].weight.fadeIn: must not be negative"},
        {"negative weight", [&](json& d) { action(d)["weight"]["peak"] = -1; },
         "characters[0].layers[0].actions[0].weight.peak: must not be negative"},
        {"sustain above 1",
         [&](json& d) {
             action(d)["weight"] = json::parse(R"({"kind": "linearAdsr", "attack": 0, "decay": 0, "sustain": 1.5, "release": 0})");
         },
         "characters[0].layers[0].actions[0].weight.sustain: must be between 0 and 1"},
        {"missing ADSR field",
         [&](json& d) { action(d)["scale"] = json::parse(R"({"kind": "cubicAdsr", "attack": 0, "decay": 0, "sustain": 1})"); },
         "characters[0].layers[0].actions[0].scale.release: this field is required but missing"},
        {"dominance alpha zero", [&](json& d) { action(d)["weight"] = json::parse(R"({"kind": "dominance", "alpha": 0, "peak": 1})"); },
         "characters[0].layers[0].actions[0].weight.alpha: must be greater than 0"},
        {"dominance without alpha", [&](json& d) { action(d)["weight"] = json::parse(R"({"kind": "dominance", "peak": 1})"); },
         "characters[0].layers[0].actions[0].weight.alpha: this field is required but missing"},
        {"no keys", [&](json& d) { action(d)["weight"] = json::parse(R"({"kind": "keyframed", "keys": []})"); },
         "characters[0].layers[0].actions[0].weight.keys: a keyframed curve needs at least one key"},
        {"keys out of order",
         [&](json& d) {
             action(d)["weight"] = json::parse(R"({"kind": "keyframed", "keys": [{"time": 1, "value": 0}, {"time": 1, "value": 1}]})");
         },
         "characters[0].layers[0].actions[0].weight.keys[1].time: keys must be in increasing time order"},
        {"unknown tangent",
         [&](json& d) {
             action(d)["weight"] = json::parse(R"({"kind": "keyframed", "keys": [{"time": 0, "value": 0, "tangent": "smooth"}]})");
         },
         "characters[0].layers[0].actions[0].weight.keys[0].tangent: expected \"autoClamped\""},
        {"unknown modifier", [&](json& d) { action(d)["modifiers"][0]["kind"] = "reverse"; },
         "characters[0].layers[0].actions[0].modifiers[0].kind: expected \"timeStretch\""},
        {"negative loop count", [&](json& d) { action(d)["modifiers"][0]["count"] = -1; },
         "characters[0].layers[0].actions[0].modifiers[0].count: must be between 0 and"},
        {"fractional loop count", [&](json& d) { action(d)["modifiers"][0]["count"] = 1.5; },
         "characters[0].layers[0].actions[0].modifiers[0].count: expected a whole number"},
        {"zero stretch", [&](json& d) { action(d)["modifiers"][0] = json::parse(R"({"kind": "timeStretch", "factor": 0})"); },
         "characters[0].layers[0].actions[0].modifiers[0].factor: must be greater than 0"},
        {"trim backwards", [&](json& d) { action(d)["modifiers"][0] = json::parse(R"({"kind": "trim", "start": 1, "end": 0.5})"); },
         "characters[0].layers[0].actions[0].modifiers[0].end: must be after start"},
        {"mirror axis", [&](json& d) { action(d)["modifiers"][0] = json::parse(R"({"kind": "mirror", "axis": 3})"); },
         "characters[0].layers[0].actions[0].modifiers[0].axis: must be between 0 and 2"},
        {"not a rotation",
         [&](json& d) { action(d)["modifiers"][0] = json::parse(R"({"kind": "globalTransform", "rotation": [0, 0, 0, 2]})"); },
         "characters[0].layers[0].actions[0].modifiers[0].rotation: expected a unit quaternion"},
        {"short translation",
         [&](json& d) { action(d)["modifiers"][0] = json::parse(R"({"kind": "globalTransform", "translation": [0, 1]})"); },
         "characters[0].layers[0].actions[0].modifiers[0].translation: expected a vector [x, y, z]"},
        {"warp without duration",
         [&](json& d) {
             action(d)["modifiers"][0] = json::parse(R"({"kind": "timeWarp", "warp": {"kind": "constant", "value": 0}})");
         },
         "characters[0].layers[0].actions[0].modifiers[0].duration: this field is required but missing"},
        {"bad warp curve",
         [&](json& d) { action(d)["modifiers"][0] = json::parse(R"({"kind": "timeWarp", "warp": 3, "duration": 1})"); },
         "characters[0].layers[0].actions[0].modifiers[0].warp: expected an object"},
        {"unknown blend mode", [&](json& d) { action(d)["mode"] = "multiply"; },
         "characters[0].layers[0].actions[0].mode: expected \"normalized\", \"additive\" or \"override\""},
        {"flag not boolean", [&](json& d) { action(d)["renderOutsideDomain"] = "yes"; },
         "characters[0].layers[0].actions[0].renderOutsideDomain: expected true or false"},
        {"mask not text", [&](json& d) { action(d)["mask"] = json::array(); },
         "characters[0].layers[0].actions[0].mask: expected a text"},
        {"unknown layer kind", [&](json& d) { d["characters"][0]["layers"][0]["kind"] = "hands"; },
         "characters[0].layers[0].kind: expected \"body\", \"face\" or \"gaze\""},
        {"duplicate layer", [&](json& d) { d["characters"][0]["layers"].push_back(d["characters"][0]["layers"][0]); },
         "characters[0].layers[1].name: another layer of this character is already named \"body\""},
        {"unknown skeleton", [&](json& d) { d["characters"][0]["skeleton"] = "hanim-99"; },
         "characters[0].skeleton: expected \"hanim-loa1\""},
        {"empty clip skeleton", [&](json& d) { d["characters"][0]["skeleton"] = "clip:"; },
         "characters[0].skeleton: expected \"hanim-loa1\""},
        {"frame of the wrong length", [&](json& d) { clip(d)["frames"][1].erase(3); },
         "characters[0].clips[0].frames[1]: expected a list of 11 numbers (2 rotations x y z w, a root translation x y z), found 10 values"},
        {"frame value not a number", [&](json& d) { clip(d)["frames"][0][3] = "one"; },
         "characters[0].clips[0].frames[0][3]: expected a number"},
        {"frame value beyond float", [&](json& d) { clip(d)["frames"][0][3] = 1e39; },
         "characters[0].clips[0].frames[0][3]: the number 1e+39 is too large"},
        {"frame not a list", [&](json& d) { clip(d)["frames"][0] = 1.0; },
         "characters[0].clips[0].frames[0]: expected a list of 11 numbers"},
        {"no frames", [&](json& d) { clip(d)["frames"] = json::array(); },
         "characters[0].clips[0].frames: an inline clip needs at least one frame"},
        {"zero frame rate", [&](json& d) { clip(d)["frameRate"] = 0; },
         "characters[0].clips[0].frameRate: must be greater than 0"},
        {"joint listed twice", [&](json& d) { clip(d)["joints"][1] = "humanoid_root"; },
         "characters[0].clips[0].joints[1]: \"humanoid_root\" is listed twice"},
        {"file and frames", [&](json& d) { clip(d)["file"] = "walk.bvh"; },
         "characters[0].clips[0].joints: a clip read from a file cannot also hold inline keyframes"},
        {"empty file", [&](json& d) { clip(d) = json::parse(R"({"name": "c", "file": ""})"); },
         "characters[0].clips[0].file: must not be empty"},
        {"file frame rate", [&](json& d) { clip(d) = json::parse(R"({"name": "c", "file": "a.bvh", "frameRate": -30})"); },
         "characters[0].clips[0].frameRate: must be greater than 0"},
        {"translation without joint",
         [&](json& d) { clip(d) = json::parse(R"({"name": "c", "frameRate": 30, "scalars": ["fap3"], "rootTranslation": true, "frames": [[0]]})"); },
         "characters[0].clips[0].rootTranslation: a root translation needs a root joint"},
        {"duplicate clip", [&](json& d) { d["characters"][0]["clips"].push_back(clip(d)); },
         "characters[0].clips[1].name: another clip of this character is already named \"c\""},
    };
    for (const MalformedCase& c : cases) {
        SCOPED_TRACE(c.what);
        json doc = minimalDocument();
        c.mutate(doc);
        auto result = parseJson(doc);
        ASSERT_FALSE(result.ok());
        EXPECT_EQ(result.error().code, ErrorCode::CorruptData);
        EXPECT_EQ(result.error().message.rfind(c.expectedStart, 0), 0u) << result.error().message;
    }
    // The base document itself is valid: each case fails for its own reason.
    EXPECT_TRUE(parseJson(minimalDocument()).ok());
}

TEST(ScenarioIo, LoadNamesTheFileAndMissingFiles)
{
    TempDir dir;
    const fs::path path = dir.path() / "broken.thespis";
    std::ofstream(path) << R"({"format": "thespis-scenario", "version": 1, "duration": -1})";
    auto broken = loadScenario(path);
    ASSERT_FALSE(broken.ok());
    EXPECT_EQ(broken.error().message.rfind("duration: must not be negative", 0), 0u);
    EXPECT_NE(broken.error().detail.find(path.string()), std::string::npos);

    auto missing = loadScenario(dir.path() / "nothing.thespis");
    ASSERT_FALSE(missing.ok());
    EXPECT_EQ(missing.error().code, ErrorCode::FileNotFound);
}

// ---------------------------------------------------------------------------------------------
// Atomic saves

TEST(ScenarioSave, ReplacesTheFileAndLeavesNoTemporary)
{
    TempDir dir;
    const fs::path path = dir.path() / "scene.thespis";
    Scenario first;
    first.name = "first";
    ASSERT_TRUE(saveScenario(path, first).ok());
    Scenario second = loadOrFail(goldenV1());
    ASSERT_TRUE(saveScenario(path, second).ok());
    EXPECT_EQ(loadOrFail(path), second);
    EXPECT_EQ(filesIn(dir.path()), (std::vector<std::string>{"scene.thespis"}));
}

TEST(ScenarioSave, FailedSaveKeepsTheOldFile)
{
    TempDir dir;
    // The target is a folder: the temporary file is written, but cannot replace it. The folder
    // and its content stay, and the temporary file is removed.
    const fs::path target = dir.path() / "scene.thespis";
    fs::create_directories(target);
    std::ofstream(target / "keep.txt") << "old";
    auto result = saveScenario(target, loadOrFail(goldenV1()));
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.error().code, ErrorCode::IoError);
    EXPECT_EQ(readFile(target / "keep.txt"), "old");
    EXPECT_EQ(filesIn(dir.path()), (std::vector<std::string>{"scene.thespis"}));
}

TEST(ScenarioSave, UnwritableFolderKeepsTheOldFile)
{
    if (::geteuid() == 0)
        GTEST_SKIP() << "root writes into read-only folders; FailedSaveKeepsTheOldFile covers the same path";
    TempDir dir;
    const fs::path path = dir.path() / "scene.thespis";
    Scenario old;
    old.name = "old";
    ASSERT_TRUE(saveScenario(path, old).ok());
    const std::string before = readFile(path);
    fs::permissions(dir.path(), fs::perms::owner_read | fs::perms::owner_exec);
    auto result = saveScenario(path, loadOrFail(goldenV1()));
    fs::permissions(dir.path(), fs::perms::owner_all);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.error().code, ErrorCode::IoError);
    EXPECT_EQ(readFile(path), before);
    EXPECT_EQ(filesIn(dir.path()), (std::vector<std::string>{"scene.thespis"}));
}

TEST(ScenarioSave, RefusesToWriteWhatCannotBeReadBack)
{
    TempDir dir;
    const fs::path path = dir.path() / "scene.thespis";
    Scenario good;
    good.name = "good";
    ASSERT_TRUE(saveScenario(path, good).ok());
    const std::string before = readFile(path);

    Scenario bad = loadOrFail(goldenV1());
    bad.characters[0].layers[0].actions[0].weight = anim::Curve::constant(std::nan(""));
    auto result = saveScenario(path, bad);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.error().code, ErrorCode::InvalidArgument);
    EXPECT_NE(result.error().message.find("characters[0].layers[0].actions[0].weight.value"), std::string::npos)
        << result.error().message;
    EXPECT_EQ(readFile(path), before);
}

// ---------------------------------------------------------------------------------------------
// Upgrade steps

namespace {

Result<void> renameTitleToName(json& doc)
{
    doc["name"] = doc.value("title", "");
    doc.erase("title");
    return {};
}

Result<void> secondsToTicks(json& doc)
{
    doc["duration"] = Tick(std::llround(doc.at("durationSeconds").get<double>() * double(TicksPerSecond)));
    doc.erase("durationSeconds");
    return {};
}

Result<void> refuse(json&) { return makeError(ErrorCode::CorruptData, "the masks are unreadable"); }

} // namespace

TEST(ScenarioUpgrade, RunsStepsInOrderFromTheFileVersion)
{
    const detail::UpgradeStep steps[] = {{1, "name field", &renameTitleToName}, {2, "exact ticks", &secondsToTicks}};
    json doc = {{"version", 1}, {"title", "old"}, {"durationSeconds", 2.5}};
    ASSERT_TRUE(detail::runUpgradeSteps(doc, 1, 3, steps).ok());
    EXPECT_EQ(doc, (json{{"version", 3}, {"name", "old"}, {"duration", 1764000000}}));

    // A file of version 2 only runs the second step.
    json v2 = {{"version", 2}, {"title", "kept"}, {"durationSeconds", 1.0}};
    ASSERT_TRUE(detail::runUpgradeSteps(v2, 2, 3, steps).ok());
    EXPECT_EQ(v2, (json{{"version", 3}, {"title", "kept"}, {"duration", TicksPerSecond}}));

    // Current files run nothing.
    json current = {{"version", 3}, {"title", "x"}};
    ASSERT_TRUE(detail::runUpgradeSteps(current, 3, 3, steps).ok());
    EXPECT_EQ(current, (json{{"version", 3}, {"title", "x"}}));
}

TEST(ScenarioUpgrade, ReportsMissingFailingAndThrowingSteps)
{
    const detail::UpgradeStep gap[] = {{1, "first", &renameTitleToName}};
    json doc = {{"version", 1}, {"durationSeconds", 1.0}};
    auto missing = detail::runUpgradeSteps(doc, 1, 3, gap);
    ASSERT_FALSE(missing.ok());
    EXPECT_EQ(missing.error().code, ErrorCode::Internal);
    EXPECT_NE(missing.error().message.find("from format 2 to 3"), std::string::npos);

    const detail::UpgradeStep failing[] = {{1, "joint mask weights", &refuse}};
    json other = {{"version", 1}};
    auto failed = detail::runUpgradeSteps(other, 1, 2, failing);
    ASSERT_FALSE(failed.ok());
    EXPECT_EQ(failed.error().code, ErrorCode::CorruptData);
    EXPECT_EQ(failed.error().message,
              "Upgrading the scenario from format 1 to 2 (joint mask weights) failed: the masks are unreadable");

    // json::at throws on a missing member; the runner turns that into an error.
    const detail::UpgradeStep throwing[] = {{1, "exact ticks", &secondsToTicks}};
    json noDuration = {{"version", 1}};
    auto thrown = detail::runUpgradeSteps(noDuration, 1, 2, throwing);
    ASSERT_FALSE(thrown.ok());
    EXPECT_EQ(thrown.error().code, ErrorCode::CorruptData);
}

TEST(ScenarioUpgrade, BuiltInTableCoversEveryOlderVersion)
{
    const auto steps = detail::upgradeSteps();
    ASSERT_EQ(int(steps.size()), int(format::Current) - int(format::Initial));
    for (std::size_t i = 0; i < steps.size(); ++i) {
        EXPECT_EQ(steps[i].from, int(format::Initial) + int(i));
        EXPECT_NE(steps[i].apply, nullptr);
    }
    json doc = minimalDocument();
    EXPECT_TRUE(detail::runUpgradeSteps(doc, format::Initial, format::Current, steps).ok());
}

// Version 5 tags could carry "posture" (pi / pd), which nothing read: a version 5 file keeps its
// roles and loses only that member; in a version 6 file the member is unknown and named.
TEST(ScenarioUpgrade, Version5SegmentTagsKeepTheirRolesAndLoseThePosture)
{
    const std::string character = R"({"schema": "Character.3", "name": "Robot", "skeleton": "hanim-loa1",
        "segments": [{"name": "Hair", "role": "receiver", "posture": "pi"}, {"name": "Arm", "posture": "pd"}]})";
    const std::string v5 = R"({"format": "thespis-scenario", "version": 5, "schema": "Scenario.5", "name": "s",
        "duration": 0, "characters": [)" + character + "]}";
    auto upgraded = parseScenario(v5);
    ASSERT_TRUE(upgraded.ok()) << describe(upgraded.error());
    EXPECT_EQ(upgraded->characters[0].segmentTags,
              (std::vector<scene::SegmentTag>{{"Hair", scene::SegmentRole::Receiver}, {"Arm", scene::SegmentRole::None}}));
    EXPECT_EQ(serializeScenario(*upgraded).find("posture"), std::string::npos);

    json v6 = json::parse(v5);
    v6["version"] = 6;
    v6["schema"] = "Scenario.6";
    v6["characters"][0]["schema"] = "Character.4";
    auto refused = parseScenario(v6.dump());
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().message.find("characters[0].segments[0].posture"), std::string::npos)
        << refused.error().message;
}

// ---------------------------------------------------------------------------------------------
// Runtime: the demo

TEST(ScenarioDemo, IsCanonicalAndValid)
{
    const Scenario demo = loadOrFail(demoPath());
    // scripts/make_demo_scenario.py writes exactly what the studio would save.
    EXPECT_EQ(serializeScenario(demo), readFile(demoPath()));
    ASSERT_EQ(demo.characters.size(), 2u);
    EXPECT_NE(demo.findCharacter("Creon"), nullptr);
    EXPECT_NE(demo.findCharacter("Antigone"), nullptr);
    for (const Error& e : validateScenario(demo, demoPath().parent_path()))
        ADD_FAILURE() << describe(e);

    // It shows what the format can do: no motion files (inline clips and synthesized idles),
    // masks, several curve kinds, an override gesture and looping blinks.
    std::set<anim::CurveKind> kinds;
    std::set<anim::BlendMode> modes;
    std::set<ModifierKind> modifiers;
    for (const Character& c : demo.characters) {
        for (const ClipAsset& clip : c.clips)
            EXPECT_TRUE(clip.file.empty()) << clip.name;
        for (const Layer& layer : c.layers)
            for (const ActionSpec& a : layer.actions) {
                kinds.insert(a.weight.kind());
                modes.insert(a.mode);
                for (const ModifierSpec& m : a.modifiers)
                    modifiers.insert(m.kind);
            }
    }
    EXPECT_TRUE(kinds.count(anim::CurveKind::CubicFade));
    EXPECT_TRUE(kinds.count(anim::CurveKind::CubicAdsr));
    EXPECT_TRUE(modes.count(anim::BlendMode::Override));
    EXPECT_TRUE(modifiers.count(ModifierKind::Loop));
    EXPECT_GE(demo.masks.size(), 2u);
}

TEST(ScenarioDemo, BuildsAndEvaluatesToUnitRotations)
{
    const Scenario demo = loadOrFail(demoPath());
    auto built = buildRuntime(demo, demoPath().parent_path());
    ASSERT_TRUE(built.ok()) << describe(built.error());
    const ScenarioRuntime& runtime = *built;
    EXPECT_EQ(runtime.duration, 12 * TicksPerSecond);
    ASSERT_EQ(runtime.characters.size(), 2u);

    for (const CharacterRuntime& character : runtime.characters) {
        SCOPED_TRACE(character.name);
        EXPECT_TRUE(character.warnings.empty()) << character.warnings.front();
        EXPECT_EQ(character.skeleton.jointCount(), 25);
        const auto& layout = *character.body->layout();
        std::vector<float> frame(layout.floatCount());
        for (double t : {0.0, 0.3, 1.7, 2.2, 3.4, 5.6, 6.9, 8.8, 11.9}) {
            character.body->evaluate(t, frame);
            for (float v : frame)
                ASSERT_TRUE(std::isfinite(v)) << "t = " << t;
            for (int r = 0; r < layout.rotationCount(); ++r)
                EXPECT_NEAR(quatLength(frame, r), 1.0f, 1e-4f) << layout.name(r) << " at t = " << t;
        }
        for (const auto& ids : character.actionIds)
            for (anim::ActionId id : ids)
                EXPECT_NE(id, 0u);
    }

    // Creon waves his right arm at 1.5 s: before it the arm hangs (its upper arm points about as
    // at rest: the idle lets it swing a little), during it the arm is raised far; his left arm
    // only idles.
    const auto upperArmSwing = [](const CharacterRuntime& c, std::span<const float> frame, const char* side) {
        const std::string shoulder = std::string(side) + "_shoulder", elbow = std::string(side) + "_elbow";
        const auto now = c.skeleton.worldPositions(frame), rest = c.skeleton.worldPositions(c.skeleton.restFrame());
        const auto direction = [&](const std::vector<anim::Vec3d>& p) {
            const anim::Vec3d d = p[std::size_t(c.skeleton.find(elbow))] - p[std::size_t(c.skeleton.find(shoulder))];
            return d * (1.0 / std::sqrt(anim::dot(d, d)));
        };
        return std::acos(std::clamp(anim::dot(direction(now), direction(rest)), -1.0, 1.0));
    };
    const CharacterRuntime* creon = runtime.findCharacter("Creon");
    ASSERT_NE(creon, nullptr);
    std::vector<float> before(creon->body->layout()->floatCount()), during(before.size());
    creon->body->evaluate(1.0, before);
    creon->body->evaluate(2.6, during);
    EXPECT_LT(upperArmSwing(*creon, before, "r"), 0.35);
    EXPECT_GT(upperArmSwing(*creon, during, "r"), 1.2);
    EXPECT_LT(upperArmSwing(*creon, during, "l"), 0.35);

    // Antigone's wave is Creon's mirrored: her left arm rises at 7 s.
    const CharacterRuntime* antigone = runtime.findCharacter("Antigone");
    ASSERT_NE(antigone, nullptr);
    std::vector<float> waving(antigone->body->layout()->floatCount());
    antigone->body->evaluate(7.2, waving);
    EXPECT_GT(upperArmSwing(*antigone, waving, "l"), 1.2);
    EXPECT_LT(upperArmSwing(*antigone, waving, "r"), 0.35);

    // Creon's face layer blinks (FAP 19, top left eyelid) and is still between blinks.
    std::vector<float> face(creon->face->layout()->floatCount());
    const int fap19 = creon->face->layout()->find("fap19", anim::ElementKind::Scalar);
    ASSERT_GE(fap19, 0);
    creon->face->evaluate(0.475, face);
    EXPECT_GT(face[creon->face->layout()->floatOffset(fap19)], 700.0f);
    creon->face->evaluate(1.5, face);
    EXPECT_NEAR(face[creon->face->layout()->floatOffset(fap19)], 0.0f, 1e-3f);
}

// ---------------------------------------------------------------------------------------------
// Runtime: BVH clips, layers, and problems

TEST(ScenarioRuntime, MutedAndNonSoloLayersDoNotPlay)
{
    const fs::path path = thespis::test::testData("scenarios/bvh_character.thespis");
    Scenario s = loadOrFail(path);
    ASSERT_GE(s.characters.at(0).layers.size(), 2u);
    auto rotationsAt = [&](const Scenario& scenario, double t) {
        auto built = buildRuntime(scenario, path.parent_path());
        EXPECT_TRUE(built.ok()) << describe(built.error());
        const CharacterRuntime& c = built->characters.at(0);
        EXPECT_EQ(c.layers.size(), scenario.characters[0].layers.size()); // every layer is built
        std::vector<float> frame(c.body->layout()->floatCount()), layer0(frame.size()), layer1(frame.size());
        c.body->evaluate(t, frame);
        c.layers[0]->evaluate(t, layer0);
        c.layers[1]->evaluate(t, layer1);
        return std::tuple{frame, layer0, layer1};
    };
    const double t = 0.6; // the head layer plays over the base
    auto near = [](const std::vector<float>& a, const std::vector<float>& b) {
        for (std::size_t i = 0; i < a.size(); ++i)
            if (std::abs(a[i] - b[i]) > 1e-6f)
                return false;
        return true;
    };
    {
        auto [all, base, head] = rotationsAt(s, t);
        EXPECT_FALSE(near(all, base)); // both layers play
    }
    s.characters[0].layers[1].mute = true;
    {
        auto [all, base, head] = rotationsAt(s, t);
        EXPECT_TRUE(near(all, base)); // the muted head layer is left out
    }
    s.characters[0].layers[1].mute = false;
    s.characters[0].layers[1].solo = true;
    {
        auto [all, base, head] = rotationsAt(s, t);
        EXPECT_FALSE(near(all, base));
        // Only the solo layer plays, as the base now: joints it does not drive keep the rest pose.
        auto alone = buildRuntime(s, path.parent_path());
        ASSERT_TRUE(alone.ok());
        std::vector<float> rest = alone->characters[0].skeleton.restFrame();
        const int shoulder = alone->characters[0].skeleton.find("r_shoulder");
        EXPECT_LT(anim::angleBetween(anim::rotationAt(std::span<const float>(all), shoulder),
                                     anim::rotationAt(std::span<const float>(rest), shoulder)), 1e-5f);
    }
}

TEST(ScenarioRuntime, GesturesNeedTheirClipAndMask)
{
    Scenario s = loadOrFail(goldenV2());
    s.characters[0].gestures[0].clip = "no such clip";
    s.characters[0].gestures[1].mask = "no such mask";
    const auto problems = validateScenario(s, goldenV2().parent_path());
    ASSERT_EQ(problems.size(), 2u);
    EXPECT_NE(problems[0].message.find("gesture \"greet\", clip"), std::string::npos) << problems[0].message;
    EXPECT_NE(problems[1].message.find("gesture \"stroll\", mask"), std::string::npos) << problems[1].message;
}

TEST(ScenarioRuntime, AssetCacheReadsEachFileOnceUntilItChanges)
{
    TempDir dir;
    const fs::path folder = dir.path();
    const fs::path source = thespis::test::testData("scenarios");
    for (const char* name : {"bvh_character.thespis", "tiny_body.bvh"})
        fs::copy_file(source / name, folder / name, fs::copy_options::overwrite_existing);
    const Scenario s = loadOrFail(folder / "bvh_character.thespis");
    ASSERT_FALSE(s.characters.at(0).clips.empty());
    const ClipAsset& clip = s.characters[0].clips[0];
    ASSERT_FALSE(clip.file.empty());
    const fs::path bvh = folder / clip.file;

    AssetCache cache;
    EXPECT_FALSE(cache.holds(clip, folder));
    auto first = buildRuntime(s, folder, &cache);
    ASSERT_TRUE(first.ok()) << describe(first.error());
    EXPECT_TRUE(cache.holds(clip, folder));
    auto second = buildRuntime(s, folder, &cache);
    ASSERT_TRUE(second.ok());
    EXPECT_EQ(second->characters[0].warnings, first->characters[0].warnings); // reported from the cache too

    // A newer file on disk is read again.
    fs::last_write_time(bvh, fs::last_write_time(bvh) + std::chrono::seconds(5));
    EXPECT_FALSE(cache.holds(clip, folder));
    cache.clear();
}

TEST(ScenarioRuntime, BuildsACharacterOnItsBvhSkeleton)
{
    const fs::path path = thespis::test::testData("scenarios/bvh_character.thespis");
    const Scenario s = loadOrFail(path);
    auto built = buildRuntime(s, path.parent_path());
    ASSERT_TRUE(built.ok()) << describe(built.error());
    const CharacterRuntime& mocap = built->characters.at(0);
    EXPECT_EQ(mocap.skeleton.jointCount(), 18);
    ASSERT_NE(mocap.skeleton.find("r_shoulder"), -1);
    ASSERT_EQ(mocap.clips.count("body"), 1u);
    const auto body = std::dynamic_pointer_cast<const anim::KeyframeClip>(mocap.clips.at("body"));
    ASSERT_TRUE(body);
    EXPECT_EQ(body->frameCount(), 5);
    // The tail is no H-Anim joint, but the skeleton is the file's own: it plays, nothing to tell.
    EXPECT_NE(mocap.skeleton.find("Tail"), -1);
    EXPECT_TRUE(mocap.warnings.empty()) << mocap.warnings.front();
    EXPECT_EQ(built->duration, secondsToTicks(0.6)); // the head action ends at 0.5 + 0.1 s

    const auto& layout = *mocap.body->layout();
    const int shoulder = mocap.skeleton.find("r_shoulder");
    const int head = mocap.skeleton.find("skullbase");
    std::vector<float> frame(layout.floatCount()), baseOnly(layout.floatCount());
    // At 0.3 s only the base layer plays: the override layer covers nothing yet.
    mocap.body->evaluate(0.3, frame);
    mocap.layers[0]->evaluate(0.3, baseOnly);
    for (std::size_t i = 0; i < frame.size(); ++i)
        EXPECT_NEAR(frame[i], baseOnly[i], 1e-6f) << i;
    // BVH frame 3 raises the right arm by 60 degrees about z.
    const anim::Quat raised = anim::Quat::fromAxisAngle({0, 0, 1}, float(-60.0 * std::numbers::pi / 180.0));
    EXPECT_LT(anim::angleBetween(anim::rotationAt(std::span<const float>(frame), shoulder), raised), 1e-3f);

    // At 0.6 s the head layer overrides the head only (30 degrees down), the arm keeps the base.
    mocap.body->evaluate(0.6, frame);
    mocap.layers[0]->evaluate(0.6, baseOnly);
    const anim::Quat down = anim::Quat::fromAxisAngle({1, 0, 0}, float(30.0 * std::numbers::pi / 180.0));
    EXPECT_LT(anim::angleBetween(anim::rotationAt(std::span<const float>(frame), head), down), 1e-3f);
    for (int r = 0; r < layout.rotationCount(); ++r) {
        if (r != head) {
            EXPECT_LT(anim::angleBetween(anim::rotationAt(std::span<const float>(frame), r),
                                         anim::rotationAt(std::span<const float>(baseOnly), r)), 1e-5f)
                << layout.name(r);
        }
    }
    // After the head action ends the base shows through again.
    mocap.body->evaluate(0.75, frame);
    mocap.layers[0]->evaluate(0.75, baseOnly);
    EXPECT_LT(anim::angleBetween(anim::rotationAt(std::span<const float>(frame), head),
                                 anim::rotationAt(std::span<const float>(baseOnly), head)), 1e-5f);
}

TEST(ScenarioRuntime, ProblemsNameCharacterLayerActionAndField)
{
    json doc = minimalDocument();
    json& action = doc["characters"][0]["layers"][0]["actions"][0];
    action["clip"] = "missing_clip";
    json second = action;
    second["name"] = "b";
    second["clip"] = "c";
    second["mask"] = "no_such_mask";
    doc["characters"][0]["layers"][0]["actions"].push_back(second);
    doc["characters"][0]["clips"].push_back(json::parse(R"({"name": "mocap", "file": "no/such/file.bvh"})"));
    auto s = parseJson(doc);
    ASSERT_TRUE(s.ok()) << describe(s.error());

    const auto problems = validateScenario(*s, "/nonexistent");
    ASSERT_EQ(problems.size(), 3u);
    auto has = [&](const std::string& start, ErrorCode code) {
        return std::any_of(problems.begin(), problems.end(), [&](const Error& e) {
            return e.code == code && e.message.rfind(start, 0) == 0;
        });
    };
    EXPECT_TRUE(has("Character \"A\", clip \"mocap\", file \"no/such/file.bvh\": ", ErrorCode::FileNotFound));
    EXPECT_TRUE(has("Character \"A\", layer \"body\", action \"a\", clip: the character has no clip named \"missing_clip\"",
                    ErrorCode::InvalidSchedule));
    EXPECT_TRUE(has("Character \"A\", layer \"body\", action \"b\", mask: the scenario has no mask named \"no_such_mask\"",
                    ErrorCode::InvalidSchedule));

    auto built = buildRuntime(*s, "/nonexistent");
    ASSERT_FALSE(built.ok());
    EXPECT_NE(built.error().detail.find("2 more problem(s)"), std::string::npos) << built.error().detail;
}

TEST(ScenarioRuntime, CatchesWhatTheParserCannotSee)
{
    // Documents built in code (the editor, Python) get the same rules as files.
    Scenario s = parseJson(minimalDocument()).value();
    s.characters.push_back(s.characters[0]);                          // a second "A"
    s.characters[0].layers[0].actions[0].weight = anim::Curve::constant(-1);
    s.characters[0].clips[0].frames.pop_back();                        // not whole frames
    s.characters[1].skeleton = "clip:c";                               // an inline clip has no skeleton
    s.masks[0].mask.setWeight("r_elbow", 2.0f);
    const auto problems = validateScenario(s, {});
    std::string all;
    for (const Error& e : problems)
        all += e.message + "\n";
    EXPECT_EQ(problems.size(), 5u) << all;
    EXPECT_NE(all.find("Two characters are named \"A\""), std::string::npos) << all;
    EXPECT_NE(all.find("Mask \"arm\": "), std::string::npos) << all;
    EXPECT_NE(all.find("skeleton \"clip:c\": the clip is stored inline"), std::string::npos) << all;
    EXPECT_NE(all.find("Character \"A\", clip \"c\": "), std::string::npos) << all;
    EXPECT_NE(all.find("action \"a\", weight: a weight must not be negative"), std::string::npos) << all;
}

TEST(ScenarioRuntime, ValidatesModelsSegmentTagsAndTheProbe)
{
    const fs::path characters = thespis::test::sharedData("characters");
    ASSERT_TRUE(fs::exists(characters / "RobotExpressive/RobotExpressive.glb")) << "the real characters are not in " << characters;
    Scenario s = parseJson(minimalDocument()).value();
    s.characters[0].model = "RobotExpressive/RobotExpressive.glb";
    s.characters[0].segmentTags = {{"Head", scene::SegmentRole::Receiver}};
    EXPECT_TRUE(validateScenario(s, characters).empty());

    s.characters[0].segmentTags.push_back({"Tail", scene::SegmentRole::Occluder});
    s.lighting.probe = "no_such_probe.hdr";
    auto problems = validateScenario(s, characters);
    ASSERT_EQ(problems.size(), 2u);
    EXPECT_NE(problems[0].message.find("characters[0].segments: "), std::string::npos) << problems[0].message;
    EXPECT_NE(problems[0].message.find("Tail"), std::string::npos) << problems[0].message;
    EXPECT_EQ(problems[1].code, ErrorCode::FileNotFound);
    EXPECT_EQ(problems[1].message.rfind("lighting.probe: ", 0), 0u) << problems[1].message;

    s.characters[0].model = "missing.glb";
    s.lighting = {};
    problems = validateScenario(s, characters);
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_EQ(problems[0].message.rfind("characters[0].model: ", 0), 0u) << problems[0].message;
}

TEST(ScenarioRuntime, FaceLayersNeedFapClipsAndBodyLayersJoints)
{
    json doc = minimalDocument();
    doc["masks"] = json::array();
    json& character = doc["characters"][0];
    character["clips"].push_back(json::parse(R"({"name": "smile", "frameRate": 10, "scalars": ["fap12"], "frames": [[0], [100]]})"));
    json& action = character["layers"][0]["actions"][0];
    action.erase("mask");
    action["clip"] = "smile"; // a FAP clip on a body layer
    json face = json::parse(R"({"name": "face", "kind": "face", "actions": [{"name": "f", "clip": "c", "start": 0}]})");
    character["layers"].push_back(face); // a body clip on a face layer
    auto s = parseJson(doc);
    ASSERT_TRUE(s.ok()) << describe(s.error());
    const auto problems = validateScenario(*s, {});
    ASSERT_EQ(problems.size(), 2u);
    EXPECT_NE(problems[0].message.find("layer \"body\", action \"a\", clip \"smile\": it moves no joint"), std::string::npos)
        << problems[0].message;
    EXPECT_NE(problems[1].message.find("layer \"face\", action \"f\", clip \"c\": a face layer needs MPEG-4 FAP"),
              std::string::npos)
        << problems[1].message;

    // Swapped the right way round, both build, and the face plays the FAP.
    s->characters[0].layers[0].actions[0].clip = "c";
    s->characters[0].layers[1].actions[0].clip = "smile";
    auto built = buildRuntime(*s, {});
    ASSERT_TRUE(built.ok()) << describe(built.error());
    const auto& faceSchedule = *built->characters[0].face;
    std::vector<float> frame(faceSchedule.layout()->floatCount());
    faceSchedule.evaluate(0.1, frame);
    EXPECT_FLOAT_EQ(frame[faceSchedule.layout()->floatOffset(faceSchedule.layout()->find("fap12", anim::ElementKind::Scalar))],
                    100.0f);
}

// Format 7: a clip may be blinks (core/motion/blink_synthesizer.h) for a face layer. The demo's
// Antigone blinks so, open-ended, and smiles while she waves.
TEST(ScenarioBlinks, TheDemosAntigoneBlinksByHerOwnGeneratorAndSmiles)
{
    const Scenario demo = loadOrFail(demoPath());
    const ClipAsset* blinks = demo.findCharacter("Antigone")->findClip("antigone_blinks");
    ASSERT_TRUE(blinks && blinks->blinks);
    EXPECT_EQ(blinks->blinks->rate, 17.0);
    auto built = buildRuntime(demo, demoPath().parent_path());
    ASSERT_TRUE(built.ok()) << describe(built.error());
    const CharacterRuntime* antigone = built->findCharacter("Antigone");
    ASSERT_TRUE(antigone && antigone->face);
    ASSERT_TRUE(antigone->faceClips.count("antigone_blinks"));
    std::vector<float> face(antigone->face->layout()->floatCount());
    int shut = 0, smiling = 0;
    for (double t = 0; t < 12; t += 0.01) {
        antigone->face->evaluate(t, face);
        shut += face[18] > 800; // fap19, her upper left lid
        smiling += face[68 + 14] > 0.5; // expression1, joy
    }
    EXPECT_GT(shut, 2) << "she blinks within the demo's 12 s";
    EXPECT_GT(smiling, 50) << "and smiles while she waves";
}

TEST(ScenarioBlinks, ABlinkClipIsWrittenReadAndCheckedWhereItPlays)
{
    Scenario s;
    Character c;
    c.name = "A";
    ClipAsset blinks;
    blinks.name = "blinks";
    blinks.blinks = BlinkClip{26, 7, 0.08, 0.02, 0.2};
    c.clips.push_back(blinks);
    s.characters.push_back(c);
    auto back = parseScenario(serializeScenario(s));
    ASSERT_TRUE(back.ok()) << describe(back.error());
    EXPECT_EQ(*back, s);

    json doc = json::parse(serializeScenario(s));
    doc["characters"][0]["clips"][0]["frames"] = json::array();
    auto both = parseScenario(doc.dump());
    ASSERT_FALSE(both.ok());
    EXPECT_NE(both.error().message.find("characters[0].clips[0].frames"), std::string::npos) << both.error().message;
    doc = json::parse(serializeScenario(s));
    doc["characters"][0]["clips"][0]["blinks"]["rate"] = 500;
    auto fast = parseScenario(doc.dump());
    ASSERT_FALSE(fast.ok());
    EXPECT_NE(fast.error().message.find("characters[0].clips[0].blinks.rate"), std::string::npos) << fast.error().message;

    // On a body layer it moves nothing and says so.
    Layer body;
    body.name = "body";
    body.actions.push_back(ActionSpec{});
    body.actions.back().name = "b";
    body.actions.back().clip = "blinks";
    s.characters[0].layers.push_back(body);
    auto built = buildRuntime(s, fs::temp_directory_path());
    ASSERT_FALSE(built.ok());
    EXPECT_NE(built.error().message.find("blinks"), std::string::npos) << built.error().message;
}
