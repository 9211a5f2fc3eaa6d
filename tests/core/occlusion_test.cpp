// The two ray backends of the transfer bake (lighting/occlusion.h): hand-made scenes for the
// query's rules (ε, tfar, origin-vertex exclusion, empty proxy), each backend, and the real
// characters, where Embree and the uniform grid must agree on ≥ 99.99% of the bake's rays.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <numbers>
#include <thread>
#include <vector>

#include "lighting/occlusion.h"
#include "scene/gltf_mesh.h"
#include "test_support.h"

namespace thespis::core::lighting {
namespace {

using anim::Vec3;

/// Rays as structure of arrays, owning their storage.
struct Rays {
    std::vector<float> ox, oy, oz, dx, dy, dz;
    std::vector<std::uint32_t> originVertex;

    void add(Vec3 origin, Vec3 direction, std::uint32_t vertex = kNoVertex)
    {
        const float length = std::sqrt(direction.x * direction.x + direction.y * direction.y + direction.z * direction.z);
        ox.push_back(origin.x);
        oy.push_back(origin.y);
        oz.push_back(origin.z);
        dx.push_back(direction.x / length);
        dy.push_back(direction.y / length);
        dz.push_back(direction.z / length);
        originVertex.push_back(vertex);
    }
    RayBatch batch(float tnear = 1.71e-4f, float tfar = 1e30f) const
    {
        RayBatch b;
        b.originX = ox.data();
        b.originY = oy.data();
        b.originZ = oz.data();
        b.directionX = dx.data();
        b.directionY = dy.data();
        b.directionZ = dz.data();
        b.originVertex = originVertex.data();
        b.count = ox.size();
        b.tnear = tnear;
        b.tfar = tfar;
        return b;
    }
};

std::vector<std::uint8_t> trace(const OcclusionScene& scene, const RayBatch& batch)
{
    std::vector<std::uint8_t> occluded(batch.count, 0xee);
    scene.occluded(batch, occluded);
    return occluded;
}

std::unique_ptr<OcclusionScene> build(OcclusionBackendKind kind, const std::vector<Vec3>& positions,
                                      const std::vector<std::uint32_t>& indices)
{
    Result<std::unique_ptr<OcclusionScene>> scene = buildOcclusionScene(kind, {positions, indices});
    EXPECT_TRUE(scene.ok()) << describe(scene.error());
    EXPECT_EQ((*scene)->kind(), kind);
    return std::move(*scene);
}

/// A square [-1, 1]² at height z, as two triangles sharing the diagonal (0→2).
void addSquare(std::vector<Vec3>& positions, std::vector<std::uint32_t>& indices, float z)
{
    const std::uint32_t base = std::uint32_t(positions.size());
    positions.insert(positions.end(), {{-1, -1, z}, {1, -1, z}, {1, 1, z}, {-1, 1, z}});
    indices.insert(indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
}

class Backend : public ::testing::TestWithParam<OcclusionBackendKind> {};

TEST_P(Backend, ParallelPlanesHitAndMiss)
{
    std::vector<Vec3> positions;
    std::vector<std::uint32_t> indices;
    addSquare(positions, indices, 1.0f);
    const auto scene = build(GetParam(), positions, indices);
    Rays rays;
    rays.add({0.2f, 0.3f, 0}, {0, 0, 1});       // straight up: hits
    rays.add({0.2f, 0.3f, 0}, {0, 0, -1});      // down: misses
    rays.add({0.2f, 0.3f, 0}, {1, 0, 0});       // parallel to the plane: misses
    rays.add({0.2f, 0.3f, 0}, {0.5f, 0.2f, 1}); // slanted, lands inside: hits
    rays.add({0.2f, 0.3f, 0}, {3, 0, 1});       // slanted, lands outside the square: misses
    rays.add({0.2f, 0.3f, 2}, {0, 0, -1});      // from above, downward: hits (two-sided)
    rays.add({5, 5, 0}, {0, 0, 1});             // beside the square: misses
    rays.add({-3, 0.5f, 0.5f}, {4, 0, 1});      // from outside the grid's box, lands inside: hits
    EXPECT_EQ(trace(*scene, rays.batch()), (std::vector<std::uint8_t>{1, 0, 0, 1, 0, 1, 0, 1}));
}

TEST_P(Backend, HitsNearerThanEpsilonAreIgnored)
{
    std::vector<Vec3> positions;
    std::vector<std::uint32_t> indices;
    addSquare(positions, indices, 1.0e-4f); // nearer than ε = 1.71e-4
    const auto nearScene = build(GetParam(), positions, indices);
    positions.clear();
    indices.clear();
    addSquare(positions, indices, 3.0e-4f); // farther than ε
    const auto farScene = build(GetParam(), positions, indices);
    Rays rays;
    rays.add({0.1f, 0.1f, 0}, {0, 0, 1});
    EXPECT_EQ(trace(*nearScene, rays.batch())[0], 0);
    EXPECT_EQ(trace(*farScene, rays.batch())[0], 1);
    EXPECT_EQ(trace(*nearScene, rays.batch(5e-5f))[0], 1); // ε is the caller's
}

TEST_P(Backend, TfarBoundsTheRay)
{
    std::vector<Vec3> positions;
    std::vector<std::uint32_t> indices;
    addSquare(positions, indices, 1.0f);
    const auto scene = build(GetParam(), positions, indices);
    Rays rays;
    rays.add({0, 0.5f, 0}, {0, 0, 1});
    EXPECT_EQ(trace(*scene, rays.batch(1.71e-4f, 0.5f))[0], 0);
    EXPECT_EQ(trace(*scene, rays.batch(1.71e-4f, 1.5f))[0], 1);
}

TEST_P(Backend, OnlyTheOriginVertexOneRingIsExcluded)
{
    // Square A at z = 1 (triangles 0: {0,1,2} and 1: {0,2,3}), square B at z = 2 above it.
    std::vector<Vec3> positions;
    std::vector<std::uint32_t> indices;
    addSquare(positions, indices, 1.0f);
    const auto oneLayer = build(GetParam(), positions, indices);
    addSquare(positions, indices, 2.0f);
    const auto twoLayers = build(GetParam(), positions, indices);

    const Vec3 below{0.5f, -0.5f, 0}; // under triangle 0 only (x > y)
    const Vec3 up{0, 0, 1};
    Rays rays;
    rays.add(below, up, 1);         // vertex 1 is only in triangle 0: excluded, nothing else is hit
    rays.add(below, up, 0);         // vertex 0 is in both triangles of A: excluded
    rays.add(below, up, 3);         // vertex 3 is only in triangle 1, not the one hit: occluded
    rays.add(below, up, kNoVertex); // no origin vertex: occluded
    rays.add(below, up, 5);         // a vertex of square B: A still occludes
    EXPECT_EQ(trace(*oneLayer, rays.batch()), (std::vector<std::uint8_t>{0, 0, 1, 1, 1}));
    // With B above, the excluded one-ring of A does not hide B.
    EXPECT_EQ(trace(*twoLayers, rays.batch()), (std::vector<std::uint8_t>{1, 1, 1, 1, 1}));

    RayBatch withoutVertices = rays.batch();
    withoutVertices.originVertex = nullptr; // no exclusion at all
    EXPECT_EQ(trace(*oneLayer, withoutVertices), (std::vector<std::uint8_t>{1, 1, 1, 1, 1}));
}

TEST_P(Backend, RaysThroughSharedEdgesAndCornersHit)
{
    // A 2×2 patch of unit squares at z = 1, each split along its diagonal. Rays aimed exactly at
    // shared edges, diagonals and shared corners (the centre corner has six triangles) must hit:
    // no ray slips between neighbours, whatever its slant. Direction components of equal
    // magnitude keep the aim exact in float.
    std::vector<Vec3> positions;
    std::vector<std::uint32_t> indices;
    for (int j = 0; j <= 2; ++j)
        for (int i = 0; i <= 2; ++i)
            positions.push_back({float(i) - 1, float(j) - 1, 1});
    for (std::uint32_t j = 0; j < 2; ++j)
        for (std::uint32_t i = 0; i < 2; ++i) {
            const std::uint32_t v = 3 * j + i;
            indices.insert(indices.end(), {v, v + 1, v + 4, v, v + 4, v + 3});
        }
    const auto scene = build(GetParam(), positions, indices);
    Rays rays;
    const float targets[][2] = {{0, 0}, {0.5f, 0.5f}, {-0.5f, -0.5f}, {0, 0.5f}, {-0.5f, 0}, {0.5f, 0}, {0, -0.5f}};
    for (const auto& [x, y] : targets) {
        rays.add({x, y, 0}, {0, 0, 1});
        rays.add({x, y, 2}, {0, 0, -1});
        for (const float s : {-1.0f, 1.0f}) {
            rays.add({x - s, y, 0}, {s, 0, 1});
            rays.add({x, y - s, 0}, {0, s, 1});
            rays.add({x - s, y - s, 0}, {s, s, 1});
            rays.add({x - s, y + s, 2}, {s, -s, -1});
        }
    }
    EXPECT_EQ(trace(*scene, rays.batch()), std::vector<std::uint8_t>(rays.ox.size(), 1));
}

TEST_P(Backend, EmptyProxyNeverOccludes)
{
    const std::vector<Vec3> positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    const auto scene = build(GetParam(), positions, {});
    Rays rays;
    for (int i = 0; i < 700; ++i)
        rays.add({0, 0, -1}, {std::sin(float(i)), std::cos(float(i)), 1}, std::uint32_t(i % 3));
    EXPECT_EQ(trace(*scene, rays.batch()), std::vector<std::uint8_t>(700, 0));
}

TEST_P(Backend, ManyThreadsGetTheSameAnswers)
{
    // A 40×40 grid of squares at z = 1 with holes; rays fan out from below.
    std::vector<Vec3> positions;
    std::vector<std::uint32_t> indices;
    for (int i = 0; i < 40; ++i)
        for (int j = 0; j < 40; ++j) {
            if ((i * 7 + j * 3) % 5 == 0)
                continue;
            const float x = -2 + 0.1f * float(i), y = -2 + 0.1f * float(j);
            const std::uint32_t base = std::uint32_t(positions.size());
            positions.insert(positions.end(), {{x, y, 1}, {x + 0.1f, y, 1}, {x + 0.1f, y + 0.1f, 1}, {x, y + 0.1f, 1}});
            indices.insert(indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
        }
    const auto scene = build(GetParam(), positions, indices);
    Rays rays;
    for (int i = 0; i < 5000; ++i)
        rays.add({0, 0, 0}, {std::sin(0.37f * float(i)), std::cos(0.53f * float(i)), 1.2f});
    const std::vector<std::uint8_t> expected = trace(*scene, rays.batch());
    std::size_t hits = 0;
    for (std::uint8_t o : expected)
        hits += o;
    EXPECT_GT(hits, 1000u);
    EXPECT_LT(hits, 4900u);
    std::vector<std::vector<std::uint8_t>> results(4);
    {
        std::vector<std::jthread> threads;
        for (std::size_t t = 0; t < results.size(); ++t)
            threads.emplace_back([&, t] { results[t] = trace(*scene, rays.batch()); });
    }
    for (const auto& result : results)
        EXPECT_EQ(result, expected);
}

INSTANTIATE_TEST_SUITE_P(, Backend, ::testing::Values(OcclusionBackendKind::Embree, OcclusionBackendKind::Grid),
                         [](const auto& test) { return std::string(occlusionBackendName(test.param)); });

TEST(Occlusion, BackendNamesRoundTrip)
{
    for (OcclusionBackendKind kind : {OcclusionBackendKind::Embree, OcclusionBackendKind::Grid})
        EXPECT_EQ(*parseOcclusionBackend(occlusionBackendName(kind)), kind);
    EXPECT_FALSE(parseOcclusionBackend("optix").ok());
}

TEST(Occlusion, ProxyIndicesAreChecked)
{
    const std::vector<Vec3> positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    for (OcclusionBackendKind kind : {OcclusionBackendKind::Embree, OcclusionBackendKind::Grid}) {
        const std::vector<std::uint32_t> outside = {0, 1, 3};
        EXPECT_FALSE(buildOcclusionScene(kind, {positions, outside}).ok());
        const std::vector<std::uint32_t> partial = {0, 1};
        EXPECT_FALSE(buildOcclusionScene(kind, {positions, partial}).ok());
    }
}

// ---- the real characters ----------------------------------------------------------------------

/// Deterministic uniform numbers in [0, 1) (xorshift64*, the same on every platform).
class Random {
public:
    explicit Random(std::uint64_t seed) : m_state(seed * 0x9E3779B97F4A7C15ull + 1) {}
    float next()
    {
        m_state ^= m_state >> 12;
        m_state ^= m_state << 25;
        m_state ^= m_state >> 27;
        return float((m_state * 0x2545F4914F6CDD1Dull) >> 40) * 0x1.0p-24f;
    }

private:
    std::uint64_t m_state;
};

/// Cosine-weighted directions about each vertex's normal, from the vertex itself, as the bake
/// shoots them.
Rays bakeRays(const scene::CharacterMesh& mesh, std::uint32_t firstVertex, std::uint32_t vertexCount, int raysPerVertex,
              Random& random)
{
    Rays rays;
    for (std::uint32_t v = firstVertex; v < firstVertex + vertexCount; ++v) {
        const Vec3 n = mesh.normals[v];
        // Orthonormal basis about n (Duff et al. 2017).
        const float sign = std::copysign(1.0f, n.z);
        const float a = -1.0f / (sign + n.z);
        const float b = n.x * n.y * a;
        const Vec3 t1{1 + sign * n.x * n.x * a, sign * b, -sign * n.x};
        const Vec3 t2{b, sign + n.y * n.y * a, -n.y};
        for (int k = 0; k < raysPerVertex; ++k) {
            const float u1 = random.next(), u2 = random.next();
            const float r = std::sqrt(u1), phi = 2 * std::numbers::pi_v<float> * u2;
            const float x = r * std::cos(phi), y = r * std::sin(phi), z = std::sqrt(std::max(0.0f, 1 - u1));
            rays.add(mesh.positions[v],
                     {x * t1.x + y * t2.x + z * n.x, x * t1.y + y * t2.y + z * n.y, x * t1.z + y * t2.z + z * n.z}, v);
        }
    }
    return rays;
}

struct Agreement {
    std::size_t rays = 0;
    std::size_t disagreements = 0;
    std::size_t occluded = 0;
    void add(const std::vector<std::uint8_t>& embree, const std::vector<std::uint8_t>& grid)
    {
        ASSERT_EQ(embree.size(), grid.size());
        for (std::size_t i = 0; i < embree.size(); ++i) {
            ASSERT_LE(embree[i], 1);
            ASSERT_LE(grid[i], 1);
            disagreements += embree[i] != grid[i];
            occluded += embree[i];
        }
        rays += embree.size();
    }
};

Agreement compareBackends(const scene::CharacterMesh& mesh, std::span<const std::uint32_t> proxy, std::uint32_t firstVertex,
                          std::uint32_t vertexCount, int raysPerVertex, std::uint64_t seed)
{
    const auto embree = build(OcclusionBackendKind::Embree, mesh.positions, {proxy.begin(), proxy.end()});
    const auto grid = build(OcclusionBackendKind::Grid, mesh.positions, {proxy.begin(), proxy.end()});
    Random random(seed);
    const Rays rays = bakeRays(mesh, firstVertex, vertexCount, raysPerVertex, random);
    Agreement agreement;
    agreement.add(trace(*embree, rays.batch()), trace(*grid, rays.batch()));
    return agreement;
}

TEST(OcclusionOnCharacters, EmbreeAndTheGridAgree)
{
    const char* characters[] = {"characters/CesiumMan/CesiumMan.glb", "characters/RiggedFigure/RiggedFigure.gltf",
                                "characters/RiggedSimple/RiggedSimple.gltf",
                                "characters/RobotExpressive/RobotExpressive.glb"};
    Agreement total;
    for (const char* path : characters) {
        Result<scene::CharacterMesh> mesh = scene::loadGltfMesh(test::sharedData(path));
        ASSERT_TRUE(mesh.ok()) << describe(mesh.error());
        const std::uint32_t vertices = std::uint32_t(mesh->vertexCount());
        // DSM: every segment's rays against the proxy of all segments.
        const Agreement dsm = compareBackends(*mesh, mesh->indices, 0, vertices, 8, 17);
        // DS: each segment's rays against its own triangles.
        Agreement ds;
        for (const scene::Segment& segment : mesh->segments) {
            const std::span<const std::uint32_t> own(mesh->indices.data() + 3 * std::size_t(segment.firstTriangle),
                                                     3 * std::size_t(segment.triangleCount));
            const Agreement one = compareBackends(*mesh, own, segment.firstVertex, segment.vertexCount, 4, 29);
            ds.rays += one.rays;
            ds.disagreements += one.disagreements;
            ds.occluded += one.occluded;
        }
        for (const auto& [name, a] : {std::pair{"DSM", dsm}, std::pair{"DS", ds}}) {
            std::printf("%-48s %-3s %7zu rays, %5.1f%% occluded, agreement %.5f%% (%zu differ)\n", path, name, a.rays,
                        100.0 * double(a.occluded) / double(a.rays),
                        100.0 * (1.0 - double(a.disagreements) / double(a.rays)), a.disagreements);
            total.rays += a.rays;
            total.disagreements += a.disagreements;
            total.occluded += a.occluded;
        }
    }
    const double agreement = 1.0 - double(total.disagreements) / double(total.rays);
    std::printf("all characters: %zu rays, agreement %.5f%% (%zu differ)\n", total.rays, 100.0 * agreement,
                total.disagreements);
    EXPECT_GT(total.rays, 100000u);
    EXPECT_GT(total.occluded, total.rays / 10); // the rays do meet the characters' other parts
    EXPECT_GE(agreement, 0.9999);
}

} // namespace
} // namespace thespis::core::lighting
