// Character meshes (core/scene): the glTF bind-pose import on the real characters, splitting a
// skinned mesh by dominant joint, segment tags, and broken glTF files refused with a message.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "scene/character_mesh.h"
#include "scene/gltf_mesh.h"
#include "test_support.h"

namespace thespis::core::scene {
namespace {

using test::sharedData;

struct CharacterFile {
    const char* path;
    std::size_t vertices;  // as counted in the file's accessors by an independent JSON reader
    std::size_t triangles;
    std::size_t meshNodes;
    double height;         // bind-pose height along +Y, metres (approximate)
};

const CharacterFile kCharacters[] = {
    {"characters/CesiumMan/CesiumMan.glb", 3273, 4672, 1, 1.5},
    {"characters/RiggedFigure/RiggedFigure.gltf", 370, 256, 1, 1.45},
    {"characters/RiggedSimple/RiggedSimple.gltf", 96, 188, 1, 9.15},
    {"characters/RobotExpressive/RobotExpressive.glb", 7214, 3237, 14, 4.6},
};

std::array<float, 3> boundsExtent(const CharacterMesh& mesh)
{
    std::array<float, 3> lower{1e30f, 1e30f, 1e30f}, upper{-1e30f, -1e30f, -1e30f};
    for (const Vec3& p : mesh.positions) {
        const float c[3] = {p.x, p.y, p.z};
        for (int a = 0; a < 3; ++a) {
            lower[a] = std::min(lower[a], c[a]);
            upper[a] = std::max(upper[a], c[a]);
        }
    }
    return {upper[0] - lower[0], upper[1] - lower[1], upper[2] - lower[2]};
}

TEST(GltfMesh, LoadsTheRealCharactersWithTheFileCounts)
{
    for (const CharacterFile& file : kCharacters) {
        SCOPED_TRACE(file.path);
        Result<CharacterMesh> mesh = loadGltfMesh(sharedData(file.path), {.splitSkinnedByJoint = false});
        ASSERT_TRUE(mesh.ok()) << describe(mesh.error());
        EXPECT_EQ(mesh->vertexCount(), file.vertices);
        EXPECT_EQ(mesh->triangleCount(), file.triangles);
        EXPECT_EQ(mesh->segments.size(), file.meshNodes);
        EXPECT_TRUE(mesh->validate().ok());
        for (const Vec3& n : mesh->normals)
            ASSERT_NEAR(std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z), 1.0, 1e-5);
        // Placed in the scene: the characters stand along +Y (the files' root nodes turn their
        // Z-up meshes), about as tall as the artists made them.
        const std::array<float, 3> extent = boundsExtent(*mesh);
        EXPECT_NEAR(extent[1], file.height, 0.1 * file.height);
        EXPECT_LT(extent[2], extent[1]);
        for (const Segment& segment : mesh->segments) {
            EXPECT_FALSE(segment.name.empty());
            const Quatd& q = segment.bindRotation;
            EXPECT_NEAR(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w, 1.0, 1e-9);
        }
    }
}

TEST(GltfMesh, RobotExpressiveKeepsItsMeshNodesAsSegments)
{
    Result<CharacterMesh> mesh =
        loadGltfMesh(sharedData("characters/RobotExpressive/RobotExpressive.glb"), {.splitSkinnedByJoint = false});
    ASSERT_TRUE(mesh.ok()) << describe(mesh.error());
    for (const char* name : {"Head", "Torso", "Foot.L", "Hand.R", "LowerLeg.R"})
        EXPECT_NE(mesh->findSegment(name), nullptr) << name;
    const Segment* head = mesh->findSegment("Head");
    const Segment* foot = mesh->findSegment("Foot.L");
    ASSERT_TRUE(head && foot);
    // The head (three primitives) sits well above the foot.
    auto centreY = [&](const Segment& s) {
        double sum = 0;
        for (std::uint32_t v = s.firstVertex; v < s.firstVertex + s.vertexCount; ++v)
            sum += mesh->positions[v].y;
        return sum / s.vertexCount;
    };
    EXPECT_EQ(head->vertexCount, 302u + 876u + 564u);
    EXPECT_GT(centreY(*head), centreY(*foot) + 2.0);
    EXPECT_EQ(head->joint, "Head");
}

/// Triangles as sorted corner positions, to compare two meshes' surfaces whatever the order.
std::vector<std::array<float, 9>> triangleSet(const CharacterMesh& mesh)
{
    std::vector<std::array<float, 9>> triangles;
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        std::array<float, 9> corners;
        for (int k = 0; k < 3; ++k) {
            const Vec3& p = mesh.positions[mesh.indices[3 * t + std::size_t(k)]];
            corners[std::size_t(3 * k)] = p.x;
            corners[std::size_t(3 * k + 1)] = p.y;
            corners[std::size_t(3 * k + 2)] = p.z;
        }
        triangles.push_back(corners);
    }
    std::sort(triangles.begin(), triangles.end());
    return triangles;
}

