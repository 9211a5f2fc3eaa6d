#include "edit/gaze_edits.h"

#include "edit/document_edits.h"
#include "edit/layer_insert.h"

namespace thespis::core::edit {

scenario::ActionSpec gazeAction(std::string name, scenario::GazeSpec gaze, Tick start, double seconds)
{
    scenario::ActionSpec action;
    action.name = std::move(name);
    action.gaze = std::move(gaze);
    action.start = start;
    action.modifiers.push_back(stretchTo(seconds, scenario::kGazeActionSeconds));
    return action;
}

Result<Edit> addGaze(const scenario::Scenario& scenario, int character, scenario::GazeSpec gaze, Tick start,
                     double seconds)
{
    if (character < 0 || character >= int(scenario.characters.size()))
        return makeError(ErrorCode::InvalidArgument, "There is no character " + std::to_string(character) + " to look.");
    if (start < 0 || !(seconds > 0))
        return makeError(ErrorCode::InvalidArgument, "A gaze starts on the timeline and lasts a while.");
    scenario::Scenario after = scenario;
    auto layer = layerNamed(after, character, kGazeLayer, scenario::LayerKind::Gaze, anim::BlendMode::Normalized);
    if (!layer)
        return layer.error();
    std::string name = "look at " + gaze.target;
    std::vector<scenario::ActionSpec> actions{gazeAction(std::move(name), std::move(gaze), start, seconds)};
    if (auto added = take(insertActions(after, *layer, std::move(actions)), after); !added)
        return added.error();
    return characterEdit(scenario, after, character);
}

} // namespace thespis::core::edit
