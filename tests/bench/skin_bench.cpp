// Skinning benchmarks (issue 4 goal: ≤ 1 ms for 30k vertices on one core).
//
// SkinLBS/<vertices>, SkinDQS/<vertices>: one frame of a synthetic character on the calling
//   thread (skinVertices directly): a tube over a chain of 25 joints, 30 vertices per ring, each
//   vertex weighted to the 2–4 nearest bones in 4 influence slots, random joint rotations.
//   Each iteration builds the frame's palette and skins positions and normals.
// SkinLBS/<vertices>/threads:<n>, SkinDQS/…: the same through SkinningWorkers (real time).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "allocation_counter.h"
#include "scene/skinning.h"

using namespace thespis::core;
using namespace thespis::core::scene;

namespace {

constexpr int kJoints = 25;
constexpr int kAround = 30;
constexpr float kBone = 0.1f;

Character chainCharacter(int vertices)
{
    std::vector<anim::Joint> chain;
    for (int j = 0; j < kJoints; ++j) {
        std::string name = "j"; // not "j" + std::to_string(j): g++ 12 -O3 warns there (-Wrestrict, PR 105329)
        name += std::to_string(j);
        chain.push_back({.name = name, .parent = j - 1, .offset = {0, j == 0 ? 0 : kBone, 0}});
    }
    Character character;
    character.skeleton = std::move(anim::Skeleton::create(std::move(chain))).value();
    const int rings = vertices / kAround;
    const float height = kBone * kJoints;
    character.skin.influences = 4;
    for (int r = 0; r < rings; ++r) {
        const float y = height * (float(r) + 0.5f) / float(rings);
        for (int a = 0; a < kAround; ++a) {
            const float phi = 6.2831853f * float(a) / kAround;
            character.mesh.positions.push_back({0.05f * std::cos(phi), y, 0.05f * std::sin(phi)});
            character.mesh.normals.push_back({std::cos(phi), 0, std::sin(phi)});
            // Bone b pulls with (1 − |y − middle of b| / 1.6 bones)²: 2 to 4 bones at each height.
            std::vector<std::pair<float, int>> pulls;
            for (int b = 0; b < kJoints; ++b) {
                const float d = std::abs(y - (float(b) + 0.5f) * kBone) / (1.6f * kBone);
                pulls.push_back({d < 1 ? (1 - d) * (1 - d) : 0.0f, b});
            }
            std::partial_sort(pulls.begin(), pulls.begin() + 4, pulls.end(), std::greater<>());
            const float sum = pulls[0].first + pulls[1].first + pulls[2].first + pulls[3].first;
            for (int i = 0; i < 4; ++i) {
                character.skin.joints.push_back(std::uint16_t(pulls[std::size_t(i)].second));
                character.skin.weights.push_back(pulls[std::size_t(i)].first / sum);
            }
        }
    }
    return character;
}

std::vector<RigidTransform> randomPose(const anim::Skeleton& skeleton)
{
    std::mt19937 rng(1);
    std::normal_distribution<float> gaussian;
    std::vector<float> frame = skeleton.restFrame();
    for (int j = 0; j < skeleton.jointCount(); ++j)
        anim::rotationAt(std::span<float>(frame), j) =
            normalize(anim::Quat{0.3f * gaussian(rng), 0.3f * gaussian(rng), 0.3f * gaussian(rng), 1.0f});
    const auto n = std::size_t(skeleton.jointCount());
    std::vector<anim::Vec3d> positions(n);
    std::vector<anim::Quatd> orientations(n);
    std::vector<RigidTransform> joints(n);
    computeSkinningTransforms(skeleton, frame, skeleton.worldPositions(skeleton.restFrame()), positions,
                              orientations, joints);
    return joints;
}

void skinOneCore(benchmark::State& state, SkinningMethod method)
{
    const Character character = chainCharacter(int(state.range(0)));
    const std::vector<RigidTransform> joints = randomPose(character.skeleton);
    const std::size_t n = character.mesh.vertexCount();
    std::vector<anim::Vec3> positions(n), normals(n);
    SkinningPalette palette;
    palette.update(joints);
    const long before = thespis::test::allocationCount();
    for (auto _ : state) {
        palette.update(joints);
        skinVertices(character.skin, character.mesh.positions, character.mesh.normals, palette, method, 0, n,
                     positions, normals);
        benchmark::DoNotOptimize(positions.data());
        benchmark::DoNotOptimize(normals.data());
        benchmark::ClobberMemory();
    }
    state.counters["allocs/frame"] =
        benchmark::Counter(double(thespis::test::allocationCount() - before) / double(state.iterations()));
    state.counters["ns/vertex"] = benchmark::Counter(double(n) * double(state.iterations()),
                                                     benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void skinThreaded(benchmark::State& state, SkinningMethod method)
{
    const Character character = chainCharacter(int(state.range(0)));
    const std::vector<RigidTransform> joints = randomPose(character.skeleton);
    const std::size_t n = character.mesh.vertexCount();
    std::vector<anim::Vec3> positions(n), normals(n);
    SkinningWorkers workers(int(state.range(1)));
    for (auto _ : state) {
        workers.skin(character, joints, method, positions, normals);
        benchmark::DoNotOptimize(positions.data());
        benchmark::ClobberMemory();
    }
}

void SkinLBS(benchmark::State& state) { skinOneCore(state, SkinningMethod::Linear); }
void SkinDQS(benchmark::State& state) { skinOneCore(state, SkinningMethod::DualQuaternion); }
void SkinLBSThreaded(benchmark::State& state) { skinThreaded(state, SkinningMethod::Linear); }
void SkinDQSThreaded(benchmark::State& state) { skinThreaded(state, SkinningMethod::DualQuaternion); }

} // namespace

BENCHMARK(SkinLBS)->Arg(7500)->Arg(15000)->Arg(30000)->Unit(benchmark::kMicrosecond);
BENCHMARK(SkinDQS)->Arg(7500)->Arg(15000)->Arg(30000)->Unit(benchmark::kMicrosecond);
BENCHMARK(SkinLBSThreaded)->Name("SkinLBS")->Args({30000, 2})->ArgNames({"", "threads"})->UseRealTime()
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(SkinDQSThreaded)->Name("SkinDQS")->Args({30000, 2})->ArgNames({"", "threads"})->UseRealTime()
    ->Unit(benchmark::kMicrosecond);
