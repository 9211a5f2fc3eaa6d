#pragma once
// FrameBlender (paper §4.2): combines frames. The default is quaternion-aware (rotations
// hemisphere-aligned and normalized, translations and scalars linear); LinearBlender blends
// every float linearly, as the paper's default blender; users may plug in their own.
//
// Rules of blend(): per element, with total weight W = Σ wᵢ,
//   W ≥ 1:  x = Σ wᵢ·xᵢ / W                  (the paper's normalized weighted blend)
//   W < 1:  x = Σ wᵢ·xᵢ + (1 − W)·rest        (the rest pose fills the remainder)
// so an element nobody drives keeps the rest pose, and a weight fading to zero reaches the rest
// pose continuously, without a pop. With fillRest = false nothing is filled in:
// x = Σ wᵢ·xᵢ / W (the rest pose where W = 0), which lets a nested schedule hand its partial
// result to its parent together with the totals W. The caller owns every buffer: blending
// allocates nothing.

#include <memory>
#include <span>

#include "anim/frame.h"

namespace thespis::core::anim {

/// One frame taking part in a blend, with one weight per layout element.
struct BlendInput {
    const float* values = nullptr;
    const float* weights = nullptr;
};

class FrameBlender {
public:
    virtual ~FrameBlender() = default;
    /// Normalized weighted blend of `inputs` into `out` (see the rules above); `totals` (one
    /// float per element) receives each element's total weight W.
    virtual void blend(const FrameLayout& layout, std::span<const BlendInput> inputs,
                       std::span<const float> rest, std::span<float> out, std::span<float> totals,
                       bool fillRest = true) const = 0;
    /// Override layer: out = interpolate(out, input, w) per element.
    virtual void overlay(const FrameLayout& layout, const BlendInput& input, std::span<float> out) const = 0;
    /// Additive layer: out = out ∘ (input ⊖ reference)·w per element.
    virtual void add(const FrameLayout& layout, const BlendInput& input, std::span<const float> reference,
                     std::span<float> out) const = 0;
};

class QuaternionBlender final : public FrameBlender {
public:
    void blend(const FrameLayout& layout, std::span<const BlendInput> inputs, std::span<const float> rest,
               std::span<float> out, std::span<float> totals, bool fillRest = true) const override;
    void overlay(const FrameLayout& layout, const BlendInput& input, std::span<float> out) const override;
    void add(const FrameLayout& layout, const BlendInput& input, std::span<const float> reference,
             std::span<float> out) const override;
};

class LinearBlender final : public FrameBlender {
public:
    void blend(const FrameLayout& layout, std::span<const BlendInput> inputs, std::span<const float> rest,
               std::span<float> out, std::span<float> totals, bool fillRest = true) const override;
    void overlay(const FrameLayout& layout, const BlendInput& input, std::span<float> out) const override;
    void add(const FrameLayout& layout, const BlendInput& input, std::span<const float> reference,
             std::span<float> out) const override;
};

/// The shared default blender instance (a QuaternionBlender).
std::shared_ptr<const FrameBlender> defaultBlender();

} // namespace thespis::core::anim
