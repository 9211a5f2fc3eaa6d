// Blending engine benchmarks, comparable to ozz-animation's "sample K clips + blend" figures.
//
// ScheduleEval/N/K/mask: a schedule of K keyframed clips (2 s, 30 keys/s, N joints + root
//   translation), each with a cubic-fade weight curve (and a per-joint mask when mask = 1),
//   evaluated at a new time every iteration: sampling (slerp) + weights + normalized blend.
// Blend/N/K/mask: the blend step alone on K already-sampled frames.
// Both report ns per frame (the iteration time) and heap allocations per frame.
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include "allocation_counter.h"
#include "anim/blending_schedule.h"
#include "anim/frame_blender.h"
#include "anim/keyframe_clip.h"

using namespace thespis::core::anim;

namespace {

FrameLayoutPtr layoutOf(int joints)
{
    std::vector<std::string> names;
    for (int j = 0; j < joints; ++j)
        names.push_back("joint" + std::to_string(j));
    return FrameLayout::create(names, {"joint0"});
}

std::shared_ptr<KeyframeClip> randomClip(const FrameLayoutPtr& layout, std::mt19937& rng)
{
    std::normal_distribution<float> gaussian;
    const int keys = 61; // 2 s at 30 keys/s
    std::vector<float> data;
    std::vector<Quat> previous(std::size_t(layout->rotationCount()));
    for (int k = 0; k < keys; ++k) {
        for (int r = 0; r < layout->rotationCount(); ++r) {
            // A random walk of small steps, like motion capture.
            const Quat step = normalize(Quat{0.05f * gaussian(rng), 0.05f * gaussian(rng), 0.05f * gaussian(rng), 1.0f});
            const Quat q = k == 0 ? normalize(Quat{gaussian(rng), gaussian(rng), gaussian(rng), gaussian(rng)})
                                  : normalize(previous[std::size_t(r)] * step);
            previous[std::size_t(r)] = q;
            data.insert(data.end(), {q.x, q.y, q.z, q.w});
        }
        data.insert(data.end(), {0.01f * float(k), 1.0f, 0.0f});
    }
    return std::move(KeyframeClip::create(layout, 30.0, std::move(data))).value();
}

std::shared_ptr<JointMask> randomMask(int joints, std::mt19937& rng)
{
    std::uniform_real_distribution<float> weight(0.0f, 1.0f);
    std::map<std::string, float> weights;
    for (int j = 0; j < joints; ++j)
        weights["joint" + std::to_string(j)] = weight(rng);
    return std::make_shared<JointMask>(std::move(weights), 0.0f);
}

void reportAllocations(benchmark::State& state, long before)
{
    state.counters["allocs/frame"] = benchmark::Counter(double(thespis::test::allocationCount() - before) / double(state.iterations()));
}

void ScheduleEval(benchmark::State& state)
{
    const int joints = int(state.range(0)), clips = int(state.range(1));
    const bool masked = state.range(2) != 0;
    std::mt19937 rng(42);
    const auto layout = layoutOf(joints);
    BlendingSchedule schedule(layout);
    for (int k = 0; k < clips; ++k) {
        BlendingAction action;
        action.name = "clip" + std::to_string(k);
        action.source = randomClip(layout, rng);
        action.params.weight = Curve::cubicFade(0.5, 0.5);
        action.renderOutsideDomain = true;
        if (masked)
            action.params.mask = randomMask(joints, rng);
        (void)schedule.addAction(std::move(action));
    }
    std::vector<float> out(layout->floatCount());
    double t = 0.6;
    const long before = thespis::test::allocationCount();
    for (auto _ : state) {
        schedule.evaluate(t, out);
        benchmark::DoNotOptimize(out.data());
        t += 1.0 / 120.0; // a new time each frame: no two samples fall on the same key
        if (t > 1.4)
            t -= 0.8;
    }
    reportAllocations(state, before);
}

void Blend(benchmark::State& state)
{
    const int joints = int(state.range(0)), clips = int(state.range(1));
    const bool masked = state.range(2) != 0;
    std::mt19937 rng(7);
    const auto layout = layoutOf(joints);
    std::vector<std::vector<float>> frames, weights;
    std::uniform_real_distribution<float> weight(0.0f, 1.0f);
    for (int k = 0; k < clips; ++k) {
        frames.emplace_back(layout->floatCount());
        randomClip(layout, rng)->evaluate(0.7, frames.back());
        weights.emplace_back(std::size_t(layout->elementCount()), 0.8f);
        if (masked)
            for (float& w : weights.back())
                w *= weight(rng);
    }
    std::vector<BlendInput> inputs;
    for (int k = 0; k < clips; ++k)
        inputs.push_back({frames[std::size_t(k)].data(), weights[std::size_t(k)].data()});
    const std::vector<float> rest = neutralFrame(*layout);
    std::vector<float> out(layout->floatCount()), totals(std::size_t(layout->elementCount()));
    QuaternionBlender blender;
    const long before = thespis::test::allocationCount();
    for (auto _ : state) {
        blender.blend(*layout, inputs, rest, out, totals);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    reportAllocations(state, before);
}

void grid(benchmark::internal::Benchmark* b)
{
    for (int n : {25, 70, 100})
        for (int k : {2, 4, 8})
            for (int mask : {0, 1})
                b->Args({n, k, mask});
    b->ArgNames({"", "", ""});
}

} // namespace

BENCHMARK(ScheduleEval)->Apply(grid);
BENCHMARK(Blend)->Apply(grid);
