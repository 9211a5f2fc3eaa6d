// Transfer bake benchmarks (issue 3 §6), on RobotExpressive refined by one midpoint subdivision
// (every triangle split in four inside its segment; the counts are printed as counters:
// about 12.9k triangles and 12–13k vertices, the largest real character we have).
//
// The ray benchmarks shoot the very same rays: those the DSM bake shoots (order-independent:
// the bake's own sampler, ε = 1.71e-4, origin vertex set) from 512 vertices spread over the
// mesh, 1024 rays per vertex, against M′ = the whole mesh. One iteration = one vertex's batch of
// 1024 rays per thread; items/s = rays/s over all threads.
// - BakeRays: through the bake's visibility path (OcclusionScene::occluded of the Embree
//   backend: SoA → RTCRay, rtcOccluded1M, the origin-triangle filter).
// - RawEmbreeOcclusion: bare rtcOccluded1M on prebuilt RTCRay arrays, same mesh and scene
//   flags, no filter (only tfar is reset between runs). The anchor: goal BakeRays ≥ 0.8× this.
// - GridOcclusion: the uniform grid backend on the same rays (goal: within 4× of Embree).
// BakeDS/<threads>: a whole DS bake, order 5 × 1024 rays (goal ≤ 0.8 s on 2 threads).
// BakeDU/<threads>: the same without visibility: what sampling and the SH sums cost alone.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <unordered_map>
#include <vector>

#include <embree3/rtcore.h>
#include <pmmintrin.h>
#include <xmmintrin.h>

#include "lighting/transfer_bake.h"
#include "scene/gltf_mesh.h"

using namespace thespis::core;
using namespace thespis::core::lighting;

namespace {

constexpr int kRaysPerVertex = 1024;
constexpr std::size_t kShootingVertices = 512;
constexpr float kEpsilon = 1.71e-4f;

/// One midpoint subdivision, segment by segment (new vertices stay inside their segment).
scene::CharacterMesh subdivide(const scene::CharacterMesh& mesh)
{
    scene::CharacterMesh out;
    for (const scene::Segment& segment : mesh.segments) {
        scene::Segment refined = segment;
        refined.firstVertex = std::uint32_t(out.positions.size());
        refined.firstTriangle = std::uint32_t(out.triangleCount());
        for (std::uint32_t v = segment.firstVertex; v < segment.firstVertex + segment.vertexCount; ++v) {
            out.positions.push_back(mesh.positions[v]);
            out.normals.push_back(mesh.normals[v]);
        }
        const std::uint32_t shift = refined.firstVertex - segment.firstVertex;
        std::unordered_map<std::uint64_t, std::uint32_t> midpoints;
        auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
            const std::uint64_t key = std::uint64_t(std::min(a, b)) << 32 | std::max(a, b);
            if (auto found = midpoints.find(key); found != midpoints.end())
                return found->second;
            const anim::Vec3 pa = mesh.positions[a], pb = mesh.positions[b];
            const anim::Vec3 na = mesh.normals[a], nb = mesh.normals[b];
            anim::Vec3 n = na + nb;
            const float length = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
            n = length > 1e-3f ? n * (1 / length) : na;
            out.positions.push_back((pa + pb) * 0.5f);
            out.normals.push_back(n);
            return midpoints[key] = std::uint32_t(out.positions.size() - 1);
        };
        for (std::uint32_t t = segment.firstTriangle; t < segment.firstTriangle + segment.triangleCount; ++t) {
            const std::uint32_t a = mesh.indices[3 * t], b = mesh.indices[3 * t + 1], c = mesh.indices[3 * t + 2];
            const std::uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
            out.indices.insert(out.indices.end(), {a + shift, ab, ca, ab, b + shift, bc, ca, bc, c + shift, ab, bc, ca});
        }
        refined.vertexCount = std::uint32_t(out.positions.size()) - refined.firstVertex;
        refined.triangleCount = std::uint32_t(out.triangleCount()) - refined.firstTriangle;
        out.segments.push_back(refined);
    }
    return out;
}

/// The refined character and the stored rays, built once for every benchmark.
struct Fixture {
    scene::CharacterMesh mesh;
    std::vector<float> ox, oy, oz, dx, dy, dz;
    std::vector<std::uint32_t> originVertex;
    std::unique_ptr<OcclusionScene> embree, grid;
    RTCDevice device = nullptr;
    RTCScene rawScene = nullptr;
    std::vector<RTCRay> rawRays; ///< the same rays as RTCRay, batch after batch
    bool ok = false;

