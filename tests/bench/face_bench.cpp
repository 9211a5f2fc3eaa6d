// Face benchmarks (issue 31 goals, one thread):
//
// FaceDeform/humanoid: one frame of the built-in humanoid's face with all 68 FAPs moving (the
//   jaw, lids and eyes turned, every influence region's target active): FaceDeformer::deform,
//   normals of the moved vertices included. Goal ≤ 0.2 ms.
// FaceMorph/60x5k: a 5 000-vertex head (a sphere) with 60 morph targets, each over a third of
//   the vertices as a blend shape of a glTF model is, all active. Goal ≤ 0.3 ms.
// Both report allocations per frame (goal 0).
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "allocation_counter.h"
#include "scene/default_humanoid.h"
#include "scene/face_rig.h"

using namespace thespis::core;
using namespace thespis::core::scene;

namespace {

void runFace(benchmark::State& state, const Character& character, const std::vector<float>& face)
{
    FaceDeformer deformer(character);
    std::vector<anim::Vec3> positions = character.mesh.positions, normals = character.mesh.normals;
    deformer.deform(face, positions, normals); // warm up
    const long before = thespis::test::allocationCount();
    for (auto _ : state) {
        deformer.deform(face, positions, normals);
        benchmark::DoNotOptimize(positions.data());
    }
    state.counters["allocations"] =
        benchmark::Counter(double(thespis::test::allocationCount() - before) / double(state.iterations()));
    state.counters["vertices"] = double(deformer.vertices().size());
}

void FaceDeform(benchmark::State& state)
{
    static const Character humanoid = *makeDefaultHumanoid({});
    std::vector<float> face(std::size_t(kFaceChannelCount), 0.0f);
    std::mt19937 random(3);
    std::uniform_real_distribution<float> value(-200, 200);
    for (int fap = 3; fap <= kFapCount; ++fap)
        face[std::size_t(fapChannel(fap))] = value(random);
    face[std::size_t(fapChannel(3))] = 300; // open_jaw is one-sided
    runFace(state, humanoid, face);
}

Character sphereHead(int targets)
{
    Character character;
    character.skeleton = std::move(anim::Skeleton::create({{.name = "skullbase"}})).value();
    const int rings = 50, around = 100; // 5 000 vertices
    CharacterMesh& mesh = character.mesh;
    for (int r = 0; r < rings; ++r)
        for (int a = 0; a < around; ++a) {
            const double polar = std::numbers::pi * (r + 0.5) / rings, angle = 2 * std::numbers::pi * a / around;
            const anim::Vec3 d{float(std::sin(polar) * std::cos(angle)), float(std::cos(polar)),
                               float(std::sin(polar) * std::sin(angle))};
            mesh.positions.push_back(d * 0.1f);
            mesh.normals.push_back(d);
        }
    for (int r = 0; r + 1 < rings; ++r)
        for (int a = 0; a < around; ++a) {
            const std::uint32_t i = std::uint32_t(r * around + a), j = std::uint32_t(r * around + (a + 1) % around);
            mesh.indices.insert(mesh.indices.end(), {i, j + around, j, i, i + around, j + around});
        }
    Segment head;
    head.name = "skull";
    head.joint = "skullbase";
    head.vertexCount = std::uint32_t(mesh.positions.size());
    head.triangleCount = std::uint32_t(mesh.triangleCount());
    mesh.segments = {head};
    std::mt19937 random(5);
    for (int t = 0; t < targets; ++t) {
        MorphTarget target;
        const std::uint32_t start = random() % mesh.positions.size();
        for (std::uint32_t k = 0; k < mesh.positions.size() / 3; ++k) {
            target.vertices.push_back((start + k) % std::uint32_t(mesh.positions.size()));
            target.offsets.push_back({0.001f, 0.002f * float(k % 7), -0.001f});
        }
        std::sort(target.vertices.begin(), target.vertices.end());
        character.face.drives.push_back({t, fapChannel(3 + t), 1.0f / 1024});
        character.face.targets.push_back(std::move(target));
    }
    return character;
}

void FaceMorph(benchmark::State& state)
{
    static const Character head = sphereHead(60);
    std::vector<float> face(std::size_t(kFaceChannelCount), 0.0f);
    for (int t = 0; t < 60; ++t)
        face[std::size_t(fapChannel(3 + t))] = float(100 + 10 * t);
    runFace(state, head, face);
}

} // namespace

BENCHMARK(FaceDeform)->Name("FaceDeform/humanoid")->Unit(benchmark::kMicrosecond);
BENCHMARK(FaceMorph)->Name("FaceMorph/60x5k")->Unit(benchmark::kMicrosecond);
