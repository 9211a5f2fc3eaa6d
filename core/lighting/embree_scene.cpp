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
    const std::uint32_t* originVertex = nullptr; ///< per ray of the chunk, or null
};

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
        if (m_scene)
            rtcReleaseScene(m_scene);
    }
    EmbreeScene(const EmbreeScene&) = delete;
    EmbreeScene& operator=(const EmbreeScene&) = delete;

    Result<void> build(RTCDevice device, std::span<const anim::Vec3> positions);
    OcclusionBackendKind kind() const override { return OcclusionBackendKind::Embree; }
    void occluded(const RayBatch& rays, std::span<std::uint8_t> occluded) const override;

private:
    std::vector<std::uint32_t> m_indices; ///< global vertex indices, read by the filter
    RTCScene m_scene = nullptr;           ///< null for an empty proxy
};

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
    rtcSetGeometryOccludedFilterFunction(geometry, rejectOriginTriangles);
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(m_scene, geometry);
    rtcReleaseGeometry(geometry);
    rtcCommitScene(m_scene);
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
    thread_local std::vector<RTCRay> scratch; // RTCRay is 16-byte aligned: aligned operator new
    if (scratch.size() < kChunk)
        scratch.resize(kChunk);

    OcclusionContext context;
    rtcInitIntersectContext(&context.base);
    for (std::size_t start = 0; start < rays.count; start += kChunk) {
        const std::size_t count = std::min(kChunk, rays.count - start);
        context.originVertex = rays.originVertex ? rays.originVertex + start : nullptr;
        for (std::size_t i = 0; i < count; ++i) {
            RTCRay& ray = scratch[i];
            const std::size_t r = start + i;
            assert(std::isfinite(rays.directionX[r]) && std::isfinite(rays.directionY[r]) &&
                   std::isfinite(rays.directionZ[r]));
            ray.org_x = rays.originX[r];
            ray.org_y = rays.originY[r];
            ray.org_z = rays.originZ[r];
            ray.tnear = rays.tnear;
            ray.dir_x = rays.directionX[r];
            ray.dir_y = rays.directionY[r];
            ray.dir_z = rays.directionZ[r];
            ray.time = 0;
            ray.tfar = rays.tfar;
            ray.mask = 0xffffffffu;
            ray.id = unsigned(i);
            ray.flags = 0;
        }
        rtcOccluded1M(m_scene, &context.base, scratch.data(), unsigned(count), sizeof(RTCRay));
        for (std::size_t i = 0; i < count; ++i)
            occluded[start + i] = scratch[i].tfar < 0 ? 1 : 0; // Embree sets tfar = -inf on a hit
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
