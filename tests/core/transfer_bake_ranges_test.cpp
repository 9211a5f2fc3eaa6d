// A transfer bake in pieces (the farm's path): ranges planned, split, baked out of order in
// separate calls and placed back equal the whole bake bit for bit, on a real character; and each
// malformed range is refused with a message naming it.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <optional>
#include <random>
#include <vector>

#include "lighting/transfer_bake.h"
#include "scene/gltf_mesh.h"
#include "test_support.h"

using namespace thespis::core;
using namespace thespis::core::lighting;

namespace {

// RobotExpressive split by joint, with an occluder (not baked) and a receiver (transparent), so
// that the plan has holes and M′ differs from the mesh. Loaded once; null when it cannot be.
const scene::CharacterMesh* taggedRobot()
{
    static const std::optional<scene::CharacterMesh> mesh = []() -> std::optional<scene::CharacterMesh> {
        Result<scene::CharacterMesh> loaded =
            scene::loadGltfMesh(thespis::test::sharedData("characters/RobotExpressive/RobotExpressive.glb"));
        if (!loaded || loaded->segments.size() < 5)
            return std::nullopt;
        const std::vector<scene::SegmentTag> tags = {{loaded->segments[1].name, scene::SegmentRole::Occluder},
                                                     {loaded->segments[3].name, scene::SegmentRole::Receiver}};
        if (!scene::applySegmentTags(*loaded, tags))
            return std::nullopt;
        return std::move(loaded).value();
    }();
    return mesh ? &*mesh : nullptr;
}

class TransferBakeRanges : public ::testing::Test {
protected:
    void SetUp() override
    {
        m_mesh = taggedRobot();
        ASSERT_TRUE(m_mesh) << "RobotExpressive.glb (../shared/data) did not load with 5 segments or more";
    }
    static BakeSettings settings(TransferKind transfer)
    {
        BakeSettings s;
        s.order = 3;
        s.raysPerVertex = 32;
        s.transfer = transfer;
        s.seed = 7;
        return s;
    }
    const scene::CharacterMesh* m_mesh = nullptr;
};

/// Bakes the plan's ranges of at most `maxVertices`, shuffled, `perCall` ranges per call, with
/// alternating thread counts, and places them into the plan.
TransferBake bakeInPieces(const scene::CharacterMesh& mesh, BakeSettings s, std::uint32_t maxVertices, std::size_t perCall)
{
    Result<TransferBake> plan = planTransferBake(mesh, s);
    EXPECT_TRUE(plan.ok());
    if (!plan)
        return {};
    std::vector<VertexRange> ranges = splitTransferBake(*plan, maxVertices);
    std::shuffle(ranges.begin(), ranges.end(), std::mt19937(42));
    const std::size_t perVertex = std::size_t(s.order) * s.order;
    for (std::size_t first = 0; first < ranges.size(); first += perCall) {
        const std::span<const VertexRange> call = std::span(ranges).subspan(first, std::min(perCall, ranges.size() - first));
        s.threads = int(1 + first / perCall % 2);
        Result<std::vector<float>> floats = bakeTransferRanges(mesh, s, call);
        EXPECT_TRUE(floats.ok()) << describe(floats.error());
        if (!floats)
            return {};
        std::size_t offset = 0;
        for (const VertexRange& range : call) {
            const std::size_t count = std::size_t(range.vertexCount) * perVertex;
            EXPECT_TRUE(placeTransferRange(*plan, range, std::span(*floats).subspan(offset, count)).ok());
            offset += count;
        }
    }
    return std::move(plan).value();
}

void expectBitIdentical(const TransferBake& pieces, const TransferBake& whole)
{
    EXPECT_EQ(pieces.segments, whole.segments);
    EXPECT_EQ(pieces.geometryHash, whole.geometryHash);
    ASSERT_EQ(pieces.transfer.size(), whole.transfer.size());
    ASSERT_FALSE(whole.transfer.empty());
    EXPECT_EQ(std::memcmp(pieces.transfer.data(), whole.transfer.data(), whole.transfer.size() * sizeof(float)), 0);
    EXPECT_TRUE(pieces == whole);
}

} // namespace

