// A character's own face mapping table in the scenario (format 8, Character::faceMapping): the
// field's round trip, the 7 → 8 upgrade on the golden files, the reader naming the field; and
// the table playing: RobotExpressive (../shared/data) loaded through loadCharacterBody with a
// hand-written table mapping joy onto its "Surprised" target (the names it has are not joy's, so
// the recognised table leaves joy still), a table naming a target the model lacks, a missing
// table (a warning naming the file, the recognised table kept), the built-in humanoid (told it
// has its own face), validation, the edit, and a package carrying the table.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "edit/content_edits.h"
#include "scenario/open_scenario.h"
#include "scenario/package_export_job.h"
#include "scenario/scenario_character.h"
#include "scenario/scenario_io.h"
#include "scenario/scenario_runtime.h"
#include "scene/fap.h"
#include "scene/face_mapping.h"
#include "scene/face_rig.h"
#include "test_support.h"

namespace fs = std::filesystem;
using namespace thespis::core;
using namespace thespis::core::scenario;
using nlohmann::json;

namespace {

const char* const kRobot = "characters/RobotExpressive/RobotExpressive.glb";

// A fresh folder for one test (removed first, left for people to look at).
fs::path freshFolder()
{
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const fs::path folder = thespis::test::artifact("scenario_face_mapping") / info->name();
    fs::remove_all(folder);
    fs::create_directories(folder);
    return folder;
}

// RobotExpressive (by its absolute path: it lives in ../shared/data) with a face layer.
Scenario robotScenario(const std::string& faceMapping)
{
    Character robot = edit::newCharacter("Robot", thespis::test::sharedData(kRobot).string(), "model");
    robot.faceMapping = faceMapping;
    Scenario s;
    s.name = "robot face";
    s.characters.push_back(robot);
    return s;
}

// joy → the model's "Surprised" target, which the recognised table drives with surprise only.
scene::FaceMapping joyIsSurprised()
{
    scene::FaceMapping mapping;
    mapping.name = "joy as surprise";
    mapping.drives = {{"Surprised", scene::expressionChannel(1), 0.8, scene::MorphDrive::Side::Both}};
    return mapping;
}

void writeTable(const fs::path& path, const scene::FaceMapping& mapping)
{
    fs::create_directories(path.parent_path());
    ASSERT_TRUE(scene::saveFaceMapping(path, mapping));
}

// The weight the body's face gives its target `name` for a face frame with `channel` at 1.
float targetWeight(const scene::Character& body, const std::string& name, int channel)
{
    std::vector<float> face(scene::kFaceChannelCount, 0.0f), channels(scene::kFaceChannelCount, 0.0f);
    face[std::size_t(channel)] = 1.0f;
    scene::expandFaceChannels(body.face, face, channels);
    std::vector<float> weights(body.face.targets.size(), 0.0f);
    scene::morphTargetWeights(body.face, channels, weights);
    float weight = 0;
    for (std::size_t t = 0; t < body.face.targets.size(); ++t)
        if (body.face.targets[t].name == name)
            weight = std::max(weight, weights[t]);
    return weight;
}

std::vector<std::string> warningsNaming(const scene::Character& body, const std::string& text)
{
    std::vector<std::string> found;
    for (const std::string& warning : body.warnings)
        if (warning.find(text) != std::string::npos)
            found.push_back(warning);
    return found;
}

} // namespace

// ---- the format ---------------------------------------------------------------------------------

TEST(ScenarioFaceMapping, TheFieldRoundTripsAndIsWrittenOnlyWhenSet)
{
    Scenario s = robotScenario("tables/robot face.json");
    const std::string text = serializeScenario(s);
    EXPECT_EQ(json::parse(text)["characters"][0]["faceMapping"], "tables/robot face.json");
    auto back = parseScenario(text);
    ASSERT_TRUE(back) << describe(back.error());
    EXPECT_EQ(*back, s);
    s.characters[0].faceMapping.clear();
    EXPECT_FALSE(json::parse(serializeScenario(s))["characters"][0].contains("faceMapping"));
}

TEST(ScenarioFaceMapping, Version7UpgradesToVersion8WithoutATable)
{
    // The version 8 golden file is the version 7 one with a model and its table on "Inline":
    // taking them away gives exactly what the upgraded version 7 file reads as.
    auto v8 = loadScenario(thespis::test::testData("formats/v8/scenario.thespis"));
    auto v7 = loadScenario(thespis::test::testData("formats/v7/scenario.thespis"));
    ASSERT_TRUE(v8 && v7) << describe(v8 ? v7.error() : v8.error());
    ASSERT_EQ(v8->characters.size(), 2u);
    EXPECT_EQ(v8->characters[1].faceMapping, "models/robot_face.json");
    v8->characters[1].model.clear();
    v8->characters[1].faceMapping.clear();
    v7->name = v8->name;
    EXPECT_EQ(*v7, *v8);
    json upgraded = json::parse(serializeScenario(*v7));
    EXPECT_EQ(upgraded["version"], int(format::Current));
    EXPECT_EQ(upgraded["schema"], "Scenario." + std::to_string(int(format::Current)));
}

