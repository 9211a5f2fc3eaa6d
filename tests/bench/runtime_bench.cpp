// The live runtime's tick (core/runtime/stage.h).
//
// StageTick/C: C characters on H-Anim 25-joint bodies, each with 4 authored actions (2 s
//   keyframed clips with cubic fades, held past their end) and one live action activated at run
//   time (so every character plays through the stage's live path); one Stage::evaluate per
//   iteration at a new time. The clips come from a library of 12, as the characters of a
//   scenario share their motion files (each character its own choice of them, from its own
//   start). Reports ns per character per tick and allocations per tick.
// StageScrub/F: the same stage (10 characters) scrubbed back and forth over 2 s, with a frame
//   cache of F frames (Stage::setFrameCache; the studio keeps 600) or none.
#include <benchmark/benchmark.h>

#include <memory>
#include <random>

#include "allocation_counter.h"
#include "anim/hanim.h"
#include "anim/keyframe_clip.h"
#include "runtime/stage.h"

using namespace thespis::core;
using namespace thespis::core::anim;

namespace {

std::shared_ptr<KeyframeClip> randomWalkClip(const Skeleton& skeleton, std::mt19937& rng)
{
    const FrameLayoutPtr& layout = skeleton.frameLayout();
    std::normal_distribution<float> gaussian;
    std::vector<float> data;
    std::vector<Quat> previous(std::size_t(layout->rotationCount()), Quat{0, 0, 0, 1});
    for (int k = 0; k < 61; ++k) { // 2 s at 30 keys/s
        for (auto& q : previous) {
            q = normalize(q * normalize(Quat{0.03f * gaussian(rng), 0.03f * gaussian(rng), 0.03f * gaussian(rng), 1.0f}));
            data.insert(data.end(), {q.x, q.y, q.z, q.w});
        }
        for (int t = 0; t < layout->translationCount(); ++t)
            data.insert(data.end(), {0.01f * float(k), 0.95f, 0.0f});
    }
    return std::move(KeyframeClip::create(layout, 30.0, std::move(data))).value();
}

// The stage StageTick and StageScrub play: `characters` characters, each with 4 authored actions
// and one live action.
std::unique_ptr<runtime::Stage> benchStage(int characters)
{
    const Skeleton& skeleton = hanim::skeleton(hanim::Level::Subset25);
    std::mt19937 rng(11);
    std::vector<std::shared_ptr<KeyframeClip>> library;
    for (int k = 0; k < 12; ++k)
        library.push_back(randomWalkClip(skeleton, rng));
    scenario::ScenarioRuntime runtime;
    for (int c = 0; c < characters; ++c) {
        scenario::CharacterRuntime character;
        character.name = "character" + std::to_string(c);
        character.skeleton = skeleton;
        character.body = std::make_shared<BlendingSchedule>(skeleton);
        character.face = std::make_shared<BlendingSchedule>(FrameLayout::mpeg4Face());
        for (int a = 0; a < 4; ++a) {
            BlendingAction action;
            action.name = "action" + std::to_string(a);
            action.source = library[std::size_t(c * 5 + a) % library.size()];
            action.params.weight = Curve::cubicFade(0.5, 0.5);
            action.start = 0.3 * a - 0.01 * (c % 7);
            action.renderOutsideDomain = true;
            (void)character.body->addAction(std::move(action));
        }
        character.clips["gesture"] = library[std::size_t(c * 5 + 4) % library.size()];
        runtime.characters.push_back(std::move(character));
    }
    auto stage = std::make_unique<runtime::Stage>(std::move(runtime));
    for (int c = 0; c < characters; ++c) {
        auto made = stage->defineAction("character" + std::to_string(c), runtime::Track::Body, "gesture",
                                        {stage->runtime().characters[std::size_t(c)].clips.at("gesture"), {}, true});
        (void)made;
        (void)stage->activateAction("character" + std::to_string(c), runtime::Track::Body, "gesture", secondsToTicks(0.1));
    }
    return stage;
}

void StageTick(benchmark::State& state)
{
    const int characters = int(state.range(0));
    auto made = benchStage(characters);
    runtime::Stage& stage = *made;
    runtime::PoseSet poses = stage.makePoseSet();
    Tick t = secondsToTicks(1.0);
    const Tick step = ticksPerFrame(60);
    stage.evaluate(t, poses);
    const long before = thespis::test::allocationCount();
    for (auto _ : state) {
        t += step;
        stage.evaluate(t, poses);
        benchmark::DoNotOptimize(poses.characters.back().body.data());
    }
    state.counters["ns/character"] = benchmark::Counter(double(characters) * double(state.iterations()),
                                                        benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
    state.counters["allocs/tick"] = double(thespis::test::allocationCount() - before) / double(state.iterations());
}

} // namespace

BENCHMARK(StageTick)->Arg(2)->Arg(10)->Arg(100);

// StageScrub/F: the playhead scrubbed back and forth over the same 2 s at 30 frames per second
// (as a user drags it), 10 characters, with a frame cache of F frames per character (0: none).
void StageScrub(benchmark::State& state)
{
    constexpr int characters = 10;
    auto stage = benchStage(characters);
    stage->setFrameCache(int(state.range(0)));
    runtime::PoseSet poses = stage->makePoseSet();
    const Tick frame = ticksPerFrame(30);
    long step = 0;
    for (auto _ : state) {
        const long f = step++ % 120; // 0 … 60, then back
        stage->evaluate(secondsToTicks(1.0) + frame * (f <= 60 ? f : 120 - f), poses);
        benchmark::DoNotOptimize(poses.characters.back().body.data());
    }
    state.counters["ns/character"] = benchmark::Counter(double(characters) * double(state.iterations()),
                                                        benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
    state.counters["hits"] = double(stage->frameCacheHits()) / double(state.iterations());
}
BENCHMARK(StageScrub)->Arg(0)->Arg(600);
