#pragma once
// The OSG node of one character: one osg::Geometry per mesh segment, sharing the character's
// vertex buffers — posed positions and normals in world space (rewritten every frame), texture
// coordinates, and the per-vertex transfer vector as generic vertex attributes (see shaders.h).
// Each segment carries its own copy of the light rotated into its current frame (paper §6.1.1:
// L_seg = R(Q_seg⁻¹)·L with Q_seg = Q_joint·segment.bindRotation), and its material.
//
// The transfer comes from a bake (lighting::TransferBake) when there is one. Without a bake,
// and for segments the bake leaves out (occluders), it is the diffuse unshadowed (DU) transfer
// in closed form, t_lm = (Â_l/π)·Y_lm(n) for the rest normal n expressed in the segment's bind
// frame, as a bake stores it. The paper does not shade occluders with PRT at all — they are
// props that only cast shadows, often invisible (phantom geometry) — so DU is just a sensible
// look for them when they are drawn.
//
// The node owns persistent buffers: setPose allocates nothing. It is not thread-safe; pose it
// between frames of a single-threaded viewer.

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include <osg/Geometry>
#include <osg/Group>
#include <osg/Program>
#include <osg/Uniform>
#include <osg/ref_ptr>

#include "lighting/sh.h"
#include "lighting/sh_rotation.h"
#include "lighting/transfer_bake.h"
#include "render/camera.h"
#include "render/shading.h"
#include "scene/character.h"
#include "scene/face_rig.h"
#include "scene/skinning.h"
#include "util/error.h"

namespace thespis::core::render {

struct CharacterNodeOptions {
    scene::SkinningMethod skinning = scene::SkinningMethod::Linear;
    /// Shared worker threads; null: the node skins on the calling thread.
    scene::SkinningWorkers* workers = nullptr;
    /// Order of the DU transfer when there is no bake (bands above 2 add little to a diffuse surface).
    int unbakedOrder = 3;
};

class CharacterNode {
public:
    /// Builds the node in the rest pose, lit by no light until setLight. The bake, when given,
    /// must belong to the character's mesh and have order ≤ shaders::kMaxTransferOrder (6).
    static Result<std::unique_ptr<CharacterNode>> create(std::shared_ptr<const scene::Character> character,
                                                         const lighting::TransferBake* bake = nullptr,
                                                         const CharacterNodeOptions& options = {});
    CharacterNode(const CharacterNode&) = delete;
    CharacterNode& operator=(const CharacterNode&) = delete;

    osg::Group* node() const { return m_group.get(); }
    const scene::Character& character() const { return *m_character; }
    int transferOrder() const { return m_order; }
    std::size_t segmentCount() const { return m_geometries.size(); }
    osg::Geometry* segmentGeometry(std::size_t segment) const { return m_geometries[segment].get(); }

    void setShading(Shading shading);
    Shading shading() const { return m_shading; }

    /// The world light (any order; bands beyond the transfer order are dropped, missing ones are 0).
    void setLight(const lighting::ShRgb& worldLight);

    /// Poses the character: moves its face for `face` (a face frame, anim::FrameLayout::mpeg4Face;
    /// empty: neutral) and skins the mesh for `frame` (the skeleton's frame layout), uploads
    /// positions and normals, and rotates the light into every segment's new frame. The PRT
    /// transfer stays the rest face's, per vertex: a moving face is lit as if it had not moved.
    void setPose(std::span<const float> frame, std::span<const float> face = {});
    /// How many times setPose skinned the mesh.
    std::uint64_t poseCount() const { return m_poseCount; }

    /// The posed mesh, as uploaded (world space, indexed like the character's mesh).
    std::span<const anim::Vec3> posedPositions() const { return m_positions; }
    std::span<const anim::Vec3> posedNormals() const { return m_normals; }
    Bounds bounds() const;
    /// A joint's current world rotation (its turn from the rest pose).
    anim::Quatd jointRotation(int joint) const
    {
        const anim::Quat& q = m_jointTransforms[std::size_t(joint)].rotation;
        return {q.x, q.y, q.z, q.w};
    }
    /// A segment's current world rotation Q_joint·bindRotation.
    const anim::Quatd& segmentRotation(std::size_t segment) const { return m_segmentRotations[segment]; }
    /// The light coefficients a segment's shader receives, order² RGB triplets (coefficient i's
    /// red, green, blue at 3i, 3i+1, 3i+2): the uniform's own storage.
    std::span<const float> segmentLight(std::size_t segment) const;

    /// Tints a segment as selected (the segment tag editor's selection), in every shading mode:
    /// 35 % towards orange plus an orange rim. Off for every segment at first.
    void setSegmentHighlighted(std::size_t segment, bool highlighted);
    bool segmentHighlighted(std::size_t segment) const { return m_highlighted[segment] != 0; }

private:
    CharacterNode() = default;
    void buildGeometry(const lighting::TransferBake* bake);
    void updateSegmentLights();

    std::shared_ptr<const scene::Character> m_character;
    int m_order = 0;
    scene::SkinningMethod m_skinning = scene::SkinningMethod::Linear;
    std::unique_ptr<scene::SkinningWorkers> m_ownWorkers;
    scene::SkinningWorkers* m_workers = nullptr;

    // Per-frame buffers, sized once.
    scene::FaceDeformer m_face;
    std::vector<float> m_frame;                       // the body frame with the face's joint turns
    std::vector<anim::Vec3> m_facePositions, m_faceNormals; // the rest mesh with the face moved
    std::vector<anim::Vec3d> m_restJointPositions, m_jointPositions;
    std::vector<anim::Quatd> m_jointOrientations;
    std::vector<scene::RigidTransform> m_jointTransforms;
    std::vector<anim::Vec3> m_positions, m_normals;
    std::vector<int> m_segmentJoints;
    std::vector<anim::Quatd> m_segmentRotations;
    lighting::ShRgb m_worldLight, m_segmentLight;
    lighting::ShRotation m_rotation;

    Shading m_shading = Shading::Prt;
    std::array<osg::ref_ptr<osg::Program>, 3> m_programs; // by Shading
    osg::ref_ptr<osg::Group> m_group;
    osg::ref_ptr<osg::Vec3Array> m_vertexArray, m_normalArray;
    std::vector<osg::ref_ptr<osg::Geometry>> m_geometries;
    std::vector<osg::ref_ptr<osg::Uniform>> m_lightUniforms; // shLight of each segment
    std::vector<osg::ref_ptr<osg::Uniform>> m_highlightUniforms; // selectionHighlight of each segment
    std::vector<char> m_highlighted;
    osg::ref_ptr<osg::Uniform> m_lightDirection, m_lightColor, m_ambientIrradiance;
    std::uint64_t m_poseCount = 0;
};

} // namespace thespis::core::render
