#pragma once
// The PRT transfer bake (paper §6; Sloan, Kautz & Snyder 2002): for every vertex a transfer
// vector t of order² SH coefficients such that the exit radiance of a white diffuse surface under
// a distant light with SH coefficients L is  Σ L_i t_i.
//
//   t_i = (1/π) ∫ V(x, ω) max(n·ω, 0) Y_i(ω) dω
//
// estimated with N stratified cosine-weighted directions (pdf = cos/π, so t_i ≈ (1/N) Σ V Y_i).
// - DU  (diffuse unshadowed): V = 1.
// - DS  (diffuse shadowed, Sloan): V against the vertex's own segment only.
// - DSM (diffuse shadowed merged, the paper's): V against the proxy mesh M′ of all segments;
//   receiver segments are not in M′; occluder segments are in M′ and get no transfer.
// Relaxation: tnear = ε and the origin vertex's triangles are excluded (see occlusion.h).
//
// Transfer is stored in each segment's bind frame (t_local = R(bindRotation⁻¹)·t_world), so at
// run time the light is rotated into the segment's current frame: radiance = t · R(q⁻¹)·L.
//
// Determinism: each vertex draws its directions from its own generator seeded by (seed, global
// vertex index) and sums in a fixed order, so the result is bit-identical whatever the thread count.

#include <array>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <span>
#include <functional>
#include <stop_token>
#include <string>
#include <vector>

#include "lighting/occlusion.h"
#include "lighting/sh.h"
#include "scene/character_mesh.h"
#include "util/error.h"

namespace thespis::core::lighting {

enum class TransferKind : std::uint8_t { DiffuseUnshadowed, DiffuseShadowed, DiffuseShadowedMerged };
const char* transferKindName(TransferKind kind); ///< "du", "ds", "dsm"
Result<TransferKind> parseTransferKind(std::string_view name);

struct BakeSettings {
    int order = 5;                ///< bands 0 … order−1 (1 … kMaxShOrder)
    int raysPerVertex = 1024;     ///< N ≥ 1; stratified on a ⌊√N⌋ × ⌈N/⌊√N⌋⌉ grid trimmed to N (see sampleBakeDirections)
    TransferKind transfer = TransferKind::DiffuseShadowedMerged;
    OcclusionBackendKind backend = OcclusionBackendKind::Embree;
    float epsilon = 1.71e-4f;     ///< relaxation distance, metres (paper: H-Anim segment gap)
    std::uint64_t seed = 1;
    int threads = 0;              ///< 0: all hardware threads
};
/// Checks ranges (order, rays, ε ≥ 0 and finite, threads ≥ 0) with a message naming the field.
Result<void> validateBakeSettings(const BakeSettings& settings);

struct BakeProgress {
    std::uint64_t verticesDone = 0;
    std::uint64_t verticesTotal = 0;
};
/// Called from worker threads, serialised by the bake (never two calls at once), at most about
/// every 1 % of the vertices and once at the end.
using BakeProgressCallback = std::function<void(const BakeProgress&)>;

struct BakedSegment {
    std::string name;
    std::uint32_t firstVertex = 0;  ///< in the character mesh
    std::uint32_t vertexCount = 0;
    std::uint64_t transferOffset = 0; ///< index of its first vertex's first coefficient in `transfer`
    bool baked = true;              ///< false for occluder segments (no transfer stored)
    scene::SegmentRole role = scene::SegmentRole::None;
    bool operator==(const BakedSegment&) const = default;
};

struct TransferBake {
    int order = 0;
    TransferKind transferKind = TransferKind::DiffuseShadowedMerged; ///< (`transfer` is the floats)
    int raysPerVertex = 0;
    float epsilon = 0;
    std::uint64_t seed = 0;
    std::uint64_t vertexCount = 0;   ///< of the whole character mesh
    /// meshGeometryHash() of the mesh baked; 0 when unknown (bake files of format 1).
    std::uint64_t geometryHash = 0;
    std::vector<BakedSegment> segments;
    /// order² floats per vertex of each baked segment, segment after segment, in bind frames.
    std::vector<float> transfer;
    bool operator==(const TransferBake&) const = default;

