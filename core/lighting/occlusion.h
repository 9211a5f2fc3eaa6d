#pragma once
// Visibility queries of the transfer bake (paper §6.1.2–6.1.3): does a ray from a vertex hit the
// proxy mesh M′? Two backends answer exactly the same queries:
// - Embree 3 (the fast path): one scene per proxy, rays in streams through rtcOccluded1M, the
//   origin-triangle exclusion done in an occlusion filter callback;
// - a uniform grid with Amanatides–Woo traversal (the paper's own ray tracer, the reference).
//
// Relaxation (paper §6.1.3): hits nearer than ε along the ray are ignored (tnear = ε), and the
// triangles that contain the ray's origin vertex are excluded (the vertex's one-ring; the query
// names the origin vertex, the backend knows the triangles' vertex indices).

#include <cstdint>
#include <memory>
#include <span>
#include <string>

#include "anim/quat.h"
#include "util/error.h"

namespace thespis::core::lighting {

enum class OcclusionBackendKind { Embree, Grid };
const char* occlusionBackendName(OcclusionBackendKind kind); ///< "embree", "grid"
Result<OcclusionBackendKind> parseOcclusionBackend(std::string_view name);

/// Triangles of a proxy mesh. Vertex indices are the character's global vertex indices, so the
/// origin-vertex exclusion compares them directly; `positions` is the whole character.
struct ProxyMeshView {
    std::span<const anim::Vec3> positions;
    std::span<const std::uint32_t> indices; ///< 3 per triangle, only the proxy's triangles
};

/// A batch of rays, structure of arrays. Directions are unit length and finite (Embree aborts
/// on NaN directions: callers guarantee it, the backends assert it).
struct RayBatch {
    const float* originX = nullptr;
    const float* originY = nullptr;
    const float* originZ = nullptr;
    const float* directionX = nullptr;
    const float* directionY = nullptr;
    const float* directionZ = nullptr;
    const std::uint32_t* originVertex = nullptr; ///< global vertex index, or kNoVertex
    std::size_t count = 0;
    float tnear = 1.71e-4f; ///< ε of the relaxation, metres
    float tfar = 1e30f;
};
inline constexpr std::uint32_t kNoVertex = 0xffffffffu;

/// Answers visibility queries against one proxy mesh. Built once, then `occluded` may be called
/// from many threads at once (each with its own scratch).
class OcclusionScene {
public:
    virtual ~OcclusionScene() = default;
    virtual OcclusionBackendKind kind() const = 0;
    /// occluded[i] = 1 if ray i hits a triangle of the proxy (not excluded) at t ∈ [tnear, tfar],
    /// else 0. No allocation after the first call on a thread.
    virtual void occluded(const RayBatch& rays, std::span<std::uint8_t> occluded) const = 0;
};

/// Builds a scene over the proxy. The mesh data is copied (the scene does not keep the view).
/// Errors: Embree device or scene creation failed (message from rtcGetDeviceError), empty
/// proxy meshes are allowed (nothing is ever occluded).
Result<std::unique_ptr<OcclusionScene>> buildOcclusionScene(OcclusionBackendKind kind, const ProxyMeshView& proxy);

} // namespace thespis::core::lighting
