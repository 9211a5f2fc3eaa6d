#include "lighting/embree_scene.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include <embree3/rtcore.h>
#include <pmmintrin.h>
#include <xmmintrin.h>

#include "lighting/float4.h"

namespace thespis::core::lighting {
namespace {

/// Rays per rtcOccluded1M call: large enough to amortize the call, small enough for the scratch
/// to stay in L1/L2.
constexpr std::size_t kChunk = 512;

thread_local std::string t_lastEmbreeError;

void recordEmbreeError(void*, RTCError code, const char* message)
{
    t_lastEmbreeError = "Embree error " + std::to_string(int(code)) + ": " + (message ? message : "");
}

/// The one Embree device of the process, created on first use (thread-safe static init) and
/// kept for the program's life: devices are costly to make (thread pool, ISA detection).
struct SharedDevice {
    RTCDevice device = nullptr;
    std::string error;

    SharedDevice()
    {
        device = rtcNewDevice(nullptr);
        if (!device) {
            error = "rtcNewDevice failed with error " + std::to_string(int(rtcGetDeviceError(nullptr)));
            return;
        }
        rtcSetDeviceErrorFunction(device, recordEmbreeError, nullptr);
        if (!rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_FILTER_FUNCTION_SUPPORTED))
            error = "this Embree library was built without filter functions";
    }
    ~SharedDevice()
    {
        if (device)
            rtcReleaseDevice(device);
    }
};

const SharedDevice& sharedDevice()
{
    static const SharedDevice device;
    return device;
}

/// Extended intersect context (the Embree idiom): the filter finds the ray's origin vertex
/// through the context it is given and the ray's id (its index in the chunk).
struct OcclusionContext {
    RTCIntersectContext base;
    const std::uint32_t* originVertex = nullptr; ///< per ray of the chunk (by ray id)
};

/// A ray that leaves its origin vertex at least this steeply (|cos| to every triangle around the
/// vertex) can meet those triangles only at t ≈ 0: rounding puts such a hit within about
/// 1e-7 · edge / |cos| ≤ 1e-5 · edge of the origin, far below any ε ≥ kUnfilteredMinEpsilon.
/// Such rays skip the exclusion filter, which costs Embree about a third of its speed; the
/// others (near-tangent rays, or ε too small) go through it.
constexpr float kUnfilteredMinCos = 1e-2f;
constexpr float kUnfilteredMinEpsilon = 1e-5f;

/// Rejects hits on triangles that contain the ray's origin vertex (its one-ring).
void rejectOriginTriangles(const RTCFilterFunctionNArguments* args)
{
    const auto* context = reinterpret_cast<const OcclusionContext*>(args->context);
    if (!context->originVertex)
        return;
    const auto* indices = static_cast<const std::uint32_t*>(args->geometryUserPtr);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1)
            continue;
        const std::uint32_t vertex = context->originVertex[RTCRayN_id(args->ray, args->N, i)];
        const std::uint32_t* triangle = indices + 3 * std::size_t(RTCHitN_primID(args->hit, args->N, i));
        if (triangle[0] == vertex || triangle[1] == vertex || triangle[2] == vertex)
            args->valid[i] = 0;
    }
}

Error embreeFailure(const std::string& what)
{
    std::string detail = t_lastEmbreeError.empty() ? "no message from Embree" : t_lastEmbreeError;
    t_lastEmbreeError.clear();
    return makeError(ErrorCode::Internal, "The ray tracer (Embree) could not " + what + ".", detail);
}

class EmbreeScene final : public OcclusionScene {
public:
    explicit EmbreeScene(std::vector<std::uint32_t> indices) : m_indices(std::move(indices)) {}
    ~EmbreeScene() override
    {
        if (m_plainScene) // first: its geometry reads m_scene's buffers
            rtcReleaseScene(m_plainScene);
        if (m_scene)
            rtcReleaseScene(m_scene);
    }
    EmbreeScene(const EmbreeScene&) = delete;
    EmbreeScene& operator=(const EmbreeScene&) = delete;

