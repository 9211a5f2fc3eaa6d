#include "scene/skinning.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cassert>
#include <cmath>
#include <condition_variable>
#include <cstring>
#include <mutex>
#include <utility>

namespace thespis::core::scene {

namespace {

using anim::Quat;

// Four floats in one SIMD register (SSE on x86-64, NEON on ARM) through the GCC/Clang vector
// extension: portable, and the build needs no -march flag for it.
using Float4 = float __attribute__((vector_size(16)));

Float4 load(const float* p)
{
    Float4 v;
    std::memcpy(&v, p, sizeof v);
    return v;
}
Float4 load(const Quat& q)
{
    static_assert(sizeof(Quat) == sizeof(Float4));
    Float4 v;
    std::memcpy(&v, &q, sizeof v);
    return v;
}
void store(Vec3& out, Float4 v) { out = {v[0], v[1], v[2]}; }
float dot3(Float4 a, Float4 b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/// A 3×4 matrix by columns: x, y, z axes and translation.
struct Columns {
    Float4 x, y, z, t;
    Float4 point(Vec3 p) const { return x * p.x + y * p.y + z * p.z + t; }
    Float4 direction(Vec3 d) const { return x * d.x + y * d.y + z * d.z; }
};

Columns rigidColumns(const RigidTransform& joint)
{
    const auto column = [&](Vec3 v) { return Float4{v.x, v.y, v.z, 0}; };
    return {column(rotate(joint.rotation, Vec3{1, 0, 0})), column(rotate(joint.rotation, Vec3{0, 1, 0})),
            column(rotate(joint.rotation, Vec3{0, 0, 1})), column(joint.translation)};
}

SkinningPalette::DualQuaternion dualQuaternion(const RigidTransform& joint)
{
    const Quat& q = joint.rotation;
    const Quat dual = Quat{joint.translation.x, joint.translation.y, joint.translation.z, 0} * q;
    return {q, {0.5f * dual.x, 0.5f * dual.y, 0.5f * dual.z, 0.5f * dual.w}};
}

template <int Influences>
Columns blendMatrices(const SkinningPalette::Matrix* matrices, const std::uint16_t* joints, const float* weights)
{
    const auto column = [&](int i, int c) { return load(matrices[joints[i]].columns[c]) * weights[i]; };
    Columns sum{column(0, 0), column(0, 1), column(0, 2), column(0, 3)};
    for (int i = 1; i < Influences; ++i) {
        sum.x += column(i, 0);
        sum.y += column(i, 1);
        sum.z += column(i, 2);
        sum.t += column(i, 3);
    }
    return sum;
}

template <int Influences>
void skinLinear(const Skin& skin, const Vec3* restPositions, const Vec3* restNormals, const SkinningPalette& palette,
                std::size_t begin, std::size_t end, Vec3* outPositions, Vec3* outNormals)
{
    for (std::size_t v = begin; v < end; ++v) {
        const std::uint16_t* joints = skin.joints.data() + v * Influences;
        const float* weights = skin.weights.data() + v * Influences;
        const Columns m = blendMatrices<Influences>(palette.matrices.data(), joints, weights);
        // m blends the joints' displacements (see SkinningPalette). Dividing by the weights' sum,
        // which is 1 only within 1e-3 (Skin::validate), keeps the mesh from scaling. A blend of
        // rotations is no rotation, so the normal needs normalising.
        float weightSum = weights[0];
        for (int i = 1; i < Influences; ++i)
            weightSum += weights[i];
        const Vec3 p = restPositions[v], n = restNormals[v];
        const Float4 normal = Float4{n.x, n.y, n.z, 0} * weightSum + m.direction(n);
        store(outPositions[v], Float4{p.x, p.y, p.z, 0} + m.point(p) * (1.0f / weightSum));
        store(outNormals[v], normal * (1.0f / std::sqrt(dot3(normal, normal))));
    }
}

// LBS above is four wide within a vertex (one matrix column per register). DQS runs on blocks of
// four vertices, one per SIMD lane, so that its long chain of arithmetic (blend, normalise,
// rotate) runs four wide with no horizontal operations.

template <int... Lanes>
Float4 shuffle(Float4 a, Float4 b) { return __builtin_shufflevector(a, b, Lanes...); }

/// Four 3-vectors, lane k holding the k-th.
struct Vec3x4 {
    Float4 x, y, z;
    friend Vec3x4 operator+(const Vec3x4& a, const Vec3x4& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
    friend Vec3x4 operator-(const Vec3x4& a, const Vec3x4& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
    friend Vec3x4 operator*(const Vec3x4& a, Float4 s) { return {a.x * s, a.y * s, a.z * s}; }
    friend Vec3x4 cross(const Vec3x4& a, const Vec3x4& b)
    {
        return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
    }
};

/// Four quaternions, lane k holding the k-th.
struct Quatx4 {
    Float4 x, y, z, w;
    Vec3x4 vector() const { return {x, y, z}; }
    friend Float4 dot(const Quatx4& a, const Quatx4& b) { return a.x * b.x + a.y * b.y + a.z * b.z + a.w * b.w; }
    void addScaled(const Quatx4& q, Float4 s)
    {
        x += q.x * s;
        y += q.y * s;
        z += q.z * s;
        w += q.w * s;
    }
};

Quatx4 transposed(const Quat& q0, const Quat& q1, const Quat& q2, const Quat& q3)
{
    const Float4 a = load(q0), b = load(q1), c = load(q2), d = load(q3);
    const Float4 ab01 = shuffle<0, 4, 1, 5>(a, b), ab23 = shuffle<2, 6, 3, 7>(a, b);
    const Float4 cd01 = shuffle<0, 4, 1, 5>(c, d), cd23 = shuffle<2, 6, 3, 7>(c, d);
    return {shuffle<0, 1, 4, 5>(ab01, cd01), shuffle<2, 3, 6, 7>(ab01, cd01), shuffle<0, 1, 4, 5>(ab23, cd23),
            shuffle<2, 3, 6, 7>(ab23, cd23)};
}

/// Four consecutive Vec3 (12 floats: x0 y0 z0 x1 | y1 z1 x2 y2 | z2 x3 y3 z3) into lanes, and back.
Vec3x4 loadVec3x4(const Vec3* v)
{
    const auto* bytes = reinterpret_cast<const char*>(v);
    Float4 a, b, c;
    std::memcpy(&a, bytes, 16);
    std::memcpy(&b, bytes + 16, 16);
    std::memcpy(&c, bytes + 32, 16);
    return {shuffle<0, 1, 2, 5>(shuffle<0, 3, 6, 7>(a, b), c), shuffle<0, 1, 2, 6>(shuffle<1, 4, 7, 7>(a, b), c),
            shuffle<0, 1, 4, 7>(shuffle<2, 5, 5, 5>(a, b), c)};
}

void storeVec3x4(Vec3* out, const Vec3x4& v)
{
    const Float4 a = shuffle<0, 1, 4, 2>(shuffle<0, 4, 1, 1>(v.x, v.y), v.z);
    const Float4 b = shuffle<0, 5, 1, 2>(shuffle<1, 6, 2, 2>(v.y, v.x), v.z);
    const Float4 c = shuffle<6, 0, 1, 7>(shuffle<3, 7, 3, 3>(v.x, v.y), v.z);
    auto* bytes = reinterpret_cast<char*>(out);
    std::memcpy(bytes, &a, 16);
    std::memcpy(bytes + 16, &b, 16);
    std::memcpy(bytes + 32, &c, 16);
}

/// weight with the sign of `sign` (weights are ≥ 0): branchless.
Float4 withSignOf(Float4 weight, Float4 sign)
{
    using Int4 = std::int32_t __attribute__((vector_size(16)));
    return Float4(Int4(weight) | (Int4(sign) & Int4{INT32_MIN, INT32_MIN, INT32_MIN, INT32_MIN}));
}

/// Skins 4 vertices whose joints, weights, positions and normals start at the given pointers.
template <int Influences>
void skinDualQuaternionBlock(const SkinningPalette::DualQuaternion* palette, const std::uint16_t* joints,
                             const float* weights, const Vec3* restPositions, const Vec3* restNormals,
                             Vec3* outPositions, Vec3* outNormals)
{
    const auto influence = [&](int vertex, int i) -> const SkinningPalette::DualQuaternion& {
        return palette[joints[vertex * Influences + i]];
    };
    // Kavan et al. 2008: q and −q are the same rotation, so every influence is taken in the
    // hemisphere of the vertex's dominant one before blending; otherwise the blend can pass
    // through zero.
    int dominant[4] = {};
    for (int vertex = 0; vertex < 4; ++vertex) {
        const float* vertexWeights = weights + vertex * Influences;
        for (int i = 1; i < Influences; ++i)
            dominant[vertex] = vertexWeights[i] > vertexWeights[dominant[vertex]] ? i : dominant[vertex];
    }
    const Quatx4 pivot = transposed(influence(0, dominant[0]).real, influence(1, dominant[1]).real,
                                    influence(2, dominant[2]).real, influence(3, dominant[3]).real);
    Quatx4 real{}, dual{};
    for (int i = 0; i < Influences; ++i) {
        const auto part = [&](Quat SkinningPalette::DualQuaternion::*member) {
            return transposed(influence(0, i).*member, influence(1, i).*member, influence(2, i).*member,
                              influence(3, i).*member);
        };
        const Quatx4 r = part(&SkinningPalette::DualQuaternion::real);
        const Float4 weight{weights[i], weights[Influences + i], weights[2 * Influences + i],
                            weights[3 * Influences + i]};
        const Float4 w = withSignOf(weight, dot(r, pivot));
        real.addScaled(r, w);
        dual.addScaled(part(&SkinningPalette::DualQuaternion::dual), w);
    }
    // The blend is not normalised; with s = 2/|real|², v turns to v + s·(w·(u × v) + u × (u × v))
    // (u, w: the vector and scalar parts of real) and moves by s·(w·dual_u − dual_w·u + u × dual_u).
    const Float4 s = 2.0f / dot(real, real);
    const Vec3x4 u = real.vector();
    const auto turn = [&](const Vec3x4& v) {
        const Vec3x4 uv = cross(u, v);
        return v + (uv * real.w + cross(u, uv)) * s;
    };
    const Vec3x4 translation = (dual.vector() * real.w - u * dual.w + cross(u, dual.vector())) * s;
    storeVec3x4(outPositions, turn(loadVec3x4(restPositions)) + translation);
    storeVec3x4(outNormals, turn(loadVec3x4(restNormals)));
}

template <int Influences>
void skinDualQuaternions(const Skin& skin, const Vec3* restPositions, const Vec3* restNormals,
                         const SkinningPalette& palette, std::size_t begin, std::size_t end, Vec3* outPositions,
                         Vec3* outNormals)
{
    const auto* dqs = palette.dualQuaternions.data();
    std::size_t v = begin;
    for (; v + 4 <= end; v += 4)
        skinDualQuaternionBlock<Influences>(dqs, skin.joints.data() + v * Influences,
                                            skin.weights.data() + v * Influences, restPositions + v,
                                            restNormals + v, outPositions + v, outNormals + v);
    if (v == end)
        return;
    // The last 1 to 3 vertices, padded with copies of the last one: lanes are independent, so
    // every vertex gets the same bits whichever block and lane it lands in.
    std::uint16_t joints[4 * Influences];
    float weights[4 * Influences];
    Vec3 positions[4], normals[4], skinnedPositions[4], skinnedNormals[4];
    for (std::size_t lane = 0; lane < 4; ++lane) {
        const std::size_t source = std::min(v + lane, end - 1);
        std::copy_n(skin.joints.data() + source * Influences, Influences, joints + lane * Influences);
        std::copy_n(skin.weights.data() + source * Influences, Influences, weights + lane * Influences);
        positions[lane] = restPositions[source];
        normals[lane] = restNormals[source];
    }
    skinDualQuaternionBlock<Influences>(dqs, joints, weights, positions, normals, skinnedPositions, skinnedNormals);
    std::copy_n(skinnedPositions, end - v, outPositions + v);
    std::copy_n(skinnedNormals, end - v, outNormals + v);
}

template <int Influences>
void skinRange(SkinningMethod method, const Skin& skin, const Vec3* restPositions, const Vec3* restNormals,
               const SkinningPalette& palette, std::size_t begin, std::size_t end, Vec3* outPositions,
               Vec3* outNormals)
{
    if (method == SkinningMethod::Linear)
        skinLinear<Influences>(skin, restPositions, restNormals, palette, begin, end, outPositions, outNormals);
    else
        skinDualQuaternions<Influences>(skin, restPositions, restNormals, palette, begin, end, outPositions,
                                        outNormals);
}

/// skinRange<1> … skinRange<kMaxInfluences>: one loop per influence count, so that the inner
/// loops unroll completely.
template <std::size_t... Index>
constexpr auto skinRangeTable(std::index_sequence<Index...>)
{
    return std::array{&skinRange<int(Index) + 1>...};
}
constexpr auto kSkinRange = skinRangeTable(std::make_index_sequence<kMaxInfluences>());

} // namespace

const char* skinningMethodName(SkinningMethod method)
{
    return method == SkinningMethod::Linear ? "lbs" : "dqs";
}

Result<SkinningMethod> parseSkinningMethod(std::string_view name)
{
    for (SkinningMethod method : {SkinningMethod::Linear, SkinningMethod::DualQuaternion})
        if (name == skinningMethodName(method))
            return method;
    return makeError(ErrorCode::InvalidArgument, "Unknown skinning method \"" + std::string(name) +
                                                     "\": use lbs (linear blend) or dqs (dual quaternion).");
}

void computeSkinningTransforms(const anim::Skeleton& skeleton, std::span<const float> frame,
                               std::span<const Vec3d> restPositions, std::span<Vec3d> scratchPositions,
                               std::span<Quatd> scratchOrientations, std::span<RigidTransform> out)
{
    const auto joints = std::size_t(skeleton.jointCount());
    assert(restPositions.size() == joints && scratchPositions.size() == joints &&
           scratchOrientations.size() == joints && out.size() == joints);
    skeleton.worldTransforms(frame, scratchPositions, scratchOrientations);
    for (std::size_t j = 0; j < joints; ++j) {
        const Quatd& q = scratchOrientations[j];
        const Vec3d t = scratchPositions[j] - rotate(q, restPositions[j]);
        out[j] = {{float(q.x), float(q.y), float(q.z), float(q.w)}, {float(t.x), float(t.y), float(t.z)}};
    }
}

void SkinningPalette::update(std::span<const RigidTransform> joints)
{
    matrices.resize(joints.size());
    dualQuaternions.resize(joints.size());
    for (std::size_t j = 0; j < joints.size(); ++j) {
        Columns m = rigidColumns(joints[j]);
        m.x[0] -= 1; // the displacement R − I
        m.y[1] -= 1;
        m.z[2] -= 1;
        static_assert(sizeof m == sizeof matrices[j]);
        std::memcpy(&matrices[j], &m, sizeof m);
        dualQuaternions[j] = dualQuaternion(joints[j]);
    }
}

void skinVertices(const Skin& skin, std::span<const Vec3> restPositions, std::span<const Vec3> restNormals,
                  const SkinningPalette& palette, SkinningMethod method, std::size_t begin, std::size_t end,
                  std::span<Vec3> outPositions, std::span<Vec3> outNormals)
{
    assert(begin <= end && end <= restPositions.size() && restNormals.size() == restPositions.size());
    assert(outPositions.size() == restPositions.size() && outNormals.size() == restPositions.size());
    assert(skin.weights.size() == restPositions.size() * std::size_t(skin.influences));
    assert(skin.influences >= 1 && skin.influences <= kMaxInfluences && palette.jointCount() > 0);
    kSkinRange[std::size_t(skin.influences - 1)](method, skin, restPositions.data(), restNormals.data(), palette,
                                                 begin, end, outPositions.data(), outNormals.data());
}

void skinRigidSegments(const Character& character, std::span<const RigidTransform> joints,
                       std::span<Vec3> outPositions, std::span<Vec3> outNormals,
                       std::span<const Vec3> restPositions, std::span<const Vec3> restNormals)
{
    const CharacterMesh& mesh = character.mesh;
    if (restPositions.empty())
        restPositions = mesh.positions, restNormals = mesh.normals;
    assert(outPositions.size() == mesh.vertexCount() && outNormals.size() == mesh.vertexCount());
    for (std::size_t s = 0; s < mesh.segments.size(); ++s) {
        const Columns m = rigidColumns(joints[std::size_t(character.segmentJoint(s))]);
        const Segment& segment = mesh.segments[s];
        for (std::size_t v = segment.firstVertex; v < segment.firstVertex + segment.vertexCount; ++v) {
            store(outPositions[v], m.point(restPositions[v]));
            store(outNormals[v], m.direction(restNormals[v]));
        }
    }
}

// The caller publishes a job under the mutex and wakes the workers; everyone takes chunks from
// an atomic counter; the caller returns once every worker has left the job, so the job's fields
// never change under a worker's feet.
struct SkinningWorkers::Shared {
    std::mutex mutex;
    std::condition_variable wake;     ///< workers: a new job, or stop
    std::condition_variable finished; ///< caller: the last worker left the job
    std::uint64_t job = 0;            ///< bumped for every job
    bool stopping = false;
    int busyWorkers = 0;

    // The job, written by the caller before it is published.
    SkinningPalette palette;
    const Character* character = nullptr;
    std::span<const Vec3> restPositions, restNormals;
    SkinningMethod method = SkinningMethod::Linear;
    std::span<Vec3> outPositions, outNormals;
    std::size_t chunkSize = 0;
    std::size_t chunkCount = 0;
    std::atomic<std::size_t> nextChunk{0};

    void runChunks()
    {
        const std::size_t vertices = character->mesh.vertexCount();
        for (std::size_t c = nextChunk.fetch_add(1); c < chunkCount; c = nextChunk.fetch_add(1))
            skinVertices(character->skin, restPositions, restNormals, palette, method, c * chunkSize,
                         std::min(vertices, (c + 1) * chunkSize), outPositions, outNormals);
    }

    void work()
    {
        std::uint64_t seen = 0;
        for (;;) {
            {
                std::unique_lock lock(mutex);
                wake.wait(lock, [&] { return stopping || job != seen; });
                if (stopping)
                    return;
                seen = job;
            }
            runChunks();
            std::lock_guard lock(mutex);
            if (--busyWorkers == 0)
                finished.notify_one();
        }
    }
};

SkinningWorkers::SkinningWorkers(int threads) : m_shared(std::make_unique<Shared>())
{
    if (threads <= 0)
        threads = std::max(1, int(std::thread::hardware_concurrency()));
    for (int i = 1; i < threads; ++i)
        m_threads.emplace_back([shared = m_shared.get()] { shared->work(); });
}

SkinningWorkers::~SkinningWorkers()
{
    {
        std::lock_guard lock(m_shared->mutex);
        m_shared->stopping = true;
    }
    m_shared->wake.notify_all();
    for (std::thread& thread : m_threads)
        thread.join();
}

int SkinningWorkers::threadCount() const
{
    return int(m_threads.size()) + 1;
}

void SkinningWorkers::skin(const Character& character, std::span<const RigidTransform> joints,
                           SkinningMethod method, std::span<Vec3> outPositions, std::span<Vec3> outNormals,
                           std::span<const Vec3> restPositions, std::span<const Vec3> restNormals)
{
    if (restPositions.empty())
        restPositions = character.mesh.positions, restNormals = character.mesh.normals;
    if (character.skin.empty())
        return skinRigidSegments(character, joints, outPositions, outNormals, restPositions, restNormals);
    Shared& shared = *m_shared;
    shared.palette.update(joints);
    // A few chunks per thread even out uneven progress; small chunks would cost more than they save.
    const std::size_t vertices = character.mesh.vertexCount();
    const std::size_t chunkSize = std::max<std::size_t>(1024, vertices / (4 * m_threads.size() + 4) + 1);
    if (m_threads.empty() || vertices <= chunkSize)
        return skinVertices(character.skin, restPositions, restNormals, shared.palette, method, 0, vertices,
                            outPositions, outNormals);
    {
        std::lock_guard lock(shared.mutex);
        shared.character = &character;
        shared.restPositions = restPositions;
        shared.restNormals = restNormals;
        shared.method = method;
        shared.outPositions = outPositions;
        shared.outNormals = outNormals;
        shared.chunkSize = chunkSize;
        shared.chunkCount = (vertices + chunkSize - 1) / chunkSize;
        shared.nextChunk = 0;
        shared.busyWorkers = int(m_threads.size());
        ++shared.job;
    }
    shared.wake.notify_all();
    shared.runChunks();
    std::unique_lock lock(shared.mutex);
    shared.finished.wait(lock, [&] { return shared.busyWorkers == 0; });
}

} // namespace thespis::core::scene