    /// The vertex's transfer (order² floats), empty for vertices of unbaked segments.
    std::span<const float> vertexTransfer(std::uint32_t vertex) const;
};

struct BakeStatistics {
    std::uint64_t vertices = 0;  ///< vertices baked (occluder segments' vertices are not)
    std::uint64_t rays = 0;      ///< directions sampled: vertices × raysPerVertex (traced for DS/DSM)
    double seconds = 0;          ///< the whole bake, scene building included
    double sceneSeconds = 0;     ///< building the occlusion scenes
};

/// The directions the bake shoots from a vertex (world frame, unit length, in the hemisphere of
/// `normal`), in the bake's order: for benchmarks that replay the bake's rays, and for tests.
/// Stratification: the unit square is cut into r = ⌊√N⌋ rows of ⌈N/r⌉ columns, trimmed to exactly
/// N strata: with N = r·q + e, the first e rows keep q + 1 columns and the others q, and each row's
/// height is its column count / N, so that every stratum has area 1/N (unbiased, no stratum
/// dropped). Sample k is the k-th stratum in row-major order (rows from v = 0, columns from
/// u = 0), jittered inside it by the vertex's generator. Each point is mapped to the disc by
/// Shirley–Chiu's concentric map and lifted to the hemisphere (Malley: pdf = cos θ/π); the
/// tangent frame is Duff et al.'s branchless one (JCGT 2017).
void sampleBakeDirections(int raysPerVertex, std::uint64_t seed, std::uint32_t vertex, const anim::Vec3& normal,
                          std::span<anim::Vec3> directions);

/// Bakes a character. Cancelled → ErrorCode::Cancelled and no result. The mesh must validate.
Result<TransferBake> bakeTransfer(const scene::CharacterMesh& mesh, const BakeSettings& settings,
                                  std::stop_token stop = {}, const BakeProgressCallback& progress = {},
                                  BakeStatistics* statistics = nullptr);

// A bake in pieces (farm bakes, thespis.farm): plan it, split the plan into vertex ranges, bake
// the ranges anywhere (another process or machine, in any order), and place each range's floats
// into the plan. Since each vertex's result depends only on the mesh, the settings and its index,
// the assembled bake equals bakeTransfer(mesh, settings) bit for bit.

/// A run of vertices inside one baked segment; `firstVertex` indexes the whole character mesh.
struct VertexRange {
    std::uint32_t firstVertex = 0;
    std::uint32_t vertexCount = 0;
    bool operator==(const VertexRange&) const = default;
};

/// The bake of `mesh` with everything but the transfer filled in: settings, segments and their
/// offsets, geometry hash; `transfer` is sized and zero. The settings and the mesh must validate.
Result<TransferBake> planTransferBake(const scene::CharacterMesh& mesh, const BakeSettings& settings);
/// Every baked segment of a plan cut into ranges of at most `maxVertices` (≥ 1) vertices, in
/// transfer order (so their floats, concatenated, are the plan's `transfer`).
std::vector<VertexRange> splitTransferBake(const TransferBake& plan, std::uint32_t maxVertices);
/// Bakes only `ranges`, each inside one baked segment (else InvalidArgument naming the range):
/// order² floats per vertex, range after range, equal to those vertices of bakeTransfer.
/// Cancelled → ErrorCode::Cancelled. Progress counts the ranges' vertices.
Result<std::vector<float>> bakeTransferRanges(const scene::CharacterMesh& mesh, const BakeSettings& settings,
                                              std::span<const VertexRange> ranges, std::stop_token stop = {},
                                              const BakeProgressCallback& progress = {},
                                              BakeStatistics* statistics = nullptr);
/// Copies a range's floats (order² per vertex) into the plan; InvalidArgument when the range is not
/// inside one baked segment of the plan or the float count does not fit it.
Result<void> placeTransferRange(TransferBake& plan, const VertexRange& range, std::span<const float> transfer);

/// The bake file: little-endian binary, magic "THSPPRT\0", format version, order, transfer kind,
/// rays, ε, seed, vertex count, segment table (name, ranges, role, baked), the floats, and a
/// CRC-32 of everything before it. Written atomically (a cancelled or failed write leaves no
/// file). Reading refuses wrong magic (NotOurFormat), newer versions (NewerVersion), truncation,
/// inconsistent counts and checksum mismatch (CorruptData), naming the field.
Result<void> writeBakeFile(const std::filesystem::path& path, const TransferBake& bake);
/// The bake file's bytes, for a file written elsewhere (a package); `path` names it in messages.
Result<std::string> bakeFileBytes(const TransferBake& bake, const std::filesystem::path& path);
Result<TransferBake> readBakeFile(const std::filesystem::path& path);
/// The same reader over bytes already in memory (Python, fuzzing); `source` names them in messages.
Result<TransferBake> parseBakeBytes(std::string_view bytes, const std::filesystem::path& source);
/// A hash of what a bake depends on in a mesh: its bind-pose positions, normals and triangles,
/// and its segments' vertex ranges. Any moved vertex changes it.
std::uint64_t meshGeometryHash(const scene::CharacterMesh& mesh);
/// Checks that a bake belongs to a mesh (vertex count, segment names and ranges, its geometry
/// when the bake recorded it, the tags a DSM bake depends on) and says what differs.
Result<void> checkBakeMatchesMesh(const TransferBake& bake, const scene::CharacterMesh& mesh);

/// Exit radiance (RGB) of a vertex under the world light L when its segment's frame has the
/// world rotation `segmentRotation` (segment.bindRotation in the bind pose): the light is rotated
/// into the segment's frame, R(segmentRotation⁻¹)·L, and dotted with the stored transfer.
/// Unbaked (occluder) vertices shade to 0.
std::array<double, 3> shadeVertex(const TransferBake& bake, const scene::CharacterMesh& mesh,
                                  std::uint32_t vertex, const ShRgb& light, const anim::Quatd& segmentRotation);

} // namespace thespis::core::lighting
