#pragma once
// BlendingParams (paper §4.2): how an action takes part in a blend. A weight curve and a scale
// curve over the action's local time, an optional joint mask multiplexed with the weight
// (mask × weight curve = one curve per joint), custom parameter objects multiplexed the same
// way, and the blend mode.

#include <memory>
#include <span>
#include <vector>

#include "anim/curve.h"
#include "anim/joint_mask.h"

namespace thespis::core::anim {

enum class BlendMode {
    Normalized, ///< the paper's weighted blend: Σ wᵢ·xᵢ / Σ wᵢ per element (rest pose fills Σ w < 1)
    Additive,   ///< adds the difference to a reference pose, scaled by the weight, on top
    Override,   ///< moves the result towards this action by the weight (a layer above)
};

/// The pose an additive action is relative to.
enum class AdditiveReference { FirstFrame, RestPose };

/// A user-defined parameter object: multiplies per-element weights at a local time.
class CustomBlendingParams {
public:
    virtual ~CustomBlendingParams() = default;
    /// Multiplies `weights` (one per layout element) in place. Must not allocate.
    virtual void modulate(double localTime, const FrameLayout& layout, std::span<float> weights) const = 0;
};

struct BlendingParams {
    Curve weight;                           ///< constant 1 by default
    Curve scale;                            ///< motion amplitude relative to the rest pose; 1 = as is
    std::shared_ptr<const JointMask> mask;  ///< none: every element weighs 1
    BlendMode mode = BlendMode::Normalized;
    AdditiveReference additiveReference = AdditiveReference::FirstFrame;
    std::vector<std::shared_ptr<const CustomBlendingParams>> custom;
};

} // namespace thespis::core::anim