    Result<void> build(RTCDevice device, std::span<const anim::Vec3> positions);
    OcclusionBackendKind kind() const override { return OcclusionBackendKind::Embree; }
    void occluded(const RayBatch& rays, std::span<std::uint8_t> occluded) const override;

private:
    /// Whether the origin-triangle filter can be skipped for this ray (see kUnfilteredMinCos).
    bool needsFilter(std::uint32_t vertex, const anim::Vec3& origin, float dx, float dy, float dz, float tnear) const;
    /// needsFilter of rays [start, start + count) into needs[0 … count). A bake's batch starts
    /// every ray at one vertex: then the ring is looked up once and four rays are tested at a
    /// time, with the very arithmetic of needsFilter (the same decisions, so the same hits).
    void classify(const RayBatch& rays, std::size_t start, std::size_t count, std::uint8_t* needs) const;
    void trace(std::span<RTCRay> rays, const std::uint32_t* originVertex, bool filtered) const;

    std::vector<std::uint32_t> m_indices; ///< global vertex indices, read by the filter
    /// Unit normals of the triangles around each vertex (compressed rows: m_ringStart[v] …
    /// m_ringStart[v + 1]), for needsFilter.
    std::vector<std::uint32_t> m_ringStart;
    std::vector<anim::Vec3> m_ringNormals;
    std::vector<anim::Vec3> m_positions; ///< the argument rests on the ray starting at its vertex
    RTCScene m_scene = nullptr; ///< null for an empty proxy; traced by the rays that need the filter
    /// The same triangles (sharing m_scene's buffers) without RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION,
    /// for the rays that skip the filter: the flag alone slows Embree's traversal by about 6 %.
    RTCScene m_plainScene = nullptr;
};

bool EmbreeScene::needsFilter(std::uint32_t vertex, const anim::Vec3& origin, float dx, float dy, float dz,
                              float tnear) const
{
    if (vertex == kNoVertex || vertex + 1 >= m_ringStart.size())
        return false;
    if (m_ringStart[vertex] == m_ringStart[vertex + 1])
        return false; // no proxy triangle touches the vertex: nothing to exclude
    if (!(tnear >= kUnfilteredMinEpsilon) || !(origin == m_positions[vertex]))
        return true;
    for (std::uint32_t k = m_ringStart[vertex]; k < m_ringStart[vertex + 1]; ++k) {
        const anim::Vec3& n = m_ringNormals[k];
        if (std::abs(n.x * dx + n.y * dy + n.z * dz) < kUnfilteredMinCos)
            return true;
    }
    return false;
}

void EmbreeScene::classify(const RayBatch& rays, std::size_t start, std::size_t count, std::uint8_t* needs) const
{
    const std::uint32_t vertex = rays.originVertex ? rays.originVertex[start] : kNoVertex;
    const anim::Vec3 origin{rays.originX[start], rays.originY[start], rays.originZ[start]};
    bool shared = rays.originVertex != nullptr;
    for (std::size_t r = start; shared && r < start + count; ++r)
        shared = rays.originVertex[r] == vertex && rays.originX[r] == origin.x && rays.originY[r] == origin.y
                 && rays.originZ[r] == origin.z;
    std::size_t i = 0;
    if (shared && vertex != kNoVertex && vertex + 1 < m_ringStart.size() && m_ringStart[vertex] != m_ringStart[vertex + 1]
        && rays.tnear >= kUnfilteredMinEpsilon && origin == m_positions[vertex]) {
        const float* dx = rays.directionX + start;
        const float* dy = rays.directionY + start;
        const float* dz = rays.directionZ + start;
        for (; i + 4 <= count; i += 4) {
            const Float4 x = Float4::load(dx + i), y = Float4::load(dy + i), z = Float4::load(dz + i);
            Float4::Bits grazing{0, 0, 0, 0};
            for (std::uint32_t k = m_ringStart[vertex]; k < m_ringStart[vertex + 1]; ++k) {
                const anim::Vec3& n = m_ringNormals[k];
                grazing |= (Float4(kUnfilteredMinCos) > abs(Float4(n.x) * x + Float4(n.y) * y + Float4(n.z) * z)).bits;
            }
            for (int lane = 0; lane < 4; ++lane)
                needs[i + std::size_t(lane)] = grazing[lane] != 0;
        }
    }
    for (; i < count; ++i) {
        const std::size_t r = start + i;
        needs[i] = needsFilter(rays.originVertex ? rays.originVertex[r] : kNoVertex,
                               {rays.originX[r], rays.originY[r], rays.originZ[r]}, rays.directionX[r],
                               rays.directionY[r], rays.directionZ[r], rays.tnear);
    }
}

