// Building a scenario's runtime with imported motion capture, as the studio does after every
// edit: two CMU files (a 2.9 s walk and a 2.5 s wave) on the built-in humanoid, each action on
// its own layer.
//
// BuildRuntimeWithMocap/0: a cold cache — the files are read and retargeted (what opening the
// scenario costs). BuildRuntimeWithMocap/1: the cache the editor keeps — files and retargeted
// clips are reused while unchanged on disk, so only the schedules are built (what an edit costs).
#include <benchmark/benchmark.h>

#include <cstdlib>

#include "scenario/clip_file.h"
#include "scenario/scenario_runtime.h"

using namespace thespis::core;
using namespace thespis::core::scenario;

namespace {

Scenario walkerWithTwoClips()
{
    Scenario s;
    s.name = "bench";
    Character c;
    c.name = "Walker";
    c.skeleton = "hanim-25";
    for (const char* name : {"02_01", "141_16"}) {
        ClipAsset clip;
        clip.name = name;
        clip.file = std::string("mocap/cmu/") + name + ".bvh";
        c.clips.push_back(clip);
        Layer layer;
        layer.name = name;
        ActionSpec action;
        action.name = name;
        action.clip = name;
        action.placement = Placement::Continue;
        layer.actions.push_back(action);
        c.layers.push_back(layer);
    }
    s.characters.push_back(c);
    return s;
}

void BuildRuntimeWithMocap(benchmark::State& state)
{
    const Scenario scenario = walkerWithTwoClips();
    const bool warm = state.range(0) != 0;
    AssetCache cache;
    if (warm && !buildRuntime(scenario, THESPIS_SHARED_DATA, &cache).ok())
        std::abort();
    for (auto _ : state) {
        if (!warm)
            cache.clear();
        auto runtime = buildRuntime(scenario, THESPIS_SHARED_DATA, &cache);
        if (!runtime.ok())
            std::abort();
        benchmark::DoNotOptimize(runtime);
    }
}

} // namespace

BENCHMARK(BuildRuntimeWithMocap)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
