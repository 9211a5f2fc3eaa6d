#pragma once
// Skinning a Character's rest-pose mesh into a pose (see character.h for the world-aligned rest
// convention). Linear blend skinning (LBS) blends the joints' rigid transforms as matrices;
// dual-quaternion skinning (DQS, Kavan et al. 2008) blends them as unit dual quaternions, which
// keeps volume at twisting joints. Both read flat arrays and write into caller buffers: no
// allocation per frame. SkinningWorkers splits the vertices over persistent threads.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string_view>
#include <thread>
#include <vector>

#include "anim/quat.h"
#include "anim/skeleton.h"
#include "scene/character.h"
#include "util/error.h"

namespace thespis::core::scene {

enum class SkinningMethod : std::uint8_t { Linear, DualQuaternion };
const char* skinningMethodName(SkinningMethod method); ///< "lbs", "dqs"
Result<SkinningMethod> parseSkinningMethod(std::string_view name);

/// A joint's motion from the rest pose: a rest-pose point p goes to rotation·p + translation.
struct RigidTransform {
    anim::Quat rotation;     ///< unit
    anim::Vec3 translation;
};

/// One RigidTransform per skeleton joint for a frame of the skeleton's layout:
/// rotation = Q_j, translation = P_j − Q_j·restPosition_j. `restPositions` are the skeleton's
/// world joint positions at rest (skeleton.worldPositions(restFrame())). `scratchPositions` and
/// `scratchOrientations` hold jointCount() entries; nothing is allocated.
void computeSkinningTransforms(const anim::Skeleton& skeleton, std::span<const float> frame,
                               std::span<const anim::Vec3d> restPositions,
                               std::span<anim::Vec3d> scratchPositions,
                               std::span<anim::Quatd> scratchOrientations,
                               std::span<RigidTransform> out);

/// The joints' transforms of one frame in the forms the skinning loops read, computed once per
/// frame. For LBS, the displacement p ↦ (R − I)·p + t as a 3×4 matrix [R − I | t] stored as four
/// columns of 4 floats (the 4th unused), so that a column fills one SIMD register; blending
/// displacements and adding them to p gives the rest mesh back bit for bit in the rest pose,
/// whatever the weights sum to. For DQS, the unit dual quaternion (real part = rotation, dual
/// part = ½·translation·rotation). update() reuses the storage: once it has seen the joint count,
/// nothing is allocated.
struct SkinningPalette {
    struct alignas(16) Matrix {
        float columns[4][4];
    };
    struct alignas(16) DualQuaternion {
        anim::Quat real;
        anim::Quat dual;
    };
    std::vector<Matrix> matrices;
    std::vector<DualQuaternion> dualQuaternions;

    void update(std::span<const RigidTransform> joints);
    std::size_t jointCount() const { return matrices.size(); }
};

/// Skins vertices [begin, end): positions and normals into the out spans, which are indexed like
/// the mesh (out[v] for vertex v). LBS moves normals with the blended 3×3 and renormalises them;
/// DQS rotates them with the blended rotation. The skin must be valid (Skin::validate) for the
/// palette's joints. A character without skin moves each segment rigidly with its joint — use
/// skinRigidSegments for that.
void skinVertices(const Skin& skin, std::span<const anim::Vec3> restPositions,
                  std::span<const anim::Vec3> restNormals, const SkinningPalette& palette,
                  SkinningMethod method, std::size_t begin, std::size_t end,
                  std::span<anim::Vec3> outPositions, std::span<anim::Vec3> outNormals);

/// For characters without skin: every segment's vertices follow its joint (Character::segmentJoint).
/// The rest mesh is the character's, or the given one.
void skinRigidSegments(const Character& character, std::span<const RigidTransform> joints,
                       std::span<anim::Vec3> outPositions, std::span<anim::Vec3> outNormals,
                       std::span<const anim::Vec3> restPositions = {}, std::span<const anim::Vec3> restNormals = {});

/// Persistent worker threads that skin one mesh in parallel chunks; the calling thread takes
/// chunks too. threads ≤ 0: one per hardware thread; 1: everything on the calling thread.
/// skin() is called from one thread at a time; the destructor stops and joins the workers.
class SkinningWorkers {
public:
    explicit SkinningWorkers(int threads = 0);
    ~SkinningWorkers();
    SkinningWorkers(const SkinningWorkers&) = delete;
    SkinningWorkers& operator=(const SkinningWorkers&) = delete;

    int threadCount() const;
    /// skinVertices over all vertices (or skinRigidSegments when the skin is empty); returns when
    /// done. Builds its own palette from `joints` (allocating only when the joint count grows).
    /// The rest mesh is the character's, or `restPositions` / `restNormals` when given (a face
    /// deformed before skinning, face_rig.h).
    void skin(const Character& character, std::span<const RigidTransform> joints, SkinningMethod method,
              std::span<anim::Vec3> outPositions, std::span<anim::Vec3> outNormals,
              std::span<const anim::Vec3> restPositions = {}, std::span<const anim::Vec3> restNormals = {});

private:
    struct Shared;
    std::unique_ptr<Shared> m_shared;
    std::vector<std::thread> m_threads;
};

} // namespace thespis::core::scene