TEST(ScenarioFaceMapping, TheReaderNamesAFaceMappingThatIsNotAPath)
{
    json doc = json::parse(serializeScenario(robotScenario("t.json")));
    doc["characters"][0]["faceMapping"] = 3;
    auto result = parseScenario(doc.dump());
    ASSERT_FALSE(result);
    EXPECT_EQ(result.error().code, ErrorCode::CorruptData);
    EXPECT_NE(result.error().message.find("characters[0].faceMapping"), std::string::npos) << result.error().message;
    // The 7 → 8 step changes nothing but the schemas: a version 7 file naming a table reads it too.
    doc["characters"][0]["faceMapping"] = "t.json";
    doc["version"] = 7;
    doc["schema"] = "Scenario.7";
    doc["characters"][0]["schema"] = "Character.4";
    auto old = parseScenario(doc.dump());
    ASSERT_TRUE(old) << describe(old.error());
    EXPECT_EQ(old->characters[0].faceMapping, "t.json");
}

// ---- the table playing ----------------------------------------------------------------------------

TEST(ScenarioFaceMapping, RobotExpressiveFollowsItsOwnTable)
{
    const fs::path folder = freshFolder();
    writeTable(folder / "tables" / "robot.json", joyIsSurprised());
    const int joy = scene::expressionChannel(1);

    auto automatic = loadCharacterBody(robotScenario(""), 0, Assets(folder));
    ASSERT_TRUE(automatic) << describe(automatic.error());
    auto own = loadCharacterBody(robotScenario("tables/robot.json"), 0, Assets(folder));
    ASSERT_TRUE(own) << describe(own.error());

    // The model's names have no joy: the recognised table leaves it still; the table smiles it
    // as surprise, and drives nothing else (its Angry and Sad are left alone).
    EXPECT_EQ(targetWeight(*automatic, "Surprised", joy), 0.0f);
    EXPECT_FLOAT_EQ(targetWeight(*own, "Surprised", joy), 0.8f);
    EXPECT_GT(targetWeight(*automatic, "Angry", scene::expressionChannel(3)), 0.0f);
    EXPECT_EQ(targetWeight(*own, "Angry", scene::expressionChannel(3)), 0.0f);
    EXPECT_TRUE(warningsNaming(*own, "faceMapping").empty());
}

TEST(ScenarioFaceMapping, ATargetTheModelLacksIsWarnedAboutByName)
{
    const fs::path folder = freshFolder();
    scene::FaceMapping mapping = joyIsSurprised();
    mapping.drives.push_back({"Smile_Wide", scene::expressionChannel(1), 1.0, scene::MorphDrive::Side::Both});
    writeTable(folder / "robot.json", mapping);
    auto body = loadCharacterBody(robotScenario("robot.json"), 0, Assets(folder));
    ASSERT_TRUE(body) << describe(body.error());
    const auto warnings = warningsNaming(*body, "\"Smile_Wide\"");
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("does not have"), std::string::npos) << warnings[0];
    // What it could apply, it did.
    EXPECT_FLOAT_EQ(targetWeight(*body, "Surprised", scene::expressionChannel(1)), 0.8f);
}

TEST(ScenarioFaceMapping, AMissingOrBrokenTableIsNamedAndTheRecognisedOneKept)
{
    const fs::path folder = freshFolder();
    auto automatic = loadCharacterBody(robotScenario(""), 0, Assets(folder));
    ASSERT_TRUE(automatic) << describe(automatic.error());
    const float angry = targetWeight(*automatic, "Angry", scene::expressionChannel(3));
    ASSERT_GT(angry, 0.0f);

    auto missing = loadCharacterBody(robotScenario("tables/gone.json"), 0, Assets(folder));
    ASSERT_TRUE(missing) << describe(missing.error());
    auto warnings = warningsNaming(*missing, "characters[0].faceMapping");
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find((folder / "tables/gone.json").string()), std::string::npos) << warnings[0];
    EXPECT_NE(warnings[0].find("recognised"), std::string::npos) << warnings[0];
    EXPECT_EQ(targetWeight(*missing, "Angry", scene::expressionChannel(3)), angry);

    std::ofstream(folder / "broken.json") << R"({"format": "thespis-face-mapping", "version": 1, "drives": [{"target": 5}]})";
    auto broken = loadCharacterBody(robotScenario("broken.json"), 0, Assets(folder));
    ASSERT_TRUE(broken) << describe(broken.error());
    warnings = warningsNaming(*broken, "characters[0].faceMapping");
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("broken.json"), std::string::npos) << warnings[0];
    EXPECT_NE(warnings[0].find("drives[0].target"), std::string::npos) << warnings[0];
    EXPECT_EQ(targetWeight(*broken, "Angry", scene::expressionChannel(3)), angry);

    // Checking the scenario names both as problems.
    const auto problems = validateScenario(robotScenario("tables/gone.json"), Assets(folder));
    ASSERT_FALSE(problems.empty());
    EXPECT_NE(problems.back().message.find("characters[0].faceMapping"), std::string::npos) << problems.back().message;
}

