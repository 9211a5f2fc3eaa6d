#include "runtime/timeline_samples.h"

#include <algorithm>
#include <cmath>

#include "runtime/stage.h"

namespace thespis::core::runtime {

std::vector<PoseSet> sampleTimeline(const scenario::ScenarioRuntime& runtime, double step)
{
    Stage stage(runtime);
    const double duration = ticksToSeconds(std::max<Tick>(runtime.duration, 0));
    const int intervals = step > 0 ? std::max(1, int(std::ceil(duration / step))) : 1;
    std::vector<PoseSet> samples(std::size_t(intervals) + 1, stage.makePoseSet());
    for (int i = 0; i <= intervals; ++i)
        stage.evaluate(secondsToTicks(duration * i / intervals), samples[std::size_t(i)]);
    return samples;
}

} // namespace thespis::core::runtime
