// The PRT transfer bake: sampling, DU against the analytic transfer, DS/DSM and the receiver /
// occluder tags, the relaxation (ε, origin triangles), determinism, cancellation, real characters.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>
#include <vector>

#include "lighting/sh_rotation.h"
#include "lighting/transfer_bake.h"
#include "scene/gltf_mesh.h"
#include "test_support.h"

using namespace thespis::core;
using namespace thespis::core::lighting;
using anim::Quatd;
using anim::Vec3;
using anim::Vec3d;
using scene::SegmentRole;

namespace {

constexpr double kPi = std::numbers::pi;
#if defined(THESPIS_SANITIZED)
constexpr int kGridComparisonRays = 12;
#else
constexpr int kGridComparisonRays = 48;
#endif

Vec3d unit(Vec3d v)
{
    const double length = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    return v * (1.0 / length);
}
Vec3 toFloat(Vec3d v) { return {float(v.x), float(v.y), float(v.z)}; }
Vec3d toDouble(Vec3 v) { return {v.x, v.y, v.z}; }

/// Appends a segment (vertices, normals, triangles with segment-local indices).
void addSegment(scene::CharacterMesh& mesh, std::string name, const std::vector<Vec3>& positions,
                const std::vector<Vec3>& normals, const std::vector<std::uint32_t>& triangles,
                Quatd bindRotation = Quatd::identity())
{
    scene::Segment segment;
    segment.name = std::move(name);
    segment.firstVertex = std::uint32_t(mesh.positions.size());
    segment.vertexCount = std::uint32_t(positions.size());
    segment.firstTriangle = std::uint32_t(mesh.triangleCount());
    segment.triangleCount = std::uint32_t(triangles.size() / 3);
    segment.bindRotation = bindRotation;
    for (std::uint32_t index : triangles)
        mesh.indices.push_back(segment.firstVertex + index);
    mesh.positions.insert(mesh.positions.end(), positions.begin(), positions.end());
    mesh.normals.insert(mesh.normals.end(), normals.begin(), normals.end());
    mesh.segments.push_back(std::move(segment));
}

/// A horizontal square of (cells+1)² vertices at height y, facing +y (up) or −y.
void addSquare(scene::CharacterMesh& mesh, std::string name, float y, float halfSize, int cells, bool facingUp)
{
    std::vector<Vec3> positions, normals;
    std::vector<std::uint32_t> triangles;
    for (int j = 0; j <= cells; ++j)
        for (int i = 0; i <= cells; ++i) {
            positions.push_back({-halfSize + 2 * halfSize * float(i) / float(cells), y,
                                 -halfSize + 2 * halfSize * float(j) / float(cells)});
            normals.push_back({0, facingUp ? 1.0f : -1.0f, 0});
        }
    for (int j = 0; j < cells; ++j)
        for (int i = 0; i < cells; ++i) {
            const std::uint32_t a = std::uint32_t(j * (cells + 1) + i), b = a + 1, c = a + std::uint32_t(cells) + 1,
                                d = c + 1;
            // Counter-clockwise seen from the side the normal points to.
            if (facingUp)
                triangles.insert(triangles.end(), {a, c, b, b, c, d});
            else
                triangles.insert(triangles.end(), {a, b, c, b, d, c});
        }
    addSegment(mesh, std::move(name), positions, normals, triangles);
}

/// A floor (3×3 vertices, 1 m wide, facing up) under a wide ceiling (facing down) 0.25 m above:
/// each shadows the other, but only through M′ (neither shadows itself).
scene::CharacterMesh floorAndCeiling()
{
    scene::CharacterMesh mesh;
    addSquare(mesh, "Floor", 0.0f, 0.5f, 2, true);
    addSquare(mesh, "Ceiling", 0.25f, 3.0f, 2, false);
    return mesh;
}

TransferBake bakeOrFail(const scene::CharacterMesh& mesh, const BakeSettings& settings)
{
    Result<TransferBake> bake = bakeTransfer(mesh, settings);
    EXPECT_TRUE(bake.ok()) << describe(bake.error());
    return bake.ok() ? std::move(bake).value() : TransferBake{};
}

/// Mean of the DC coefficient (∝ the fraction of the cosine lobe that is visible) over a range.
double meanDc(const TransferBake& bake, std::uint32_t first, std::uint32_t count)
{
    double sum = 0;
    for (std::uint32_t v = first; v < first + count; ++v)
        sum += bake.vertexTransfer(v)[0];
    return sum / count;
}

bool sameTransfer(const TransferBake& a, const TransferBake& b, std::uint32_t vertex)
{
    const std::span<const float> x = a.vertexTransfer(vertex), y = b.vertexTransfer(vertex);
    return x.size() == y.size() && std::memcmp(x.data(), y.data(), x.size_bytes()) == 0;
}

} // namespace