TEST(ScenarioFaceMapping, TheBuiltInHumanoidIsToldItHasItsOwnFace)
{
    const fs::path folder = freshFolder();
    writeTable(folder / "robot.json", joyIsSurprised());
    Scenario s;
    Character humanoid = edit::newCharacter("Ann", "", "hanim-25");
    humanoid.faceMapping = "robot.json";
    s.characters.push_back(humanoid);
    auto body = loadCharacterBody(s, 0, Assets(folder));
    ASSERT_TRUE(body) << describe(body.error());
    const auto warnings = warningsNaming(*body, "characters[0].faceMapping (Ann)");
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("built-in humanoid"), std::string::npos) << warnings[0];
    const auto problems = validateScenario(s, Assets(folder));
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_NE(problems[0].message.find("characters[0].faceMapping"), std::string::npos) << problems[0].message;
}

// ---- the edit ---------------------------------------------------------------------------------------

TEST(ScenarioFaceMapping, TheEditSetsTheTableAndItsInverseRestoresIt)
{
    const Scenario original = robotScenario("");
    auto edit = edit::setCharacterFaceMapping(original, 0, "tables/robot.json");
    ASSERT_TRUE(edit) << describe(edit.error());
    Scenario s = original;
    ASSERT_TRUE(edit->apply(s));
    EXPECT_EQ(s.characters[0].faceMapping, "tables/robot.json");
    ASSERT_TRUE(edit->inverse().apply(s));
    EXPECT_EQ(s, original);
    // The humanoid refuses one, and becoming the humanoid drops it.
    Scenario humanoid;
    humanoid.characters.push_back(edit::newCharacter("Ann", "", "hanim-25"));
    EXPECT_FALSE(edit::setCharacterFaceMapping(humanoid, 0, "tables/robot.json"));
    EXPECT_FALSE(edit::setCharacterFaceMapping(humanoid, 3, ""));
    s.characters[0].faceMapping = "tables/robot.json";
    auto toHumanoid = edit::setCharacterBody(s, 0, "", "hanim-25");
    ASSERT_TRUE(toHumanoid);
    ASSERT_TRUE(toHumanoid->apply(s));
    EXPECT_TRUE(s.characters[0].faceMapping.empty());
}

// ---- packages ------------------------------------------------------------------------------------

TEST(ScenarioFaceMapping, APackageCarriesTheTableAndPlaysTheSameFace)
{
    // The table lives outside the scenario's folder, named by its absolute path as a user's
    // choice can be: the package takes it into its assets and names it there.
    const fs::path folder = freshFolder();
    const fs::path table = folder / "elsewhere" / "robot.json";
    writeTable(table, joyIsSurprised());
    fs::create_directories(folder / "scenario");
    const Scenario s = robotScenario(table.string());
    ExportPackageJob job;
    job.scenario = s;
    job.assets = Assets(folder / "scenario");
    job.scenarioEntry = "play.thespis";
    job.output = folder / "robot.thespkg";
    ASSERT_TRUE(job.validate());
    JobContext context;
    auto ran = job.run(context);
    ASSERT_TRUE(ran) << describe(ran.error());
    const std::string packed = job.plan.scenario.characters[0].faceMapping;
    EXPECT_EQ(packed, "assets/robot.json");
    const auto entry = std::find_if(job.plan.files.begin(), job.plan.files.end(),
                                    [&](const PackageFile& file) { return file.name == packed; });
    ASSERT_NE(entry, job.plan.files.end());
    EXPECT_EQ(entry->usedBy, "characters[Robot].faceMapping");

    // The table is gone from disk: only the package's copy can give joy its weight.
    fs::remove_all(folder / "elsewhere");
    auto opened = openScenario(folder / "robot.thespkg");
    ASSERT_TRUE(opened) << describe(opened.error());
    EXPECT_EQ(opened->scenario.characters[0].faceMapping, packed);
    auto body = loadCharacterBody(opened->scenario, 0, opened->assets);
    ASSERT_TRUE(body) << describe(body.error());
    EXPECT_TRUE(warningsNaming(*body, "faceMapping").empty()) << body->warnings.front();
    EXPECT_FLOAT_EQ(targetWeight(*body, "Surprised", scene::expressionChannel(1)), 0.8f);
}
