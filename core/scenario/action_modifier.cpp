#include "scenario/action_modifier.h"

#include <cmath>

#include "anim/modifiers.h"
#include "motion/dependent_joint_filter.h"

namespace thespis::core::scenario {

Result<anim::BlendablePtr> applyModifier(anim::BlendablePtr source, const ModifierSpec& m, const anim::Skeleton& skeleton,
                                         LayerKind kind, const PostureBasesSource& bases)
{
    auto wrap = [](auto made) -> Result<anim::BlendablePtr> {
        if (!made)
            return made.error();
        return anim::BlendablePtr(std::move(made).value());
    };
    switch (m.kind) {
    case ModifierKind::TimeStretch: return wrap(anim::TimeStretch::create(std::move(source), m.factor));
    case ModifierKind::TimeWarp: return wrap(anim::TimeWarp::create(std::move(source), m.warp, m.duration));
    case ModifierKind::Loop: return wrap(anim::Loop::create(std::move(source), m.count, m.rootMotion));
    case ModifierKind::Mirror: return wrap(anim::Mirror::create(std::move(source), m.axis));
    case ModifierKind::GlobalTransform: {
        const anim::Quat q = m.rotation;
        const float length = std::sqrt(anim::dot(q, q));
        if (!std::isfinite(length) || std::abs(length - 1.0f) > 1e-3f)
            return makeError(ErrorCode::InvalidArgument, "The rotation must be a unit quaternion.");
        return wrap(anim::GlobalTransform::create(std::move(source), anim::normalize(q), m.translation));
    }
    case ModifierKind::TimeOffset:
        if (!std::isfinite(m.offset))
            return makeError(ErrorCode::InvalidArgument, "A time offset must be a finite number.");
        return anim::BlendablePtr(std::make_shared<anim::TimeOffset>(std::move(source), m.offset));
    case ModifierKind::Trim: return wrap(anim::Trim::create(std::move(source), m.start, m.end));
    case ModifierKind::DependentJointFilter: {
        if (kind != LayerKind::Body)
            return makeError(ErrorCode::InvalidArgument, "The dependent-joint filter moves a body, not a face.");
        auto found = bases();
        if (!found)
            return found.error();
        const std::shared_ptr<const motion::PostureBases>& all = *found;
        return wrap(motion::DependentJointFilter::create(std::move(source), skeleton,
                                                         std::shared_ptr<const motion::PostureBasis>(all, &all->upper),
                                                         {m.fadeFrom, m.muteAbove}));
    }
    }
    return makeError(ErrorCode::Internal, "Unknown modifier kind.");
}

} // namespace thespis::core::scenario