TEST(TransferBakeSettings, EveryFieldIsChecked)
{
    EXPECT_TRUE(validateBakeSettings({}).ok());
    auto refused = [](BakeSettings settings, const char* field) {
        Result<void> valid = validateBakeSettings(settings);
        ASSERT_FALSE(valid.ok()) << field;
        EXPECT_EQ(valid.error().code, ErrorCode::InvalidArgument);
        EXPECT_NE(valid.error().message.find(std::string("\"") + field + "\""), std::string::npos)
            << valid.error().message;
    };
    BakeSettings s;
    s.order = 0;
    refused(s, "order");
    s.order = kMaxShOrder + 1;
    refused(s, "order");
    s = {};
    s.raysPerVertex = 0;
    refused(s, "raysPerVertex");
    s = {};
    s.epsilon = -1e-3f;
    refused(s, "epsilon");
    s.epsilon = std::numeric_limits<float>::quiet_NaN();
    refused(s, "epsilon");
    s = {};
    s.threads = -1;
    refused(s, "threads");
    s = {};
    s.transfer = TransferKind(7);
    refused(s, "transfer");

    // The bake refuses them too, before doing anything.
    s = {};
    s.order = 0;
    Result<TransferBake> bake = bakeTransfer(floorAndCeiling(), s);
    ASSERT_FALSE(bake.ok());
    EXPECT_EQ(bake.error().code, ErrorCode::InvalidArgument);
}

TEST(TransferBakeSettings, KindNamesRoundTrip)
{
    for (TransferKind kind : {TransferKind::DiffuseUnshadowed, TransferKind::DiffuseShadowed,
                              TransferKind::DiffuseShadowedMerged}) {
        Result<TransferKind> parsed = parseTransferKind(transferKindName(kind));
        ASSERT_TRUE(parsed.ok());
        EXPECT_EQ(*parsed, kind);
    }
    EXPECT_FALSE(parseTransferKind("dsx").ok());
}

TEST(BakeSampling, DirectionsAreUnitAndInTheHemisphere)
{
    const Vec3d normals[] = {{0, 0, 1}, {0, 0, -1}, {0, 1, 0}, {0, -1, 0}, unit({1, 2, -3}), unit({-1e-7, 0, -1})};
    for (int rays : {1, 2, 3, 7, 1000, 1024}) {
        std::vector<Vec3> directions(std::size_t(rays) + 1, Vec3{9, 9, 9});
        for (const Vec3d& n : normals) {
            sampleBakeDirections(rays, 7, 42, toFloat(n), directions);
            EXPECT_EQ(directions[std::size_t(rays)], (Vec3{9, 9, 9})) << "exactly N directions";
            for (int k = 0; k < rays; ++k) {
                const Vec3d d = toDouble(directions[std::size_t(k)]);
                ASSERT_TRUE(std::isfinite(d.x) && std::isfinite(d.y) && std::isfinite(d.z));
                EXPECT_NEAR(d.x * d.x + d.y * d.y + d.z * d.z, 1.0, 1e-5);
                EXPECT_GE(d.x * n.x + d.y * n.y + d.z * n.z, -1e-6);
            }
        }
    }
}

