#include "editor/pose_sampler.h"

#include <QString>

#include <algorithm>
#include <cassert>
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

PoseSampler::PoseSampler(const core::scenario::CharacterRuntime& character)
    : m_character(&character)
{
    const core::anim::Skeleton& skeleton = character.skeleton;
    const std::size_t joints = std::size_t(skeleton.jointCount());
    m_frame = skeleton.restFrame();
    // The body schedule is built on the skeleton's layout; evaluate() writes exactly that many.
    assert(!character.body || character.body->layout()->floatCount() == m_frame.size());
    m_world.resize(joints);
    m_orientation.resize(joints);
    m_positions.resize(joints);
    computeWorldPositions();
}

void PoseSampler::sample(double seconds)
{
    if (m_character->body && m_character->body->layout()->floatCount() == m_frame.size())
        m_character->evaluateBody(seconds, m_frame);
    computeWorldPositions();
}

void PoseSampler::setFrame(std::span<const float> frame)
{
    if (frame.size() != m_frame.size())
        return;
    std::copy(frame.begin(), frame.end(), m_frame.begin());
    m_character->place(*m_character->skeleton.frameLayout(), m_frame);
    computeWorldPositions();
}

void PoseSampler::computeWorldPositions()
{
    m_character->skeleton.worldTransforms(m_frame, m_world, m_orientation);
    for (std::size_t i = 0; i < m_world.size(); ++i)
        m_positions[i] = QVector3D(float(m_world[i].x), float(m_world[i].y), float(m_world[i].z));
}

widgets::PoseFigure PoseSampler::figure(const QColor& color) const
{
    const core::anim::Skeleton& skeleton = m_character->skeleton;
    widgets::PoseFigure figure;
    figure.name = fromUtf8(m_character->name);
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

std::pair<QVector3D, QVector3D> PoseSampler::sweepBounds(double duration, double step)
{
    sample(0.0);
    QVector3D low = m_positions.empty() ? QVector3D() : m_positions.front();
    QVector3D high = low;
    const auto grow = [&] {
        for (const QVector3D& p : m_positions) {
            low = QVector3D(std::min(low.x(), p.x()), std::min(low.y(), p.y()), std::min(low.z(), p.z()));
            high = QVector3D(std::max(high.x(), p.x()), std::max(high.y(), p.y()), std::max(high.z(), p.z()));
        }
    };
    grow();
    const int samples = step > 0 && duration > 0 ? int(std::ceil(duration / step)) : 0;
    for (int i = 1; i <= samples; ++i) {
        sample(std::min(duration, i * step));
        grow();
    }
    sample(0.0);
    return {low, high};
}

} // namespace thespis::editor
