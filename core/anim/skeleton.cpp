#include "anim/skeleton.h"

#include <set>

namespace thespis::core::anim {

Result<Skeleton> Skeleton::create(std::vector<Joint> joints)
{
    if (joints.empty())
        return makeError(ErrorCode::InvalidArgument, "A skeleton needs at least one joint.");
    std::set<std::string> names;
    for (std::size_t i = 0; i < joints.size(); ++i) {
        const Joint& joint = joints[i];
        if (joint.name.empty())
            return makeError(ErrorCode::InvalidArgument,
                             "Joint " + std::to_string(i) + " has no name.");
        if (!names.insert(joint.name).second)
            return makeError(ErrorCode::InvalidArgument,
                             "Two joints are named '" + joint.name + "'.");
        if (i == 0 && joint.parent != -1)
            return makeError(ErrorCode::InvalidArgument,
                             "The first joint ('" + joint.name + "') must be the root.");
        if (i > 0 && (joint.parent < 0 || std::size_t(joint.parent) >= i))
            return makeError(ErrorCode::InvalidArgument,
                             "Joint '" + joint.name + "' must come after its parent.");
    }
    Skeleton skeleton;
    joints.front().translates = true;
    std::vector<std::string> rotations, translations;
    for (const Joint& joint : joints) {
        rotations.push_back(joint.name);
        skeleton.m_translationElement.push_back(joint.translates ? int(joints.size() + translations.size()) : -1);
        if (joint.translates)
            translations.push_back(joint.name);
    }
    skeleton.m_layout = FrameLayout::create(std::move(rotations), std::move(translations));
    skeleton.m_joints = std::move(joints);
    return skeleton;
}

int Skeleton::find(std::string_view name) const
{
    for (std::size_t i = 0; i < m_joints.size(); ++i)
        if (m_joints[i].name == name)
            return int(i);
    return -1;
}

std::vector<int> Skeleton::parents() const
{
    std::vector<int> parents;
    parents.reserve(m_joints.size());
    for (const Joint& joint : m_joints)
        parents.push_back(joint.parent);
    return parents;
}

int Skeleton::translationElement(int joint) const
{
    return m_translationElement[std::size_t(joint)];
}

std::vector<float> Skeleton::restFrame() const
{
    std::vector<float> frame = neutralFrame(*m_layout);
    for (std::size_t i = 0; i < m_joints.size(); ++i) {
        const int element = m_translationElement[i];
        if (element < 0)
            continue;
        const std::size_t t = m_layout->floatOffset(element);
        frame[t + 0] = float(m_joints[i].offset.x);
        frame[t + 1] = float(m_joints[i].offset.y);
        frame[t + 2] = float(m_joints[i].offset.z);
    }
    return frame;
}

std::vector<Vec3d> Skeleton::worldPositions(std::span<const float> frame) const
{
    std::vector<Vec3d> positions(m_joints.size());
    std::vector<Quatd> orientations(m_joints.size());
    worldTransforms(frame, positions, orientations);
    return positions;
}

void Skeleton::worldTransforms(std::span<const float> frame, std::span<Vec3d> positions,
                               std::span<Quatd> orientations) const
{
    for (std::size_t i = 0; i < m_joints.size(); ++i) {
        const Quat& q = rotationAt(frame, int(i));
        const Quatd local{q.x, q.y, q.z, q.w};
        Vec3d offset = m_joints[i].offset;
        if (const int element = m_translationElement[i]; element >= 0) {
            const std::size_t t = m_layout->floatOffset(element);
            offset = {frame[t], frame[t + 1], frame[t + 2]};
        }
        if (m_joints[i].parent < 0) {
            positions[i] = offset;
            orientations[i] = local;
        } else {
            const auto p = std::size_t(m_joints[i].parent);
            positions[i] = positions[p] + rotate(orientations[p], offset);
            orientations[i] = orientations[p] * local;
        }
    }
}

} // namespace thespis::core::anim
