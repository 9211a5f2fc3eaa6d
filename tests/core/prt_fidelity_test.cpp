// PRT fidelity (issue 3 §4): the DS radiance a real character gets from PRT at orders 3, 5 and 8
// against a brute-force reference that integrates the un-projected probe (every pixel, in small
// blocks) with the same visibility (the vertex's own segment). The error must fall with the order.
// RMS relative error = √(Σ (prt − reference)² / Σ reference²) over vertices and RGB channels.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "lighting/probe.h"
#include "lighting/probe_projection_job.h"
#include "lighting/transfer_bake.h"
#include "scene/gltf_mesh.h"
#include "test_support.h"

using namespace thespis::core;
using namespace thespis::core::lighting;
using anim::Vec3d;

namespace {

#if defined(THESPIS_SANITIZED)
constexpr std::size_t kSegmentStride = 4; // DS needs only each vertex's own segment: bake a quarter
constexpr int kBlock = 8;
constexpr std::uint32_t kVertexStride = 19;
#else
constexpr std::size_t kSegmentStride = 1;
constexpr int kBlock = 4;
constexpr std::uint32_t kVertexStride = 23;
#endif
constexpr int kTransferRays = 1024;
constexpr int kOrders[] = {3, 5, 8};
constexpr double kPi = 3.14159265358979323846;

/// The un-projected lat-long probe as a quadrature: kBlock × kBlock pixel blocks, each with its
/// centre direction and ∫ L dω over its pixels (exact lat-long solid angles). Monte Carlo over
/// random directions would be hopeless here: the sun covers ~1e-4 sr and would be hit by a
/// handful of rays, or none.
struct ProbeQuadrature {
    std::vector<Vec3d> direction;
    std::vector<std::array<double, 3>> radianceTimesSolidAngle;
};

ProbeQuadrature blockQuadrature(const HdrImage& image)
{
    ProbeQuadrature quadrature;
    const int blocksX = image.width / kBlock, blocksY = image.height / kBlock;
    for (int by = 0; by < blocksY; ++by)
        for (int bx = 0; bx < blocksX; ++bx) {
            std::array<double, 3> sum{};
            for (int y = by * kBlock; y < (by + 1) * kBlock; ++y) {
                const double solidAngle = 2 * kPi / image.width *
                                          (std::cos(kPi * y / image.height) - std::cos(kPi * (y + 1) / image.height));
                for (int x = bx * kBlock; x < (bx + 1) * kBlock; ++x)
                    for (int c = 0; c < 3; ++c)
                        sum[std::size_t(c)] += double(image.pixel(x, y)[c]) * solidAngle;
            }
            Vec3d d;
            directionOfPixel(ProbeLayout::LatLong, blocksX, blocksY, bx, by, d);
            quadrature.direction.push_back(d);
            quadrature.radianceTimesSolidAngle.push_back(sum);
        }
    return quadrature;
}

/// Exit radiance of a white diffuse vertex, (1/π)∫ L·V·max(n·ω, 0) dω, by the quadrature, with
/// visibility against `scene` (one ray per block in the upper hemisphere).
std::array<double, 3> referenceRadiance(const scene::CharacterMesh& mesh, std::uint32_t vertex,
                                        const OcclusionScene& scene, const ProbeQuadrature& quadrature, float epsilon)
{
    const anim::Vec3 p = mesh.positions[vertex], n = mesh.normals[vertex];
    std::vector<float> dx, dy, dz;
    std::vector<double> weight; // cos θ / π
    std::vector<std::size_t> block;
    for (std::size_t b = 0; b < quadrature.direction.size(); ++b) {
        const Vec3d& d = quadrature.direction[b];
        const double cosine = d.x * n.x + d.y * n.y + d.z * n.z;
        if (cosine <= 0)
            continue;
        dx.push_back(float(d.x));
        dy.push_back(float(d.y));
        dz.push_back(float(d.z));
        weight.push_back(cosine / kPi);
        block.push_back(b);
    }
    const std::size_t count = dx.size();
    std::vector<float> ox(count, p.x), oy(count, p.y), oz(count, p.z);
    std::vector<std::uint32_t> origin(count, vertex);
    RayBatch batch;
    batch.originX = ox.data();
    batch.originY = oy.data();
    batch.originZ = oz.data();
    batch.directionX = dx.data();
    batch.directionY = dy.data();
    batch.directionZ = dz.data();
    batch.originVertex = origin.data();
    batch.count = count;
    batch.tnear = epsilon;
    std::vector<std::uint8_t> occluded(count);
    scene.occluded(batch, occluded);
    std::array<double, 3> sum{};
    for (std::size_t k = 0; k < count; ++k)
        if (!occluded[k])
            for (std::size_t c = 0; c < 3; ++c)
                sum[c] += weight[k] * quadrature.radianceTimesSolidAngle[block[k]][c];
    return sum;
}

/// Every stride-th segment of the mesh (DS transfer of a segment depends on that segment only).
scene::CharacterMesh everyNthSegment(const scene::CharacterMesh& mesh, std::size_t stride)
{
    scene::CharacterMesh out;
    for (std::size_t s = 0; s < mesh.segments.size(); s += stride) {
        scene::Segment segment = mesh.segments[s];
        const std::uint32_t shift = std::uint32_t(out.positions.size()) - segment.firstVertex;
        out.positions.insert(out.positions.end(), mesh.positions.begin() + segment.firstVertex,
                             mesh.positions.begin() + segment.firstVertex + segment.vertexCount);
        out.normals.insert(out.normals.end(), mesh.normals.begin() + segment.firstVertex,
                           mesh.normals.begin() + segment.firstVertex + segment.vertexCount);
        for (std::uint32_t i = segment.firstTriangle * 3; i < (segment.firstTriangle + segment.triangleCount) * 3; ++i)
            out.indices.push_back(mesh.indices[i] + shift);
        segment.firstVertex += shift;
        segment.firstTriangle = std::uint32_t(out.triangleCount()) - segment.triangleCount;
        out.segments.push_back(segment);
    }
    return out;
}

} // namespace

