#include "anim/joint_mask.h"

#include <cmath>

#include "anim/hanim.h"

namespace thespis::core::anim {
namespace {

// Every LOA 2 joint in the subtree of `root` (root included).
std::vector<std::string> subtree(std::string_view root)
{
    std::vector<std::string> names;
    for (const std::string& name : hanim::jointNames(hanim::Level::Loa2)) {
        std::string_view walk = name;
        while (!walk.empty() && walk != root)
            walk = hanim::parentName(walk);
        if (walk == root)
            names.push_back(name);
    }
    return names;
}

void setAll(std::map<std::string, float>& weights, const std::vector<std::string>& names, float weight)
{
    for (const std::string& name : names)
        weights[name] = weight;
}

} // namespace

JointMask::JointMask(std::map<std::string, float> weights, float defaultWeight)
    : m_weights(std::move(weights)), m_default(defaultWeight)
{
}

JointMask JointMask::preset(MaskPreset preset)
{
    // Every joint of the region is named (so layouts without a hierarchy work too) and the
    // region's boundary joints are named 0, so that joints unknown to H-Anim inherit correctly.
    std::map<std::string, float> w;
    switch (preset) {
    case MaskPreset::FullBody:
        return JointMask({}, 1.0f);
    case MaskPreset::UpperBody:
        setAll(w, subtree("vl5"), 1.0f);
        w["humanoid_root"] = 0.0f;
        break;
    case MaskPreset::LowerBody:
        setAll(w, subtree("sacroiliac"), 1.0f);
        w["humanoid_root"] = 1.0f;
        w["vl5"] = 0.0f;
        break;
    case MaskPreset::LeftArm:
        setAll(w, subtree("l_sternoclavicular"), 1.0f);
        w["humanoid_root"] = 0.0f;
        break;
    case MaskPreset::RightArm:
        setAll(w, subtree("r_sternoclavicular"), 1.0f);
        w["humanoid_root"] = 0.0f;
        break;
    case MaskPreset::HeadAndNeck:
        setAll(w, subtree("vc4"), 1.0f);
        w["humanoid_root"] = 0.0f;
        break;
    case MaskPreset::Spine:
        for (const char* name : {"vl5", "vl3", "vl1", "vt10", "vt6", "vt1"})
            w[name] = 1.0f;
        for (const char* name : {"humanoid_root", "vc4", "l_sternoclavicular", "r_sternoclavicular"})
            w[name] = 0.0f;
        break;
    }
    return JointMask(std::move(w), 0.0f);
}

float JointMask::weight(const std::string& joint) const
{
    const auto it = m_weights.find(joint);
    return it == m_weights.end() ? -1.0f : it->second;
}

void JointMask::setWeight(const std::string& joint, float weight)
{
    m_weights[joint] = weight;
}

JointMask JointMask::mirrored() const
{
    std::map<std::string, float> weights;
    for (const auto& [name, weight] : m_weights)
        weights[hanim::mirrorName(name)] = weight;
    return JointMask(std::move(weights), m_default);
}

JointMask JointMask::inverted() const
{
    std::map<std::string, float> weights;
    for (const auto& [name, weight] : m_weights)
        weights[name] = 1.0f - weight;
    return JointMask(std::move(weights), 1.0f - m_default);
}

Result<void> JointMask::validate() const
{
    auto bad = [](float w) { return !std::isfinite(w) || w < 0.0f || w > 1.0f; };
    if (bad(m_default))
        return makeError(ErrorCode::InvalidArgument,
                         "The mask's default weight is " + std::to_string(m_default) + "; weights must be between 0 and 1.");
    for (const auto& [name, weight] : m_weights)
        if (bad(weight))
            return makeError(ErrorCode::InvalidArgument, "The mask weight of joint '" + name + "' is "
                                                             + std::to_string(weight) + "; weights must be between 0 and 1.");
    return {};
}

std::vector<float> JointMask::resolve(const FrameLayout& layout, std::span<const int> parents) const
{
    std::vector<float> weights(std::size_t(layout.elementCount()), m_default);
    const int rotations = layout.rotationCount();
    const bool inherit = parents.size() == std::size_t(rotations);
    for (int r = 0; r < rotations; ++r) {
        const float named = weight(layout.name(r));
        if (named >= 0.0f)
            weights[std::size_t(r)] = named;
        else if (inherit && parents[std::size_t(r)] >= 0)
            weights[std::size_t(r)] = weights[std::size_t(parents[std::size_t(r)])];
    }
    for (int e = rotations; e < layout.elementCount(); ++e) {
        const int joint = layout.kind(e) == ElementKind::Translation ? layout.find(layout.name(e), ElementKind::Rotation) : -1;
        float named = weight(layout.name(e));
        if (named < 0.0f && !layout.group(e).empty())
            named = weight(layout.group(e));
        weights[std::size_t(e)] = joint >= 0 ? weights[std::size_t(joint)] : named >= 0.0f ? named : m_default;
    }
    return weights;
}

} // namespace thespis::core::anim