// E[cos θ] = 2/3 under pdf cos θ/π, with variance 1/18 per sample. Over many vertices the
// estimates must be unbiased and their spread far below plain Monte Carlo's √(1/18N): the strata
// (also when N is not a square) do their job.
TEST(BakeSampling, CosineWeightedAndStratified)
{
    for (int rays : {333, 1000, 1024}) {
        std::vector<Vec3> directions(static_cast<std::size_t>(rays));
        constexpr int kVertices = 200;
        double sumError = 0, sumSquaredError = 0;
        for (std::uint32_t vertex = 0; vertex < kVertices; ++vertex) {
            sampleBakeDirections(rays, 5, vertex, {0, 0, 1}, directions);
            double meanCos = 0;
            for (const Vec3& d : directions)
                meanCos += double(d.z) / rays;
            sumError += meanCos - 2.0 / 3.0;
            sumSquaredError += std::pow(meanCos - 2.0 / 3.0, 2);
        }
        const double plainSigma = std::sqrt(1.0 / 18.0 / rays);
        const double rms = std::sqrt(sumSquaredError / kVertices);
        EXPECT_LT(rms, 0.25 * plainSigma) << rays;
        EXPECT_LT(std::abs(sumError / kVertices), 3 * rms / std::sqrt(double(kVertices))) << rays;
    }
}

TEST(BakeSampling, DependsOnlyOnSeedAndVertex)
{
    std::vector<Vec3> a(64), b(64), c(64);
    sampleBakeDirections(64, 3, 10, {0, 1, 0}, a);
    sampleBakeDirections(64, 3, 10, {0, 1, 0}, b);
    EXPECT_EQ(a, b);
    sampleBakeDirections(64, 4, 10, {0, 1, 0}, c);
    EXPECT_NE(a, c);
    sampleBakeDirections(64, 3, 11, {0, 1, 0}, c);
    EXPECT_NE(a, c);
}

// DU's transfer has a closed form: t_lm = (Â_l/π)·Y_lm(n), n in the segment's bind frame. The
// estimate must match within 4σ of plain Monte Carlo, σ² = (E_cos[Y²] − t²)/N (stratification
// only lowers it), and do clearly better than plain Monte Carlo on the whole.
TEST(TransferBakeDu, MatchesTheAnalyticTransferWithinMonteCarloError)
{
    constexpr int kOrder = 5;
    constexpr int kCoefficients = kOrder * kOrder;
    scene::CharacterMesh mesh;
    std::vector<Vec3> positions, normals;
    for (int i = 0; i < 24; ++i) { // Fibonacci sphere of normals
        const double z = 1 - (2 * i + 1) / 24.0, r = std::sqrt(1 - z * z), phi = i * kPi * (3 - std::sqrt(5.0));
        positions.push_back({float(i), 0, 0});
        normals.push_back(toFloat(unit({r * std::cos(phi), r * std::sin(phi), z})));
    }
    const Quatd bind = anim::normalize(Quatd{0.3, -0.5, 0.2, 0.8});
    addSegment(mesh, "Identity", positions, normals, {});
    addSegment(mesh, "Turned", positions, normals, {}, bind);

    for (int rays : {1000, 1024}) {
        BakeSettings settings;
        settings.order = kOrder;
        settings.raysPerVertex = rays;
        settings.transfer = TransferKind::DiffuseUnshadowed;
        const TransferBake bake = bakeOrFail(mesh, settings);
        double sumSquaredZ = 0;
        int count = 0;
        for (std::uint32_t v = 0; v < mesh.vertexCount(); ++v) {
            const Quatd toBind = v < 24 ? Quatd::identity() : anim::conjugate(bind);
            const Vec3d n = unit(anim::rotate(toBind, toDouble(mesh.normals[v])));
            // E_cos[Y_i²] = (1/π)∫ Y_i² max(n·ω, 0) dω by the midpoint rule around n.
            std::array<double, kCoefficients> secondMoment{}, basis{};
            const int thetaSteps = 60, phiSteps = 120;
            const Vec3d helper = std::abs(n.x) < 0.9 ? Vec3d{1, 0, 0} : Vec3d{0, 1, 0};
            const Vec3d t = unit({helper.y * n.z - helper.z * n.y, helper.z * n.x - helper.x * n.z,
                                  helper.x * n.y - helper.y * n.x});
            const Vec3d b{n.y * t.z - n.z * t.y, n.z * t.x - n.x * t.z, n.x * t.y - n.y * t.x};
            for (int i = 0; i < thetaSteps; ++i) {
                const double theta = (i + 0.5) * (kPi / 2) / thetaSteps;
                const double weight = std::cos(theta) * std::sin(theta) * (kPi / 2 / thetaSteps) *
                                      (2 * kPi / phiSteps) / kPi;
                for (int j = 0; j < phiSteps; ++j) {
                    const double phi = (j + 0.5) * 2 * kPi / phiSteps;
                    const Vec3d d = t * (std::sin(theta) * std::cos(phi)) + b * (std::sin(theta) * std::sin(phi)) +
                                    n * std::cos(theta);
                    evaluateSh(kOrder, d, basis);
                    for (int c = 0; c < kCoefficients; ++c)
                        secondMoment[std::size_t(c)] += weight * basis[std::size_t(c)] * basis[std::size_t(c)];
                }
            }
            evaluateSh(kOrder, n, basis);
            const std::span<const float> baked = bake.vertexTransfer(v);
            ASSERT_EQ(baked.size(), std::size_t(kCoefficients));
            for (int l = 0; l < kOrder; ++l)
                for (int m = -l; m <= l; ++m) {
                    const std::size_t i = std::size_t(shIndex(l, m));
                    const double expected = clampedCosineKernel(l) / kPi * basis[i];
                    const double variance = std::max(secondMoment[i] - expected * expected, 0.0);
                    const double sigma = std::sqrt(variance / rays);
                    // 2e-5: the float sum of N terms (Y₀₀ is constant: no sampling error at all).
                    EXPECT_NEAR(baked[i], expected, 4 * sigma + 2e-5)
                        << "N " << rays << " vertex " << v << " l " << l << " m " << m;
                    if (variance > 1e-4) {
                        sumSquaredZ += std::pow((baked[i] - expected) / sigma, 2);
                        ++count;
                    }
                }
        }
        // Plain Monte Carlo gives an RMS z-score of 1; stratified sampling much less.
        EXPECT_LT(std::sqrt(sumSquaredZ / count), 0.3) << "N " << rays;
    }
}

