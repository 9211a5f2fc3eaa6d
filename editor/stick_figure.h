#pragma once
// StickFigure: one character of the Skeletons view — its skeleton's joints in the world for a
// pose the Session published (forward kinematics of the body frame, placed where the character
// stands), and how PoseView should draw it. It keeps its own copy of the skeleton, so it never
// points into a runtime an edit replaces. Buffers are sized once: posing allocates nothing.

#include <QVector3D>

#include <span>
#include <string>
#include <vector>

#include "anim/quat.h"
#include "anim/skeleton.h"
#include "runtime/pose_set.h"
#include "widgets/pose_view.h"

namespace thespis::editor {

class StickFigure {
public:
    StickFigure(std::string name, const core::anim::Skeleton& skeleton);

    /// Poses the figure from its character's pose (a body frame on the skeleton's layout and
    /// its placement); poses of another size are ignored. No allocation.
    void setPose(const core::runtime::CharacterPose& pose);
    const std::string& name() const { return m_name; }
    const core::anim::Skeleton& skeleton() const { return m_skeleton; }
    /// World position of every joint of the skeleton (skeleton units, H-Anim axes).
    std::span<const QVector3D> positions() const { return m_positions; }
    /// The last frame posed, placed (the skeleton's layout).
    std::span<const float> frame() const { return m_frame; }

    /// How PoseView should draw this character: parents, sides from H-Anim (or common Left/Right)
    /// joint names, the head joint and a head size matching the rest pose's height.
    widgets::PoseFigure figure(const QColor& color) const;

private:
    void computeWorldPositions();

    std::string m_name;
    core::anim::Skeleton m_skeleton;
    std::vector<float> m_frame;
    std::vector<core::anim::Vec3d> m_world;
    std::vector<core::anim::Quatd> m_orientation;
    std::vector<QVector3D> m_positions;
};

} // namespace thespis::editor
