#pragma once
// A character's joint hierarchy and rest pose. Joints are stored parents-first; joint 0 is the
// root, whose translation is animated. A body frame (FrameLayout) has one rotation per joint,
// in its parent's frame (identity = rest pose), then a translation for the root and for every
// other joint marked `translates`, in joint order.

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "anim/frame.h"
#include "util/error.h"

namespace thespis::core::anim {

struct Joint {
    std::string name;       ///< H-Anim name when mapped, else the source file's name
    std::string sourceName; ///< name in the file it came from (BVH, glTF); empty if built in
    int parent = -1;        ///< index of the parent joint, -1 for the root
    Vec3d offset;           ///< rest translation from the parent joint, in skeleton units
    std::string rotationOrder = "ZXY"; ///< Euler order used when written to BVH
    std::optional<Vec3d> endSite;      ///< BVH "End Site" offset of a leaf, kept for export
    /// The joint's translation is animated (always true for the root): the frame then holds a
    /// translation element for it, replacing `offset`.
    bool translates = false;
    bool operator==(const Joint&) const = default;
};

class Skeleton {
public:
    Skeleton() = default;
    /// Checks the rules (non-empty, unique names, parents before children, single root) and
    /// builds the frame layout.
    static Result<Skeleton> create(std::vector<Joint> joints);

    int jointCount() const { return int(m_joints.size()); }
    const Joint& joint(int index) const { return m_joints[std::size_t(index)]; }
    const std::vector<Joint>& joints() const { return m_joints; }
    int find(std::string_view name) const;
    std::vector<int> parents() const;

    /// Rotations for every joint (in joint order) and the root translation.
    const FrameLayoutPtr& frameLayout() const { return m_layout; }
    /// Translation element index of a joint (in the layout), or -1 when it does not translate.
    int translationElement(int joint) const;
    /// Identity rotations and translating joints at their rest offsets.
    std::vector<float> restFrame() const;

    /// World position of each joint for a frame of this skeleton's layout.
    std::vector<Vec3d> worldPositions(std::span<const float> frame) const;
    /// The same into caller buffers of jointCount() entries (`orientations` receives each
    /// joint's world rotation), for per-frame use without allocation.
    void worldTransforms(std::span<const float> frame, std::span<Vec3d> positions,
                         std::span<Quatd> orientations) const;

private:
    std::vector<Joint> m_joints;
    FrameLayoutPtr m_layout;
    std::vector<int> m_translationElement;
};

} // namespace thespis::core::anim
