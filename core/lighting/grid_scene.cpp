#include "lighting/grid_scene.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include <emmintrin.h>

namespace thespis::core::lighting {
namespace {

/// Cells per triangle over the proxy's bounding box. With four-triangle blocks, 4 to 16 measured
/// alike on CesiumMan and RobotExpressive (fewer cells: more triangle tests; more: more steps).
constexpr double kCellsPerTriangle = 8.0;
constexpr int kMaxCellsPerAxis = 256;

/// The four-lane float test decides alone only outside these bands; inside them the exact test
/// decides. Barycentric band (fraction of the triangle), and relative band around tnear and tfar.
/// The float error is about 1e-5 of the triangle (centimetre triangles a metre from the origin)
/// over the cosine of incidence: only nearly grazing rays (within ~0.01 rad of the plane) could
/// get another answer than the reference's.
constexpr float kEdgeBand = 1.0f / 1024;
constexpr float kDistanceBand = 1.0f / 1024;
/// Absolute floor of the band around tnear, in units of the grid's size (for tnear = 0).
constexpr double kDistanceFloor = 1e-6;

/// A triangle as the exact test reads it: corners (float, as the mesh has them).
struct GridTriangle {
    std::array<float, 3> a, b, c;
};

struct Vec3D {
    double x, y, z;
};
inline Vec3D sub(Vec3D p, Vec3D q) { return {p.x - q.x, p.y - q.y, p.z - q.z}; }
inline Vec3D cross(Vec3D p, Vec3D q) { return {p.y * q.z - p.z * q.y, p.z * q.x - p.x * q.z, p.x * q.y - p.y * q.x}; }
inline double dot(Vec3D p, Vec3D q) { return p.x * q.x + p.y * q.y + p.z * q.z; }
inline Vec3D scale(Vec3D p, double s) { return {p.x * s, p.y * s, p.z * s}; }
inline Vec3D toD(const std::array<float, 3>& v) { return {v[0], v[1], v[2]}; }

/// Möller–Trumbore in double precision on the float corners: the corner differences are exact
/// in double, so the test only disagrees with an exact one for rays within ~1e-16 of an edge.
/// This is the reference; the float test below defers to it near edges and near tnear, tfar.
bool hitsTriangle(const GridTriangle& triangle, Vec3D origin, Vec3D direction, double tnear, double tfar)
{
    const Vec3D a = toD(triangle.a);
    const Vec3D edge1 = sub(toD(triangle.b), a);
    const Vec3D edge2 = sub(toD(triangle.c), a);
    const Vec3D p = cross(direction, edge2);
    const double det = dot(edge1, p);
    if (det == 0)
        return false; // the ray lies in the triangle's plane: a grazing ray does not hit it
    const double inverse = 1 / det;
    const Vec3D s = sub(origin, a);
    const double u = dot(s, p) * inverse;
    if (u < 0 || u > 1)
        return false;
    const Vec3D q = cross(s, edge1);
    const double v = dot(direction, q) * inverse;
    if (v < 0 || u + v > 1)
        return false;
    const double t = dot(edge2, q) * inverse;
    return t >= tnear && t <= tfar;
}

/// Separating-axis test of a triangle against the box [−half, half] (Akenine-Möller 2001), for
/// a triangle already known to overlap the box's range on each axis: the triangle's normal and
/// the nine edge × axis directions.
bool triangleOverlapsBox(const std::array<Vec3D, 3>& corner, Vec3D half)
{
    auto separates = [&](Vec3D axis) {
        const double p0 = dot(axis, corner[0]), p1 = dot(axis, corner[1]), p2 = dot(axis, corner[2]);
        const double radius = half.x * std::abs(axis.x) + half.y * std::abs(axis.y) + half.z * std::abs(axis.z);
        return std::min({p0, p1, p2}) > radius || std::max({p0, p1, p2}) < -radius;
    };
    const Vec3D edges[3] = {sub(corner[1], corner[0]), sub(corner[2], corner[1]), sub(corner[0], corner[2])};
    if (separates(cross(edges[0], edges[1])))
        return false;
    for (const Vec3D& edge : edges)
        for (const Vec3D& boxAxis : {Vec3D{1, 0, 0}, Vec3D{0, 1, 0}, Vec3D{0, 0, 1}})
            if (separates(cross(edge, boxAxis)))
                return false;
    return true;
}

/// Four triangles of one cell laid out for one SSE test, in the plane form of Havel & Herout
/// (2010): the plane n·x = planeOffset (n = (b − a) × (c − a)) and the two barycentric planes
/// u(x) = uPlane·x + uOffset, v(x) = vPlane·x + vOffset, precomputed in double and rounded; the
/// global vertex indices for the origin-vertex exclusion and the triangle numbers for the exact
/// test. Unused lanes have a zero normal (det = 0: never hit). 256 bytes, four cache lines.
struct TriangleBlock {
    __m128 normalX, normalY, normalZ, planeOffset;
    __m128 uPlaneX, uPlaneY, uPlaneZ, uOffset;
    __m128 vPlaneX, vPlaneY, vPlaneZ, vOffset;
    __m128i vertex0, vertex1, vertex2;
    std::array<std::uint32_t, 4> triangle;
};

/// One ray, broadcast to the four lanes, with the bands of its t-range.
struct RayLanes {
    __m128 originX, originY, originZ;
    __m128 directionX, directionY, directionZ;
    __m128 tnearLow, tnearHigh, tfarLow, tfarHigh;
    __m128i originVertex;
};

/// The exact form of the same ray, for the reference test and the traversal.
struct Ray {
    Vec3D origin, direction;
    double tnear, tfar;
};

class GridScene final : public OcclusionScene {
public:
    explicit GridScene(const ProxyMeshView& proxy);
    OcclusionBackendKind kind() const override { return OcclusionBackendKind::Grid; }
    void occluded(const RayBatch& rays, std::span<std::uint8_t> occluded) const override;

private:
    bool traceOccluded(const Ray& ray, const RayLanes& lanes) const;
    bool blockOccludes(const TriangleBlock& block, const Ray& ray, const RayLanes& lanes) const;
    std::size_t cellIndex(int x, int y, int z) const
    {
        return std::size_t(x) + std::size_t(m_dims[0]) * (std::size_t(y) + std::size_t(m_dims[1]) * std::size_t(z));
    }