    Fixture()
    {
        Result<scene::CharacterMesh> loaded =
            scene::loadGltfMesh(std::string(THESPIS_SHARED_DATA) + "/characters/RobotExpressive/RobotExpressive.glb");
        if (!loaded) {
            std::fprintf(stderr, "bake_bench: %s\n", describe(loaded.error()).c_str());
            return;
        }
        mesh = subdivide(*loaded);
        if (Result<void> valid = mesh.validate(); !valid) {
            std::fprintf(stderr, "bake_bench: %s\n", describe(valid.error()).c_str());
            return;
        }
        const std::size_t stride = mesh.vertexCount() / kShootingVertices;
        std::vector<anim::Vec3> directions(kRaysPerVertex);
        for (std::size_t i = 0; i < kShootingVertices; ++i) {
            const std::uint32_t vertex = std::uint32_t(i * stride);
            sampleBakeDirections(kRaysPerVertex, 1, vertex, mesh.normals[vertex], directions);
            const anim::Vec3 p = mesh.positions[vertex];
            for (const anim::Vec3& d : directions) {
                ox.push_back(p.x);
                oy.push_back(p.y);
                oz.push_back(p.z);
                dx.push_back(d.x);
                dy.push_back(d.y);
                dz.push_back(d.z);
                originVertex.push_back(vertex);
                RTCRay ray{};
                ray.org_x = p.x;
                ray.org_y = p.y;
                ray.org_z = p.z;
                ray.tnear = kEpsilon;
                ray.dir_x = d.x;
                ray.dir_y = d.y;
                ray.dir_z = d.z;
                ray.tfar = 1e30f;
                ray.mask = 0xffffffffu;
                ray.id = unsigned(rawRays.size() % kRaysPerVertex);
                rawRays.push_back(ray);
            }
        }
        const ProxyMeshView proxy{mesh.positions, mesh.indices};
        auto builtEmbree = buildOcclusionScene(OcclusionBackendKind::Embree, proxy);
        auto builtGrid = buildOcclusionScene(OcclusionBackendKind::Grid, proxy);
        if (!builtEmbree || !builtGrid)
            return;
        embree = std::move(builtEmbree.value());
        grid = std::move(builtGrid.value());
        ok = buildRawScene();
    }
    ~Fixture()
    {
        if (rawScene)
            rtcReleaseScene(rawScene);
        if (device)
            rtcReleaseDevice(device);
    }

    /// The bare Embree scene: same triangles and scene flags as the backend's, no filter.
    bool buildRawScene()
    {
        device = rtcNewDevice(nullptr);
        if (!device)
            return false;
        rawScene = rtcNewScene(device);
        rtcSetSceneBuildQuality(rawScene, RTC_BUILD_QUALITY_HIGH);
        RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
            geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), mesh.vertexCount()));
        auto* triangles = static_cast<std::uint32_t*>(rtcSetNewGeometryBuffer(
            geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(std::uint32_t), mesh.triangleCount()));
        for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
            vertices[3 * v] = mesh.positions[v].x;
            vertices[3 * v + 1] = mesh.positions[v].y;
            vertices[3 * v + 2] = mesh.positions[v].z;
        }
        std::copy(mesh.indices.begin(), mesh.indices.end(), triangles);
        rtcCommitGeometry(geometry);
        rtcAttachGeometry(rawScene, geometry);
        rtcReleaseGeometry(geometry);
        rtcCommitScene(rawScene);
        return rtcGetDeviceError(device) == RTC_ERROR_NONE;
    }

    RayBatch batch(std::size_t index) const
    {
        const std::size_t first = index * kRaysPerVertex;
        RayBatch rays;
        rays.originX = ox.data() + first;
        rays.originY = oy.data() + first;
        rays.originZ = oz.data() + first;
        rays.directionX = dx.data() + first;
        rays.directionY = dy.data() + first;
        rays.directionZ = dz.data() + first;
        rays.originVertex = originVertex.data() + first;
        rays.count = kRaysPerVertex;
        rays.tnear = kEpsilon;
        return rays;
    }
};

const Fixture& fixture()
{
    static const Fixture f;
    return f;
}

