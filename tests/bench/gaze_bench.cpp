// Gaze (motion/gaze.h): one step of a character's gaze controller on an H-Anim LOA 2 body — the
// chain's forward kinematics, the shift shared among the parts, their motion, the eyes and the
// turned joints written back — toward a target moving every frame, saccades on.
// The argument is the influence: 0 eyes, 1 head, 2 shoulder (the default), 3 waist.
// Goal (issue 33): ≤ 0.5 µs per character per frame. Reports allocations per frame too.
#include <benchmark/benchmark.h>

#include <cmath>

#include "allocation_counter.h"
#include "anim/hanim.h"
#include "motion/gaze.h"

using namespace thespis::core;

namespace {

void GazeStep(benchmark::State& state)
{
    const auto& skeleton = anim::hanim::skeleton(anim::hanim::Level::Loa2);
    auto rig = motion::GazeRig::create(skeleton);
    if (!rig) {
        state.SkipWithError("no gaze rig");
        return;
    }
    motion::GazeSettings settings;
    settings.influence = motion::GazeInfluence(state.range(0));
    motion::GazeController gaze(*rig, settings);
    std::vector<float> body = skeleton.restFrame(), face = anim::neutralFrame(*anim::FrameLayout::mpeg4Face());
    const std::vector<float> rest = body;
    double t = 0;
    const auto before = thespis::test::allocationCount();
    for (auto _ : state) {
        t += 1.0 / 60;
        const anim::Vec3d target{2 * std::sin(t), 1.5 + 0.3 * std::cos(t), 2};
        std::copy(rest.begin(), rest.end(), body.begin()); // the layers below give a new pose each frame
        gaze.apply(t, target, body, face);
        benchmark::DoNotOptimize(body.data());
    }
    state.counters["allocs/frame"] =
        double(thespis::test::allocationCount() - before) / double(std::max<benchmark::IterationCount>(1, state.iterations()));
}
BENCHMARK(GazeStep)->Name("Gaze/step")->Arg(0)->Arg(1)->Arg(2)->Arg(3)->Unit(benchmark::kNanosecond);

} // namespace