TEST(GltfMesh, SplittingASkinnedMeshByJointPartitionsItsTriangles)
{
    for (const char* path : {"characters/CesiumMan/CesiumMan.glb", "characters/RiggedFigure/RiggedFigure.gltf",
                             "characters/RobotExpressive/RobotExpressive.glb"}) {
        SCOPED_TRACE(path);
        Result<CharacterMesh> whole = loadGltfMesh(sharedData(path), {.splitSkinnedByJoint = false});
        Result<CharacterMesh> split = loadGltfMesh(sharedData(path), {.splitSkinnedByJoint = true});
        ASSERT_TRUE(whole.ok() && split.ok());
        EXPECT_TRUE(split->validate().ok());
        EXPECT_GT(split->segments.size(), whole->segments.size() + 3);
        EXPECT_EQ(split->triangleCount(), whole->triangleCount());
        // Vertices on a cut are duplicated, never lost.
        EXPECT_GE(split->vertexCount(), std::size_t(0.9 * double(whole->vertexCount())));
        EXPECT_EQ(triangleSet(*split), triangleSet(*whole));
        for (const Segment& segment : split->segments) {
            EXPECT_GT(segment.triangleCount, 0u) << segment.name;
            EXPECT_FALSE(segment.joint.empty()) << segment.name;
        }
    }
}

TEST(GltfMesh, SplitSegmentsCarryTheirJointsBindFrame)
{
    Result<CharacterMesh> mesh = loadGltfMesh(sharedData("characters/RobotExpressive/RobotExpressive.glb"));
    ASSERT_TRUE(mesh.ok()) << describe(mesh.error());
    // Hand.L is skinned: split, its palm and fingers are segments named after their joints.
    const Segment* palm = mesh->findSegment("Palm2.L");
    ASSERT_NE(palm, nullptr);
    EXPECT_EQ(palm->joint, "Palm2.L");
    // The joint's bind position lies among the segment's vertices (within a hand's size).
    double nearest = 1e30;
    for (std::uint32_t v = palm->firstVertex; v < palm->firstVertex + palm->vertexCount; ++v) {
        const Vec3& p = mesh->positions[v];
        const double dx = p.x - palm->bindTranslation.x, dy = p.y - palm->bindTranslation.y,
                     dz = p.z - palm->bindTranslation.z;
        nearest = std::min(nearest, std::sqrt(dx * dx + dy * dy + dz * dz));
    }
    EXPECT_LT(nearest, 0.3);
}

TEST(CharacterMesh, ValidateNamesWhatIsBroken)
{
    Result<CharacterMesh> loaded = loadGltfMesh(sharedData("characters/RiggedSimple/RiggedSimple.gltf"));
    ASSERT_TRUE(loaded.ok());
    {
        CharacterMesh mesh = *loaded;
        mesh.normals[3] = {0, 0, 2};
        const Result<void> ok = mesh.validate();
        ASSERT_FALSE(ok.ok());
        EXPECT_NE(ok.error().message.find("Vertex 3"), std::string::npos) << ok.error().message;
    }
    {
        CharacterMesh mesh = *loaded;
        mesh.segments[0].vertexCount -= 1;
        EXPECT_FALSE(mesh.validate().ok());
    }
    {
        CharacterMesh mesh = *loaded;
        mesh.positions[0].y = std::nanf("");
        EXPECT_FALSE(mesh.validate().ok());
    }
}

TEST(CharacterMesh, RoleNamesRoundTrip)
{
    for (SegmentRole role : {SegmentRole::None, SegmentRole::Receiver, SegmentRole::Occluder})
        EXPECT_EQ(*parseSegmentRole(segmentRoleName(role)), role);
    EXPECT_FALSE(parseSegmentRole("caster").ok());
}

// ---- files the tests write --------------------------------------------------------------------

