#pragma once
// How a character's face moves (paper §4.2, §5.2): a face frame — 68 MPEG-4 FAPs and the weights
// of the visemes and expressions (fap.h) — turned into a deformation of the character's rest mesh
// before skinning, and into turns of its face joints. Every face is described by the same parts:
//   - morph targets (sparse vertex offsets) whose weights are linear in the face channels: the
//     built-in humanoid's FAPs (each FAP's influence region, an offset per FAP unit) and a glTF
//     model's own targets through its mapping table (ARKit `jawOpen`, Oculus `viseme_PP` …);
//   - rigid parts turned about a pivot (the humanoid's jaw, eyeballs, eyelids and tongue), the
//     turn's angle given by FAPs; a part may be "dropped": its angle makes a feature point move
//     down by exactly the FAP value in its unit (open_jaw of N lowers the chin by N × MNS);
//   - joints a FAP turns (a glTF model's eye and jaw bones; FAPs 48–50 turn the head);
//   - the visemes' and expressions' low-level FAPs (face_tables.h) for faces that have no
//     targets of their own for them;
//   - lip contacts: pairs of inner-lip vertices that may touch and never pass through each other.
// Zero in every channel gives the rest mesh bit for bit. FaceDeformer applies a rig with buffers
// sized once (no allocation per frame); only the vertices the rig names are touched.

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "anim/quat.h"
#include "scene/fap.h"

namespace thespis::core::scene {

struct Character;

/// Sparse offsets of a morph target at weight 1 (rest space, metres).
struct MorphTarget {
    std::string name;
    std::vector<std::uint32_t> vertices; ///< ascending, no repeats
    std::vector<anim::Vec3> offsets;     ///< one per vertex
};

/// A target's weight gets `coefficient` × the value of face channel `channel` (fap.h), or × only
/// the value's positive or negative part: a bidirectional FAP often drives two targets, one per
/// direction (yaw_l_eyeball → ARKit's eyeLookOutLeft and eyeLookInLeft), and neither may go below 0.
struct MorphDrive {
    enum class Side : unsigned char { Both, Positive, Negative };
    int target = 0;
    int channel = 0;
    float coefficient = 0;
    Side side = Side::Both;
};

/// A part of the face turned rigidly (each vertex by its weight) about `pivot`.
struct RigidFacePart {
    std::string name;
    std::vector<std::uint32_t> vertices; ///< ascending, no repeats
    std::vector<float> weights;          ///< 0 … 1, one per vertex
    anim::Vec3d pivot;
    /// Turns about rest-space axes, `radiansPerUnit` × the channel's value each, applied in order.
    struct Turn {
        int channel = 0;
        anim::Vec3d axis;
        double radiansPerUnit = 0;
    };
    std::vector<Turn> turns;
    /// A turn about `axis` (before `turns`) whose angle moves `point` down (−y) by exactly
    /// `metresPerUnit` × the channel's value (negative values move it up). channel < 0: none.
    struct Drop {
        int channel = -1;
        anim::Vec3d axis;
        anim::Vec3d point;
        double metresPerUnit = 0;
    } drop;
    /// Moves after the turns, `metresPerUnit` × the channel's value along `direction`.
    struct Shift {
        int channel = 0;
        anim::Vec3d direction;
        double metresPerUnit = 0;
    };
    std::vector<Shift> shifts;
};

/// A face channel turning a skeleton joint (its rotation in the body frame, after the body's).
struct FaceJointDrive {
    int joint = 0;
    int channel = 0;
    anim::Vec3d axis; ///< in the joint's rest frame (world-aligned rest: world axes)
    double radiansPerUnit = 0;
};

/// A FAP value, in its unit, of a viseme's or expression's low-level FAP vector.
struct FapValue {
    int fap = 0;
    float value = 0;
};

/// A named feature point of the neutral face (MPEG-4 group.index, e.g. "2.1" the chin).
struct FeaturePoint {
    std::string name;
    std::uint32_t vertex = 0;
};

struct FaceRig {
    std::vector<MorphTarget> targets;
    std::vector<MorphDrive> drives;
    std::vector<RigidFacePart> parts;
    std::vector<FaceJointDrive> joints;
    /// Low-level FAPs of each viseme (1 … 14) and expression (1 … 6) at weight 1, added to the
    /// FAP channels before the drives; empty for a viseme or expression the face drives itself.
    std::array<std::vector<FapValue>, kVisemeCount> visemes;
    std::array<std::vector<FapValue>, kExpressionCount> expressions;
    /// Upper and lower inner-lip vertices at the same place along the mouth: after the
    /// deformation the lower is never above the upper (both meet halfway).
    std::vector<std::pair<std::uint32_t, std::uint32_t>> lipContacts;
    /// The neutral face's feature points and FAP units (the built-in humanoid; empty and zero
    /// for a model that drives its targets by name).
    std::vector<FeaturePoint> featurePoints;
    FapUnits units;

    bool empty() const { return targets.empty() && parts.empty() && joints.empty(); }
    const FeaturePoint* findFeaturePoint(std::string_view name) const;
};

/// The face channels with the rig's visemes and expressions expanded into their low-level FAPs
/// (added to the FAP channels): what the drives, parts and joints read. `face` is a face frame
/// (kFaceChannelCount floats) or empty (neutral: every channel 0); `channels` has
/// kFaceChannelCount floats.
void expandFaceChannels(const FaceRig& rig, std::span<const float> face, std::span<float> channels);
/// Each target's weight (one per rig.targets) for expanded `channels`: the drives summed.
void morphTargetWeights(const FaceRig& rig, std::span<const float> channels, std::span<float> weights);

/// Applies a character's face rig frame after frame. Built once per character (it lists the
/// vertices and triangles the rig reaches); deform() allocates nothing.
class FaceDeformer {
public:
    FaceDeformer() = default;
    explicit FaceDeformer(const Character& character);

    bool empty() const { return m_vertices.empty() && m_joints.empty(); }
    /// The vertices the face may move, ascending.
    std::span<const std::uint32_t> vertices() const { return m_vertices; }

    /// Writes the face's rest-space mesh for `face` (a face frame, kFaceChannelCount floats, or
    /// empty: neutral) into `positions` and `normals`, which hold the character's rest mesh on
    /// every vertex the face does not reach (they are left untouched).
    void deform(std::span<const float> face, std::span<anim::Vec3> positions, std::span<anim::Vec3> normals);
    /// Turns the face's joints in `body` (the character skeleton's frame) for `face`.
    void turnJoints(std::span<const float> face, std::span<float> body) const;

private:
    void expandChannels(std::span<const float> face);
    void updateNormals(std::span<const anim::Vec3> positions, std::span<anim::Vec3> normals);

    const Character* m_character = nullptr;
    std::vector<std::uint32_t> m_vertices;  // every vertex a target, part or contact names
    std::vector<std::uint32_t> m_triangles; // every triangle touching one of them
    std::vector<anim::Vec3> m_restFaceNormals; // normals from the triangles at rest, per m_vertices entry
    std::vector<std::int32_t> m_slot;          // vertex → index into m_vertices, or −1
    std::vector<float> m_channels, m_weights;
    std::vector<anim::Vec3> m_faceNormals;
    std::vector<FaceJointDrive> m_joints;
};

} // namespace thespis::core::scene
