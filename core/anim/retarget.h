#pragma once
// Plays a frame of one skeleton on another by joint name: a motion capture rig's frames on the
// scenario's animation skeleton (H-Anim), that skeleton's frames on a character's own rig (a glTF
// rig mapped onto H-Anim names). Both follow the world-aligned rest convention (identity rotation
// = rest pose, rest frames aligned with the world), but their rest *shapes* differ: a CMU rig
// rests in a T-pose with its legs apart, H-Anim with its arms at its sides. So each target bone
// is turned to point where the source's bone of the same name points (its rest direction is
// aligned once, by the smallest rotation taking the target's rest bone direction onto the
// source's), and the rotations between are found from the source's own chain, so that source
// joints the target lacks (CMU's LHipJoint, a second spine joint) still move what is below them.
// Target joints the source lacks keep their rest rotation relative to their parent.
//
// The body is placed by its hips (else by its highest mapped joint, normally humanoid_root): the
// target's hips follow the source's, scaled by the bodies' size ratio (leg lengths; else the
// source's unit) from where the source stands at rest, so the legs hang from the right place
// whatever the pelvis above them is like. A rig whose rest pose hangs from its root at y = 0 (CMU) is taken to
// stand with its lowest foot joint as high above the ground as the target's (scaled), so the
// scaled motion keeps the target's feet on the ground. Given where the source's feet stand
// (RetargetOptions::sourcePlantedFeet), each frame's feet are also set as high as the source's,
// scaled, so a planted foot stays planted on bodies of other proportions.
//
// Built once; apply() allocates nothing and, where the two skeletons agree (the same rig), copies
// rotations exactly.

#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "anim/body_measure.h"
#include "anim/skeleton.h"

namespace thespis::core::anim {

struct RetargetOptions {
    /// Target units per source unit for the body's motion. 0: from the bodies — the ratio of
    /// their leg lengths when both have legs, else sourceUnit (a target in metres), else the
    /// ratio of the rest heights of two roots of the same name, else 1.
    double scale = 0;
    /// Metres per source unit (e.g. 0.01 for centimetres, CMU's 0.0564), 0 when unknown. Used when
    /// a body has no legs to measure.
    double sourceUnit = 0;
    /// How high the source's feet (footHeight() of its foot joints, body_measure.h) are when they
    /// stand on its floor, in source units. With it, every frame's target feet are set as high
    /// over the target's floor as the source's are over its own, scaled (never below it): a
    /// planted foot stays on the ground whatever the bodies' proportions. Without it, a source that stands on y = 0 at
    /// rest gives its own rest feet height; one that does not (motion capture hanging from its
    /// root) is placed by its hips alone. clip_retarget.h finds it from a whole clip.
    std::optional<double> sourcePlantedFeet;
    /// Per foot joint (H-Anim name): the turn, in the source joint's frame, that makes it flat on
    /// the floor as it is when the source stands on it. Feet are otherwise kept as the source holds
    /// them, flat when its rest pose is (clip_retarget.h measures this from a whole clip).
    std::map<std::string, Quat> flatFeet;
    /// The soles, when known better than body_measure.h's guess from the joints (from a mesh:
    /// scene/foot_soles.h).
    std::vector<BodyMeasure::SolePoint> sourceSoles, targetSoles;
};

class FrameRetarget {
public:
    enum class ScaleSource { Given, Legs, Unit, RootHeight, None };

    FrameRetarget() = default;
    FrameRetarget(const Skeleton& from, const Skeleton& to, const RetargetOptions& options = {});