class ScratchFolder : public ::testing::Test {
protected:
    void SetUp() override
    {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        m_folder = std::filesystem::temp_directory_path() /
                   (std::string("thespis_scene_test_") + info->name() + "_" + std::to_string(::getpid()));
        std::filesystem::create_directories(m_folder);
    }
    void TearDown() override { std::filesystem::remove_all(m_folder); }

    std::filesystem::path write(const std::string& name, const std::string& content)
    {
        const std::filesystem::path path = m_folder / name;
        std::ofstream(path, std::ios::binary) << content;
        return path;
    }
    static std::string readAll(const std::filesystem::path& path)
    {
        std::ifstream in(path, std::ios::binary);
        return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    }
    /// RiggedSimple's JSON, edited by `edit`, written beside a copy of its buffer.
    template <class Edit>
    std::filesystem::path riggedSimple(const std::string& name, Edit&& edit, std::string extraBuffer = {})
    {
        const std::filesystem::path source = sharedData("characters/RiggedSimple");
        nlohmann::json gltf = nlohmann::json::parse(readAll(source / "RiggedSimple.gltf"));
        std::string buffer = readAll(source / "RiggedSimple0.bin") + extraBuffer;
        gltf["buffers"][0]["byteLength"] = buffer.size();
        edit(gltf);
        write("RiggedSimple0.bin", buffer);
        return write(name, gltf.dump());
    }
    static nlohmann::json& firstPrimitive(nlohmann::json& gltf) { return gltf["meshes"][0]["primitives"][0]; }

    std::filesystem::path m_folder;
};

std::string messageOf(const Result<CharacterMesh>& result)
{
    return result.ok() ? std::string("(loaded)") : result.error().message + " | " + result.error().detail;
}

using GltfErrors = ScratchFolder;

TEST_F(GltfErrors, MissingFile)
{
    const Result<CharacterMesh> mesh = loadGltfMesh(m_folder / "nothing.glb");
    ASSERT_FALSE(mesh.ok());
    EXPECT_EQ(mesh.error().code, ErrorCode::FileNotFound);
    EXPECT_NE(mesh.error().message.find("nothing.glb"), std::string::npos);
}

TEST_F(GltfErrors, TruncatedGlb)
{
    const std::string glb = readAll(sharedData("characters/CesiumMan/CesiumMan.glb"));
    for (std::size_t size : {std::size_t(3), std::size_t(20), std::size_t(1000), glb.size() / 2, glb.size() - 1}) {
        const Result<CharacterMesh> mesh = loadGltfMesh(write("cut.glb", glb.substr(0, size)));
        ASSERT_FALSE(mesh.ok()) << size;
        EXPECT_NE(mesh.error().message.find("cut.glb"), std::string::npos) << messageOf(mesh);
    }
}

TEST_F(GltfErrors, BadJson)
{
    const Result<CharacterMesh> mesh = loadGltfMesh(write("bad.gltf", "{ \"asset\": { \"version\": \"2.0\" }, "));
    ASSERT_FALSE(mesh.ok());
    EXPECT_EQ(mesh.error().code, ErrorCode::CorruptData);
    EXPECT_NE(mesh.error().message.find("bad.gltf"), std::string::npos);
}

TEST_F(GltfErrors, RequiredExtensionsAreNamed)
{
    for (const char* extension : {"KHR_draco_mesh_compression", "EXT_meshopt_compression", "EXT_mesh_gpu_instancing"}) {
        const Result<CharacterMesh> mesh = loadGltfMesh(riggedSimple("draco.gltf", [&](nlohmann::json& gltf) {
            gltf["extensionsUsed"] = {extension};
            gltf["extensionsRequired"] = {extension};
        }));
        ASSERT_FALSE(mesh.ok()) << extension;
        EXPECT_NE(mesh.error().message.find(extension), std::string::npos) << messageOf(mesh);
    }
    // A required extension that leaves the geometry alone is accepted.
    const Result<CharacterMesh> quantized = loadGltfMesh(riggedSimple("quantized.gltf", [](nlohmann::json& gltf) {
        gltf["extensionsUsed"] = {"KHR_mesh_quantization"};
        gltf["extensionsRequired"] = {"KHR_mesh_quantization"};
    }));
    EXPECT_TRUE(quantized.ok()) << messageOf(quantized);
}

