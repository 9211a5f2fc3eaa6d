#include "lighting/transfer_bake.h"

#include <algorithm>
#include <atomic>
#include <cassert>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <numbers>
#include <thread>

#if defined(__SSE__) || defined(__x86_64__)
#include <pmmintrin.h>
#include <xmmintrin.h>
#endif

#include "lighting/float4.h"
#include "lighting/sh_rotation.h"

namespace thespis::core::lighting {

const char* transferKindName(TransferKind kind)
{
    switch (kind) {
    case TransferKind::DiffuseUnshadowed: return "du";
    case TransferKind::DiffuseShadowed: return "ds";
    case TransferKind::DiffuseShadowedMerged: return "dsm";
    }
    return "dsm";
}

Result<TransferKind> parseTransferKind(std::string_view name)
{
    for (TransferKind kind : {TransferKind::DiffuseUnshadowed, TransferKind::DiffuseShadowed,
                              TransferKind::DiffuseShadowedMerged})
        if (name == transferKindName(kind))
            return kind;
    return makeError(ErrorCode::InvalidArgument,
                     "Unknown transfer \"" + std::string(name) + "\": use du, ds or dsm.");
}

namespace {

// Rays per vertex are traced in one batch whose scratch every worker keeps; this bounds it
// (2²⁰ rays ≈ 40 MB of scratch per worker), far above any useful bake.
constexpr int kMaxRaysPerVertex = 1 << 20;
constexpr int kMaxThreads = 1024;

Error badSetting(const std::string& field, const std::string& rule, const std::string& got)
{
    return makeError(ErrorCode::InvalidArgument,
                     "The bake setting \"" + field + "\" " + rule + " (it is " + got + ").");
}

} // namespace

Result<void> validateBakeSettings(const BakeSettings& settings)
{
    if (settings.order < 1 || settings.order > kMaxShOrder)
        return badSetting("order", "must be between 1 and " + std::to_string(kMaxShOrder),
                          std::to_string(settings.order));
    if (settings.raysPerVertex < 1 || settings.raysPerVertex > kMaxRaysPerVertex)
        return badSetting("raysPerVertex", "must be between 1 and " + std::to_string(kMaxRaysPerVertex),
                          std::to_string(settings.raysPerVertex));
    if (!std::isfinite(settings.epsilon) || settings.epsilon < 0)
        return badSetting("epsilon", "must be a finite distance ≥ 0 in metres", std::to_string(settings.epsilon));
    if (settings.threads < 0 || settings.threads > kMaxThreads)
        return badSetting("threads", "must be between 0 (all hardware threads) and " + std::to_string(kMaxThreads),
                          std::to_string(settings.threads));
    if (std::uint8_t(settings.transfer) > std::uint8_t(TransferKind::DiffuseShadowedMerged))
        return badSetting("transfer", "must be du, ds or dsm", std::to_string(int(settings.transfer)));
    if (settings.backend != OcclusionBackendKind::Embree && settings.backend != OcclusionBackendKind::Grid)
        return badSetting("backend", "must be embree or grid", std::to_string(int(settings.backend)));
    return {};
}

std::span<const float> TransferBake::vertexTransfer(std::uint32_t vertex) const
{
    const std::size_t perVertex = std::size_t(order) * order;
    for (const BakedSegment& segment : segments)
        if (segment.baked && vertex >= segment.firstVertex && vertex - segment.firstVertex < segment.vertexCount)
            return {transfer.data() + segment.transferOffset + (vertex - segment.firstVertex) * perVertex, perVertex};
    return {};
}

namespace {

// splitmix64 (Steele, Lea & Flood 2014): a counter-based generator, one add and a finaliser per
// draw; each vertex gets its own stream, so no state is shared between threads.
constexpr std::uint64_t mix64(std::uint64_t z)
{
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

class SplitMix64 {
public:
    SplitMix64(std::uint64_t seed, std::uint32_t stream) : m_state(mix64(seed ^ mix64(stream + 0x9E3779B97F4A7C15ull))) {}
    std::uint64_t next() { return mix64(m_state += 0x9E3779B97F4A7C15ull); }

private:
    std::uint64_t m_state;
};

// sin and cos on [−π/4, π/4] by their Taylor series (next terms below 4e-9 and 3e-8): float
// accuracy without a libm call per ray, four lanes at a time.
inline Float4 sinQuarterPi(Float4 x)
{
    const Float4 x2 = x * x;
    return x * (1 + x2 * (-1.0f / 6 + x2 * (1.0f / 120 + x2 * (-1.0f / 5040 + x2 * (1.0f / 362880)))));
}
inline Float4 cosQuarterPi(Float4 x)
{
    const Float4 x2 = x * x;
    return 1 + x2 * (-0.5f + x2 * (1.0f / 24 + x2 * (-1.0f / 720 + x2 * (1.0f / 40320))));
}

/// The stratified, jittered points of the unit square of one vertex, in the documented order
/// (see sampleBakeDirections in the header): r = ⌊√N⌋ rows, the first e = N mod r rows of q + 1
/// columns and the rest of q = ⌊N/r⌋, each row as high as its share of the N strata.
void stratifiedPoints(int count, std::uint64_t seed, std::uint32_t vertex, float* u, float* v)
{
    int rows = std::max(1, int(std::sqrt(double(count))));
    while ((rows + 1) * (rows + 1) <= count) // rows = ⌊√N⌋ exactly, whatever sqrt's rounding
        ++rows;
    while (rows * rows > count)
        --rows;
    const int shortColumns = count / rows;
    const int longRows = count % rows;
    const float inverseCount = 1.0f / float(count);
    SplitMix64 random(seed, vertex);
    int k = 0;
    for (int row = 0, rowStart = 0; row < rows; ++row) {
        const int columns = row < longRows ? shortColumns + 1 : shortColumns;
        const float inverseColumns = 1.0f / float(columns);
        for (int column = 0; column < columns; ++column, ++k) {
            // One draw gives both jitters (24 bits each, exact in float).
            const std::uint64_t bits = random.next();
            const float jitterU = float(bits >> 40) * 0x1p-24f;
            const float jitterV = float((bits >> 16) & 0xFFFFFFu) * 0x1p-24f;
            u[k] = (float(column) + jitterU) * inverseColumns;
            v[k] = (float(rowStart) + jitterV * float(columns)) * inverseCount;
        }
        rowStart += columns;
    }
}

/// Shirley–Chiu concentric map of four points of [0,1]² onto the unit disc (keeps the strata
/// compact), lifted to the hemisphere around +z by Malley's method (pdf cos θ / π). The angle is
/// φ = π/4·(b/a) in the wedges where |a| > |b|, else π/2 − π/4·(a/b), so that only sin and cos
/// of x ∈ [−π/4, π/4] are needed (cos(π/2 − x) = sin x).
struct HemispherePoints {
    Float4 x, y, z; // z along the normal
};

HemispherePoints liftToHemisphere(Float4 u, Float4 v)
{
    const Float4 a = 2 * u - 1;
    const Float4 b = 2 * v - 1;
    const Mask4 alongA = abs(a) > abs(b);
    const Float4 radius = select(alongA, a, b);
    const Mask4 centre = radius == 0;
    // At the centre a = b = 0: the ratio is 0 (the division by 1 keeps the lane finite).
    const Float4 ratio = select(centre, 0.0f, select(alongA, b, a) / select(centre, 1.0f, radius));
    const Float4 angle = std::numbers::pi_v<float> / 4 * ratio;
    const Float4 sine = sinQuarterPi(angle), cosine = cosQuarterPi(angle);
    // The max keeps rounding (|radius| may round to just above 1) from producing a NaN.
    return {radius * select(alongA, cosine, sine), radius * select(alongA, sine, cosine),
            sqrt(max(0.0f, 1 - radius * radius))};
}

/// Orthonormal frame (tangent, bitangent, normal) from a unit normal: Duff et al., "Building an
/// Orthonormal Basis, Revisited", JCGT 6(1), 2017. Branchless, no singularity (copysign keeps
/// n.z = −0 on the right branch).
struct Frame {
    Vec3d tangent, bitangent, normal;
};

Frame tangentFrame(const Vec3d& n)
{
    const double sign = std::copysign(1.0, n.z);
    const double a = -1.0 / (sign + n.z);
    const double b = n.x * n.y * a;
    return {{1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x}, {b, sign + n.y * n.y * a, -n.y}, n};
}

Vec3d normalized(const Vec3& v)
{
    const Vec3d d{v.x, v.y, v.z};
    const double length = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
    assert(length > 0.5 && "mesh normals are validated to be unit length");
    return d * (1.0 / length);
}

/// The vertex frame in float, in world axes (for the rays) and in the segment's bind frame (for
/// the basis functions: the transfer is stored in the bind frame).
struct VertexFrames {
    Vec3 world[3];
    Vec3 local[3];
};

Vec3 toFloat(const Vec3d& v) { return {float(v.x), float(v.y), float(v.z)}; }

VertexFrames vertexFrames(const Vec3& normal, const anim::Quatd& bindRotation)
{
    const Frame frame = tangentFrame(normalized(normal));
    const anim::Quatd toBind = anim::conjugate(anim::normalize(bindRotation));
    VertexFrames frames;
    const Vec3d* axes[3] = {&frame.tangent, &frame.bitangent, &frame.normal};
    for (int i = 0; i < 3; ++i) {
        frames.world[i] = toFloat(*axes[i]);
        frames.local[i] = toFloat(anim::rotate(toBind, *axes[i]));
    }
    return frames;
}

/// Directions of a frame's hemisphere points in its axes, structure of arrays.
struct DirectionArrays {
    float* x;
    float* y;
    float* z;
};

struct FrameAxes {
    Float4 m[3][3]; // [axis][component], broadcast

    explicit FrameAxes(const Vec3 axes[3])
    {
        for (int i = 0; i < 3; ++i) {
            m[i][0] = axes[i].x;
            m[i][1] = axes[i].y;
            m[i][2] = axes[i].z;
        }
    }

    void store(const HemispherePoints& p, const DirectionArrays& out, int k) const
    {
        (p.x * m[0][0] + p.y * m[1][0] + p.z * m[2][0]).store(out.x + k);
        (p.x * m[0][1] + p.y * m[1][1] + p.z * m[2][1]).store(out.y + k);
        (p.x * m[0][2] + p.y * m[1][2] + p.z * m[2][2]).store(out.z + k);
    }
};

/// Rays rounded up to whole groups of four: the sampler fills the scratch four lanes at a time.
std::size_t paddedCount(int rays) { return (std::size_t(rays) + 3) / 4 * 4; }

/// A vertex's directions in world axes (for the rays) and in its segment's bind frame (for the
/// basis functions), computed from the same hemisphere points, four at a time. `u` and `v` are
/// scratch; every array holds paddedCount(rays) floats (the padding lanes hold the centre).
void sampleVertexDirections(int rays, std::uint64_t seed, std::uint32_t vertex, const VertexFrames& frames,
                            float* u, float* v, const DirectionArrays& world, const DirectionArrays& local)
{
    const std::size_t padded = paddedCount(rays);
    std::fill(u + rays, u + padded, 0.5f);
    std::fill(v + rays, v + padded, 0.5f);
    stratifiedPoints(rays, seed, vertex, u, v);
    const FrameAxes worldAxes(frames.world), localAxes(frames.local);
    for (std::size_t k = 0; k < padded; k += 4) {
        const HemispherePoints p = liftToHemisphere(Float4::load(u + k), Float4::load(v + k));
        worldAxes.store(p, world, int(k));
        localAxes.store(p, local, int(k));
    }
}

/// A run of vertices of one segment, the unit of work handed to a thread.
struct Chunk {
    std::uint32_t firstVertex = 0;
    std::uint32_t vertexCount = 0;
    float* output = nullptr;               ///< order² floats per vertex
    const OcclusionScene* scene = nullptr; ///< null for DU
    anim::Quatd bindRotation;
};

/// One worker's buffers, sized once: a batch of rays of one vertex, structure of arrays.
struct WorkerScratch {
    explicit WorkerScratch(int rays, int order)
        : u(paddedCount(rays)), v(paddedCount(rays)), originX(std::size_t(rays)), originY(std::size_t(rays)),
          originZ(std::size_t(rays)), directionX(paddedCount(rays)), directionY(paddedCount(rays)),
          directionZ(paddedCount(rays)), localX(paddedCount(rays)), localY(paddedCount(rays)), localZ(paddedCount(rays)),
          originVertex(std::size_t(rays)), occluded(std::size_t(rays), 0), sum(std::size_t(order) * order)
    {
    }
    std::vector<float> u, v;
    std::vector<float> originX, originY, originZ, directionX, directionY, directionZ;
    std::vector<float> localX, localY, localZ;
    std::vector<std::uint32_t> originVertex;
    std::vector<std::uint8_t> occluded;
    std::vector<float> sum;
};

void bakeVertex(const scene::CharacterMesh& mesh, const BakeSettings& settings, const Chunk& chunk,
                std::uint32_t vertex, WorkerScratch& scratch, float* transfer)
{
    const int rays = settings.raysPerVertex;
    sampleVertexDirections(rays, settings.seed, vertex, vertexFrames(mesh.normals[vertex], chunk.bindRotation),
                           scratch.u.data(), scratch.v.data(),
                           {scratch.directionX.data(), scratch.directionY.data(), scratch.directionZ.data()},
                           {scratch.localX.data(), scratch.localY.data(), scratch.localZ.data()});
    std::size_t visible = std::size_t(rays);
    if (chunk.scene) {
        const Vec3& origin = mesh.positions[vertex];
        std::fill_n(scratch.originX.begin(), rays, origin.x);
        std::fill_n(scratch.originY.begin(), rays, origin.y);
        std::fill_n(scratch.originZ.begin(), rays, origin.z);
        std::fill_n(scratch.originVertex.begin(), rays, vertex);
        RayBatch batch;
        batch.originX = scratch.originX.data();
        batch.originY = scratch.originY.data();
        batch.originZ = scratch.originZ.data();
        batch.directionX = scratch.directionX.data();
        batch.directionY = scratch.directionY.data();
        batch.directionZ = scratch.directionZ.data();
        batch.originVertex = scratch.originVertex.data();
        batch.count = std::size_t(rays);
        batch.tnear = settings.epsilon;
        chunk.scene->occluded(batch, std::span<std::uint8_t>(scratch.occluded.data(), std::size_t(rays)));
        // Keep the visible directions, in ray order, at the front (branch-free compaction).
        visible = 0;
        for (std::size_t k = 0; k < std::size_t(rays); ++k) {
            scratch.localX[visible] = scratch.localX[k];
            scratch.localY[visible] = scratch.localY[k];
            scratch.localZ[visible] = scratch.localZ[k];
            visible += scratch.occluded[k] == 0;
        }
    }
    // t_i = (1/N) Σ V·Y_i(ω): the visible directions' basis functions summed. Float sums: their
    // round-off (≲ N·2⁻²⁴, 6e-5 at N = 1024) is far below the Monte Carlo error (~1/√N).
    std::fill(scratch.sum.begin(), scratch.sum.end(), 0.0f);
    accumulateShSums(settings.order, std::span(scratch.localX).first(visible), std::span(scratch.localY).first(visible),
                     std::span(scratch.localZ).first(visible), scratch.sum);
    const float inverseRays = 1.0f / float(rays);
    for (std::size_t i = 0; i < scratch.sum.size(); ++i)
        transfer[i] = scratch.sum[i] * inverseRays;
}

void enableFlushToZero()
{
#if defined(__SSE__) || defined(__x86_64__)
    // Denormals make Embree's traversal and the SH sums slow, and every worker must use the same
    // mode for the results to be identical whatever thread ran a vertex.
    _MM_SET_FLUSH_ZERO_MODE(_MM_FLUSH_ZERO_ON);
    _MM_SET_DENORMALS_ZERO_MODE(_MM_DENORMALS_ZERO_ON);
#endif
}

/// Serialises progress reports, roughly every 1 % of the vertices, always increasing.
class ProgressReporter {
public:
    ProgressReporter(const BakeProgressCallback& callback, std::uint64_t total)
        : m_callback(callback), m_total(total), m_step(std::max<std::uint64_t>(1, (total + 99) / 100))
    {
    }

    void add(std::uint64_t vertices)
    {
        const std::uint64_t done = m_done.fetch_add(vertices, std::memory_order_relaxed) + vertices;
        if (!m_callback || done >= m_total || done < m_reported.load(std::memory_order_relaxed) + m_step)
            return; // the final report is made once, by finish()
        std::lock_guard lock(m_mutex);
        if (done < m_reported.load(std::memory_order_relaxed) + m_step)
            return;
        m_reported.store(done, std::memory_order_relaxed);
        m_callback(BakeProgress{done, m_total});
    }

    std::uint64_t done() const { return m_done.load(); }

    void finish()
    {
        if (m_callback) {
            std::lock_guard lock(m_mutex);
            m_callback(BakeProgress{m_total, m_total});
        }
    }

private:
    const BakeProgressCallback& m_callback;
    std::uint64_t m_total;
    std::uint64_t m_step;
    std::atomic<std::uint64_t> m_done{0};
    std::atomic<std::uint64_t> m_reported{0};
    std::mutex m_mutex;
};

bool isBaked(TransferKind transfer, scene::SegmentRole role)
{
    // Roles belong to DSM (paper §6.1.3); DU and DS bake every segment.
    return transfer != TransferKind::DiffuseShadowedMerged || role != scene::SegmentRole::Occluder;
}

double secondsSince(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

} // namespace

void sampleBakeDirections(int raysPerVertex, std::uint64_t seed, std::uint32_t vertex, const anim::Vec3& normal,
                          std::span<anim::Vec3> directions)
{
    assert(raysPerVertex >= 1 && directions.size() >= std::size_t(raysPerVertex));
    const std::size_t padded = paddedCount(raysPerVertex);
    std::vector<float> scratch(padded * 8); // u, v, world x, y, z, bind-frame x, y, z
    float* const u = scratch.data();
    const DirectionArrays world{u + 2 * padded, u + 3 * padded, u + 4 * padded};
    const DirectionArrays local{u + 5 * padded, u + 6 * padded, u + 7 * padded};
    sampleVertexDirections(raysPerVertex, seed, vertex, vertexFrames(normal, anim::Quatd::identity()), u, u + padded,
                           world, local);
    for (int k = 0; k < raysPerVertex; ++k)
        directions[std::size_t(k)] = {world.x[k], world.y[k], world.z[k]};
}

namespace {

std::string describeRange(const VertexRange& range)
{
    return "the vertex range " + std::to_string(range.firstVertex) + " + " + std::to_string(range.vertexCount);
}

/// The plan's segment holding the whole range, or InvalidArgument naming the range and why.
Result<std::size_t> segmentOfRange(const TransferBake& plan, const VertexRange& range)
{
    for (std::size_t s = 0; s < plan.segments.size(); ++s) {
        const BakedSegment& segment = plan.segments[s];
        if (range.firstVertex < segment.firstVertex || range.firstVertex - segment.firstVertex >= segment.vertexCount)
            continue;
        const std::string where = " (segment \"" + segment.name + "\" holds vertices "
                                  + std::to_string(segment.firstVertex) + " to "
                                  + std::to_string(std::uint64_t(segment.firstVertex) + segment.vertexCount - 1) + ")";
        if (!segment.baked)
            return makeError(ErrorCode::InvalidArgument,
                             "Cannot bake " + describeRange(range) + ": its segment is an occluder, which is not baked" + where + ".");
        if (range.vertexCount == 0
            || std::uint64_t(range.firstVertex) + range.vertexCount > std::uint64_t(segment.firstVertex) + segment.vertexCount)
            return makeError(ErrorCode::InvalidArgument,
                             "Cannot bake " + describeRange(range) + ": a range must be non-empty and inside one segment" + where + ".");
        return s;
    }
    return makeError(ErrorCode::InvalidArgument, "Cannot bake " + describeRange(range) + ": no segment holds vertex "
                                                     + std::to_string(range.firstVertex) + " (the mesh has "
                                                     + std::to_string(plan.vertexCount) + " vertices).");
}

/// A range and where its floats go.
struct Piece {
    VertexRange range;
    float* output = nullptr;
};

/// The one path every bake takes: builds the occlusion scenes, cuts the pieces into chunks and
/// bakes them on settings.threads workers. `plan` is the mesh's planTransferBake.
Result<void> bakePieces(const scene::CharacterMesh& mesh, const BakeSettings& settings, const TransferBake& plan,
                        std::span<const Piece> pieces, std::stop_token stop, const BakeProgressCallback& progress,
                        BakeStatistics* statistics, std::chrono::steady_clock::time_point started)
{
    std::vector<std::size_t> segmentOfPiece;
    std::uint64_t vertices = 0;
    for (const Piece& piece : pieces) {
        Result<std::size_t> segment = segmentOfRange(plan, piece.range);
        if (!segment)
            return segment.error();
        segmentOfPiece.push_back(*segment);
        vertices += piece.range.vertexCount;
    }

    // Occlusion scenes: DS one per segment (its own triangles), DSM one for M′ (every segment
    // but the receivers), DU none.
    const auto sceneStarted = std::chrono::steady_clock::now();
    std::vector<std::unique_ptr<OcclusionScene>> scenes;
    auto build = [&](std::span<const std::uint32_t> indices) -> Result<void> {
        Result<std::unique_ptr<OcclusionScene>> scene =
            buildOcclusionScene(settings.backend, ProxyMeshView{mesh.positions, indices});
        if (!scene)
            return scene.error();
        scenes.push_back(std::move(scene.value()));
        return {};
    };
    if (settings.transfer == TransferKind::DiffuseShadowed) {
        for (const scene::Segment& segment : mesh.segments)
            if (Result<void> built = build(std::span(mesh.indices).subspan(std::size_t(segment.firstTriangle) * 3,
                                                                         std::size_t(segment.triangleCount) * 3));
                !built)
                return built.error();
    } else if (settings.transfer == TransferKind::DiffuseShadowedMerged) {
        std::vector<std::uint32_t> proxy;
        for (const scene::Segment& segment : mesh.segments)
            if (segment.role != scene::SegmentRole::Receiver)
                proxy.insert(proxy.end(), mesh.indices.begin() + std::ptrdiff_t(segment.firstTriangle) * 3,
                             mesh.indices.begin() + std::ptrdiff_t(segment.firstTriangle + segment.triangleCount) * 3);
        if (Result<void> built = build(proxy); !built)
            return built.error();
    }
    const double sceneSeconds = secondsSince(sceneStarted);

    // Work: runs of at most ~0.5 % of the vertices (and at most 64) within one segment, so threads
    // balance, progress comes about every 1 % and a cancel is seen quickly.
    const std::size_t perVertex = std::size_t(settings.order) * settings.order;
    const std::uint32_t chunkSize = std::uint32_t(std::clamp<std::uint64_t>(vertices / 200, 1, 64));
    std::vector<Chunk> chunks;
    for (std::size_t p = 0; p < pieces.size(); ++p) {
        const Piece& piece = pieces[p];
        const std::size_t s = segmentOfPiece[p];
        const OcclusionScene* scene = settings.transfer == TransferKind::DiffuseShadowed          ? scenes[s].get()
                                      : settings.transfer == TransferKind::DiffuseShadowedMerged ? scenes[0].get()
                                                                                                  : nullptr;
        for (std::uint32_t first = 0; first < piece.range.vertexCount; first += chunkSize) {
            const std::uint32_t count = std::min(chunkSize, piece.range.vertexCount - first);
            chunks.push_back({piece.range.firstVertex + first, count, piece.output + std::size_t(first) * perVertex,
                              scene, mesh.segments[s].bindRotation});
        }
    }

    ProgressReporter reporter(progress, vertices);
    std::atomic<std::size_t> nextChunk{0};
    auto work = [&] {
        enableFlushToZero();
        WorkerScratch scratch(settings.raysPerVertex, settings.order);
        for (;;) {
            if (stop.stop_requested())
                return;
            const std::size_t c = nextChunk.fetch_add(1, std::memory_order_relaxed);
            if (c >= chunks.size())
                return;
            const Chunk& chunk = chunks[c];
            for (std::uint32_t v = 0; v < chunk.vertexCount; ++v)
                bakeVertex(mesh, settings, chunk, chunk.firstVertex + v, scratch, chunk.output + std::size_t(v) * perVertex);
            reporter.add(chunk.vertexCount);
        }
    };
    const unsigned hardwareThreads = std::max(1u, std::thread::hardware_concurrency());
    const std::size_t threadCount = std::clamp<std::size_t>(
        settings.threads > 0 ? std::size_t(settings.threads) : hardwareThreads, 1, std::max<std::size_t>(1, chunks.size()));
    {
        std::vector<std::jthread> workers;
        for (std::size_t t = 0; t < threadCount; ++t)
            workers.emplace_back(work);
    } // joined here

    if (reporter.done() != vertices)
        return makeError(ErrorCode::Cancelled, "The lighting bake was cancelled.",
                         std::to_string(reporter.done()) + " of " + std::to_string(vertices) + " vertices baked");
    reporter.finish();
    if (statistics) {
        statistics->vertices = vertices;
        statistics->rays = vertices * std::uint64_t(settings.raysPerVertex);
        statistics->seconds = secondsSince(started);
        statistics->sceneSeconds = sceneSeconds;
    }
    return {};
}

} // namespace

Result<TransferBake> planTransferBake(const scene::CharacterMesh& mesh, const BakeSettings& settings)
{
    if (Result<void> valid = validateBakeSettings(settings); !valid)
        return valid.error();
    if (Result<void> valid = mesh.validate(); !valid)
        return valid.error();

    TransferBake bake;
    bake.order = settings.order;
    bake.transferKind = settings.transfer;
    bake.raysPerVertex = settings.raysPerVertex;
    bake.epsilon = settings.epsilon;
    bake.seed = settings.seed;
    bake.vertexCount = mesh.vertexCount();
    bake.geometryHash = meshGeometryHash(mesh);
    const std::size_t perVertex = std::size_t(settings.order) * settings.order;
    std::uint64_t bakedVertices = 0;
    for (const scene::Segment& segment : mesh.segments) {
        BakedSegment baked;
        baked.name = segment.name;
        baked.firstVertex = segment.firstVertex;
        baked.vertexCount = segment.vertexCount;
        baked.role = segment.role;
        baked.baked = isBaked(settings.transfer, segment.role);
        if (baked.baked) {
            baked.transferOffset = bakedVertices * perVertex;
            bakedVertices += segment.vertexCount;
        }
        bake.segments.push_back(std::move(baked));
    }
    bake.transfer.assign(bakedVertices * perVertex, 0.0f);
    return bake;
}

std::vector<VertexRange> splitTransferBake(const TransferBake& plan, std::uint32_t maxVertices)
{
    assert(maxVertices >= 1);
    maxVertices = std::max<std::uint32_t>(maxVertices, 1);
    std::vector<VertexRange> ranges;
    for (const BakedSegment& segment : plan.segments)
        if (segment.baked)
            for (std::uint32_t first = 0; first < segment.vertexCount; first += maxVertices)
                ranges.push_back({segment.firstVertex + first, std::min(maxVertices, segment.vertexCount - first)});
    return ranges;
}

Result<TransferBake> bakeTransfer(const scene::CharacterMesh& mesh, const BakeSettings& settings,
                                  std::stop_token stop, const BakeProgressCallback& progress,
                                  BakeStatistics* statistics)
{
    const auto started = std::chrono::steady_clock::now();
    Result<TransferBake> bake = planTransferBake(mesh, settings);
    if (!bake)
        return bake.error();
    // Whole segments, in transfer order: their floats follow one another in bake->transfer.
    const std::size_t perVertex = std::size_t(settings.order) * settings.order;
    std::vector<Piece> pieces;
    std::size_t offset = 0;
    for (const VertexRange& range : splitTransferBake(*bake, std::numeric_limits<std::uint32_t>::max())) {
        pieces.push_back({range, bake->transfer.data() + offset});
        offset += std::size_t(range.vertexCount) * perVertex;
    }
    if (Result<void> baked = bakePieces(mesh, settings, *bake, pieces, stop, progress, statistics, started); !baked)
        return baked.error();
    return bake;
}

Result<std::vector<float>> bakeTransferRanges(const scene::CharacterMesh& mesh, const BakeSettings& settings,
                                              std::span<const VertexRange> ranges, std::stop_token stop,
                                              const BakeProgressCallback& progress, BakeStatistics* statistics)
{
    const auto started = std::chrono::steady_clock::now();
    Result<TransferBake> plan = planTransferBake(mesh, settings);
    if (!plan)
        return plan.error();
    const std::size_t perVertex = std::size_t(settings.order) * settings.order;
    std::uint64_t vertices = 0;
    for (const VertexRange& range : ranges)
        vertices += range.vertexCount;
    std::vector<float> transfer(vertices * perVertex);
    std::vector<Piece> pieces;
    std::size_t offset = 0;
    for (const VertexRange& range : ranges) {
        pieces.push_back({range, transfer.data() + offset});
        offset += std::size_t(range.vertexCount) * perVertex;
    }
    if (Result<void> baked = bakePieces(mesh, settings, *plan, pieces, stop, progress, statistics, started); !baked)
        return baked.error();
    return transfer;
}

Result<void> placeTransferRange(TransferBake& plan, const VertexRange& range, std::span<const float> transfer)
{
    Result<std::size_t> s = segmentOfRange(plan, range);
    if (!s)
        return s.error();
    const BakedSegment& segment = plan.segments[*s];
    const std::size_t perVertex = std::size_t(plan.order) * plan.order;
    if (transfer.size() != std::size_t(range.vertexCount) * perVertex)
        return makeError(ErrorCode::InvalidArgument,
                         "Cannot place " + describeRange(range) + ": it needs " + std::to_string(range.vertexCount)
                             + " × " + std::to_string(perVertex) + " floats, not " + std::to_string(transfer.size()) + ".");
    std::copy(transfer.begin(), transfer.end(),
              plan.transfer.begin() + std::ptrdiff_t(segment.transferOffset
                                                     + std::size_t(range.firstVertex - segment.firstVertex) * perVertex));
    return {};
}

std::array<double, 3> shadeVertex(const TransferBake& bake, [[maybe_unused]] const scene::CharacterMesh& mesh,
                                  std::uint32_t vertex, const ShRgb& light, const anim::Quatd& segmentRotation)
{
    // The bake carries the vertex ranges; the mesh is the caller's promise that they match.
    assert(bake.vertexCount == mesh.vertexCount() && vertex < mesh.vertexCount());
    const std::span<const float> transfer = bake.vertexTransfer(vertex);
    if (transfer.empty())
        return {0, 0, 0};
    const int order = std::min(bake.order, light.order);
    assert(order >= 1);
    // Bands do not mix under rotation, so the first order² coefficients rotate on their own.
    const ShRotation toSegment(order, anim::conjugate(anim::normalize(segmentRotation)));
    const std::size_t count = std::size_t(order) * order;
    std::array<double, kMaxShCoefficients> rotated{};
    std::array<double, 3> radiance{};
    for (int c = 0; c < 3; ++c) {
        toSegment.apply(light[c].first(count), std::span(rotated).first(count));
        double sum = 0;
        for (std::size_t i = 0; i < count; ++i)
            sum += double(transfer[i]) * rotated[i];
        radiance[c] = sum;
    }
    return radiance;
}

} // namespace thespis::core::lighting
