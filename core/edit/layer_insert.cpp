#include "edit/layer_insert.h"

#include <algorithm>

#include "edit/document_edits.h"
#include "util/text.h"

namespace thespis::core::edit {

Result<void> take(Result<Edit> step, scenario::Scenario& after)
{
    if (!step)
        return step.error();
    return step->apply(after);
}

Result<LayerPath> layerNamed(scenario::Scenario& after, int character, const std::string& name,
                             scenario::LayerKind kind, anim::BlendMode mode)
{
    const auto& layers = after.characters[std::size_t(character)].layers;
    const auto it = std::find_if(layers.begin(), layers.end(),
                                 [&](const scenario::Layer& l) { return l.name == name && l.kind == kind; });
    if (it != layers.end()) {
        if (it->lock)
            return makeError(ErrorCode::InvalidArgument,
                             "The layer " + inQuotes(name) + " is locked: unlock it to insert on it.");
        return LayerPath{character, int(it - layers.begin())};
    }
    scenario::Layer layer;
    layer.name = name;
    layer.kind = kind;
    layer.mode = mode;
    const LayerPath path{character, int(layers.size())};
    if (auto added = take(Edit(LayerChange{path, std::nullopt, std::move(layer)}), after); !added)
        return added.error();
    return path;
}

scenario::ModifierSpec stretchTo(double seconds, double clipSeconds)
{
    return {.kind = scenario::ModifierKind::TimeStretch, .factor = seconds / clipSeconds};
}

Edit characterEdit(const scenario::Scenario& before, const scenario::Scenario& after, int character)
{
    Edit edit;
    for (std::size_t m = before.masks.size(); m < after.masks.size(); ++m)
        edit.add(MaskChange{int(m), std::nullopt, after.masks[m]});
    edit.add(CharacterChange{character, before.characters[std::size_t(character)],
                             after.characters[std::size_t(character)]});
    return edit;
}

} // namespace thespis::core::edit