TEST(PrtFidelity, DsRadianceErrorFallsWithTheOrder)
{
    Result<scene::CharacterMesh> character =
        scene::loadGltfMesh(thespis::test::sharedData("characters/RobotExpressive/RobotExpressive.glb"));
    ASSERT_TRUE(character.ok()) << describe(character.error());
    const scene::CharacterMesh mesh = everyNthSegment(*character, kSegmentStride);
    ASSERT_TRUE(mesh.validate().ok());
    const auto probePath = thespis::test::sharedData("probes/polyhaven_1k/royal_esplanade_1k.hdr");
    Result<LightProbe> probe = LightProbe::load(probePath, ProbeLayout::LatLong);
    ASSERT_TRUE(probe.ok()) << describe(probe.error());
    const ProbeQuadrature quadrature = blockQuadrature(probe->image());
    // Projection coefficients do not depend on the order they are cut at: project once at 8.
    Result<ShRgb> light = projectProbeFile(probePath, ProbeLayout::LatLong, 8);
    ASSERT_TRUE(light.ok()) << describe(light.error());

    BakeSettings settings;
    settings.order = 8;
    settings.raysPerVertex = kTransferRays;
    settings.transfer = TransferKind::DiffuseShadowed;
    Result<TransferBake> bake = bakeTransfer(mesh, settings);
    ASSERT_TRUE(bake.ok()) << describe(bake.error());

    // Per order, Σ(prt − reference)² and Σ reference² over vertices and channels.
    std::array<double, 3> squaredError{}, squaredReference{};
    int vertices = 0;
    for (const scene::Segment& segment : mesh.segments) {
        Result<std::unique_ptr<OcclusionScene>> scene = buildOcclusionScene(
            OcclusionBackendKind::Embree,
            {mesh.positions, std::span(mesh.indices).subspan(std::size_t(segment.firstTriangle) * 3,
                                                               std::size_t(segment.triangleCount) * 3)});
        ASSERT_TRUE(scene.ok()) << describe(scene.error());
        for (std::uint32_t v = segment.firstVertex; v < segment.firstVertex + segment.vertexCount; ++v) {
            if (v % kVertexStride != 0)
                continue;
            ++vertices;
            const std::array<double, 3> reference = referenceRadiance(mesh, v, **scene, quadrature, settings.epsilon);
            for (std::size_t o = 0; o < 3; ++o) {
                ShRgb truncated = *light;
                truncated.order = kOrders[o];
                // In the bind pose each segment's rotation is its bind rotation.
                const std::array<double, 3> prt = shadeVertex(*bake, mesh, v, truncated, segment.bindRotation);
                for (std::size_t c = 0; c < 3; ++c) {
                    squaredError[o] += std::pow(prt[c] - reference[c], 2);
                    squaredReference[o] += reference[c] * reference[c];
                }
            }
        }
    }
    ASSERT_GT(vertices, 50);
    std::array<double, 3> rmsRelative{};
    for (std::size_t o = 0; o < 3; ++o) {
        rmsRelative[o] = std::sqrt(squaredError[o] / squaredReference[o]);
        std::printf("PRT DS fidelity, RobotExpressive (%d vertices) under royal_esplanade_1k: order %d RMS relative "
                    "error %.4f (transfer %d rays, reference %dx%d-pixel blocks)\n",
                    vertices, kOrders[o], rmsRelative[o], kTransferRays, kBlock, kBlock);
    }
    EXPECT_GT(rmsRelative[0], rmsRelative[1]);
    EXPECT_GT(rmsRelative[1], rmsRelative[2]);
    EXPECT_LT(rmsRelative[2], 0.25);
}