TEST_F(TransferBakeRanges, SplitCoversEveryBakedVertexOnceInTransferOrder)
{
    const Result<TransferBake> plan = planTransferBake(*m_mesh, settings(TransferKind::DiffuseShadowedMerged));
    ASSERT_TRUE(plan.ok());
    EXPECT_TRUE(std::all_of(plan->transfer.begin(), plan->transfer.end(), [](float t) { return t == 0; }));
    const std::vector<VertexRange> ranges = splitTransferBake(*plan, 50);
    std::uint64_t covered = 0;
    for (const VertexRange& range : ranges) {
        EXPECT_GE(range.vertexCount, 1u);
        EXPECT_LE(range.vertexCount, 50u);
        EXPECT_FALSE(plan->vertexTransfer(range.firstVertex).empty()) << "range starts in an occluder";
        covered += range.vertexCount;
    }
    EXPECT_EQ(covered * 9, plan->transfer.size());
    for (std::uint32_t v = plan->segments[1].firstVertex; v < plan->segments[1].firstVertex + plan->segments[1].vertexCount; ++v)
        for (const VertexRange& range : ranges)
            EXPECT_FALSE(v >= range.firstVertex && v < range.firstVertex + range.vertexCount) << "occluder vertex " << v;
}

TEST_F(TransferBakeRanges, DsmPiecesEqualTheWholeBakeBitForBit)
{
    const BakeSettings s = settings(TransferKind::DiffuseShadowedMerged);
    Result<TransferBake> whole = bakeTransfer(*m_mesh, s);
    ASSERT_TRUE(whole.ok()) << describe(whole.error());
    expectBitIdentical(bakeInPieces(*m_mesh, s, 97, 5), *whole);
    expectBitIdentical(bakeInPieces(*m_mesh, s, 1000, 1), *whole);
}

TEST_F(TransferBakeRanges, DsPiecesEqualTheWholeBakeBitForBit)
{
    // DS traces against each segment's own scene: a piece must pick its segment's.
    const BakeSettings s = settings(TransferKind::DiffuseShadowed);
    Result<TransferBake> whole = bakeTransfer(*m_mesh, s);
    ASSERT_TRUE(whole.ok()) << describe(whole.error());
    expectBitIdentical(bakeInPieces(*m_mesh, s, 211, 3), *whole);
}

TEST_F(TransferBakeRanges, MalformedRangesAreRefusedNamingThem)
{
    const BakeSettings s = settings(TransferKind::DiffuseShadowedMerged);
    const scene::Segment& occluder = m_mesh->segments[1];
    const scene::Segment& first = m_mesh->segments[0];
    const std::uint32_t total = std::uint32_t(m_mesh->vertexCount());
    struct Case {
        VertexRange range;
        const char* says;
    };
    const Case cases[] = {
        {{occluder.firstVertex, 1}, "occluder"},
        {{first.firstVertex, first.vertexCount + 1}, "inside one segment"},
        {{first.firstVertex, 0}, "non-empty"},
        {{total, 1}, "no segment holds vertex"},
    };
    for (const Case& c : cases) {
        const VertexRange ranges[] = {c.range};
        Result<std::vector<float>> baked = bakeTransferRanges(*m_mesh, s, ranges);
        ASSERT_FALSE(baked.ok()) << c.says;
        EXPECT_EQ(baked.error().code, ErrorCode::InvalidArgument);
        const std::string named = "the vertex range " + std::to_string(c.range.firstVertex) + " + "
                                  + std::to_string(c.range.vertexCount);
        EXPECT_NE(baked.error().message.find(named), std::string::npos) << baked.error().message;
        EXPECT_NE(baked.error().message.find(c.says), std::string::npos) << baked.error().message;
    }

    Result<TransferBake> plan = planTransferBake(*m_mesh, s);
    ASSERT_TRUE(plan.ok());
    const std::vector<float> tooFew(8, 1.0f);
    const Result<void> placed = placeTransferRange(*plan, {first.firstVertex, 1}, tooFew);
    ASSERT_FALSE(placed.ok());
    EXPECT_NE(placed.error().message.find("not 8"), std::string::npos) << placed.error().message;
}

TEST_F(TransferBakeRanges, CancelledRangesReturnCancelled)
{
    Result<TransferBake> plan = planTransferBake(*m_mesh, settings(TransferKind::DiffuseShadowedMerged));
    ASSERT_TRUE(plan.ok());
    std::stop_source stop;
    stop.request_stop();
    const std::vector<VertexRange> ranges = splitTransferBake(*plan, 100);
    Result<std::vector<float>> baked =
        bakeTransferRanges(*m_mesh, settings(TransferKind::DiffuseShadowedMerged), ranges, stop.get_token());
    ASSERT_FALSE(baked.ok());
    EXPECT_EQ(baked.error().code, ErrorCode::Cancelled);
}
