// Face mapping tables (scene/face_mapping.h): the versioned JSON file (golden file of version 1,
// round trips, errors naming the file and the field), applying a table to a character (drives by
// target name, joints by name or source name, the visemes' and expressions' FAP vectors cleared
// where the table drives them, a warning naming each target it lacks) and the recognised schemes
// on characters made here (face_naming.h).

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>

#include <unistd.h>

#include "scene/character.h"
#include "scene/face_mapping.h"
#include "scene/face_naming.h"
#include "test_support.h"

namespace thespis::core::scene {
namespace {

namespace fs = std::filesystem;
using Side = MorphDrive::Side;

const fs::path kGolden = test::testData("formats/face_mapping/v1/studio_rig.json");

std::string readAll(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// What the golden file of version 1 holds.
FaceMapping studioRig()
{
    FaceMapping mapping;
    mapping.name = "studio rig";
    mapping.drives = {{"Blink_L", fapChannel(19), 0.0009765625, Side::Positive},
                      {"JawDrop", fapChannel(3), 0.00048828125, Side::Positive},
                      {"Smile_L", fapChannel(12), 0.001953125, Side::Positive},
                      {"Frown_L", fapChannel(12), -0.001953125, Side::Negative},
                      {"Viseme_AA", visemeChannel(10), 1, Side::Both},
                      {"Angry", expressionChannel(3), 0.75, Side::Both}};
    mapping.joints = {{"EyeBone_L", fapChannel(23), {0, 1, 0}, 1e-05},
                      {"EyeBone_L", fapChannel(25), {1, 0, 0}, 1e-05},
                      {"JawBone", fapChannel(3), {1, 0, 0}, 0.0002}};
    return mapping;
}

TEST(FaceMapping, TheGoldenFileOfVersion1ReadsAndIsWrittenAgainByteForByte)
{
    Result<FaceMapping> golden = loadFaceMapping(kGolden);
    ASSERT_TRUE(golden) << golden.error().message;
    EXPECT_EQ(*golden, studioRig());
    EXPECT_EQ(serializeFaceMapping(*golden), readAll(kGolden));
}

TEST(FaceMapping, SavedTablesReadBackTheSame)
{
    FaceMapping mapping = studioRig();
    mapping.drives.push_back({"Odd", fapChannel(47), 1.0 / 3.0, Side::Both}); // not a short decimal
    mapping.joints.push_back({"node7", expressionChannel(6), {0, 0.6, 0.8}, -2.5e-7});
    const fs::path path = fs::temp_directory_path() / ("thespis_face_mapping_" + std::to_string(::getpid()) + ".json");
    ASSERT_TRUE(saveFaceMapping(path, mapping));
    Result<FaceMapping> read = loadFaceMapping(path);
    fs::remove(path);
    ASSERT_TRUE(read) << read.error().message;
    EXPECT_EQ(*read, mapping);
}

TEST(FaceMapping, ChannelsAreReadByNameNumberOrAliasAndAxesNormalized)
{
    Result<FaceMapping> read = parseFaceMapping(R"({"format": "thespis-face-mapping", "version": 1,
        "drives": [{"target": "a", "channel": "FAP19", "coefficient": 1},
                   {"target": "b", "channel": 3, "coefficient": 1},
                   {"target": "c", "channel": "Sadness", "coefficient": 1},
                   {"target": "d", "channel": "expression6", "coefficient": 1}],
        "joints": [{"joint": "j", "channel": "viseme14", "axis": [0, 0, 2], "radiansPerUnit": 1}]})");
    ASSERT_TRUE(read) << read.error().message;
    EXPECT_TRUE(read->name.empty());
    ASSERT_EQ(read->drives.size(), 4u);
    EXPECT_EQ(read->drives[0].channel, fapChannel(19));
    EXPECT_EQ(read->drives[1].channel, fapChannel(3));
    EXPECT_EQ(read->drives[2].channel, expressionChannel(2));
    EXPECT_EQ(read->drives[3].channel, expressionChannel(6));
    EXPECT_EQ(read->drives[0].side, Side::Both);
    EXPECT_EQ(read->joints[0].channel, visemeChannel(14));
    EXPECT_EQ(read->joints[0].axis, (anim::Vec3d{0, 0, 1}));
}

TEST(FaceMapping, ErrorsNameTheFileAndTheField)
{
    const std::string head = R"({"format": "thespis-face-mapping", "version": 1, )";
    const std::string drive = R"({"target": "a", "channel": "open_jaw", "coefficient": 1})";
    struct Case {
        std::string text;
        ErrorCode code;
        std::string message;
    };
    const Case cases[] = {
        {head + R"("drives": [)" + drive + "," + drive + "," + drive + R"(, {"target": "", "channel": 3, "coefficient": 1}]})",
         ErrorCode::CorruptData, "drives[3].target: must not be empty"},
        {head + R"("drives": [{"channel": 3, "coefficient": 1}]})", ErrorCode::CorruptData,
         "drives[0].target: this field is required but missing"},
        {head + R"("drives": [{"target": "a", "channel": "open_mouth", "coefficient": 1}]})", ErrorCode::CorruptData,
         "drives[0].channel: \"open_mouth\" is not a face channel"},
        {head + R"("drives": [{"target": "a", "channel": 69, "coefficient": 1}]})", ErrorCode::CorruptData,
         "drives[0].channel: FAP numbers go from 1 to 68, found 69"},
        {head + R"("drives": [{"target": "a", "channel": 3, "coefficient": "1"}]})", ErrorCode::CorruptData,
         "drives[0].coefficient: expected a number"},
        {head + R"("drives": [{"target": "a", "channel": 3, "coeficient": 1}]})", ErrorCode::CorruptData,
         "drives[0].coefficient: this field is required but missing"},
        {head + R"("drives": [{"target": "a", "channel": 3, "coefficient": 1, "sides": "both"}]})",
         ErrorCode::CorruptData, "drives[0].sides: is not a field"},
        {head + R"("drives": [{"target": "a", "channel": 3, "coefficient": 1, "side": "up"}]})", ErrorCode::CorruptData,
         "drives[0].side: expected \"both\", \"positive\" or \"negative\""},
        {head + R"("drives": {}})", ErrorCode::CorruptData, "drives: expected a list"},
        {head + R"("drives": [3]})", ErrorCode::CorruptData, "drives[0]: expected an object"},
        {head + R"("joints": [{"joint": "j", "channel": 23, "axis": [0, 0, 0], "radiansPerUnit": 1}]})",
         ErrorCode::CorruptData, "joints[0].axis: the axis has no direction"},
        {head + R"("joints": [{"joint": "j", "channel": 23, "axis": [0, 1], "radiansPerUnit": 1}]})",
         ErrorCode::CorruptData, "joints[0].axis: expected a list of 3 numbers"},
        {head + R"("joints": [{"joint": "j", "channel": 23, "axis": [0, "1", 0], "radiansPerUnit": 1}]})",
         ErrorCode::CorruptData, "joints[0].axis[1]: expected a finite number"},
        {head + R"("joints": [{"joint": "j", "channel": 23, "axis": [0, 1, 0]}]})", ErrorCode::CorruptData,
         "joints[0].radiansPerUnit: this field is required but missing"},
        {head + R"("name": 7})", ErrorCode::CorruptData, "name: expected a text"},
        {head + R"("weights": []})", ErrorCode::CorruptData, "weights: is not a field"},
        {R"({"format": "thespis-face-mapping", "version": 2})", ErrorCode::NewerVersion, "newer Thespis (format 2)"},
        {R"({"format": "thespis-face-mapping", "version": 0})", ErrorCode::CorruptData, "version: 0 is not"},
        {R"({"format": "thespis-face-mapping"})", ErrorCode::CorruptData, "version: this field is required"},
        {R"({"format": "thespis-scenario", "version": 1})", ErrorCode::NotOurFormat, "not a Thespis face mapping"},
        {R"([1, 2])", ErrorCode::NotOurFormat, "not a Thespis face mapping"},
        {head + R"("drives": [)", ErrorCode::CorruptData, "line 1, column"},
    };
    const fs::path path = fs::temp_directory_path() / ("thespis_face_mapping_bad_" + std::to_string(::getpid()) + ".json");
    for (const Case& c : cases) {
        std::ofstream(path, std::ios::binary) << c.text;
        Result<FaceMapping> read = loadFaceMapping(path);
        ASSERT_FALSE(read) << c.text;
        EXPECT_EQ(read.error().code, c.code) << read.error().message;
        EXPECT_NE(read.error().message.find(path.string()), std::string::npos) << read.error().message;
        EXPECT_NE(read.error().message.find(c.message), std::string::npos)
            << "wanted: " << c.message << "\n   got: " << read.error().message;
    }
    fs::remove(path);
    const Result<FaceMapping> missing = loadFaceMapping(path);
    ASSERT_FALSE(missing);
    EXPECT_EQ(missing.error().code, ErrorCode::FileNotFound);
}

// A character of one joint "Head" (source name "head_bone") and a triangle, with targets.
Character withTargets(std::initializer_list<const char*> names)
{
    Character character;
    character.name = "Tester";
    anim::Joint head;
    head.name = "Head";
    head.sourceName = "head_bone";
    character.skeleton = std::move(anim::Skeleton::create({head})).value();
    character.mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    character.mesh.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    character.mesh.indices = {0, 1, 2};
    Segment segment;
    segment.name = "face";
    segment.vertexCount = 3;
    segment.triangleCount = 1;
    character.mesh.segments = {segment};
    std::uint32_t vertex = 0;
    for (const char* name : names)
        character.face.targets.push_back({name, {vertex++ % 3}, {{0, 0.01f, 0}}});
    return character;
}

TEST(FaceMapping, ApplyingDrivesTargetsAndJointsByNameAndWarnsOfWhatIsMissing)
{
    Character character = withTargets({"Blink_L", "Viseme_AA", "Blink_L"}); // two targets share a name
    character.face.visemes[9] = {{3, 400}};     // A: opens the jaw …
    character.face.visemes[0] = {{4, 200}};     // … p_b_m presses the lips
    character.face.expressions[2] = {{31, -80}}; // anger lowers the brows
    const std::vector<std::string> warnings = applyFaceMapping(studioRig(), character);
    ASSERT_EQ(warnings.size(), 6u);
    EXPECT_EQ(warnings[0], "The face mapping \"studio rig\" drives the morph target \"JawDrop\", which Tester does not have.");
    EXPECT_NE(warnings[1].find("\"Smile_L\""), std::string::npos);
    EXPECT_NE(warnings[2].find("\"Frown_L\""), std::string::npos);
    EXPECT_NE(warnings[3].find("\"Angry\""), std::string::npos);
    EXPECT_EQ(warnings[4], "The face mapping \"studio rig\" turns the joint \"EyeBone_L\", which Tester does not have.");
    EXPECT_NE(warnings[5].find("\"JawBone\""), std::string::npos); // each missing name once
    // Blink_L twice (one drive per target of that name), Viseme_AA once.
    ASSERT_EQ(character.face.drives.size(), 3u);
    EXPECT_EQ(character.face.drives[0].target, 0);
    EXPECT_EQ(character.face.drives[1].target, 2);
    EXPECT_EQ(character.face.drives[2].target, 1);
    EXPECT_FLOAT_EQ(character.face.drives[0].coefficient, 1.0f / 1024);
    EXPECT_EQ(character.face.drives[0].side, Side::Positive);
    EXPECT_TRUE(character.face.joints.empty());
    // A: is the model's own target now; p_b_m and anger still expand into FAPs.
    EXPECT_TRUE(character.face.visemes[9].empty());
    EXPECT_EQ(character.face.visemes[0].size(), 1u);
    EXPECT_EQ(character.face.expressions[2].size(), 1u);
    EXPECT_TRUE(character.validateFace());
}

TEST(FaceMapping, JointsAreFoundByTheirSourceNamesToo)
{
    Character character = withTargets({});
    FaceMapping mapping;
    mapping.joints = {{"head_bone", fapChannel(48), {1, 0, 0}, 1e-5}, {"Head", fapChannel(49), {0, 1, 0}, 1e-5}};
    EXPECT_TRUE(applyFaceMapping(mapping, character).empty());
    ASSERT_EQ(character.face.joints.size(), 2u);
    EXPECT_EQ(character.face.joints[0].joint, 0);
    EXPECT_EQ(character.face.joints[1].channel, fapChannel(49));
}

TEST(FaceNaming, ExpressionNamesAnyCaseAndChannelNamedTargets)
{
    const Character character = withTargets({"ANGRY", "Disgusted", "happy", "blendShape1.Scared", "fap19", "Open_Jaw",
                                             "viseme3", "Sadness", "Wink"});
    const FaceMapping mapping = recogniseFaceMapping(character);
    const auto channelOf = [&](const std::string& target) {
        for (const FaceMappingDrive& drive : mapping.drives)
            if (drive.target == target)
                return drive.channel;
        return -1;
    };
    EXPECT_EQ(channelOf("ANGRY"), expressionChannel(3));
    EXPECT_EQ(channelOf("Disgusted"), expressionChannel(5));
    EXPECT_EQ(channelOf("happy"), expressionChannel(1));
    EXPECT_EQ(channelOf("blendShape1.Scared"), expressionChannel(4));
    EXPECT_EQ(channelOf("Sadness"), expressionChannel(2));
    EXPECT_EQ(channelOf("fap19"), fapChannel(19));
    EXPECT_EQ(channelOf("Open_Jaw"), fapChannel(3));
    EXPECT_EQ(channelOf("viseme3"), visemeChannel(3));
    EXPECT_EQ(channelOf("Wink"), -1);
    EXPECT_EQ(mapping.drives.size(), 8u); // each once
    EXPECT_EQ(mapping.name, "expression targets, face channel targets");
}

TEST(FaceNaming, EveryArkitShapeButFourFollowsAFapAndTheJawBoneOnlyWithoutJawOpen)
{
    const char* arkit[] = {"eyeBlinkLeft", "eyeLookDownLeft", "eyeLookInLeft", "eyeLookOutLeft", "eyeLookUpLeft",
                           "eyeSquintLeft", "eyeWideLeft", "eyeBlinkRight", "eyeLookDownRight", "eyeLookInRight",
                           "eyeLookOutRight", "eyeLookUpRight", "eyeSquintRight", "eyeWideRight", "jawForward",
                           "jawLeft", "jawRight", "jawOpen", "mouthClose", "mouthFunnel", "mouthPucker", "mouthLeft",
                           "mouthRight", "mouthSmileLeft", "mouthSmileRight", "mouthFrownLeft", "mouthFrownRight",
                           "mouthDimpleLeft", "mouthDimpleRight", "mouthStretchLeft", "mouthStretchRight",
                           "mouthRollLower", "mouthRollUpper", "mouthShrugLower", "mouthShrugUpper", "mouthPressLeft",
                           "mouthPressRight", "mouthLowerDownLeft", "mouthLowerDownRight", "mouthUpperUpLeft",
                           "mouthUpperUpRight", "browDownLeft", "browDownRight", "browInnerUp", "browOuterUpLeft",
                           "browOuterUpRight", "cheekPuff", "cheekSquintLeft", "cheekSquintRight", "noseSneerLeft",
                           "noseSneerRight", "tongueOut"};
    Character character = withTargets({});
    for (const char* name : arkit)
        character.face.targets.push_back({name, {}, {}});
    const FaceMapping mapping = recogniseFaceMapping(character);
    std::set<std::string> followFaps;
    for (const FaceMappingDrive& drive : mapping.drives)
        if (drive.channel < kFapCount) {
            followFaps.insert(drive.target);
            EXPECT_NE(drive.side, Side::Both) << drive.target; // weights never go below 0
        }
    EXPECT_EQ(followFaps.size(), 48u);
    for (const char* unmapped : {"mouthLeft", "mouthRight", "mouthDimpleLeft", "mouthDimpleRight"})
        EXPECT_FALSE(followFaps.contains(unmapped)) << unmapped;
    // Every viseme and expression is played by some ARKit shape.
    std::set<int> channels;
    for (const FaceMappingDrive& drive : mapping.drives)
        channels.insert(drive.channel);
    for (int v = 1; v <= kVisemeCount; ++v)
        EXPECT_TRUE(channels.contains(visemeChannel(v))) << "viseme " << v;
    for (int e = 1; e <= kExpressionCount; ++e)
        EXPECT_TRUE(channels.contains(expressionChannel(e))) << "expression " << e;
    EXPECT_TRUE(mapping.joints.empty());

    // A jaw bone turns with open_jaw only when no target does.
    anim::Joint root, jaw;
    root.name = "skullbase";
    jaw.name = "jaw_root";
    jaw.parent = 0;
    character.skeleton = std::move(anim::Skeleton::create({root, jaw})).value();
    const auto jawJoints = [](const FaceMapping& m) {
        return std::count_if(m.joints.begin(), m.joints.end(), [](const FaceMappingJoint& j) { return j.joint == "jaw_root"; });
    };
    EXPECT_EQ(jawJoints(recogniseFaceMapping(character)), 0);
    character.face.targets.erase(character.face.targets.begin() + 17); // jawOpen
    EXPECT_EQ(jawJoints(recogniseFaceMapping(character)), 1);
}

} // namespace
} // namespace thespis::core::scene