void addMeshCounters(benchmark::State& state, const Fixture& f)
{
    state.counters["vertices"] = benchmark::Counter(double(f.mesh.vertexCount()), benchmark::Counter::kAvgThreads);
    state.counters["triangles"] = benchmark::Counter(double(f.mesh.triangleCount()), benchmark::Counter::kAvgThreads);
}

/// Each thread walks its own batches (thread t takes t, t + n, …) so threads never share one.
void shootThroughScene(benchmark::State& state, const OcclusionScene& scene)
{
    const Fixture& f = fixture();
    std::vector<std::uint8_t> occluded(kRaysPerVertex);
    std::size_t next = std::size_t(state.thread_index());
    std::size_t hits = 0;
    for (auto _ : state) {
        scene.occluded(f.batch(next % kShootingVertices), occluded);
        hits += occluded[0];
        next += std::size_t(state.threads());
    }
    benchmark::DoNotOptimize(hits);
    state.SetItemsProcessed(std::int64_t(state.iterations()) * kRaysPerVertex);
    addMeshCounters(state, f);
}

void BakeRays(benchmark::State& state)
{
    const Fixture& f = fixture();
    if (!f.ok) {
        state.SkipWithError("RobotExpressive could not be loaded");
        return;
    }
    shootThroughScene(state, *f.embree);
}

void GridOcclusion(benchmark::State& state)
{
    const Fixture& f = fixture();
    if (!f.ok) {
        state.SkipWithError("RobotExpressive could not be loaded");
        return;
    }
    shootThroughScene(state, *f.grid);
}

void RawEmbreeOcclusion(benchmark::State& state)
{
    const Fixture& f = fixture();
    if (!f.ok) {
        state.SkipWithError("RobotExpressive could not be loaded");
        return;
    }
    _MM_SET_FLUSH_ZERO_MODE(_MM_FLUSH_ZERO_ON);
    _MM_SET_DENORMALS_ZERO_MODE(_MM_DENORMALS_ZERO_ON);
    std::vector<RTCRay> rays(kRaysPerVertex);
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    std::size_t next = std::size_t(state.thread_index());
    std::size_t hits = 0;
    for (auto _ : state) {
        // The stored rays, fresh (rtcOccluded1M writes tfar): a copy, as cheap as a tfar reset.
        const RTCRay* stored = f.rawRays.data() + (next % kShootingVertices) * kRaysPerVertex;
        std::copy(stored, stored + kRaysPerVertex, rays.begin());
        rtcOccluded1M(f.rawScene, &context, rays.data(), kRaysPerVertex, sizeof(RTCRay));
        hits += rays[0].tfar < 0;
        next += std::size_t(state.threads());
    }
    benchmark::DoNotOptimize(hits);
    state.SetItemsProcessed(std::int64_t(state.iterations()) * kRaysPerVertex);
    addMeshCounters(state, f);
}

void bakeWhole(benchmark::State& state, TransferKind transfer)
{
    const Fixture& f = fixture();
    if (!f.ok) {
        state.SkipWithError("RobotExpressive could not be loaded");
        return;
    }
    BakeSettings settings;
    settings.order = 5;
    settings.raysPerVertex = 1024;
    settings.transfer = transfer;
    settings.threads = int(state.range(0));
    BakeStatistics statistics;
    for (auto _ : state) {
        Result<TransferBake> bake = bakeTransfer(f.mesh, settings, {}, {}, &statistics);
        if (!bake) {
            state.SkipWithError(describe(bake.error()).c_str());
            return;
        }
        benchmark::DoNotOptimize(bake->transfer.data());
    }
    state.SetItemsProcessed(std::int64_t(state.iterations() * statistics.rays));
    state.counters["sceneSeconds"] = statistics.sceneSeconds;
    addMeshCounters(state, f);
}

void BakeDS(benchmark::State& state) { bakeWhole(state, TransferKind::DiffuseShadowed); }
void BakeDU(benchmark::State& state) { bakeWhole(state, TransferKind::DiffuseUnshadowed); }

} // namespace

BENCHMARK(BakeRays)->ThreadRange(1, 2)->UseRealTime();
BENCHMARK(RawEmbreeOcclusion)->ThreadRange(1, 2)->UseRealTime();
BENCHMARK(GridOcclusion)->ThreadRange(1, 2)->UseRealTime();
BENCHMARK(BakeDS)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BakeDU)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