void EmbreeScene::trace(std::span<RTCRay> rays, const std::uint32_t* originVertex, bool filtered) const
{
    if (rays.empty())
        return;
    OcclusionContext context;
    rtcInitIntersectContext(&context.base);
    context.base.filter = filtered ? rejectOriginTriangles : nullptr;
    context.originVertex = originVertex;
    rtcOccluded1M(filtered ? m_scene : m_plainScene, &context.base, rays.data(), unsigned(rays.size()), sizeof(RTCRay));
}

Result<void> EmbreeScene::build(RTCDevice device, std::span<const anim::Vec3> positions)
{
    if (m_indices.empty())
        return {};
    m_scene = rtcNewScene(device);
    if (!m_scene)
        return embreeFailure("create a scene");
    // Embree's default (non-robust) traversal: about 1.5× faster here than RTC_SCENE_FLAG_ROBUST,
    // and it still agrees with the watertight grid on all rays of the real-character tests.
    rtcSetSceneBuildQuality(m_scene, RTC_BUILD_QUALITY_HIGH); // built once, traced by millions of rays

    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    if (!geometry)
        return embreeFailure("create the triangle geometry");
    // All the character's positions, so that the index buffer keeps global vertex indices.
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                                 3 * sizeof(float), positions.size()));
    auto* triangles = static_cast<std::uint32_t*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(std::uint32_t), m_indices.size() / 3));
    if (!vertices || !triangles) {
        rtcReleaseGeometry(geometry);
        return embreeFailure("allocate the mesh buffers");
    }
    for (std::size_t v = 0; v < positions.size(); ++v) {
        vertices[3 * v] = positions[v].x;
        vertices[3 * v + 1] = positions[v].y;
        vertices[3 * v + 2] = positions[v].z;
    }
    std::copy(m_indices.begin(), m_indices.end(), triangles);
    rtcSetGeometryUserData(geometry, m_indices.data());
    // The exclusion filter is passed per query in the context, so rays that cannot need it
    // trace without it.
    rtcSetSceneFlags(m_scene, RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION);

    m_positions.assign(positions.begin(), positions.end());
    m_ringStart.assign(positions.size() + 1, 0);
    for (std::uint32_t v : m_indices)
        ++m_ringStart[v + 1];
    for (std::size_t v = 0; v < positions.size(); ++v)
        m_ringStart[v + 1] += m_ringStart[v];
    m_ringNormals.resize(m_indices.size());
    std::vector<std::uint32_t> filled(m_ringStart.begin(), m_ringStart.end() - 1);
    for (std::size_t t = 0; t < m_indices.size(); t += 3) {
        const anim::Vec3 a = positions[m_indices[t]], b = positions[m_indices[t + 1]], c = positions[m_indices[t + 2]];
        const anim::Vec3 e1 = b - a, e2 = c - a;
        anim::Vec3 n{e1.y * e2.z - e1.z * e2.y, e1.z * e2.x - e1.x * e2.z, e1.x * e2.y - e1.y * e2.x};
        const float length = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
        // A degenerate triangle has no plane to graze: keep a zero normal, which always
        // asks for the filter.
        n = length > 0 ? n * (1.0f / length) : anim::Vec3{};
        for (int k = 0; k < 3; ++k)
            m_ringNormals[filled[m_indices[t + k]]++] = n;
    }
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(m_scene, geometry);
    rtcReleaseGeometry(geometry);
    rtcCommitScene(m_scene);

    m_plainScene = rtcNewScene(device);
    RTCGeometry plain = m_plainScene ? rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE) : nullptr;
    if (!plain)
        return embreeFailure("create the unfiltered scene");
    rtcSetSceneBuildQuality(m_plainScene, RTC_BUILD_QUALITY_HIGH);
    rtcSetSharedGeometryBuffer(plain, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, vertices, 0, 3 * sizeof(float),
                               positions.size());
    rtcSetSharedGeometryBuffer(plain, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, triangles, 0,
                               3 * sizeof(std::uint32_t), m_indices.size() / 3);
    rtcCommitGeometry(plain);
    rtcAttachGeometry(m_plainScene, plain);
    rtcReleaseGeometry(plain);
    rtcCommitScene(m_plainScene);
    if (rtcGetDeviceError(device) != RTC_ERROR_NONE)
        return embreeFailure("build the scene");
    return {};
}

