#include "scenario/action_placement.h"

#include <algorithm>
#include <tuple>

#include "anim/frame.h"
#include "anim/modifiers.h"
#include "anim/root_motion.h"

namespace thespis::core::scenario {

void placeActions(const Layer& layer, std::vector<std::optional<anim::BlendingAction>>& actions)
{
    std::vector<std::size_t> order(actions.size());
    for (std::size_t a = 0; a < order.size(); ++a)
        order[a] = a;
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return layer.actions[a].start < layer.actions[b].start; });
    const anim::BlendingAction* previous = nullptr;
    std::vector<float> frame;
    // The root's place on the floor and heading in a source's frame at `seconds`.
    const auto rootAt = [&](const anim::BlendablePtr& source, double seconds) {
        const anim::RootElements root = anim::rootElements(*source->layout());
        frame.assign(source->layout()->floatCount(), 0.0f);
        source->evaluate(seconds, frame);
        const anim::Vec3 at{frame[root.translation], 0.0f, frame[root.translation + 2]};
        const double facing = root.rotation >= 0 ? anim::heading(anim::rotationAt(std::span<const float>(frame), root.rotation)) : 0.0;
        return std::pair{at, facing};
    };
    for (std::size_t a : order) {
        std::optional<anim::BlendingAction>& action = actions[a];
        if (!action)
            continue;
        const Placement placement = layer.actions[a].placement;
        if (placement != Placement::World && anim::rootElements(*action->source->layout()).valid) {
            const anim::TimeDomain domain = action->source->domain();
            const auto [from, fromHeading] = rootAt(action->source, domain.start);
            anim::Vec3 to;
            double toHeading = 0;
            if (placement == Placement::Continue && previous) {
                const anim::TimeDomain before = previous->source->domain();
                const double local = std::clamp(before.start + action->start - previous->start, before.start, before.end);
                std::tie(to, toHeading) = rootAt(previous->source, local);
            }
            const anim::FloorMove move = anim::FloorMove::onto(from, fromHeading, to, toHeading);
            const auto shift = move.apply(anim::Vec3{});
            if (auto placed = anim::GlobalTransform::create(action->source, move.rotation(), shift))
                action->source = std::move(placed).value();
        }
        previous = &*action;
    }
}

} // namespace thespis::core::scenario
