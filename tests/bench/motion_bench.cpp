// core/motion (paper §4.1, §4.3).
//
// IdleFrame/C: C characters (H-Anim LOA 1 bodies, so each frame is also retargeted) idling on
//   one database built from the CMU standing clips, each with its own seed; one frame of each per
//   iteration at a new time. Reports ns per character per frame and allocations per frame.
// IdleFrameOwnSkeleton/C: the same on the idle's own 25-joint H-Anim body (the demo's characters'):
//   rotations are copied, not re-composed.
// PcDistance/k: the paper's eq. 1 over k PCs between two postures already in PC space, against
//   JointDistance: the same postures compared joint by joint (the angle between each joint's
//   quaternions, and the roots' distance), the way a joint-based method does.
// TrainPca: reading every clip of ../shared/data/mocap/cmu onto the posture skeleton at 30
//   postures per second and training both bases (what `thespis-cli train-pca` does).
#include <benchmark/benchmark.h>

#include <filesystem>
#include <random>

#include "allocation_counter.h"
#include "anim/hanim.h"
#include "motion/idle_builder.h"
#include "motion/idle_motion.h"
#include "scenario/posture_clip.h"

using namespace thespis::core;
using namespace thespis::core::motion;

namespace {

const std::filesystem::path kCmu = std::filesystem::path(THESPIS_SHARED_DATA) / "mocap" / "cmu";

std::vector<float> posturesOf(const std::string& file, double rate, double skip)
{
    scenario::ClipAsset asset;
    asset.name = file;
    asset.file = file;
    asset.frameRateOverride = rate;
    auto clip = scenario::readPostureClip(asset, kCmu);
    return clip ? clip->postures(PostureSet::WholeBody, 30, skip) : std::vector<float>{};
}

std::shared_ptr<const IdleDatabase> standingDatabase()
{
    static const auto db = [] {
        std::vector<IdleRecording> recordings = {{"113_21", posturesOf("113_21.bvh", 0, 2), {}},
                                                 {"77_02", posturesOf("77_02.bvh", 60, 2), {}},
                                                 {"111_28", posturesOf("111_28.bvh", 0, 6), {}}};
        auto built = buildIdleDatabase(recordings, {});
        return built ? std::make_shared<const IdleDatabase>(std::move(built).value()) : nullptr;
    }();
    return db;
}

void idleFrames(benchmark::State& state, const anim::Skeleton& body)
{
    const auto db = standingDatabase();
    if (!db) {
        state.SkipWithError("the CMU standing clips are missing");
        return;
    }
    std::vector<std::shared_ptr<IdleMotion>> crowd;
    for (int c = 0; c < state.range(0); ++c)
        crowd.push_back(*IdleMotion::create(db, body, {.seed = std::uint64_t(c + 1)}));
    std::vector<float> frame(body.frameLayout()->floatCount());
    for (auto& idle : crowd)
        idle->evaluate(3600, frame); // the programs for an hour
    double t = 0;
    const long before = thespis::test::allocationCount();
    for (auto _ : state) {
        for (auto& idle : crowd)
            idle->evaluate(t, frame);
        benchmark::DoNotOptimize(frame.data());
        t += 1.0 / 60;
        if (t > 3600)
            t = 0;
    }
    state.counters["s/char"] = benchmark::Counter(double(state.iterations()) * double(crowd.size()),
                                                  benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
    state.counters["allocs/frame"] =
        double(thespis::test::allocationCount() - before) / double(std::max<benchmark::IterationCount>(1, state.iterations()));
}

void IdleFrame(benchmark::State& state)
{
    idleFrames(state, anim::hanim::skeleton(anim::hanim::Level::Loa1));
}

void IdleFrameOwnSkeleton(benchmark::State& state)
{
    idleFrames(state, postureSkeleton());
}

void PcDistance(benchmark::State& state)
{
    const auto db = standingDatabase();
    if (!db) {
        state.SkipWithError("the CMU standing clips are missing");
        return;
    }
    const int k = int(state.range(0));
    const std::size_t frames = db->postures.size() / 78;
    std::vector<float> pcs(frames * 78);
    for (std::size_t f = 0; f < frames; ++f)
        db->whole.project(db->posture(std::uint32_t(f)), std::span<float>(pcs).subspan(f * 78, 78));
    std::size_t a = 0, b = frames / 2;
    float sum = 0;
    for (auto _ : state) {
        sum += db->whole.distance(std::span<const float>(pcs).subspan(a * 78, 78),
                                  std::span<const float>(pcs).subspan(b * 78, 78), k);
        a = a + 1 == frames ? 0 : a + 1;
        b = b + 1 == frames ? 0 : b + 1;
    }
    benchmark::DoNotOptimize(sum);
}

void JointDistance(benchmark::State& state)
{
    const auto db = standingDatabase();
    if (!db) {
        state.SkipWithError("the CMU standing clips are missing");
        return;
    }
    const anim::Skeleton& skeleton = postureSkeleton();
    const PostureMap map = *PostureMap::create(skeleton, PostureSet::WholeBody);
    const std::size_t frames = db->postures.size() / 78, floats = skeleton.frameLayout()->floatCount();
    std::vector<float> all(frames * floats);
    for (std::size_t f = 0; f < frames; ++f) {
        const std::span<float> frame(all.data() + f * floats, floats);
        const std::vector<float> rest = skeleton.restFrame();
        std::copy(rest.begin(), rest.end(), frame.begin());
        map.toFrame(db->posture(std::uint32_t(f)), frame);
    }
    std::size_t a = 0, b = frames / 2;
    float sum = 0;
    for (auto _ : state) {
        const float* p = all.data() + a * floats;
        const float* q = all.data() + b * floats;
        float d = 0;
        for (int j = 0; j < 25; ++j) {
            const float angle = anim::angleBetween(*reinterpret_cast<const anim::Quat*>(p + 4 * j),
                                                   *reinterpret_cast<const anim::Quat*>(q + 4 * j));
            d += angle * angle;
        }
        for (int i = 100; i < 103; ++i)
            d += (p[i] - q[i]) * (p[i] - q[i]);
        sum += std::sqrt(d);
        a = a + 1 == frames ? 0 : a + 1;
        b = b + 1 == frames ? 0 : b + 1;
    }
    benchmark::DoNotOptimize(sum);
}

void TrainPca(benchmark::State& state)
{
    std::vector<std::string> files;
    for (const auto& entry : std::filesystem::directory_iterator(kCmu))
        if (entry.path().extension() == ".bvh")
            files.push_back(entry.path().filename().string());
    if (files.empty()) {
        state.SkipWithError("../shared/data/mocap/cmu is missing");
        return;
    }
    for (auto _ : state) {
        std::vector<float> all;
        for (const std::string& file : files) {
            const auto more = posturesOf(file, 0, 0);
            all.insert(all.end(), more.begin(), more.end());
        }
        auto whole = PostureBasis::train(PostureSet::WholeBody, all);
        auto upper = PostureBasis::train(PostureSet::UpperBody, upperBodyOf(all));
        benchmark::DoNotOptimize(whole);
        benchmark::DoNotOptimize(upper);
        state.counters["postures"] = double(all.size() / 78);
    }
    state.counters["clips"] = double(files.size());
}

} // namespace

BENCHMARK(IdleFrame)->Arg(1)->Arg(100);
BENCHMARK(IdleFrameOwnSkeleton)->Arg(1)->Arg(100);
BENCHMARK(PcDistance)->Arg(5)->Arg(10)->Arg(20)->Arg(78);
BENCHMARK(JointDistance);
BENCHMARK(TrainPca)->Unit(benchmark::kMillisecond);
