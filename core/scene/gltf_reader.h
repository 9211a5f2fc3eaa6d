#pragma once
// Private to core/scene's glTF importers (gltf_mesh.cpp, gltf_character.cpp, gltf_animation.cpp):
// one reading of a glTF file that loadGltfMesh and loadGltfCharacter share. It opens the file
// (refusing the extensions that change geometry), reads accessors with every bound checked,
// places the nodes at rest (gltf_reader.cpp) and builds the rest-pose mesh (see gltf_mesh.h)
// together with the per-vertex data a character needs: skin joints and weights, texture
// coordinates, and where each segment came from (gltf_mesh.cpp). Not installed for other parts
// of core: everything here speaks tinygltf.

#include <array>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "scene/character_mesh.h"
#include "scene/face_rig.h"
#include "scene/gltf_mesh.h"
#include "util/error.h"

namespace thespis::core::scene::gltf {

// ---- 4×4 affine matrices, column-major as glTF stores them -------------------------------------

using Mat4 = std::array<double, 16>;

inline constexpr Mat4 kIdentity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

Mat4 multiply(const Mat4& a, const Mat4& b);
Vec3d transformPoint(const Mat4& m, Vec3d p);
/// The 3×3 part applied to a direction (no translation).
Vec3d transformVector(const Mat4& m, Vec3d v);
double determinant3(const Mat4& m);
/// Cofactor matrix of the 3×3 part, row-major: transforms normals (the inverse transpose up to a
/// positive factor times the determinant's sign, which the caller normalizes away and handles).
std::array<double, 9> normalMatrix(const Mat4& m);
/// Inverse of an affine matrix (last row 0 0 0 1); nullopt when singular.
std::optional<Mat4> invertAffine(const Mat4& m);
/// A node's own transform: its matrix, or translation · rotation · scale.
Mat4 localMatrix(const tinygltf::Node& node);
/// The rotation of an affine matrix with scale removed (Gram–Schmidt on its columns); a
/// mirroring matrix gives the rotation of its negation.
Quatd rotationOf(const Mat4& m);

// ---- the file ------------------------------------------------------------------------------------

struct File {
    tinygltf::Model model;
    std::string name; ///< the path as given, for messages
    /// Images that could not be decoded (the file still loads, without those textures).
    std::vector<std::string> imageWarnings;
};

/// Reads a .gltf or .glb file (by its first bytes). Images are decoded to 8 or 16 bits per
/// channel, 4 channels, when `decodeImages` is set, else left empty. Refuses files that require
/// an extension changing geometry (Draco, meshopt …) with the extension named.
Result<File> readFile(const std::filesystem::path& path, bool decodeImages);

/// An accessor's elements as doubles (normalized integers mapped to [0, 1] or [-1, 1]).
struct AccessorData {
    std::vector<double> values;
    int components = 0;
    std::size_t count = 0;
    double operator()(std::size_t element, int component) const
    {
        return values[element * std::size_t(components) + std::size_t(component)];
    }
};

/// Reads accessors of one file, checking every offset, stride and sparse index against the
/// buffers; errors name the file and what the accessor was for.
class AccessorReader {
public:
    explicit AccessorReader(const File& file) : m_model(file.model), m_file(file.name) {}

    const std::string& file() const { return m_file; }
    /// "The glTF file F is broken: <what>."
    Error broken(const std::string& what) const;
    /// Reads accessor `index`, which `use` names for messages ("mesh \"Body\" POSITION").
    Result<AccessorData> read(int index, const std::string& use) const;

private:
    Result<std::span<const unsigned char>> viewBytes(int viewIndex, const std::string& where) const;
    Result<std::span<const unsigned char>> viewRange(int viewIndex, int offset, std::size_t length,
                                                     const std::string& where) const;

    const tinygltf::Model& m_model;
    std::string m_file;
};

/// The node hierarchy at rest: every node at its own TRS / matrix.
struct NodeTree {
    std::vector<int> parent; ///< -1 for a root
    std::vector<Mat4> world; ///< world transform of each node at rest
};

/// Checks the hierarchy (children exist, one parent each, no cycle) and places the nodes.
Result<NodeTree> nodeTree(const tinygltf::Model& model, const AccessorReader& reader);

/// A node's name, else its mesh's name, else "node<index>".
std::string nodeName(const tinygltf::Model& model, int node);

/// The names of a mesh's morph targets (as many as its primitives with the most have): Blender,
/// three.js and FBX2glTF name them in the mesh's extras ("targetNames"); without names, or with
/// names that do not fit, they are "<mesh name>:<index>" ("mesh<index>:<index>" when unnamed).
std::vector<std::string> morphTargetNames(const tinygltf::Mesh& mesh, int meshIndex);

/// The rest world transform of a node's parent (identity for a scene root).
Mat4 parentWorld(const NodeTree& tree, int node);

// ---- the rest-pose mesh ------------------------------------------------------------------------

/// Where a segment of the mesh came from.
struct SegmentSource {
    int meshNode = -1;  ///< the mesh node whose primitives it holds (the first one, for a joint segment)
    int jointNode = -1; ///< the node it follows: its joint when split from a skinned mesh, the
                        ///< skin's root joint for an unsplit skinned mesh, the mesh node itself otherwise
    bool splitFromJoint = false;
    int material = -1;  ///< glTF material of its primitives (of the first one when they differ), -1: none
    bool mixedMaterials = false; ///< its primitives use different materials
};

struct MeshData {
    CharacterMesh mesh;
    std::vector<SegmentSource> sources; ///< per segment
    /// Per vertex: the texture coordinates its material's base colour texture reads (TEXCOORD_n),
    /// (0, 0) where a primitive has none.
    std::vector<std::array<float, 2>> texcoords;
    bool hasTexcoords = false; ///< some primitive had texture coordinates
    /// Per vertex of a skinned primitive: the glTF node of each of its 8 influences (-1: unused)
    /// and their weights as the file gives them (not normalized; a vertex the file leaves
    /// unweighted gets weight 1 on the skin's root joint). Rigid vertices have no influence.
    std::vector<std::array<int, 8>> jointNodes;
    std::vector<std::array<float, 8>> weights;
    /// The meshes' morph targets as rest-space offsets of the vertices they move (see gltf_mesh.h),
    /// one per name: targets of several meshes and primitives that share a name are one target.
    std::vector<MorphTarget> targets;
};

/// Builds the rest-pose mesh of the default scene (the rules of gltf_mesh.h). `names` gives the
/// name each node lends to segments (a mesh node's segment, a joint's split segment and its
/// Segment.joint), one per node.
Result<MeshData> readMesh(const File& file, const NodeTree& tree, const GltfMeshOptions& options,
                          std::span<const std::string> names);

} // namespace thespis::core::scene::gltf
