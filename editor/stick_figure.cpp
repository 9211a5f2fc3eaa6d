#include "editor/stick_figure.h"

#include <QString>

#include <algorithm>
#include <cmath>

#include "editor/qt_conversions.h"

namespace thespis::editor {

namespace {

widgets::BodySide sideOf(const std::string& name)
{
    const QString n = fromUtf8(name);
    // H-Anim "l_elbow"; BVH "LeftArm", "lShldr", "upperarm.L", "Bip01 L UpperArm".
    if (n.startsWith(QLatin1String("l_")) || n.startsWith(QLatin1String("Left")) || n.endsWith(QLatin1String(".L")) ||
        n.endsWith(QLatin1String("_L")) || n.contains(QLatin1String(" L ")) ||
        (n.size() > 1 && n[0] == QLatin1Char('l') && n[1].isUpper()))
        return widgets::BodySide::Left;
    if (n.startsWith(QLatin1String("r_")) || n.startsWith(QLatin1String("Right")) || n.endsWith(QLatin1String(".R")) ||
        n.endsWith(QLatin1String("_R")) || n.contains(QLatin1String(" R ")) ||
        (n.size() > 1 && n[0] == QLatin1Char('r') && n[1].isUpper()))
        return widgets::BodySide::Right;
    return widgets::BodySide::Centre;
}

int findHeadJoint(const core::anim::Skeleton& skeleton)
{
    if (const int skullbase = skeleton.find("skullbase"); skullbase >= 0)
        return skullbase;
    for (int joint = 0; joint < skeleton.jointCount(); ++joint)
        if (fromUtf8(skeleton.joint(joint).name).compare(QLatin1String("head"), Qt::CaseInsensitive) == 0)
            return joint;
    return -1;
}

} // namespace

StickFigure::StickFigure(std::string name, const core::anim::Skeleton& skeleton)
    : m_name(std::move(name)), m_skeleton(skeleton)
{
    const std::size_t joints = std::size_t(m_skeleton.jointCount());
    m_frame = m_skeleton.restFrame();
    m_world.resize(joints);
    m_orientation.resize(joints);
    m_positions.resize(joints);
    computeWorldPositions();
}

void StickFigure::setPose(const core::runtime::CharacterPose& pose)
{
    if (pose.body.size() != m_frame.size())
        return;
    std::copy(pose.body.begin(), pose.body.end(), m_frame.begin());
    pose.placement.apply(*m_skeleton.frameLayout(), m_frame);
    computeWorldPositions();
}

void StickFigure::computeWorldPositions()
{
    m_skeleton.worldTransforms(m_frame, m_world, m_orientation);
    for (std::size_t i = 0; i < m_world.size(); ++i)
        m_positions[i] = QVector3D(float(m_world[i].x), float(m_world[i].y), float(m_world[i].z));
}

widgets::PoseFigure StickFigure::figure(const QColor& color) const
{
    const core::anim::Skeleton& skeleton = m_skeleton;
    widgets::PoseFigure figure;
    figure.name = fromUtf8(m_name);
    figure.color = color;
    figure.parents = skeleton.parents();
    figure.sides.reserve(figure.parents.size());
    for (const core::anim::Joint& joint : skeleton.joints())
        figure.sides.push_back(sideOf(joint.name));
    figure.headJoint = findHeadJoint(skeleton);

    // Head size from the rest pose's height (an adult head is about 1/8 of the body, so the
    // radius is about 1/16), which works for metres and for centimetre BVH skeletons alike.
    const std::vector<core::anim::Vec3d> rest = skeleton.worldPositions(skeleton.restFrame());
    double low = 0, high = 0;
    if (!rest.empty()) {
        low = high = rest.front().y;
        for (const core::anim::Vec3d& p : rest) {
            low = std::min(low, p.y);
            high = std::max(high, p.y);
        }
    }
    figure.headRadius = high > low ? float((high - low) / 16.0) : 0.1f;
    return figure;
}

} // namespace thespis::editor