void EmbreeScene::occluded(const RayBatch& rays, std::span<std::uint8_t> occluded) const
{
    assert(occluded.size() >= rays.count);
    if (!m_scene) {
        std::fill_n(occluded.begin(), rays.count, std::uint8_t(0));
        return;
    }
    // Embree's traversal expects denormals flushed (speed, and its documented requirement).
    _MM_SET_FLUSH_ZERO_MODE(_MM_FLUSH_ZERO_ON);
    _MM_SET_DENORMALS_ZERO_MODE(_MM_DENORMALS_ZERO_ON);
    // Per thread: the chunk's rays, unfiltered ones from the front and filtered ones from the
    // back, and for each slot the batch index it answers (RTCRay is 16-byte aligned).
    thread_local std::vector<RTCRay> scratch;
    thread_local std::vector<std::uint32_t> slotOrigin, slotRay;
    thread_local std::vector<std::uint8_t> needs;
    if (scratch.size() < kChunk) {
        scratch.resize(kChunk);
        slotOrigin.resize(kChunk);
        slotRay.resize(kChunk);
        needs.resize(kChunk);
    }

    for (std::size_t start = 0; start < rays.count; start += kChunk) {
        const std::size_t count = std::min(kChunk, rays.count - start);
        classify(rays, start, count, needs.data());
        std::size_t plain = 0, filtered = count;
        for (std::size_t i = 0; i < count; ++i) {
            const std::size_t r = start + i;
            const float dx = rays.directionX[r], dy = rays.directionY[r], dz = rays.directionZ[r];
            assert(std::isfinite(dx) && std::isfinite(dy) && std::isfinite(dz));
            const std::uint32_t vertex = rays.originVertex ? rays.originVertex[r] : kNoVertex;
            const anim::Vec3 origin{rays.originX[r], rays.originY[r], rays.originZ[r]};
            const std::size_t slot = needs[i] ? --filtered : plain++;
            RTCRay& ray = scratch[slot];
            ray.org_x = origin.x;
            ray.org_y = origin.y;
            ray.org_z = origin.z;
            ray.tnear = rays.tnear;
            ray.dir_x = dx;
            ray.dir_y = dy;
            ray.dir_z = dz;
            ray.time = 0;
            ray.tfar = rays.tfar;
            ray.mask = 0xffffffffu;
            ray.flags = 0;
            slotOrigin[slot] = vertex;
            slotRay[slot] = std::uint32_t(r);
        }
        for (std::size_t slot = filtered; slot < count; ++slot)
            scratch[slot].id = unsigned(slot - filtered); // the filter's index into slotOrigin
        trace({scratch.data(), plain}, nullptr, false);
        trace({scratch.data() + filtered, count - filtered}, slotOrigin.data() + filtered, true);
        for (std::size_t slot = 0; slot < count; ++slot)
            occluded[slotRay[slot]] = scratch[slot].tfar < 0 ? 1 : 0; // Embree sets tfar = -inf on a hit
    }
}

} // namespace

Result<std::unique_ptr<OcclusionScene>> buildEmbreeScene(const ProxyMeshView& proxy)
{
    const SharedDevice& device = sharedDevice();
    if (!device.device || !device.error.empty())
        return makeError(ErrorCode::Internal, "The ray tracer (Embree) could not start.", device.error);
    auto scene = std::make_unique<EmbreeScene>(std::vector<std::uint32_t>(proxy.indices.begin(), proxy.indices.end()));
    if (Result<void> ok = scene->build(device.device, proxy.positions); !ok)
        return ok.error();
    return std::unique_ptr<OcclusionScene>(std::move(scene));
}

} // namespace thespis::core::lighting
