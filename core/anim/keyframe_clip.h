#pragma once
// A keyframed clip: frames sampled at a fixed rate (motion capture, baked motion), evaluated at
// any time by spherical linear interpolation of rotations and linear interpolation of
// translations and scalars. Slerp angles are precomputed per key interval and keys are stored
// hemisphere-aligned, so sampling is a few multiply-adds per joint and allocates nothing.

#include <string>
#include <vector>

#include "anim/blendable.h"
#include "util/error.h"

namespace thespis::core::anim {

class KeyframeClip final : public BlendableObject {
public:
    /// `frames` holds frameCount × layout->floatCount() floats, frame after frame. Rotations are
    /// normalized; the rules: frameRate > 0, at least one frame, every value finite.
    static Result<std::shared_ptr<KeyframeClip>> create(FrameLayoutPtr layout, double frameRate,
                                                        std::vector<float> frames, std::string name = {});

    const std::string& name() const { return m_name; }
    double frameRate() const { return m_frameRate; }
    int frameCount() const { return m_frameCount; }
    /// The stored values of key `index` (rotations may have flipped sign: same rotation).
    std::span<const float> frame(int index) const;
    const std::vector<float>& data() const { return m_frames; }

    const FrameLayoutPtr& layout() const override { return m_layout; }
    TimeDomain domain() const override { return {0.0, double(m_frameCount - 1) / m_frameRate}; }
    void evaluate(double t, std::span<float> out) const override;

private:
    KeyframeClip() = default;

    FrameLayoutPtr m_layout;
    std::string m_name;
    double m_frameRate = 30;
    int m_frameCount = 0;
    std::vector<float> m_frames;
    // Per interval i (between keys i and i+1) and rotation r: the angle θ between the keys and
    // 1/sin θ (0 when θ is so small that linear interpolation is exact to float precision).
    std::vector<float> m_theta, m_invSinTheta;
};

/// Copies `clip` onto another layout: elements are matched by name and kind; elements the clip
/// lacks take their value from `rest` (a frame of `target`). Reports the clip's elements that
/// the target lacks through `dropped` when given.
Result<std::shared_ptr<KeyframeClip>> remapClip(const KeyframeClip& clip, FrameLayoutPtr target,
                                                std::span<const float> rest,
                                                std::vector<std::string>* dropped = nullptr);

} // namespace thespis::core::anim