// Shading a DU bake equals the analytic irradiance/π, in the bind pose and when the segment turns:
// the light is rotated into the segment's frame at run time (paper §6.1.1).
TEST(TransferBakeDu, ShadingFollowsTheSegmentRotation)
{
    scene::CharacterMesh mesh;
    const Quatd bind = anim::normalize(Quatd{-0.2, 0.4, 0.1, 0.9});
    addSegment(mesh, "Arm", {{0, 0, 0}, {1, 0, 0}}, {toFloat(unit({0.3, 0.9, -0.2})), toFloat(unit({-1, 0.1, 0.4}))},
               {}, bind);
    BakeSettings settings;
    settings.order = 3;
    settings.raysPerVertex = 4096;
    settings.transfer = TransferKind::DiffuseUnshadowed;
    const TransferBake bake = bakeOrFail(mesh, settings);

    ShRgb light;
    light.order = 3;
    for (int c = 0; c < 3; ++c)
        for (int i = 0; i < 9; ++i)
            light.channel[std::size_t(c)][std::size_t(i)] = std::cos(1.3 * i + c) * (i == 0 ? 3.0 : 1.0);
    const Quatd pose = anim::normalize(Quatd{0.5, 0.1, -0.3, 0.7});
    for (const Quatd& segmentRotation : {bind, pose * bind}) {
        for (std::uint32_t v = 0; v < 2; ++v) {
            // The world normal now: the bind normal carried by the segment's motion.
            const Vec3d bindNormal = toDouble(mesh.normals[v]);
            const Vec3d normal = unit(anim::rotate(segmentRotation * anim::conjugate(bind), bindNormal));
            std::array<double, 9> basis{};
            evaluateSh(3, normal, basis);
            const std::array<double, 3> shaded = shadeVertex(bake, mesh, v, light, segmentRotation);
            for (int c = 0; c < 3; ++c) {
                double expected = 0;
                for (int l = 0; l < 3; ++l)
                    for (int m = -l; m <= l; ++m)
                        expected += clampedCosineKernel(l) / kPi * light.channel[std::size_t(c)][std::size_t(shIndex(l, m))] *
                                    basis[std::size_t(shIndex(l, m))];
                EXPECT_NEAR(shaded[std::size_t(c)], expected, 0.01 * (1 + std::abs(expected))) << v << " " << c;
            }
        }
    }
}

