// Spherical-harmonic rotation benchmarks (issue 3 §6), comparable to google/spherical-harmonics
// (Rotation::Create and Rotation::Apply on Eigen arrays; on this machine l = 4: build ≈ 2.0 µs,
// RGB apply ≈ 0.7 µs).
//
// SHRotationBuild/<l>: all band matrices 0 … l from a 3×3 rotation (a new random one each time).
// SHRotationApplyRGB/<l>: rotating the RGB coefficients of bands 0 … l by a prebuilt rotation.
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "lighting/sh_rotation.h"

using namespace thespis::core::lighting;

namespace {

std::vector<Matrix3d> randomRotations(int count)
{
    std::mt19937 rng(11);
    std::normal_distribution<double> gaussian;
    std::vector<Matrix3d> rotations;
    for (int i = 0; i < count; ++i)
        rotations.push_back(
            rotationMatrix(normalize(Quatd{gaussian(rng), gaussian(rng), gaussian(rng), gaussian(rng)})));
    return rotations;
}

void SHRotationBuild(benchmark::State& state)
{
    const int order = int(state.range(0)) + 1;
    const std::vector<Matrix3d> rotations = randomRotations(64);
    ShRotation rotation;
    size_t next = 0;
    for (auto _ : state) {
        rotation.build(order, rotations[next]);
        next = (next + 1) % rotations.size();
        benchmark::DoNotOptimize(rotation);
        benchmark::ClobberMemory();
    }
}

void SHRotationApplyRGB(benchmark::State& state)
{
    const int order = int(state.range(0)) + 1;
    const ShRotation rotation(order, randomRotations(1)[0]);
    std::mt19937 rng(12);
    std::uniform_real_distribution<double> uniform(-1, 1);
    ShRgb in, out;
    in.order = order;
    for (auto& channel : in.channel)
        for (double& v : channel)
            v = uniform(rng);
    for (auto _ : state) {
        rotation.applyRgb(in, out);
        benchmark::DoNotOptimize(out);
        benchmark::ClobberMemory();
    }
}

} // namespace

BENCHMARK(SHRotationBuild)->Arg(2)->Arg(3)->Arg(4)->Arg(6)->Arg(8)->Unit(benchmark::kNanosecond);
BENCHMARK(SHRotationApplyRGB)->Arg(2)->Arg(3)->Arg(4)->Arg(6)->Arg(8)->Unit(benchmark::kNanosecond);
