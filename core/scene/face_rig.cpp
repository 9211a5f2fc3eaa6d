#include "scene/face_rig.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>

#include "anim/frame.h"
#include "scene/character.h"

namespace thespis::core::scene {

namespace {

using anim::Quatd;
using anim::Vec3;
using anim::Vec3d;

Vec3d cross(Vec3d a, Vec3d b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
Vec3d toDouble(Vec3 v) { return {v.x, v.y, v.z}; }

// The angle about unit `axis` through `pivot` that puts `point` at height point.y − drop, the
// one nearest to no turn (the farthest reachable when the drop is out of reach): with
// r = point − pivot, y(θ) = K + A cos θ + B sin θ (Rodrigues' formula's y component).
double dropAngle(Vec3d axis, Vec3d pivot, Vec3d point, double drop)
{
    const Vec3d r = point - pivot;
    const double along = dot(axis, r);
    const double a = r.y - axis.y * along, b = cross(axis, r).y, k = pivot.y + axis.y * along;
    const double radius = std::hypot(a, b);
    if (radius < 1e-12)
        return 0;
    const double phi = std::atan2(b, a);
    const double spread = std::acos(std::clamp((point.y - drop - k) / radius, -1.0, 1.0));
    const auto wrap = [](double angle) { return std::remainder(angle, 2 * std::numbers::pi); };
    const double first = wrap(phi - spread), second = wrap(phi + spread);
    return std::abs(first) <= std::abs(second) ? first : second;
}

} // namespace

const FeaturePoint* FaceRig::findFeaturePoint(std::string_view name) const
{
    for (const FeaturePoint& point : featurePoints)
        if (point.name == name)
            return &point;
    return nullptr;
}

FaceDeformer::FaceDeformer(const Character& character) : m_character(&character)
{
    const FaceRig& rig = character.face;
    const CharacterMesh& mesh = character.mesh;
    for (const MorphTarget& target : rig.targets)
        m_vertices.insert(m_vertices.end(), target.vertices.begin(), target.vertices.end());
    for (const RigidFacePart& part : rig.parts)
        m_vertices.insert(m_vertices.end(), part.vertices.begin(), part.vertices.end());
    for (const auto& [upper, lower] : rig.lipContacts)
        m_vertices.insert(m_vertices.end(), {upper, lower});
    std::sort(m_vertices.begin(), m_vertices.end());
    m_vertices.erase(std::unique(m_vertices.begin(), m_vertices.end()), m_vertices.end());
    m_slot.assign(mesh.vertexCount(), -1);
    for (std::size_t i = 0; i < m_vertices.size(); ++i)
        m_slot[m_vertices[i]] = std::int32_t(i);
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const std::uint32_t* corner = &mesh.indices[3 * t];
        if (m_slot[corner[0]] >= 0 || m_slot[corner[1]] >= 0 || m_slot[corner[2]] >= 0)
            m_triangles.push_back(std::uint32_t(t));
    }
    m_faceNormals.resize(m_vertices.size());
    m_restFaceNormals.resize(m_vertices.size());
    updateNormals(mesh.positions, {}); // the triangles' normals at rest, for the differences
    m_restFaceNormals = m_faceNormals;
    m_channels.resize(kFaceChannelCount);
    m_weights.resize(rig.targets.size());
    m_joints = rig.joints;
}

void expandFaceChannels(const FaceRig& rig, std::span<const float> face, std::span<float> channels)
{
    assert(channels.size() == std::size_t(kFaceChannelCount));
    std::fill(channels.begin(), channels.end(), 0.0f);
    if (face.size() != channels.size())
        return; // no face frame: neutral
    std::copy(face.begin(), face.end(), channels.begin());
    const auto expand = [&](const std::vector<FapValue>& values, float weight) {
        if (weight != 0)
            for (const FapValue& v : values)
                channels[std::size_t(fapChannel(v.fap))] += weight * v.value;
    };
    for (int v = 1; v <= kVisemeCount; ++v)
        expand(rig.visemes[std::size_t(v - 1)], face[std::size_t(visemeChannel(v))]);
    for (int e = 1; e <= kExpressionCount; ++e)
        expand(rig.expressions[std::size_t(e - 1)], face[std::size_t(expressionChannel(e))]);
}

void morphTargetWeights(const FaceRig& rig, std::span<const float> channels, std::span<float> weights)
{
    assert(weights.size() == rig.targets.size());
    std::fill(weights.begin(), weights.end(), 0.0f);
    for (const MorphDrive& drive : rig.drives) {
        float value = channels[std::size_t(drive.channel)];
        if (drive.side == MorphDrive::Side::Positive)
            value = std::max(value, 0.0f);
        else if (drive.side == MorphDrive::Side::Negative)
            value = std::min(value, 0.0f);
        weights[std::size_t(drive.target)] += drive.coefficient * value;
    }
}

void FaceDeformer::expandChannels(std::span<const float> face)
{
    expandFaceChannels(m_character->face, face, m_channels);
}

void FaceDeformer::deform(std::span<const float> face, std::span<Vec3> positions, std::span<Vec3> normals)
{
    if (!m_character)
        return;
    const FaceRig& rig = m_character->face;
    const CharacterMesh& mesh = m_character->mesh;
    assert(positions.size() == mesh.vertexCount() && normals.size() == mesh.vertexCount());
    for (const std::uint32_t v : m_vertices) {
        positions[v] = mesh.positions[v];
        normals[v] = mesh.normals[v];
    }
    expandChannels(face);
    if (std::all_of(m_channels.begin(), m_channels.end(), [](float c) { return c == 0; }))
        return; // the neutral face, exactly

    morphTargetWeights(rig, m_channels, m_weights);
    for (std::size_t t = 0; t < rig.targets.size(); ++t) {
        const float weight = m_weights[t];
        if (weight == 0)
            continue;
        const MorphTarget& target = rig.targets[t];
        for (std::size_t i = 0; i < target.vertices.size(); ++i) {
            Vec3& p = positions[target.vertices[i]];
            p = p + target.offsets[i] * weight;
        }
    }

    for (const RigidFacePart& part : rig.parts) {
        Quatd turn;
        if (part.drop.channel >= 0)
            if (const double value = m_channels[std::size_t(part.drop.channel)]; value != 0)
                turn = Quatd::fromAxisAngle(part.drop.axis, dropAngle(part.drop.axis, part.pivot, part.drop.point,
                                                                      value * part.drop.metresPerUnit));
        for (const RigidFacePart::Turn& t : part.turns)
            if (const double value = m_channels[std::size_t(t.channel)]; value != 0)
                turn = Quatd::fromAxisAngle(t.axis, value * t.radiansPerUnit) * turn;
        Vec3d shift;
        for (const RigidFacePart::Shift& s : part.shifts)
            shift = shift + s.direction * (m_channels[std::size_t(s.channel)] * s.metresPerUnit);
        if (turn == Quatd{} && shift == Vec3d{})
            continue;
        for (std::size_t i = 0; i < part.vertices.size(); ++i) {
            Vec3& p = positions[part.vertices[i]];
            const Vec3d from = toDouble(p);
            const Vec3d to = anim::rotate(turn, from - part.pivot) + part.pivot + shift;
            const Vec3d moved = from + (to - from) * double(part.weights[i]);
            p = {float(moved.x), float(moved.y), float(moved.z)};
        }
    }

    for (const auto& [upper, lower] : rig.lipContacts)
        if (positions[lower].y > positions[upper].y) {
            const float middle = 0.5f * (positions[lower].y + positions[upper].y);
            positions[lower].y = positions[upper].y = middle;
        }
    updateNormals(positions, normals);
}

void FaceDeformer::updateNormals(std::span<const Vec3> positions, std::span<Vec3> normals)
{
    const CharacterMesh& mesh = m_character->mesh;
    std::fill(m_faceNormals.begin(), m_faceNormals.end(), Vec3{});
    for (const std::uint32_t t : m_triangles) {
        const std::uint32_t* corner = &mesh.indices[3 * std::size_t(t)];
        const Vec3d a = toDouble(positions[corner[0]]), b = toDouble(positions[corner[1]]), c = toDouble(positions[corner[2]]);
        const Vec3d n = cross(b - a, c - a); // area-weighted
        const Vec3 nf{float(n.x), float(n.y), float(n.z)};
        for (int k = 0; k < 3; ++k)
            if (const std::int32_t slot = m_slot[corner[k]]; slot >= 0)
                m_faceNormals[std::size_t(slot)] = m_faceNormals[std::size_t(slot)] + nf;
    }
    if (normals.empty())
        return;
    // The rest normal turned as the triangles round it turned: the artist's (or generator's)
    // normal stays exactly where nothing moved.
    for (std::size_t i = 0; i < m_vertices.size(); ++i) {
        const Vec3 now = m_faceNormals[i], rest = m_restFaceNormals[i];
        if (now == rest)
            continue;
        const auto unit = [](Vec3 v) {
            const float length = std::sqrt(dot(v, v));
            return length > 0 ? v * (1 / length) : v;
        };
        normals[m_vertices[i]] = unit(normals[m_vertices[i]] + unit(now) - unit(rest));
    }
}

void FaceDeformer::turnJoints(std::span<const float> face, std::span<float> body) const
{
    if (m_joints.empty() || face.size() != std::size_t(kFaceChannelCount))
        return;
    const FaceRig& rig = m_character->face;
    for (const FaceJointDrive& drive : m_joints) {
        double value = face[std::size_t(drive.channel)];
        if (drive.channel < kFapCount) { // the visemes' and expressions' share of this FAP
            const int fap = drive.channel + 1;
            const auto add = [&](const std::vector<FapValue>& values, float weight) {
                if (weight != 0)
                    for (const FapValue& v : values)
                        if (v.fap == fap)
                            value += weight * v.value;
            };
            for (int v = 1; v <= kVisemeCount; ++v)
                add(rig.visemes[std::size_t(v - 1)], face[std::size_t(visemeChannel(v))]);
            for (int e = 1; e <= kExpressionCount; ++e)
                add(rig.expressions[std::size_t(e - 1)], face[std::size_t(expressionChannel(e))]);
        }
        if (value == 0)
            continue;
        anim::Quat& rotation = anim::rotationAt(body, drive.joint);
        const Quatd turned = anim::normalize(Quatd{rotation.x, rotation.y, rotation.z, rotation.w} *
                                             Quatd::fromAxisAngle(drive.axis, value * drive.radiansPerUnit));
        rotation = {float(turned.x), float(turned.y), float(turned.z), float(turned.w)};
    }
}

} // namespace thespis::core::scene