TEST(TransferBakeTags, DsSeesOnlyItsOwnSegmentDsmSeesTheProxy)
{
    const scene::CharacterMesh mesh = floorAndCeiling();
    BakeSettings settings;
    settings.order = 3;
    settings.raysPerVertex = 256;
    settings.transfer = TransferKind::DiffuseUnshadowed;
    const TransferBake du = bakeOrFail(mesh, settings);
    settings.transfer = TransferKind::DiffuseShadowed;
    const TransferBake ds = bakeOrFail(mesh, settings);
    settings.transfer = TransferKind::DiffuseShadowedMerged;
    const TransferBake dsm = bakeOrFail(mesh, settings);

    // A flat segment never shadows itself: DS is DU to the bit (same directions, all visible).
    for (std::uint32_t v = 0; v < mesh.vertexCount(); ++v)
        EXPECT_TRUE(sameTransfer(du, ds, v)) << v;
    // Through M′ the ceiling darkens the floor (it covers all but grazing directions) and the
    // floor darkens the middle of the ceiling.
    EXPECT_LT(meanDc(dsm, 0, 9), 0.2 * meanDc(du, 0, 9));
    EXPECT_LT(dsm.vertexTransfer(9 + 4)[0], 0.5f * du.vertexTransfer(9 + 4)[0]);
}

TEST(TransferBakeTags, ReceiverIsTransparentButStillBaked)
{
    scene::CharacterMesh mesh = floorAndCeiling();
    BakeSettings settings;
    settings.order = 3;
    settings.raysPerVertex = 256;
    settings.transfer = TransferKind::DiffuseUnshadowed;
    const TransferBake du = bakeOrFail(mesh, settings);
    settings.transfer = TransferKind::DiffuseShadowedMerged;

    mesh.segments[1].role = SegmentRole::Receiver; // the ceiling casts nothing
    const TransferBake ceilingReceives = bakeOrFail(mesh, settings);
    for (std::uint32_t v = 0; v < 9; ++v)
        EXPECT_TRUE(sameTransfer(du, ceilingReceives, v)) << "floor vertex " << v << " is unshadowed";
    ASSERT_TRUE(ceilingReceives.segments[1].baked);
    EXPECT_EQ(ceilingReceives.segments[1].role, SegmentRole::Receiver);
    EXPECT_LT(ceilingReceives.vertexTransfer(9 + 4)[0], 0.5f * du.vertexTransfer(9 + 4)[0])
        << "the receiver is still shadowed by the floor";

    mesh.segments[1].role = SegmentRole::None;
    mesh.segments[0].role = SegmentRole::Receiver; // now the floor casts nothing
    const TransferBake floorReceives = bakeOrFail(mesh, settings);
    for (std::uint32_t v = 9; v < 18; ++v)
        EXPECT_TRUE(sameTransfer(du, floorReceives, v)) << "ceiling vertex " << v << " is unshadowed";
    EXPECT_LT(meanDc(floorReceives, 0, 9), 0.2 * meanDc(du, 0, 9));
}

TEST(TransferBakeTags, OccluderCastsButIsNotBaked)
{
    scene::CharacterMesh mesh = floorAndCeiling();
    mesh.segments[1].role = SegmentRole::Occluder;
    BakeSettings settings;
    settings.order = 3;
    settings.raysPerVertex = 256;
    settings.transfer = TransferKind::DiffuseShadowedMerged;
    const TransferBake dsm = bakeOrFail(mesh, settings);
    ASSERT_EQ(dsm.segments.size(), 2u);
    EXPECT_TRUE(dsm.segments[0].baked);
    EXPECT_FALSE(dsm.segments[1].baked);
    EXPECT_EQ(dsm.transfer.size(), 9u * 9u) << "only the floor's transfer is stored";
    EXPECT_TRUE(dsm.vertexTransfer(12).empty());
    settings.transfer = TransferKind::DiffuseUnshadowed;
    const TransferBake du = bakeOrFail(mesh, settings);
    EXPECT_LT(meanDc(dsm, 0, 9), 0.2 * meanDc(du, 0, 9)) << "the occluder still shadows the floor";
    // Tags are DSM's: DU and DS bake every segment.
    EXPECT_TRUE(du.segments[1].baked);
    EXPECT_EQ(du.vertexTransfer(12).size(), 9u);
}