    std::vector<GridTriangle> m_triangles;
    std::array<double, 3> m_lower{}, m_upper{};
    std::array<double, 3> m_cellSize{1, 1, 1}, m_inverseCellSize{1, 1, 1};
    std::array<int, 3> m_dims{1, 1, 1};
    std::array<std::ptrdiff_t, 3> m_axisStride{1, 1, 1}; ///< cell index step along x, y, z
    double m_distanceFloor = 0;
    std::vector<std::uint32_t> m_cellStart; ///< per cell, into m_blocks; one more at the end
    std::vector<TriangleBlock> m_blocks;    ///< each cell's triangles, four to a block, cell after cell
};

GridScene::GridScene(const ProxyMeshView& proxy)
{
    const std::size_t triangleCount = proxy.indices.size() / 3;
    if (triangleCount == 0) {
        m_cellStart.assign(2, 0);
        return;
    }
    m_triangles.resize(triangleCount);
    std::array<double, 3> lower{std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
                                std::numeric_limits<double>::max()};
    std::array<double, 3> upper{-lower[0], -lower[1], -lower[2]};
    for (std::size_t t = 0; t < triangleCount; ++t) {
        GridTriangle& triangle = m_triangles[t];
        std::array<float, 3>* corners[3] = {&triangle.a, &triangle.b, &triangle.c};
        for (std::size_t k = 0; k < 3; ++k) {
            const anim::Vec3& p = proxy.positions[proxy.indices[3 * t + k]];
            *corners[k] = {p.x, p.y, p.z};
            for (std::size_t axis = 0; axis < 3; ++axis) {
                lower[axis] = std::min(lower[axis], double((*corners[k])[axis]));
                upper[axis] = std::max(upper[axis], double((*corners[k])[axis]));
            }
        }
    }

    // Pad the box so that no triangle lies on its faces, then choose near-cubic cells.
    double largest = 0;
    for (std::size_t axis = 0; axis < 3; ++axis)
        largest = std::max(largest, upper[axis] - lower[axis]);
    const double pad = largest * 1e-3 + 1e-6;
    std::array<double, 3> extent{};
    for (std::size_t axis = 0; axis < 3; ++axis) {
        lower[axis] -= pad;
        upper[axis] += pad;
        extent[axis] = upper[axis] - lower[axis];
    }
    const double cellEdge =
        std::cbrt(extent[0] * extent[1] * extent[2] / (kCellsPerTriangle * double(triangleCount)));
    for (std::size_t axis = 0; axis < 3; ++axis) {
        m_dims[axis] = std::clamp(int(std::lround(extent[axis] / cellEdge)), 1, kMaxCellsPerAxis);
        m_cellSize[axis] = extent[axis] / m_dims[axis];
        m_inverseCellSize[axis] = 1 / m_cellSize[axis];
    }
    m_lower = lower;
    m_upper = upper;
    m_axisStride = {1, m_dims[0], std::ptrdiff_t(m_dims[0]) * m_dims[1]};
    m_distanceFloor = kDistanceFloor * std::max({extent[0], extent[1], extent[2]});

    // Bin each triangle into the cells it overlaps (bounding-box range, then the separating-axis
    // test). Cell boxes are grown by a small margin: a ray that rounding moves into a neighbouring
    // cell at a cell face still finds the triangles near that face.
    const double margin = 1e-3;
    const Vec3D half = scale({m_cellSize[0], m_cellSize[1], m_cellSize[2]}, 0.5 + margin);
    auto forEachCell = [&](const GridTriangle& triangle, auto&& visit) {
        std::array<int, 3> first{}, last{};
        for (std::size_t axis = 0; axis < 3; ++axis) {
            const double lo = std::min({triangle.a[axis], triangle.b[axis], triangle.c[axis]});
            const double hi = std::max({triangle.a[axis], triangle.b[axis], triangle.c[axis]});
            first[axis] = std::clamp(int(std::floor((lo - m_lower[axis]) / m_cellSize[axis] - margin)), 0, m_dims[axis] - 1);
            last[axis] = std::clamp(int(std::floor((hi - m_lower[axis]) / m_cellSize[axis] + margin)), 0, m_dims[axis] - 1);
        }
        for (int z = first[2]; z <= last[2]; ++z)
            for (int y = first[1]; y <= last[1]; ++y)
                for (int x = first[0]; x <= last[0]; ++x) {
                    const Vec3D center{m_lower[0] + (x + 0.5) * m_cellSize[0], m_lower[1] + (y + 0.5) * m_cellSize[1],
                                       m_lower[2] + (z + 0.5) * m_cellSize[2]};
                    const std::array<Vec3D, 3> corners = {sub(toD(triangle.a), center), sub(toD(triangle.b), center),
                                                          sub(toD(triangle.c), center)};
                    if (triangleOverlapsBox(corners, half))
                        visit(cellIndex(x, y, z));
                }
    };
    const std::size_t cellCount = std::size_t(m_dims[0]) * std::size_t(m_dims[1]) * std::size_t(m_dims[2]);
    std::vector<std::uint32_t> triangleStart(cellCount + 1, 0);
    for (const GridTriangle& triangle : m_triangles)
        forEachCell(triangle, [&](std::size_t cell) { ++triangleStart[cell + 1]; });
    for (std::size_t cell = 0; cell < cellCount; ++cell)
        triangleStart[cell + 1] += triangleStart[cell];
    std::vector<std::uint32_t> cellTriangles(triangleStart.back());
    std::vector<std::uint32_t> fill(triangleStart.begin(), triangleStart.end() - 1);
    for (std::size_t t = 0; t < triangleCount; ++t)
        forEachCell(m_triangles[t], [&](std::size_t cell) { cellTriangles[fill[cell]++] = std::uint32_t(t); });

    // Pack each cell's triangles four to a block.
    m_cellStart.assign(cellCount + 1, 0);
    for (std::size_t cell = 0; cell < cellCount; ++cell)
        m_cellStart[cell + 1] = m_cellStart[cell] + (triangleStart[cell + 1] - triangleStart[cell] + 3) / 4;
    m_blocks.resize(m_cellStart.back());
    for (std::size_t cell = 0; cell < cellCount; ++cell)
        for (std::uint32_t b = m_cellStart[cell]; b < m_cellStart[cell + 1]; ++b) {
            alignas(16) std::array<float, 4> lanes[12] = {};
            alignas(16) std::array<std::uint32_t, 4> vertices[3] = {};
            TriangleBlock& block = m_blocks[b];
            block.triangle = {};
            for (std::uint32_t lane = 0; lane < 4; ++lane) {
                const std::uint32_t k = triangleStart[cell] + 4 * (b - m_cellStart[cell]) + lane;
                if (k >= triangleStart[cell + 1])
                    break;
                const std::uint32_t t = cellTriangles[k];
                const GridTriangle& triangle = m_triangles[t];
                const Vec3D corner = toD(triangle.a);
                const Vec3D edge1 = sub(toD(triangle.b), corner);
                const Vec3D edge2 = sub(toD(triangle.c), corner);
                const Vec3D normal = cross(edge1, edge2);
                const double area2 = dot(normal, normal);
                if (area2 == 0)
                    continue; // degenerate: never hit, as in the exact test
                const Vec3D uPlane = scale(cross(edge2, normal), 1 / area2);
                const Vec3D vPlane = scale(cross(normal, edge1), 1 / area2);
                const Vec3D planes[3] = {normal, uPlane, vPlane};
                for (std::size_t plane = 0; plane < 3; ++plane) {
                    lanes[4 * plane][lane] = float(planes[plane].x);
                    lanes[4 * plane + 1][lane] = float(planes[plane].y);
                    lanes[4 * plane + 2][lane] = float(planes[plane].z);
                }
                lanes[3][lane] = float(dot(normal, corner));
                lanes[7][lane] = float(-dot(uPlane, corner));
                lanes[11][lane] = float(-dot(vPlane, corner));
                for (std::size_t k3 = 0; k3 < 3; ++k3)
                    vertices[k3][lane] = proxy.indices[3 * std::size_t(t) + k3];
                block.triangle[lane] = t;
            }
            __m128* const destinations[12] = {&block.normalX, &block.normalY, &block.normalZ, &block.planeOffset,
                                               &block.uPlaneX,  &block.uPlaneY,  &block.uPlaneZ,  &block.uOffset,
                                               &block.vPlaneX,  &block.vPlaneY,  &block.vPlaneZ,  &block.vOffset};
            for (std::size_t i = 0; i < 12; ++i)
                *destinations[i] = _mm_load_ps(lanes[i].data());
            block.vertex0 = _mm_load_si128(reinterpret_cast<const __m128i*>(vertices[0].data()));
            block.vertex1 = _mm_load_si128(reinterpret_cast<const __m128i*>(vertices[1].data()));
            block.vertex2 = _mm_load_si128(reinterpret_cast<const __m128i*>(vertices[2].data()));
        }
}

/// The plane test on four triangles in float, without division. With det = n·d and
/// T = planeOffset − n·o (t = T/det), the hit point times det is P = det·o + T·d, and the
/// barycentrics times det are U = uPlane·P + det·uOffset, V likewise. After multiplying by det's
/// sign (a = |det|) the ray hits when U, V, a − U − V ≥ 0 and tnear·a ≤ T ≤ tfar·a. The t-range
/// is tested first: most triangles near a ray's origin lie behind it or before tnear.
/// Lanes that pass with room to spare (outside the bands) are hits; lanes that pass only within
/// the bands are decided by the exact test, so the answer is the reference's.
bool GridScene::blockOccludes(const TriangleBlock& block, const Ray& ray, const RayLanes& lanes) const
{
    const __m128 det = _mm_add_ps(_mm_add_ps(_mm_mul_ps(block.normalX, lanes.directionX),
                                             _mm_mul_ps(block.normalY, lanes.directionY)),
                                  _mm_mul_ps(block.normalZ, lanes.directionZ));
    const __m128 distance = _mm_sub_ps(block.planeOffset, _mm_add_ps(_mm_add_ps(_mm_mul_ps(block.normalX, lanes.originX),
                                                                                _mm_mul_ps(block.normalY, lanes.originY)),
                                                                     _mm_mul_ps(block.normalZ, lanes.originZ)));
    const __m128 sign = _mm_and_ps(det, _mm_set1_ps(-0.0f));
    const __m128 a = _mm_xor_ps(det, sign);
    const __m128 t = _mm_xor_ps(distance, sign);
    const __m128i excluded = _mm_or_si128(_mm_or_si128(_mm_cmpeq_epi32(block.vertex0, lanes.originVertex),
                                                       _mm_cmpeq_epi32(block.vertex1, lanes.originVertex)),
                                          _mm_cmpeq_epi32(block.vertex2, lanes.originVertex));
    __m128 maybe = _mm_and_ps(_mm_cmpge_ps(t, _mm_mul_ps(lanes.tnearLow, a)), _mm_cmple_ps(t, _mm_mul_ps(lanes.tfarHigh, a)));
    maybe = _mm_and_ps(maybe, _mm_cmpgt_ps(a, _mm_setzero_ps()));
    maybe = _mm_andnot_ps(_mm_castsi128_ps(excluded), maybe);
    if (_mm_movemask_ps(maybe) == 0)
        return false;

    const __m128 px = _mm_add_ps(_mm_mul_ps(det, lanes.originX), _mm_mul_ps(distance, lanes.directionX));
    const __m128 py = _mm_add_ps(_mm_mul_ps(det, lanes.originY), _mm_mul_ps(distance, lanes.directionY));
    const __m128 pz = _mm_add_ps(_mm_mul_ps(det, lanes.originZ), _mm_mul_ps(distance, lanes.directionZ));
    const __m128 u = _mm_xor_ps(_mm_add_ps(_mm_add_ps(_mm_mul_ps(block.uPlaneX, px), _mm_mul_ps(block.uPlaneY, py)),
                                           _mm_add_ps(_mm_mul_ps(block.uPlaneZ, pz), _mm_mul_ps(block.uOffset, det))),
                                sign);
    const __m128 v = _mm_xor_ps(_mm_add_ps(_mm_add_ps(_mm_mul_ps(block.vPlaneX, px), _mm_mul_ps(block.vPlaneY, py)),
                                           _mm_add_ps(_mm_mul_ps(block.vPlaneZ, pz), _mm_mul_ps(block.vOffset, det))),
                                sign);
    const __m128 w = _mm_sub_ps(_mm_sub_ps(a, u), v);
    const __m128 band = _mm_mul_ps(a, _mm_set1_ps(kEdgeBand));
    const __m128 minusBand = _mm_sub_ps(_mm_setzero_ps(), band);
    maybe = _mm_and_ps(maybe, _mm_and_ps(_mm_cmpge_ps(u, minusBand), _mm_cmpge_ps(v, minusBand)));
    maybe = _mm_and_ps(maybe, _mm_cmpge_ps(w, minusBand));
    const int maybeLanes = _mm_movemask_ps(maybe);
    if (maybeLanes == 0)
        return false;
    __m128 sure = _mm_and_ps(_mm_cmpge_ps(u, band), _mm_cmpge_ps(v, band));
    sure = _mm_and_ps(sure, _mm_cmpge_ps(w, band));
    sure = _mm_and_ps(sure, _mm_cmpge_ps(t, _mm_mul_ps(lanes.tnearHigh, a)));
    sure = _mm_and_ps(sure, _mm_cmple_ps(t, _mm_mul_ps(lanes.tfarLow, a)));
    if (_mm_movemask_ps(_mm_and_ps(sure, maybe)) != 0)
        return true;
    for (int lane = 0; lane < 4; ++lane)
        if ((maybeLanes >> lane & 1) &&
            hitsTriangle(m_triangles[block.triangle[std::size_t(lane)]], ray.origin, ray.direction, ray.tnear, ray.tfar))
            return true;
    return false;
}

bool GridScene::traceOccluded(const Ray& ray, const RayLanes& lanes) const
{
    // Clip the ray to the grid's box. A zero direction component is replaced by a tiny one of
    // the same sign, so that no axis needs a branch of its own (the walk never steps along it).
    const double o[3] = {ray.origin.x, ray.origin.y, ray.origin.z};
    const double d[3] = {ray.direction.x, ray.direction.y, ray.direction.z};
    constexpr double kTiny = 1e-30;
    double inverse[3];
    double t0 = ray.tnear, t1 = ray.tfar;
    for (std::size_t axis = 0; axis < 3; ++axis) {
        inverse[axis] = 1 / (std::abs(d[axis]) < kTiny ? std::copysign(kTiny, d[axis]) : d[axis]);
        const double ta = (m_lower[axis] - o[axis]) * inverse[axis];
        const double tb = (m_upper[axis] - o[axis]) * inverse[axis];
        t0 = std::max(t0, std::min(ta, tb));
        t1 = std::min(t1, std::max(ta, tb));
    }
    if (!(t0 <= t1))
        return false;

    // Amanatides–Woo: walk the cells the ray crosses, in order. Any hit in [tnear, tfar] answers
    // the query, even one beyond the current cell, so the first one found ends the walk.
    std::ptrdiff_t cell = 0;
    std::ptrdiff_t stride[3];
    int stepsLeft[3];
    double tMax[3], tDelta[3];
    for (std::size_t axis = 0; axis < 3; ++axis) {
        // Truncation is floor here: the clamp keeps the value non-negative.
        const double entry = (o[axis] + d[axis] * t0 - m_lower[axis]) * m_inverseCellSize[axis];
        const int index = int(std::clamp(entry, 0.0, double(m_dims[axis] - 1)));
        const bool forward = inverse[axis] > 0;
        cell += index * m_axisStride[axis];
        stride[axis] = forward ? m_axisStride[axis] : -m_axisStride[axis];
        stepsLeft[axis] = forward ? m_dims[axis] - 1 - index : index;
        tMax[axis] = (m_lower[axis] + (index + int(forward)) * m_cellSize[axis] - o[axis]) * inverse[axis];
        tDelta[axis] = m_cellSize[axis] * std::abs(inverse[axis]);
    }
    // The three axes unrolled, so that the walk's state stays in registers.
    double tMaxX = tMax[0], tMaxY = tMax[1], tMaxZ = tMax[2];
    int stepsX = stepsLeft[0], stepsY = stepsLeft[1], stepsZ = stepsLeft[2];
    const std::uint32_t* cellStart = m_cellStart.data();
    for (;;) {
        for (std::uint32_t b = cellStart[cell], end = cellStart[cell + 1]; b < end; ++b)
            if (blockOccludes(m_blocks[b], ray, lanes))
                return true;
        do {
            if (tMaxX < tMaxY && tMaxX < tMaxZ) {
                if (tMaxX > t1 || stepsX-- == 0)
                    return false;
                cell += stride[0];
                tMaxX += tDelta[0];
            } else if (tMaxY < tMaxZ) {
                if (tMaxY > t1 || stepsY-- == 0)
                    return false;
                cell += stride[1];
                tMaxY += tDelta[1];
            } else {
                if (tMaxZ > t1 || stepsZ-- == 0)
                    return false;
                cell += stride[2];
                tMaxZ += tDelta[2];
            }
        } while (cellStart[cell] == cellStart[cell + 1]); // skip empty cells in a tight loop
    }
}

void GridScene::occluded(const RayBatch& rays, std::span<std::uint8_t> occluded) const
{
    assert(occluded.size() >= rays.count);
    if (m_triangles.empty()) {
        std::fill_n(occluded.begin(), rays.count, std::uint8_t(0));
        return;
    }
    const float nearBand = std::max(rays.tnear * kDistanceBand, float(m_distanceFloor));
    RayLanes lanes;
    lanes.tnearLow = _mm_set1_ps(rays.tnear - nearBand);
    lanes.tnearHigh = _mm_set1_ps(rays.tnear + nearBand);
    lanes.tfarLow = _mm_set1_ps(rays.tfar * (1 - kDistanceBand));
    lanes.tfarHigh = _mm_set1_ps(rays.tfar * (1 + kDistanceBand));
    for (std::size_t r = 0; r < rays.count; ++r) {
        assert(std::isfinite(rays.directionX[r]) && std::isfinite(rays.directionY[r]) &&
               std::isfinite(rays.directionZ[r]));
        const Ray ray{{rays.originX[r], rays.originY[r], rays.originZ[r]},
                      {rays.directionX[r], rays.directionY[r], rays.directionZ[r]},
                      rays.tnear,
                      rays.tfar};
        lanes.originX = _mm_set1_ps(rays.originX[r]);
        lanes.originY = _mm_set1_ps(rays.originY[r]);
        lanes.originZ = _mm_set1_ps(rays.originZ[r]);
        lanes.directionX = _mm_set1_ps(rays.directionX[r]);
        lanes.directionY = _mm_set1_ps(rays.directionY[r]);
        lanes.directionZ = _mm_set1_ps(rays.directionZ[r]);
        lanes.originVertex = _mm_set1_epi32(int(rays.originVertex ? rays.originVertex[r] : kNoVertex));
        occluded[r] = traceOccluded(ray, lanes) ? 1 : 0;
    }
}

} // namespace

Result<std::unique_ptr<OcclusionScene>> buildGridScene(const ProxyMeshView& proxy)
{
    return std::unique_ptr<OcclusionScene>(std::make_unique<GridScene>(proxy));
}

} // namespace thespis::core::lighting
