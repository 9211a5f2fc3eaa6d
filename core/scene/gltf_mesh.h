#pragma once
// glTF 2.0 (.gltf / .glb) → CharacterMesh in bind pose, through tinygltf (Debian's compiled
// library). The full character import (skins, clips, materials, H-Anim joint mapping) is
// gltf_character.h, which builds the same mesh.
//
// The pose is the scene's rest pose: every node at its own TRS/matrix. Positions and normals are
// in world space (node world transforms). A skinned mesh ignores its node's transform and is
// skinned (linear blend, up to 8 weights) by joint world · inverse bind matrix at that rest pose:
// when the rest pose is the bind pose (the usual case) every such matrix is the same transform B
// and the mesh comes out as modelled, placed where the skeleton stands; when a file rests in
// another pose (RobotExpressive's hands are bound in a T-pose, its arms rest down) the skinned
// parts follow the skeleton like the unskinned mesh nodes do. Morph targets at their default
// weights (mesh.weights, or the node's) are part of the rest shape, as the file shows the model;
// the character import also keeps their POSITION offsets as the face's targets, which a face frame
// adds on top of that shape (gltf_character.h). Missing (or zero) normals are computed, area-weighted.
//
// Segments: every mesh node (each primitive of a mesh becomes part of that node's segment) is a
// segment named after the node (or its mesh, or "node<index>"). When `splitSkinnedByJoint` is
// set, skinned triangles are grouped by dominant joint (the joint with the largest weight summed
// over a triangle's three vertices; vertices shared across the cut are duplicated), one segment
// per joint node named after it, merged across the skinned meshes that share that joint. Names are
// kept unique with a "#2", "#3" suffix. Segment.joint is the raw glTF node name (mesh node or
// joint; "" for an unsplit skinned mesh); mapping to H-Anim comes with the character import.
// With `splitByMaterial`, a segment holds the primitives of one material only: a mesh with several
// materials gives segments named "<name>/<material name>" (the character import uses this so that
// every segment has one material).
// Segment bind frames (rotation with scale removed, and translation): the mesh node's world
// transform, the root joint's skinning matrix for an unsplit skinned mesh, the joint's world
// transform for a split segment.
// Refused with a clear error naming the feature: Draco / meshopt / other required extensions
// that change geometry, points and lines (strips and fans are converted), missing positions,
// anything out of range (accessors, buffer views, sparse indices, joints, node links).

#include <filesystem>

#include "scene/character_mesh.h"
#include "util/error.h"

namespace thespis::core::scene {

struct GltfMeshOptions {
    bool splitSkinnedByJoint = true;
    bool splitByMaterial = false;
};

Result<CharacterMesh> loadGltfMesh(const std::filesystem::path& path, const GltfMeshOptions& options = {});

} // namespace thespis::core::scene