// Paper §6.1.3: a surface closer than ε (separately modelled segments that touch in the bind
// pose) does not shadow; with ε = 0 it does.
TEST(TransferBakeRelaxation, SurfaceCloserThanEpsilonDoesNotShadow)
{
    scene::CharacterMesh mesh;
    addSquare(mesh, "Skin", 0.0f, 0.5f, 2, true);
    // A tiny cap 0.05 mm over the middle vertex (0, 0, 0), every point within 0.1 mm of it.
    const float h = 5e-5f, r = 6e-5f;
    addSegment(mesh, "Cap", {{-r, h, -r}, {r, h, -r}, {0, h, r}}, {{0, -1, 0}, {0, -1, 0}, {0, -1, 0}}, {0, 2, 1});
    for (OcclusionBackendKind backend : {OcclusionBackendKind::Embree, OcclusionBackendKind::Grid}) {
        BakeSettings settings;
        settings.order = 2;
        settings.raysPerVertex = 400;
        settings.backend = backend;
        settings.transfer = TransferKind::DiffuseUnshadowed;
        const TransferBake du = bakeOrFail(mesh, settings);
        settings.transfer = TransferKind::DiffuseShadowedMerged;
        settings.epsilon = 1.71e-4f;
        const TransferBake relaxed = bakeOrFail(mesh, settings);
        EXPECT_TRUE(sameTransfer(du, relaxed, 4)) << occlusionBackendName(backend);
        settings.epsilon = 0;
        const TransferBake strict = bakeOrFail(mesh, settings);
        EXPECT_LT(strict.vertexTransfer(4)[0], 0.9f * du.vertexTransfer(4)[0]) << occlusionBackendName(backend);
    }
}

// Rays leave a vertex along (or touching) the triangles around it; hits on those at t ≈ 0 must
// not count. With ε = 0 only the exclusion of the origin vertex's triangles prevents them: the apex
// of a concave fan (a bowl) stays unshadowed by its own triangles on both backends. A second vertex
// at the same place that no triangle uses is not protected: the grid's Möller–Trumbore test counts
// its t = 0 corner hits (Embree happens to reject corner hits, so only the grid shows it).
TEST(TransferBakeRelaxation, OriginTrianglesAreExcluded)
{
    std::vector<Vec3> positions{{0, 0, 0}};
    std::vector<Vec3> normals{{0, 1, 0}};
    std::vector<std::uint32_t> triangles;
    constexpr int kSides = 8;
    for (int k = 0; k < kSides; ++k) {
        const double angle = 2 * kPi * k / kSides;
        positions.push_back({float(std::cos(angle)), 0.6f, float(std::sin(angle))});
        normals.push_back(toFloat(unit({-std::cos(angle), 1.6, -std::sin(angle)})));
        const std::uint32_t next = std::uint32_t(1 + (k + 1) % kSides);
        triangles.insert(triangles.end(), {0, next, std::uint32_t(1 + k)});
    }
    positions.push_back({0, 0, 0}); // the unprotected twin of the apex
    normals.push_back({0, 1, 0});
    scene::CharacterMesh mesh;
    addSegment(mesh, "Bowl", positions, normals, triangles);
    const std::uint32_t twin = std::uint32_t(positions.size() - 1);

    for (OcclusionBackendKind backend : {OcclusionBackendKind::Embree, OcclusionBackendKind::Grid}) {
        BakeSettings settings;
        settings.order = 2;
        settings.raysPerVertex = 256;
        settings.epsilon = 0;
        settings.backend = backend;
        settings.transfer = TransferKind::DiffuseUnshadowed;
        const TransferBake du = bakeOrFail(mesh, settings);
        settings.transfer = TransferKind::DiffuseShadowed;
        const TransferBake ds = bakeOrFail(mesh, settings);
        EXPECT_TRUE(sameTransfer(du, ds, 0)) << occlusionBackendName(backend);
        if (backend == OcclusionBackendKind::Grid) {
            EXPECT_LT(ds.vertexTransfer(twin)[0], 0.5f * du.vertexTransfer(twin)[0]);
        }
    }
}