    /// Target joints that found a source joint of the same name.
    int mappedJointCount() const { return m_mappedJoints; }
    /// Target units per source unit for the body's motion, and how it was found.
    double scale() const { return m_scale; }
    ScaleSource scaleSource() const { return m_scaleSource; }
    /// `toFrame` has the target layout's floatCount().
    void apply(std::span<const float> fromFrame, std::span<float> toFrame) const;
    /// The same with where the source's feet stand in this frame (a capture whose floor drifts);
    /// infinity stands the target's feet at their rest height whatever the source's do.
    void apply(std::span<const float> fromFrame, std::span<float> toFrame, float sourcePlantedFeet) const;
    /// True when apply() sets the target's feet on its floor (both bodies have feet below the
    /// placed joint).
    bool matchesFeet() const { return m_matchFeet; }

private:
    // A mapped target rotation: local = before · conj(Π up) · (Π down) · after, with up / down
    // the source rotations from the two joints' common ancestor down to the source joint of the
    // nearest mapped target ancestor (up) and to the joint's own source joint (down).
    struct RotationMap {
        std::size_t to = 0;
        Quat before, after;
        bool hasBefore = false, hasAfter = false;
        std::uint32_t upBegin = 0, upEnd = 0, downBegin = 0, downEnd = 0; // into m_path
    };
    // A step of forward kinematics: the joint's rotation and its offset from its parent (a
    // translation element, or its rest offset), as float offsets in a frame.
    struct ChainStep {
        std::size_t rotation = 0;
        int translation = -1;
        Vec3 offset;
    };
    static ChainStep chainStep(const Skeleton& skeleton, int joint);
    // The few joints placement and feet need (hips, legs, feet) as a tree walked once per frame:
    // each joint once, parents first, with its parent's place in the tree (-1: the first joint,
    // the source's root or the target's placed joint).
    struct TreeStep {
        ChainStep step;
        int parent = -1;
    };
    using Tree = std::vector<TreeStep>;
    static constexpr std::size_t kMaxTree = 32; // legs and feet; more, and the feet are not matched
    /// Adds `chain` (joints from the tree's first one down) to the tree; returns the place of its
    /// last joint. `places` maps joints already in the tree to theirs.
    static std::uint32_t addChain(const Skeleton& skeleton, std::span<const int> chain, Tree& tree,
                                  std::map<int, std::uint32_t>& places);
    /// Positions and orientations of the tree's first `count` joints: from the first joint's
    /// translation (`fromOrigin`: the source's root) or relative to the first joint.
    static void treePoses(const Tree& tree, std::size_t count, std::span<const float> frame, bool fromOrigin,
                          Vec3* positions, Quat* orientations);
    // A sole point (body_measure.h) on a joint of the tree, its offset there.
    struct Sole {
        std::uint32_t joint = 0;
        Vec3 offset;
    };
    struct TranslationCopy {
        std::size_t from = 0, to = 0;
        Vec3 add; ///< to = from · scale + add
    };

    std::vector<RotationMap> m_rotations;
    std::vector<std::size_t> m_path;          ///< float offsets of source rotations
    std::vector<std::size_t> m_restRotations; ///< float offsets of target rotations left at rest
    // The body's placement: points (both hips, else the anchor) in the source's tree from its
    // root, and in the target's from the joint whose translation is written; the soles follow
    // in the trees. The source's placement needs only its tree's first joints.
    Tree m_sourceTree, m_targetTree;
    std::vector<std::uint32_t> m_sourcePoints, m_targetPoints;
    std::size_t m_sourcePlacementJoints = 0;
    std::size_t m_placedTranslation = 0; ///< float offset of the translation written
    Vec3 m_placeAdd;                     ///< it is source points · scale + add − target points
    float m_placedBaseY = 0;             ///< world height of the placed joint's parent at rest
    // Feet: the soles (source chains from its root, target chains from the placed joint) and the
    // heights that keep a planted foot on the ground.
    std::vector<Sole> m_sourceSoles, m_targetSoles;
    static constexpr std::size_t kMaxSoles = 96; ///< more, and the feet are not matched
    bool m_matchFeet = false;
    float m_sourcePlanted = 0, m_targetFeetRest = 0, m_sourceSoftness = 1, m_targetSoftness = 1;
    std::vector<TranslationCopy> m_translations;
    std::vector<std::pair<std::size_t, Vec3>> m_restTranslations;
    float m_scaleF = 1.0f;
    double m_scale = 1.0;
    ScaleSource m_scaleSource = ScaleSource::None;
    int m_mappedJoints = 0;
};

} // namespace thespis::core::anim
