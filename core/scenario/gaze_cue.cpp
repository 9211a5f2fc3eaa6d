#include "scenario/gaze_cue.h"

#include <algorithm>

#include "anim/keyframe_clip.h"
#include "util/text.h"

namespace thespis::core::scenario {

Result<motion::GazeTarget> readStageTarget(const char* field, const std::string& target, const Scenario& scenario)
{
    auto read = motion::parseGazeTarget(target);
    if (!read)
        return makeError(ErrorCode::InvalidSchedule, std::string(field) + ": " + read.error().message);
    if (read->kind == motion::GazeTarget::Kind::Joint && !scenario.findCharacter(read->character))
        return makeError(ErrorCode::InvalidSchedule, std::string(field) + ": the scenario has no character named " +
                                                         inQuotes(read->character) + ".");
    return read;
}

Result<GazeCue> readGazeCue(const GazeSpec& gaze, const Scenario& scenario)
{
    const auto invalid = [](const char* field, const std::string& what) {
        return makeError(ErrorCode::InvalidSchedule, std::string(field) + ": " + what);
    };
    GazeCue cue;
    auto target = readStageTarget("gaze.target", gaze.target, scenario);
    if (!target)
        return target.error();
    cue.target = *target;
    auto influence = motion::parseGazeInfluence(gaze.influence);
    if (!influence)
        return invalid("gaze.influence", influence.error().message);
    cue.settings.influence = *influence;
    if (auto offset = motion::setGazeOffset(cue.settings, gaze.offsetAngle, gaze.offsetDirection); !offset)
        return invalid("gaze.offsetDirection", offset.error().message);
    return cue;
}

void addGazeCues(const Layer& layer, const anim::BlendingSchedule& schedule, std::span<const anim::ActionId> ids,
                 const Scenario& scenario, std::vector<GazeCue>& cues)
{
    for (std::size_t a = 0; a < layer.actions.size() && a < ids.size(); ++a)
        if (const anim::BlendingAction* built = schedule.action(ids[a]); built && layer.actions[a].gaze)
            if (auto cue = readGazeCue(*layer.actions[a].gaze, scenario)) {
                cue->start = built->start;
                cue->end = built->start + built->source->domain().duration();
                cues.push_back(std::move(*cue));
            }
    std::stable_sort(cues.begin(), cues.end(), [](const GazeCue& a, const GazeCue& b) { return a.start < b.start; });
}

anim::BlendablePtr gazeSpanClip()
{
    static const anim::BlendablePtr clip = [] {
        const auto layout = anim::FrameLayout::mpeg4Face();
        std::vector<float> frames = anim::neutralFrame(*layout);
        frames.insert(frames.end(), frames.begin(), frames.end());
        return anim::BlendablePtr(anim::KeyframeClip::create(layout, 1.0 / kGazeActionSeconds, std::move(frames), "gaze").value());
    }();
    return clip;
}

} // namespace thespis::core::scenario