TEST(TransferBakeRun, CancelledBeforeOrDuringReturnsCancelled)
{
    const scene::CharacterMesh mesh = floorAndCeiling();
    BakeSettings settings;
    settings.order = 2;
    settings.raysPerVertex = 64;
    std::stop_source stop;
    stop.request_stop();
    Result<TransferBake> bake = bakeTransfer(mesh, settings, stop.get_token());
    ASSERT_FALSE(bake.ok());
    EXPECT_EQ(bake.error().code, ErrorCode::Cancelled);

    // Cancelled from the progress callback, part way through a bigger mesh.
    scene::CharacterMesh big;
    addSquare(big, "Floor", 0.0f, 0.5f, 40, true);
    std::stop_source during;
    std::uint64_t lastDone = 0;
    int calls = 0;
    bake = bakeTransfer(big, settings, during.get_token(), [&](const BakeProgress& progress) {
        ++calls;
        lastDone = progress.verticesDone;
        during.request_stop();
    });
    ASSERT_FALSE(bake.ok());
    EXPECT_EQ(bake.error().code, ErrorCode::Cancelled);
    EXPECT_GE(calls, 1);
    EXPECT_LT(lastDone, big.vertexCount());
}

TEST(TransferBakeRun, ProgressIsSerialisedIncreasingAndEndsAtTheTotal)
{
    scene::CharacterMesh mesh;
    addSquare(mesh, "Floor", 0.0f, 0.5f, 40, true); // 1681 vertices
    BakeSettings settings;
    settings.order = 2;
    settings.raysPerVertex = 16;
    settings.threads = 3;
    std::vector<std::uint64_t> done;
    std::atomic<int> inside{0};
    bool overlapped = false;
    BakeStatistics statistics;
    Result<TransferBake> bake = bakeTransfer(
        mesh, settings, {},
        [&](const BakeProgress& progress) {
            overlapped |= inside.fetch_add(1) != 0;
            EXPECT_EQ(progress.verticesTotal, mesh.vertexCount());
            done.push_back(progress.verticesDone);
            inside.fetch_sub(1);
        },
        &statistics);
    ASSERT_TRUE(bake.ok());
    EXPECT_FALSE(overlapped);
    ASSERT_FALSE(done.empty());
    EXPECT_TRUE(std::is_sorted(done.begin(), done.end()));
    EXPECT_EQ(done.back(), mesh.vertexCount());
    EXPECT_EQ(std::count(done.begin(), done.end(), mesh.vertexCount()), 1);
    EXPECT_LE(done.size(), 102u);
    EXPECT_GE(done.size(), 20u);
    EXPECT_EQ(statistics.vertices, mesh.vertexCount());
    EXPECT_EQ(statistics.rays, mesh.vertexCount() * 16u);
    EXPECT_GT(statistics.seconds, 0.0);
}

TEST(TransferBakeRun, SeedChangesTheResult)
{
    const scene::CharacterMesh mesh = floorAndCeiling();
    BakeSettings settings;
    settings.order = 3;
    settings.raysPerVertex = 64;
    const TransferBake a = bakeOrFail(mesh, settings);
    const TransferBake same = bakeOrFail(mesh, settings);
    EXPECT_EQ(a.transfer, same.transfer);
    settings.seed = 2;
    const TransferBake b = bakeOrFail(mesh, settings);
    EXPECT_NE(a.transfer, b.transfer);
}

TEST(TransferBakeRun, InvalidMeshIsRefused)
{
    scene::CharacterMesh mesh = floorAndCeiling();
    mesh.normals[3] = {0, 0, 0};
    Result<TransferBake> bake = bakeTransfer(mesh, {});
    ASSERT_FALSE(bake.ok());
    EXPECT_NE(bake.error().message.find("normal"), std::string::npos) << bake.error().message;
}

