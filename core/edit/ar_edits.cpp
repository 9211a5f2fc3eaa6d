#include "edit/ar_edits.h"

#include <cmath>
#include <string>
#include <utility>

namespace thespis::core::edit {

namespace {

using namespace scenario;

constexpr double MaximumScale = 1000; // a character a kilometre and a half tall: surely a typo beyond

Error invalid(std::string message) { return makeError(ErrorCode::InvalidArgument, std::move(message)); }

Result<void> checkPlacement(const std::array<double, 2>& offset, double heading, double scale)
{
    if (!std::isfinite(offset[0]) || !std::isfinite(offset[1]))
        return invalid("The world's offset on the target must be a distance in metres.");
    if (!std::isfinite(heading))
        return invalid("The world's heading on the target must be a number of degrees.");
    if (!std::isfinite(scale) || scale <= 0 || scale > MaximumScale)
        return invalid("The world's scale on the target must be above 0 and at most " +
                       std::to_string(int(MaximumScale)) + " (0.1 stands a 1.8 m character 18 cm tall).");
    return {};
}

Result<void> checkOccluder(const PhantomOccluder& occluder, std::size_t index)
{
    const std::string which = occluder.name.empty() ? "Occluder " + std::to_string(index + 1)
                                                    : "Occluder \"" + occluder.name + "\"";
    for (double p : occluder.position)
        if (!std::isfinite(p))
            return invalid(which + ": its position must be in metres.");
    if (!std::isfinite(occluder.heading))
        return invalid(which + ": its heading must be a number of degrees.");
    const int sizes = occluder.shape == PhantomOccluder::Shape::Plane ? 2 : 3;
    for (int i = 0; i < sizes; ++i)
        if (!std::isfinite(occluder.size[std::size_t(i)]) || occluder.size[std::size_t(i)] <= 0)
            return invalid(which + ": its sizes must be above 0.");
    if (occluder.shape == PhantomOccluder::Shape::Model && occluder.model.empty())
        return invalid(which + ": a model occluder needs a glTF file.");
    return {};
}

} // namespace

Result<Edit> setArPlacement(const Scenario& scenario, std::array<double, 2> offset, double heading, double scale)
{
    if (auto ok = checkPlacement(offset, heading, scale); !ok)
        return ok.error();
    ArSpec after = scenario.ar;
    after.offset = offset;
    after.heading = heading;
    after.scale = scale;
    return Edit(ArChange{scenario.ar, std::move(after)});
}

Result<Edit> setArShadowCatcher(const Scenario& scenario, bool on)
{
    ArSpec after = scenario.ar;
    after.shadowCatcher = on;
    return Edit(ArChange{scenario.ar, std::move(after)});
}

Result<Edit> setArSpec(const Scenario& scenario, ArSpec spec)
{
    if (auto ok = checkPlacement(spec.offset, spec.heading, spec.scale); !ok)
        return ok.error();
    for (std::size_t i = 0; i < spec.occluders.size(); ++i)
        if (auto ok = checkOccluder(spec.occluders[i], i); !ok)
            return ok.error();
    return Edit(ArChange{scenario.ar, std::move(spec)});
}

} // namespace thespis::core::edit