TEST_F(GltfErrors, AccessorOutOfRange)
{
    const Result<CharacterMesh> past = loadGltfMesh(riggedSimple("past.gltf", [](nlohmann::json& gltf) {
        const int position = firstPrimitive(gltf)["attributes"]["POSITION"];
        gltf["accessors"][position]["byteOffset"] = 4000;
    }));
    ASSERT_FALSE(past.ok());
    EXPECT_NE(past.error().message.find("POSITION"), std::string::npos) << messageOf(past);

    const Result<CharacterMesh> index = loadGltfMesh(riggedSimple("index.gltf", [](nlohmann::json& gltf) {
        firstPrimitive(gltf)["attributes"]["NORMAL"] = 999;
    }));
    ASSERT_FALSE(index.ok());
    EXPECT_NE(messageOf(index).find("999"), std::string::npos) << messageOf(index);

    const Result<CharacterMesh> view = loadGltfMesh(riggedSimple("view.gltf", [](nlohmann::json& gltf) {
        for (auto& bufferView : gltf["bufferViews"])
            bufferView["byteLength"] = 1 << 20;
    }));
    EXPECT_FALSE(view.ok());
}

TEST_F(GltfErrors, PointsLinesAndMissingPositionsAreRefused)
{
    const Result<CharacterMesh> points =
        loadGltfMesh(riggedSimple("points.gltf", [](nlohmann::json& gltf) { firstPrimitive(gltf)["mode"] = 0; }));
    ASSERT_FALSE(points.ok());
    EXPECT_NE(points.error().message.find("points or lines"), std::string::npos) << messageOf(points);

    const Result<CharacterMesh> noPositions = loadGltfMesh(riggedSimple("nopos.gltf", [](nlohmann::json& gltf) {
        firstPrimitive(gltf)["attributes"].erase("POSITION");
    }));
    ASSERT_FALSE(noPositions.ok());
    EXPECT_NE(noPositions.error().message.find("POSITION"), std::string::npos) << messageOf(noPositions);
}

TEST_F(GltfErrors, StripsAndFansBecomeTriangles)
{
    // The first 6 indices read as a strip give 4 triangles, as a fan 4 too.
    for (int mode : {5, 6}) {
        const Result<CharacterMesh> mesh = loadGltfMesh(riggedSimple("strip.gltf", [&](nlohmann::json& gltf) {
            firstPrimitive(gltf)["mode"] = mode;
            const int indices = firstPrimitive(gltf)["indices"];
            gltf["accessors"][indices]["count"] = 6;
        }));
        ASSERT_TRUE(mesh.ok()) << messageOf(mesh);
        EXPECT_LE(mesh->triangleCount(), 4u);
        EXPECT_GE(mesh->triangleCount(), 3u); // a strip drops degenerate triangles
    }
}

TEST_F(GltfErrors, MissingNormalsAreComputedAreaWeighted)
{
    const Result<CharacterMesh> original = loadGltfMesh(sharedData("characters/RiggedSimple/RiggedSimple.gltf"));
    const Result<CharacterMesh> computed = loadGltfMesh(riggedSimple("nonormals.gltf", [](nlohmann::json& gltf) {
        firstPrimitive(gltf)["attributes"].erase("NORMAL");
    }));
    ASSERT_TRUE(original.ok() && computed.ok()) << messageOf(computed);
    ASSERT_EQ(original->vertexCount(), computed->vertexCount());
    double meanCosine = 0;
    for (std::size_t v = 0; v < original->vertexCount(); ++v) {
        const Vec3 a = original->normals[v], b = computed->normals[v];
        meanCosine += a.x * b.x + a.y * b.y + a.z * b.z;
    }
    meanCosine /= double(original->vertexCount());
    // A cylinder with flat caps: the file's normals are split at the caps, ours point outward.
    EXPECT_GT(meanCosine, 0.8);
    EXPECT_TRUE(computed->validate().ok());
}