// The real character tests: RobotExpressive, split into one segment per joint.
class TransferBakeCharacter : public ::testing::Test {
protected:
    static void SetUpTestSuite()
    {
        Result<scene::CharacterMesh> loaded =
            scene::loadGltfMesh(thespis::test::sharedData("characters/RobotExpressive/RobotExpressive.glb"));
        ASSERT_TRUE(loaded.ok()) << describe(loaded.error());
        s_mesh = new scene::CharacterMesh(std::move(loaded).value());
    }
    static void TearDownTestSuite()
    {
        delete s_mesh;
        s_mesh = nullptr;
    }
    static BakeSettings settings(TransferKind transfer)
    {
        BakeSettings s;
        s.order = 3;
        s.raysPerVertex = 48;
        s.transfer = transfer;
        return s;
    }
    static inline scene::CharacterMesh* s_mesh = nullptr;
};

TEST_F(TransferBakeCharacter, BitIdenticalWhateverTheThreadCount)
{
    ASSERT_TRUE(s_mesh);
    BakeSettings s = settings(TransferKind::DiffuseShadowedMerged);
    s.threads = 1;
    const TransferBake one = bakeOrFail(*s_mesh, s);
    s.threads = 3;
    const TransferBake three = bakeOrFail(*s_mesh, s);
    ASSERT_EQ(one.transfer.size(), three.transfer.size());
    ASSERT_FALSE(one.transfer.empty());
    EXPECT_EQ(std::memcmp(one.transfer.data(), three.transfer.data(), one.transfer.size() * sizeof(float)), 0);
}

TEST_F(TransferBakeCharacter, ShadowsDarkenDsThenDsm)
{
    ASSERT_TRUE(s_mesh);
    ASSERT_GT(s_mesh->segments.size(), 5u);
    const TransferBake du = bakeOrFail(*s_mesh, settings(TransferKind::DiffuseUnshadowed));
    const TransferBake ds = bakeOrFail(*s_mesh, settings(TransferKind::DiffuseShadowed));
    const TransferBake dsm = bakeOrFail(*s_mesh, settings(TransferKind::DiffuseShadowedMerged));
    const std::uint32_t vertices = std::uint32_t(s_mesh->vertexCount());
    const double meanDu = meanDc(du, 0, vertices), meanDs = meanDc(ds, 0, vertices), meanDsm = meanDc(dsm, 0, vertices);
    EXPECT_LT(meanDs, 0.98 * meanDu);
    EXPECT_LT(meanDsm, meanDs);
    // The same directions meet a superset of triangles: DSM never sees more than DS (a ray's
    // worth of slack for traversal rounding), and clearly less where other segments are near.
    const float oneRay = 0.2821f / 48;
    int darker = 0;
    for (std::uint32_t v = 0; v < vertices; ++v) {
        EXPECT_LE(dsm.vertexTransfer(v)[0], ds.vertexTransfer(v)[0] + oneRay) << v;
        darker += dsm.vertexTransfer(v)[0] < ds.vertexTransfer(v)[0] - 4 * oneRay;
    }
    EXPECT_GT(darker, int(vertices / 20)) << "vertices where other segments cast shadows";
    std::printf("RobotExpressive %u vertices, %zu triangles, %zu segments: mean DC DU %.4f DS %.4f DSM %.4f; "
                "DSM darker than DS at %d vertices\n",
                vertices, s_mesh->triangleCount(), s_mesh->segments.size(), meanDu, meanDs, meanDsm, darker);
}

TEST_F(TransferBakeCharacter, GridAndEmbreeGiveNearlyTheSameTransfer)
{
    ASSERT_TRUE(s_mesh);
    BakeSettings s = settings(TransferKind::DiffuseShadowedMerged);
    s.raysPerVertex = kGridComparisonRays;
    const TransferBake embree = bakeOrFail(*s_mesh, s);
    s.backend = OcclusionBackendKind::Grid;
    const TransferBake grid = bakeOrFail(*s_mesh, s);
    const std::uint32_t vertices = std::uint32_t(s_mesh->vertexCount());
    int identical = 0;
    double largestDc = 0;
    for (std::uint32_t v = 0; v < vertices; ++v) {
        identical += sameTransfer(embree, grid, v);
        largestDc = std::max(largestDc, double(std::abs(embree.vertexTransfer(v)[0] - grid.vertexTransfer(v)[0])));
    }
    // A vertex differs only if one of its rays is decided differently (a grazing hit).
    EXPECT_GE(identical, int(0.99 * vertices));
    EXPECT_LE(largestDc, 2 * 0.2821 / kGridComparisonRays + 1e-6);
}
