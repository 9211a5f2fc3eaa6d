// The PRT bake file: round trip, and every kind of damage refused with a clear error.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <unistd.h>

#include "lighting/transfer_bake.h"
#include "util/crc32.h"

namespace fs = std::filesystem;
using namespace thespis::core;
using namespace thespis::core::lighting;

namespace {

// A fresh, empty folder for one test, removed afterwards.
class TempDir {
public:
    TempDir()
    {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        m_path = fs::temp_directory_path() /
                 ("thespis_bake_file_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
        fs::remove_all(m_path);
        fs::create_directories(m_path);
    }
    ~TempDir()
    {
        std::error_code ec;
        fs::remove_all(m_path, ec);
    }
    const fs::path& path() const { return m_path; }

private:
    fs::path m_path;
};

std::string readBytes(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
}

void writeBytes(const fs::path& path, const std::string& bytes)
{
    std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

// Three segments, the middle one an unbaked occluder, order 3: 9 floats per baked vertex.
TransferBake sampleBake()
{
    TransferBake bake;
    bake.order = 3;
    bake.transferKind = TransferKind::DiffuseShadowedMerged;
    bake.raysPerVertex = 256;
    bake.epsilon = 1.71e-4f;
    bake.seed = 0x1234'5678'9abc'def0ull;
    bake.vertexCount = 9;
    bake.segments = {{"Torso", 0, 4, 0, true, scene::SegmentRole::None},
                     {"Hair", 4, 2, 0, false, scene::SegmentRole::Occluder},
                     {"Head", 6, 3, 4 * 9, true, scene::SegmentRole::Receiver}};
    bake.transfer.resize((4 + 3) * 9);
    for (std::size_t i = 0; i < bake.transfer.size(); ++i)
        bake.transfer[i] = float(i % 7) * 0.125f - 0.3f + float(i) * 1e-3f;
    return bake;
}

// The mesh the sample bake belongs to: only counts, names and roles matter here.
scene::CharacterMesh sampleMesh()
{
    scene::CharacterMesh mesh;
    mesh.positions.resize(9);
    mesh.normals.assign(9, {0, 1, 0});
    mesh.segments.resize(3);
    const char* names[] = {"Torso", "Hair", "Head"};
    const std::uint32_t first[] = {0, 4, 6}, count[] = {4, 2, 3};
    const scene::SegmentRole roles[] = {scene::SegmentRole::None, scene::SegmentRole::Occluder,
                                        scene::SegmentRole::Receiver};
    for (int s = 0; s < 3; ++s) {
        mesh.segments[s].name = names[s];
        mesh.segments[s].firstVertex = first[s];
        mesh.segments[s].vertexCount = count[s];
        mesh.segments[s].role = roles[s];
    }
    return mesh;
}

// Byte offsets of fields in the sample file (see the layout in bake_file.cpp).
constexpr std::size_t kVersionOffset = 8;
constexpr std::size_t kSegmentCountOffset = 8 + 4 * 4 + 4 + 8 + 8 + 8;

void putU32(std::string& bytes, std::size_t offset, std::uint32_t value)
{
    for (int i = 0; i < 4; ++i)
        bytes[offset + i] = char((value >> (8 * i)) & 0xffu);
}

} // namespace

TEST(Crc32, MatchesTheStandardCheckValueAndChains)
{
    EXPECT_EQ(crc32("123456789"), 0xCBF43926u);
    EXPECT_EQ(crc32(""), 0u);
    EXPECT_EQ(crc32("The quick brown fox jumps over the lazy dog"), 0x414FA339u);
    // Pieces of every alignment give the same result as the whole.
    const std::string text = "The quick brown fox jumps over the lazy dog";
    for (std::size_t cut = 0; cut <= text.size(); ++cut)
        EXPECT_EQ(crc32(std::string_view(text).substr(cut), crc32(std::string_view(text).substr(0, cut))),
                  0x414FA339u);
}

TEST(BakeFile, RoundTripIsExact)
{
    TempDir dir;
    const TransferBake bake = sampleBake();
    const fs::path path = dir.path() / "robot.prt";
    ASSERT_TRUE(writeBakeFile(path, bake).ok());
    Result<TransferBake> read = readBakeFile(path);
    ASSERT_TRUE(read.ok()) << describe(read.error());
    EXPECT_EQ(*read, bake);
    EXPECT_TRUE(read->vertexTransfer(5).empty()); // the occluder stored nothing
    ASSERT_EQ(read->vertexTransfer(7).size(), 9u);
    EXPECT_EQ(read->vertexTransfer(7)[0], bake.transfer[(4 + 1) * 9]);
    // Only the file: no temporary left beside it.
    EXPECT_EQ(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator()), 1);
}

TEST(BakeFile, Format1FilesStillReadWithoutAGeometryHash)
{
    // A format 1 file is a format 2 file without the geometry hash after the vertex count.
    TempDir dir;
    TransferBake bake = sampleBake();
    bake.geometryHash = meshGeometryHash(sampleMesh());
    const fs::path path = dir.path() / "robot.prt";
    ASSERT_TRUE(writeBakeFile(path, bake).ok());
    std::string bytes = readBytes(path);
    bytes.erase(kSegmentCountOffset - 8, 8);
    putU32(bytes, kVersionOffset, 1);
    bytes.resize(bytes.size() - 4);
    const std::uint32_t crc = crc32(bytes);
    bytes.resize(bytes.size() + 4);
    putU32(bytes, bytes.size() - 4, crc);
    writeBytes(path, bytes);
    Result<TransferBake> read = readBakeFile(path);
    ASSERT_TRUE(read.ok()) << describe(read.error());
    EXPECT_EQ(read->geometryHash, 0u);
    read->geometryHash = bake.geometryHash;
    EXPECT_EQ(*read, bake);
    EXPECT_TRUE(checkBakeMatchesMesh(*read, sampleMesh()).ok());
}

TEST(BakeFile, EveryTruncationIsRefused)
{
    TempDir dir;
    const fs::path path = dir.path() / "robot.prt";
    ASSERT_TRUE(writeBakeFile(path, sampleBake()).ok());
    const std::string bytes = readBytes(path);
    for (std::size_t length = 0; length < bytes.size(); ++length) {
        Result<TransferBake> read = parseBakeBytes(std::string_view(bytes).substr(0, length), path);
        ASSERT_FALSE(read.ok()) << "length " << length;
        EXPECT_EQ(read.error().code, length < 8 ? ErrorCode::NotOurFormat : ErrorCode::CorruptData) << length;
    }
    // A cut in the floats says where the file ends.
    writeBytes(path, bytes.substr(0, bytes.size() - 10));
    Result<TransferBake> read = readBakeFile(path);
    ASSERT_FALSE(read.ok());
    EXPECT_NE(read.error().message.find("ends inside the transfer"), std::string::npos) << read.error().message;
    EXPECT_NE(read.error().message.find(path.string()), std::string::npos);
}

TEST(BakeFile, EveryFlippedByteIsRefused)
{
    TempDir dir;
    const fs::path path = dir.path() / "robot.prt";
    ASSERT_TRUE(writeBakeFile(path, sampleBake()).ok());
    const std::string bytes = readBytes(path);
    for (std::size_t at = 0; at < bytes.size(); ++at) {
        std::string damaged = bytes;
        damaged[at] = char(damaged[at] ^ 0x10);
        EXPECT_FALSE(parseBakeBytes(damaged, path).ok()) << "byte " << at;
    }
    // A change in the floats passes every count check: the checksum catches it.
    std::string damaged = bytes;
    damaged[bytes.size() - 20] = char(damaged[bytes.size() - 20] ^ 0x01);
    writeBytes(path, damaged);
    Result<TransferBake> read = readBakeFile(path);
    ASSERT_FALSE(read.ok());
    EXPECT_EQ(read.error().code, ErrorCode::CorruptData);
    EXPECT_NE(read.error().message.find("checksum"), std::string::npos) << read.error().message;
}

TEST(BakeFile, WrongMagicIsNotOurFormat)
{
    TempDir dir;
    const fs::path path = dir.path() / "robot.prt";
    writeBytes(path, "glTF\x02\0\0\0 something else entirely");
    Result<TransferBake> read = readBakeFile(path);
    ASSERT_FALSE(read.ok());
    EXPECT_EQ(read.error().code, ErrorCode::NotOurFormat);
    EXPECT_NE(read.error().message.find("not a Thespis bake file"), std::string::npos);
}

TEST(BakeFile, MissingFileIsFileNotFound)
{
    TempDir dir;
    Result<TransferBake> read = readBakeFile(dir.path() / "none.prt");
    ASSERT_FALSE(read.ok());
    EXPECT_EQ(read.error().code, ErrorCode::FileNotFound);
}

TEST(BakeFile, NewerVersionAsksForAnUpdate)
{
    TempDir dir;
    const fs::path path = dir.path() / "robot.prt";
    ASSERT_TRUE(writeBakeFile(path, sampleBake()).ok());
    std::string bytes = readBytes(path);
    putU32(bytes, kVersionOffset, 3);
    writeBytes(path, bytes);
    Result<TransferBake> read = readBakeFile(path);
    ASSERT_FALSE(read.ok());
    EXPECT_EQ(read.error().code, ErrorCode::NewerVersion);
    EXPECT_NE(read.error().message.find("newer"), std::string::npos) << read.error().message;
}

TEST(BakeFile, HugeCountsAreRefusedBeforeAllocating)
{
    TempDir dir;
    const fs::path path = dir.path() / "robot.prt";
    ASSERT_TRUE(writeBakeFile(path, sampleBake()).ok());
    const std::string bytes = readBytes(path);
    // Trusting this count would allocate about 200 GB of segments.
    std::string damaged = bytes;
    putU32(damaged, kSegmentCountOffset, 0xffffffffu);
    writeBytes(path, damaged);
    Result<TransferBake> read = readBakeFile(path);
    ASSERT_FALSE(read.ok());
    EXPECT_EQ(read.error().code, ErrorCode::CorruptData);
    EXPECT_NE(read.error().message.find("segment count"), std::string::npos) << read.error().message;
    // A name length past the end of the file.
    damaged = bytes;
    putU32(damaged, kSegmentCountOffset + 4, 0x7fffffffu);
    writeBytes(path, damaged);
    read = readBakeFile(path);
    ASSERT_FALSE(read.ok());
    EXPECT_NE(read.error().message.find("segment 0 name"), std::string::npos) << read.error().message;
}

TEST(BakeFile, InconsistentBakeIsNotWritten)
{
    TempDir dir;
    TransferBake bake = sampleBake();
    bake.transfer.pop_back();
    const fs::path path = dir.path() / "robot.prt";
    Result<void> written = writeBakeFile(path, bake);
    ASSERT_FALSE(written.ok());
    EXPECT_EQ(written.error().code, ErrorCode::InvalidArgument);
    EXPECT_FALSE(fs::exists(path));
}

TEST(BakeFile, NonFiniteValuesAreRefusedEvenWithAGoodChecksum)
{
    // Found by fuzz_bake_file: a NaN in the transfer, under a checksum that matches, was accepted.
    TempDir dir;
    const fs::path path = dir.path() / "robot.prt";
    ASSERT_TRUE(writeBakeFile(path, sampleBake()).ok());
    std::string bytes = readBytes(path);
    const std::size_t crcOffset = bytes.size() - 4;
    const std::size_t lastFloat = crcOffset - 4;
    bytes.replace(lastFloat, 4, std::string("\x00\x00\xc0\x7f", 4)); // a quiet NaN, little-endian
    putU32(bytes, crcOffset, crc32(std::string_view(bytes).substr(0, crcOffset)));
    writeBytes(path, bytes);
    Result<TransferBake> read = readBakeFile(path);
    ASSERT_FALSE(read.ok());
    EXPECT_EQ(read.error().code, ErrorCode::CorruptData);
    EXPECT_NE(read.error().message.find("is not a finite number"), std::string::npos) << read.error().message;

    TransferBake bake = sampleBake();
    bake.transfer.back() = std::numeric_limits<float>::infinity();
    const fs::path other = dir.path() / "other.prt";
    EXPECT_EQ(writeBakeFile(other, bake).error().code, ErrorCode::InvalidArgument);
    EXPECT_FALSE(fs::exists(other));
}

TEST(BakeFile, MismatchedMeshIsNamed)
{
    const TransferBake bake = sampleBake();
    EXPECT_TRUE(checkBakeMatchesMesh(bake, sampleMesh()).ok());

    scene::CharacterMesh mesh = sampleMesh();
    mesh.positions.resize(10);
    Result<void> check = checkBakeMatchesMesh(bake, mesh);
    ASSERT_FALSE(check.ok());
    EXPECT_NE(check.error().message.find("9 vertices, the mesh 10"), std::string::npos) << check.error().message;

    mesh = sampleMesh();
    mesh.segments[2].name = "Skull";
    check = checkBakeMatchesMesh(bake, mesh);
    ASSERT_FALSE(check.ok());
    EXPECT_NE(check.error().message.find("\"Head\" in the bake and \"Skull\""), std::string::npos)
        << check.error().message;

    mesh = sampleMesh();
    mesh.segments[0].vertexCount = 3;
    mesh.segments[1].firstVertex = 3;
    mesh.segments[1].vertexCount = 3;
    check = checkBakeMatchesMesh(bake, mesh);
    ASSERT_FALSE(check.ok());
    EXPECT_NE(check.error().message.find("\"Torso\""), std::string::npos) << check.error().message;

    // A DSM bake depends on the tags: a re-tagged segment makes it stale.
    mesh = sampleMesh();
    mesh.segments[2].role = scene::SegmentRole::None;
    check = checkBakeMatchesMesh(bake, mesh);
    ASSERT_FALSE(check.ok());
    EXPECT_NE(check.error().message.find("baked as receiver"), std::string::npos) << check.error().message;
    TransferBake shadowed = bake;
    shadowed.transferKind = TransferKind::DiffuseShadowed;
    EXPECT_TRUE(checkBakeMatchesMesh(shadowed, mesh).ok());

    // A bake that recorded the mesh's geometry sees a moved vertex, though counts and names
    // still match.
    TransferBake recorded = bake;
    recorded.geometryHash = meshGeometryHash(sampleMesh());
    EXPECT_TRUE(checkBakeMatchesMesh(recorded, sampleMesh()).ok());
    mesh = sampleMesh();
    mesh.positions[4].y += 0.01f;
    check = checkBakeMatchesMesh(recorded, mesh);
    ASSERT_FALSE(check.ok());
    EXPECT_NE(check.error().message.find("shape changed"), std::string::npos) << check.error().message;
    EXPECT_NE(meshGeometryHash(mesh), recorded.geometryHash);
}
