#include "render/picking.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "render/character_node.h"
#include "render/render_scene.h"

namespace thespis::core::render {

namespace {

using anim::Vec3d;

Vec3d toDouble(const anim::Vec3& v)
{
    return {double(v.x), double(v.y), double(v.z)};
}

double dot(const Vec3d& a, const Vec3d& b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

Vec3d cross(const Vec3d& a, const Vec3d& b)
{
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

// Slab test: does the ray (unit direction, inverse components precomputed) meet the box at a
// distance below `limit`?
bool rayMeetsBox(const Vec3d& origin, const Vec3d& inverse, const Vec3d& low, const Vec3d& high, double limit)
{
    double enter = 0, leave = limit;
    const double o[3] = {origin.x, origin.y, origin.z};
    const double inv[3] = {inverse.x, inverse.y, inverse.z};
    const double lo[3] = {low.x, low.y, low.z};
    const double hi[3] = {high.x, high.y, high.z};
    for (int axis = 0; axis < 3; ++axis) {
        double t0 = (lo[axis] - o[axis]) * inv[axis];
        double t1 = (hi[axis] - o[axis]) * inv[axis];
        if (std::isnan(t0) || std::isnan(t1)) { // origin on a slab plane of a flat box, direction parallel
            if (o[axis] < lo[axis] || o[axis] > hi[axis])
                return false;
            continue;
        }
        if (t0 > t1)
            std::swap(t0, t1);
        enter = std::max(enter, t0);
        leave = std::min(leave, t1);
        if (enter > leave)
            return false;
    }
    return true;
}

} // namespace

std::optional<PickHit> pick(const CharacterNode& node, const PickRay& ray, std::size_t character)
{
    const double length = std::sqrt(dot(ray.direction, ray.direction));
    if (!(length > 0) || !std::isfinite(length))
        return std::nullopt;
    const Vec3d direction = ray.direction * (1.0 / length);
    const Vec3d inverse{1.0 / direction.x, 1.0 / direction.y, 1.0 / direction.z};
    const Vec3d& origin = ray.origin;
    const scene::CharacterMesh& mesh = node.character().mesh;
    const auto positions = node.posedPositions();
    constexpr double kParallel = 1e-14;

    std::optional<PickHit> best;
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t s = 0; s < mesh.segments.size(); ++s) {
        const scene::Segment& segment = mesh.segments[s];
        if (segment.triangleCount == 0)
            continue;
        // The segment's posed box first: most segments are nowhere near the ray.
        Vec3d low{1e300, 1e300, 1e300}, high{-1e300, -1e300, -1e300};
        for (std::uint32_t v = segment.firstVertex; v < segment.firstVertex + segment.vertexCount; ++v) {
            const anim::Vec3& p = positions[v];
            low = {std::min(low.x, double(p.x)), std::min(low.y, double(p.y)), std::min(low.z, double(p.z))};
            high = {std::max(high.x, double(p.x)), std::max(high.y, double(p.y)), std::max(high.z, double(p.z))};
        }
        if (!rayMeetsBox(origin, inverse, low, high, nearest))
            continue;
        for (std::uint32_t t = segment.firstTriangle; t < segment.firstTriangle + segment.triangleCount; ++t) {
            // Möller–Trumbore, both faces.
            const Vec3d a = toDouble(positions[mesh.indices[3 * std::size_t(t)]]);
            const Vec3d edge1 = toDouble(positions[mesh.indices[3 * std::size_t(t) + 1]]) - a;
            const Vec3d edge2 = toDouble(positions[mesh.indices[3 * std::size_t(t) + 2]]) - a;
            const Vec3d p = cross(direction, edge2);
            const double determinant = dot(edge1, p);
            if (std::abs(determinant) < kParallel)
                continue;
            const double inverseDeterminant = 1.0 / determinant;
            const Vec3d toOrigin = origin - a;
            const double u = dot(toOrigin, p) * inverseDeterminant;
            if (u < 0.0 || u > 1.0)
                continue;
            const Vec3d q = cross(toOrigin, edge1);
            const double v = dot(direction, q) * inverseDeterminant;
            if (v < 0.0 || u + v > 1.0)
                continue;
            const double distance = dot(edge2, q) * inverseDeterminant;
            if (distance > 0.0 && distance < nearest) {
                nearest = distance;
                best = PickHit{character, s, t, distance, origin + direction * distance};
            }
        }
    }
    return best;
}

std::optional<PickHit> pick(const RenderScene& scene, const PickRay& ray)
{
    std::optional<PickHit> best;
    for (std::size_t c = 0; c < scene.characterCount(); ++c)
        if (auto hit = pick(scene.character(c), ray, c); hit && (!best || hit->distance < best->distance))
            best = hit;
    return best;
}

} // namespace thespis::core::render
