#include "scenario/pointing_cue.h"

#include <algorithm>

#include "scenario/gaze_cue.h"

namespace thespis::core::scenario {

Result<PointingCue> readPointingCue(const PointingSpec& pointing, const Scenario& scenario,
                                    const anim::Skeleton& skeleton)
{
    const auto invalid = [](const char* field, const std::string& what) {
        return makeError(ErrorCode::InvalidSchedule, std::string(field) + ": " + what);
    };
    PointingCue cue;
    auto target = readStageTarget("pointing.target", pointing.target, scenario);
    if (!target)
        return target.error();
    cue.target = *target;
    auto hand = motion::parsePointingHand(pointing.hand);
    if (!hand)
        return invalid("pointing.hand", hand.error().message);
    if (auto arms = motion::pointingArms(skeleton, *hand); !arms)
        return invalid("pointing.hand", arms.error().message);
    cue.hand = *hand;
    return cue;
}

void addPointingCues(const Layer& layer, const anim::BlendingSchedule& schedule, std::span<const anim::ActionId> ids,
                     const Scenario& scenario, const anim::Skeleton& skeleton, std::vector<PointingCue>& cues)
{
    for (std::size_t a = 0; a < layer.actions.size() && a < ids.size(); ++a)
        if (const anim::BlendingAction* built = schedule.action(ids[a]); built && layer.actions[a].pointing)
            if (auto cue = readPointingCue(*layer.actions[a].pointing, scenario, skeleton)) {
                cue->start = built->start;
                cue->end = built->start + built->source->domain().duration();
                cue->weight = built->params.weight;
                cues.push_back(std::move(*cue));
            }
    std::stable_sort(cues.begin(), cues.end(),
                     [](const PointingCue& a, const PointingCue& b) { return a.start < b.start; });
}

} // namespace thespis::core::scenario