TEST_F(GltfErrors, SparseAccessorsReplaceElements)
{
    // Sparse part of POSITION: element 5 becomes (0.5, 0.25, 2), appended to the buffer.
    const std::string base = readAll(sharedData("characters/RiggedSimple/RiggedSimple0.bin"));
    std::string extra(16, '\0');
    const std::uint32_t element = 5;
    const float value[3] = {0.5f, 0.25f, 2.0f};
    std::memcpy(extra.data(), &element, 4);
    std::memcpy(extra.data() + 4, value, 12);
    auto addSparse = [&](nlohmann::json& gltf) {
            gltf["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", base.size()}, {"byteLength", 4}});
            gltf["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", base.size() + 4}, {"byteLength", 12}});
            const int views = int(gltf["bufferViews"].size());
            const int position = firstPrimitive(gltf)["attributes"]["POSITION"];
            gltf["accessors"][position]["sparse"] = {
                {"count", 1},
                {"indices", {{"bufferView", views - 2}, {"componentType", 5125}}},
                {"values", {{"bufferView", views - 1}}}};
    };
    const Result<CharacterMesh> original = loadGltfMesh(sharedData("characters/RiggedSimple/RiggedSimple.gltf"));
    const Result<CharacterMesh> sparse = loadGltfMesh(riggedSimple("sparse.gltf", addSparse, extra));
    ASSERT_TRUE(original.ok() && sparse.ok()) << messageOf(sparse);
    for (std::size_t v = 0; v < original->vertexCount(); ++v)
        EXPECT_EQ(original->positions[v] == sparse->positions[v], v != element) << v;

    std::string outOfRange = extra;
    const std::uint32_t badElement = 96; // RiggedSimple has 96 vertices
    std::memcpy(outOfRange.data(), &badElement, 4);
    const Result<CharacterMesh> bad = loadGltfMesh(riggedSimple("badsparse.gltf", addSparse, outOfRange));
    ASSERT_FALSE(bad.ok());
    EXPECT_NE(bad.error().message.find("sparse"), std::string::npos) << messageOf(bad);
}

// ---- segment tags -----------------------------------------------------------------------------

using SegmentTags = ScratchFolder;

TEST_F(SegmentTags, ReadsBothForms)
{
    const Result<std::vector<SegmentTag>> tags = readSegmentTagsFile(write(
        "tags.json", R"({"hair": "receiver", "Head": {"role": "occluder"}, "arm": {}})"));
    ASSERT_TRUE(tags.ok()) << describe(tags.error());
    const std::vector<SegmentTag> expected = {
        {"hair", SegmentRole::Receiver},
        {"Head", SegmentRole::Occluder},
        {"arm", SegmentRole::None},
    };
    EXPECT_EQ(*tags, expected);
}

TEST_F(SegmentTags, ErrorsNameTheFileAndTheMember)
{
    struct Case {
        const char* json;
        const char* member;
    };
    for (const Case& c : {Case{R"({"hair": "caster"})", "hair"}, Case{R"({"hair": {"role": 3}})", "hair.role"},
                          Case{R"({"hair": {"colour": "red"}})", "hair.colour"},
                          Case{R"({"hair": {"posture": "pi"}})", "hair.posture"}, Case{R"({"hair": 1})", "hair"}}) {
        const Result<std::vector<SegmentTag>> tags = readSegmentTagsFile(write("bad_tags.json", c.json));
        ASSERT_FALSE(tags.ok()) << c.json;
        EXPECT_NE(tags.error().message.find("bad_tags.json"), std::string::npos) << tags.error().message;
        EXPECT_NE(tags.error().message.find(std::string("\"") + c.member + "\""), std::string::npos)
            << tags.error().message;
    }
    for (const char* json : {"[1, 2]", "{\"hair\": ", ""}) {
        const Result<std::vector<SegmentTag>> tags = readSegmentTagsFile(write("broken.json", json));
        ASSERT_FALSE(tags.ok()) << json;
        EXPECT_NE(tags.error().message.find("broken.json"), std::string::npos) << tags.error().message;
    }
    EXPECT_EQ(readSegmentTagsFile(m_folder / "none.json").error().code, ErrorCode::FileNotFound);
}

TEST(SegmentTagsApply, AppliesByNameAndRefusesUnknownSegments)
{
    Result<CharacterMesh> mesh =
        loadGltfMesh(sharedData("characters/RobotExpressive/RobotExpressive.glb"), {.splitSkinnedByJoint = false});
    ASSERT_TRUE(mesh.ok());
    ASSERT_TRUE(applySegmentTags(*mesh, {{"Head", SegmentRole::Receiver}}).ok());
    EXPECT_EQ(mesh->findSegment("Head")->role, SegmentRole::Receiver);

    const Result<void> unknown =
        applySegmentTags(*mesh, {{"Torso", SegmentRole::Occluder}, {"Tail", SegmentRole::None}});
    ASSERT_FALSE(unknown.ok());
    EXPECT_NE(unknown.error().message.find("\"Tail\""), std::string::npos);
    EXPECT_NE(unknown.error().detail.find("Torso"), std::string::npos);
    EXPECT_EQ(mesh->findSegment("Torso")->role, SegmentRole::None); // nothing applied
}

} // namespace
} // namespace thespis::core::scene
