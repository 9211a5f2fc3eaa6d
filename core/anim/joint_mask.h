#pragma once
// JointMask: a weight in [0, 1] per joint (or per element of any frame layout), a named asset
// shared by actions. Multiplexed with a weight curve it gives one weight curve per joint.
// Joints the mask does not name inherit the weight of their nearest named ancestor when the
// skeleton hierarchy is known, else take the default weight. A root translation element takes
// its joint's weight. A scalar the mask does not name takes its group's weight (a face mask names
// the face's regions, "mouth", "eyes" …: FrameLayout::group), else the default.

#include <map>
#include <span>
#include <string>
#include <vector>

#include "anim/frame.h"
#include "util/error.h"

namespace thespis::core::anim {

enum class MaskPreset { FullBody, UpperBody, LowerBody, LeftArm, RightArm, HeadAndNeck, Spine };

class JointMask {
public:
    JointMask() = default;
    explicit JointMask(std::map<std::string, float> weights, float defaultWeight = 0.0f);
    /// A preset over H-Anim joint names (LOA 2).
    static JointMask preset(MaskPreset preset);

    const std::map<std::string, float>& weights() const { return m_weights; }
    float defaultWeight() const { return m_default; }
    /// Weight of a named joint, or nullopt-like -1 when the mask does not name it.
    float weight(const std::string& joint) const;
    void setWeight(const std::string& joint, float weight);
    void setDefaultWeight(float weight) { m_default = weight; }

    /// Left and right swapped (H-Anim names and common Left/Right spellings).
    JointMask mirrored() const;
    /// 1 − w for every named weight and the default.
    JointMask inverted() const;

    /// Weights outside [0, 1] or not finite are errors naming the joint.
    Result<void> validate() const;

    /// One weight per element of `layout`. `parents` (optional) gives the parent rotation index of
    /// each rotation element, for inheritance.
    std::vector<float> resolve(const FrameLayout& layout, std::span<const int> parents = {}) const;

    bool operator==(const JointMask&) const = default;

private:
    std::map<std::string, float> m_weights;
    float m_default = 0.0f;
};

} // namespace thespis::core::anim
