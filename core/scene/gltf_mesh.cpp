// The rest-pose mesh of a glTF file: gltf::readMesh (segments, skin joints and weights, texture
// coordinates; the rules of gltf_mesh.h) and loadGltfMesh. Reading the file, its accessors and
// nodes is gltf_reader.cpp's.

#include "scene/gltf_mesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <tuple>
#include <vector>

#include "scene/gltf_reader.h"

namespace thespis::core::scene {
namespace gltf {

namespace {

/// One primitive in world space, triangles as a list.
struct PrimitiveGeometry {
    std::vector<Vec3> positions;
    std::vector<Vec3> normals;
    std::vector<std::array<float, 2>> texcoords; ///< empty when the primitive has none
    std::vector<std::uint32_t> indices;
    std::vector<std::array<int, 8>> joints; ///< skin joint slots per vertex (skinned meshes only)
    std::vector<std::array<float, 8>> weights;
    /// Its morph targets' offsets in world space, where they are not zero.
    struct Target {
        int index = 0; ///< into MeshData::targets
        std::vector<std::uint32_t> vertices;
        std::vector<Vec3> offsets;
    };
    std::vector<Target> targets;
};

constexpr std::uint32_t kUnmapped = 0xffffffffu;

struct SegmentBuilder {
    Segment segment;
    SegmentSource source;
    std::vector<Vec3> positions;
    std::vector<Vec3> normals;
    std::vector<std::array<float, 2>> texcoords;
    std::vector<std::array<int, 8>> jointNodes;
    std::vector<std::array<float, 8>> weights;
    std::vector<std::uint32_t> indices; ///< local to the builder
    /// Morph target offsets of its vertices: (MeshData::targets index, local vertex, offset).
    struct TargetOffset {
        int target;
        std::uint32_t vertex;
        Vec3 offset;
    };
    std::vector<TargetOffset> targetOffsets;
};

struct SkinBind {
    Mat4 placement = kIdentity;  ///< the root joint's skinning matrix: frame of an unsplit mesh
    int rootNode = -1;           ///< the skin's root joint
    std::vector<int> jointNodes; ///< skin joint slot → node index
    std::vector<Mat4> skinning;  ///< per joint slot: joint world · inverse bind matrix
};

Vec3 normalizedOr(Vec3d v, Vec3 fallback)
{
    const double length = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    if (!(length > 1e-20) || !std::isfinite(length))
        return fallback;
    return {float(v.x / length), float(v.y / length), float(v.z / length)};
}

class MeshBuilder {
public:
    MeshBuilder(const File& file, const AccessorReader& reader, const NodeTree& tree, const GltfMeshOptions& options,
                std::span<const std::string> names)
        : m_model(file.model), m_reader(reader), m_tree(tree), m_options(options), m_names(names)
    {
    }

    Result<std::vector<int>> meshNodesOfScene() const;
    Result<void> addMeshNode(int nodeIndex);
    MeshData finish();

private:
    /// Segments are keyed by what they gather: a mesh node or a joint, and the material when
    /// splitting by material.
    enum class Kind { MeshNode, Joint };
    using Key = std::tuple<Kind, int, int>;

    Result<SkinBind> skinBind(int skinIndex) const;
    Result<PrimitiveGeometry> readPrimitive(const tinygltf::Primitive& primitive, const std::string& use,
                                            const std::vector<double>& morphWeights, std::span<const int> targets,
                                            const SkinBind* skin, const Mat4& nodeWorld) const;
    std::vector<int> targetsOf(const tinygltf::Mesh& mesh, int meshIndex);
    Result<std::vector<std::uint32_t>> readTriangles(const tinygltf::Primitive& primitive, std::size_t vertexCount,
                                                     const std::string& use) const;
    std::string materialName(int material) const;
    std::size_t builderFor(Key key, const std::string& baseName, const std::string& joint, const Mat4& frame,
                           const SegmentSource& source);
    void append(std::size_t builder, const PrimitiveGeometry& geometry, std::span<const std::uint32_t> triangles,
                const SkinBind* skin, int material);

    const tinygltf::Model& m_model;
    const AccessorReader& m_reader;
    const NodeTree& m_tree;
    const GltfMeshOptions& m_options;
    std::span<const std::string> m_names;
    std::vector<SegmentBuilder> m_builders;
    std::map<Key, std::size_t> m_builderByKey;
    std::vector<std::string> m_targetNames;
    std::map<std::string, int> m_targetByName;
    bool m_hasTexcoords = false;
};

Result<std::vector<int>> MeshBuilder::meshNodesOfScene() const
{
    std::vector<int> roots;
    if (m_model.scenes.empty()) {
        for (std::size_t n = 0; n < m_model.nodes.size(); ++n)
            if (m_tree.parent[n] < 0)
                roots.push_back(int(n));
    } else {
        const int scene = m_model.defaultScene >= 0 ? m_model.defaultScene : 0;
        if (std::size_t(scene) >= m_model.scenes.size())
            return m_reader.broken("the default scene " + std::to_string(scene) + " does not exist");
        roots = m_model.scenes[std::size_t(scene)].nodes;
        for (int root : roots)
            if (root < 0 || std::size_t(root) >= m_model.nodes.size())
                return m_reader.broken("the scene names node " + std::to_string(root) + ", which does not exist");
    }
    // Depth first, children in file order: segments come out in the file's hierarchy order.
    std::vector<int> meshNodes;
    std::vector<int> stack(roots.rbegin(), roots.rend());
    while (!stack.empty()) {
        const int n = stack.back();
        stack.pop_back();
        const tinygltf::Node& node = m_model.nodes[std::size_t(n)];
        if (node.mesh >= 0)
            meshNodes.push_back(n);
        stack.insert(stack.end(), node.children.rbegin(), node.children.rend());
    }
    return meshNodes;
}

Result<SkinBind> MeshBuilder::skinBind(int skinIndex) const
{
    if (std::size_t(skinIndex) >= m_model.skins.size())
        return m_reader.broken("a node names skin " + std::to_string(skinIndex) + ", which does not exist");
    const tinygltf::Skin& skin = m_model.skins[std::size_t(skinIndex)];
    const std::string use = "skin " + std::to_string(skinIndex);
    if (skin.joints.empty())
        return m_reader.broken(use + " has no joints");
    for (int joint : skin.joints)
        if (joint < 0 || std::size_t(joint) >= m_model.nodes.size())
            return m_reader.broken(use + " names joint node " + std::to_string(joint) + ", which does not exist");
    std::vector<Mat4> inverseBind(skin.joints.size(), kIdentity);
    if (skin.inverseBindMatrices >= 0) {
        Result<AccessorData> matrices = m_reader.read(skin.inverseBindMatrices, use + " inverse bind matrices");
        if (!matrices)
            return matrices.error();
        if (matrices->components != 16 || matrices->count < skin.joints.size())
            return m_reader.broken(use + " needs one 4×4 inverse bind matrix per joint");
        for (std::size_t j = 0; j < skin.joints.size(); ++j)
            std::copy_n(matrices->values.begin() + std::ptrdiff_t(j * 16), 16, inverseBind[j].begin());
    }
    // Skinning matrices at the nodes' rest pose (the pose every unskinned mesh node is placed
    // in): joint world · inverse bind. When the rest pose is the bind pose they all equal the
    // transform B that places the mesh as modelled; when it is not (RobotExpressive's hands are
    // bound in a T-pose, its arms rest down) skinning puts the mesh where the skeleton is.
    std::size_t root = 0;
    for (std::size_t j = 0; j < skin.joints.size(); ++j) {
        const int parent = m_tree.parent[std::size_t(skin.joints[j])];
        if (std::find(skin.joints.begin(), skin.joints.end(), parent) == skin.joints.end()) {
            root = j;
            break;
        }
    }
    SkinBind bind;
    bind.jointNodes = skin.joints;
    for (std::size_t j = 0; j < skin.joints.size(); ++j) {
        bind.skinning.push_back(multiply(m_tree.world[std::size_t(skin.joints[j])], inverseBind[j]));
        if (!invertAffine(bind.skinning.back()))
            return m_reader.broken(use + " has a singular skinning matrix for joint " +
                                   nodeName(m_model, skin.joints[j]));
    }
    bind.placement = bind.skinning[root];
    bind.rootNode = skin.joints[root];
    return bind;
}

Result<std::vector<std::uint32_t>> MeshBuilder::readTriangles(const tinygltf::Primitive& primitive,
                                                              std::size_t vertexCount, const std::string& use) const
{
    std::vector<std::uint32_t> elements;
    if (primitive.indices >= 0) {
        Result<AccessorData> indices = m_reader.read(primitive.indices, use + " indices");
        if (!indices)
            return indices.error();
        const tinygltf::Accessor& accessor = m_model.accessors[std::size_t(primitive.indices)];
        if (indices->components != 1 || accessor.normalized ||
            (accessor.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
             accessor.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
             accessor.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
            return m_reader.broken(use + " indices are not unsigned integer scalars");
        elements.reserve(indices->count);
        for (double index : indices->values) {
            if (index >= double(vertexCount))
                return m_reader.broken(use + " uses vertex " + std::to_string(std::uint64_t(index)) + " of " +
                                       std::to_string(vertexCount));
            elements.push_back(std::uint32_t(index));
        }
    } else {
        elements.resize(vertexCount);
        for (std::size_t i = 0; i < vertexCount; ++i)
            elements[i] = std::uint32_t(i);
    }

    std::vector<std::uint32_t> triangles;
    switch (primitive.mode) {
    case TINYGLTF_MODE_TRIANGLES:
        if (elements.size() % 3 != 0)
            return m_reader.broken(use + " has " + std::to_string(elements.size()) +
                                   " triangle indices, not a multiple of 3");
        return elements;
    case TINYGLTF_MODE_TRIANGLE_STRIP:
        // Every other triangle of a strip is flipped to keep the winding; degenerate ones (strip
        // restarts) carry no surface and are dropped.
        for (std::size_t i = 2; i < elements.size(); ++i) {
            const std::uint32_t a = elements[i - 2], b = elements[i - 1], c = elements[i];
            if (a == b || b == c || a == c)
                continue;
            if (i % 2 == 0)
                triangles.insert(triangles.end(), {a, b, c});
            else
                triangles.insert(triangles.end(), {b, a, c});
        }
        return triangles;
    case TINYGLTF_MODE_TRIANGLE_FAN:
        for (std::size_t i = 2; i < elements.size(); ++i)
            triangles.insert(triangles.end(), {elements[i - 1], elements[i], elements[0]});
        return triangles;
    default:
        return makeError(ErrorCode::NotOurFormat,
                         "The glTF file " + m_reader.file() + " has " + use +
                             " made of points or lines; only triangle meshes can be used as characters.",
                         "primitive mode " + std::to_string(primitive.mode));
    }
}

Result<PrimitiveGeometry> MeshBuilder::readPrimitive(const tinygltf::Primitive& primitive, const std::string& use,
                                                     const std::vector<double>& morphWeights,
                                                     std::span<const int> targets, const SkinBind* skin,
                                                     const Mat4& nodeWorld) const
{
    const auto attribute = [&](const std::string& name) {
        const auto found = primitive.attributes.find(name);
        return found == primitive.attributes.end() ? -1 : found->second;
    };
    if (attribute("POSITION") < 0)
        return makeError(ErrorCode::CorruptData,
                         "The glTF file " + m_reader.file() + " has " + use + " without vertex positions (POSITION).");
    Result<AccessorData> positions = m_reader.read(attribute("POSITION"), use + " POSITION");
    if (!positions)
        return positions.error();
    if (positions->components != 3)
        return m_reader.broken(use + " POSITION is not made of 3D vectors");
    const std::size_t vertexCount = positions->count;

    std::optional<AccessorData> normals;
    if (attribute("NORMAL") >= 0) {
        Result<AccessorData> read = m_reader.read(attribute("NORMAL"), use + " NORMAL");
        if (!read)
            return read.error();
        if (read->components != 3 || read->count != vertexCount)
            return m_reader.broken(use + " NORMAL does not hold one 3D vector per vertex");
        normals = std::move(*read);
    }

    // Morph targets: at their default weights they are part of the rest shape (as the file shows
    // the model); their POSITION offsets are kept, where not zero, as targets a face moves on top
    // of it. NORMAL offsets are not kept: the face deformer turns normals with the triangles.
    struct FileOffsets {
        int target;
        std::vector<std::uint32_t> vertices;
        std::vector<Vec3d> deltas;
    };
    std::vector<FileOffsets> fileOffsets;
    for (std::size_t t = 0; t < primitive.targets.size(); ++t) {
        const double weight = t < morphWeights.size() ? morphWeights[t] : 0.0;
        for (const char* name : {"POSITION", "NORMAL"}) {
            const bool isPosition = std::string_view(name) == "POSITION";
            const auto found = primitive.targets[t].find(name);
            AccessorData* base = isPosition ? &*positions : (normals ? &*normals : nullptr);
            if (found == primitive.targets[t].end() || !base || (!isPosition && weight == 0))
                continue;
            const std::string targetUse = use + " morph target " + std::to_string(t) + " " + name;
            Result<AccessorData> delta = m_reader.read(found->second, targetUse);
            if (!delta)
                return delta.error();
            if (delta->components != 3 || delta->count != vertexCount)
                return m_reader.broken(targetUse + " does not hold one 3D vector per vertex");
            if (weight != 0)
                for (std::size_t i = 0; i < base->values.size(); ++i)
                    base->values[i] += weight * delta->values[i];
            if (!isPosition)
                continue;
            FileOffsets& offsets = fileOffsets.emplace_back(FileOffsets{targets[t], {}, {}});
            for (std::size_t v = 0; v < vertexCount; ++v) {
                const Vec3d d{(*delta)(v, 0), (*delta)(v, 1), (*delta)(v, 2)};
                if (d.x != 0 || d.y != 0 || d.z != 0) {
                    offsets.vertices.push_back(std::uint32_t(v));
                    offsets.deltas.push_back(d);
                }
            }
        }
    }

    Result<std::vector<std::uint32_t>> triangles = readTriangles(primitive, vertexCount, use);
    if (!triangles)
        return triangles.error();
    PrimitiveGeometry geometry;
    geometry.indices = std::move(*triangles);

    // The texture coordinates the base colour texture reads (TEXCOORD_0 unless it says otherwise).
    int texcoordSet = 0;
    if (primitive.material >= 0 && std::size_t(primitive.material) < m_model.materials.size()) {
        const tinygltf::TextureInfo& base =
            m_model.materials[std::size_t(primitive.material)].pbrMetallicRoughness.baseColorTexture;
        if (base.index >= 0)
            texcoordSet = base.texCoord;
    }
    if (const int texcoords = attribute("TEXCOORD_" + std::to_string(texcoordSet)); texcoords >= 0) {
        const std::string texcoordUse = use + " TEXCOORD_" + std::to_string(texcoordSet);
        Result<AccessorData> read = m_reader.read(texcoords, texcoordUse);
        if (!read)
            return read.error();
        if (read->components != 2 || read->count != vertexCount)
            return m_reader.broken(texcoordUse + " does not hold one 2D vector per vertex");
        geometry.texcoords.resize(vertexCount);
        for (std::size_t v = 0; v < vertexCount; ++v) {
            geometry.texcoords[v] = {float((*read)(v, 0)), float((*read)(v, 1))};
            if (!std::isfinite(geometry.texcoords[v][0]) || !std::isfinite(geometry.texcoords[v][1]))
                return m_reader.broken(texcoordUse + " has a value that is not finite");
        }
    }

    if (skin) {
        geometry.joints.assign(vertexCount, {});
        geometry.weights.assign(vertexCount, {});
        for (int set = 0; set < 2; ++set) {
            const int jointsIndex = attribute("JOINTS_" + std::to_string(set));
            const int weightsIndex = attribute("WEIGHTS_" + std::to_string(set));
            if (jointsIndex < 0 || weightsIndex < 0)
                continue;
            Result<AccessorData> joints = m_reader.read(jointsIndex, use + " JOINTS_" + std::to_string(set));
            if (!joints)
                return joints.error();
            Result<AccessorData> weights = m_reader.read(weightsIndex, use + " WEIGHTS_" + std::to_string(set));
            if (!weights)
                return weights.error();
            if (joints->components != 4 || weights->components != 4 || joints->count != vertexCount ||
                weights->count != vertexCount)
                return m_reader.broken(use + " skin weights do not hold 4 joints and 4 weights per vertex");
            for (std::size_t v = 0; v < vertexCount; ++v)
                for (int k = 0; k < 4; ++k) {
                    const double joint = (*joints)(v, k);
                    const float weight = float((*weights)(v, k));
                    const bool known = joint >= 0 && joint < double(skin->jointNodes.size());
                    if (!known && weight != 0) {
                        // Any number: a float accessor (which the spec forbids here) may hold 1e20.
                        char number[32];
                        std::snprintf(number, sizeof number, "%.15g", joint);
                        return m_reader.broken(use + " weights joint " + number + " of a skin with " +
                                               std::to_string(skin->jointNodes.size()) + " joints");
                    }
                    geometry.joints[v][std::size_t(set * 4 + k)] = known ? int(joint) : 0;
                    geometry.weights[v][std::size_t(set * 4 + k)] = known ? weight : 0.0f;
                }
        }
    }
    // The transform of vertex v: the node's world matrix, or for a skinned mesh the weighted
    // blend of its joints' skinning matrices (linear blend skinning at the rest pose).
    auto vertexTransform = [&](std::size_t v) {
        if (!skin)
            return nodeWorld;
        Mat4 blend{};
        double total = 0;
        for (std::size_t k = 0; k < 8; ++k) {
            const double w = geometry.weights[v][k];
            if (w == 0)
                continue;
            const Mat4& m = skin->skinning[std::size_t(geometry.joints[v][k])];
            for (std::size_t i = 0; i < 16; ++i)
                blend[i] += w * m[i];
            total += w;
        }
        if (!(total > 0))
            return skin->placement; // unweighted vertices stay with the skeleton's root
        for (double& entry : blend)
            entry /= total;
        return blend;
    };

    // A mirroring transform turns the faces inside out: swap two corners to keep them outward.
    if (determinant3(skin ? skin->placement : nodeWorld) < 0)
        for (std::size_t t = 0; t < geometry.indices.size(); t += 3)
            std::swap(geometry.indices[t + 1], geometry.indices[t + 2]);

    geometry.positions.resize(vertexCount);
    std::vector<Vec3d> fileNormals(normals ? vertexCount : 0);
    for (std::size_t v = 0; v < vertexCount; ++v) {
        const Mat4 transform = vertexTransform(v);
        const Vec3d p = transformPoint(transform, {(*positions)(v, 0), (*positions)(v, 1), (*positions)(v, 2)});
        geometry.positions[v] = {float(p.x), float(p.y), float(p.z)}; // checked as floats: a huge double overflows
        if (!std::isfinite(geometry.positions[v].x) || !std::isfinite(geometry.positions[v].y) ||
            !std::isfinite(geometry.positions[v].z))
            return m_reader.broken(use + " has a vertex position that is not finite");
        if (normals) {
            const std::array<double, 9> m = normalMatrix(transform);
            const double sign = determinant3(transform) < 0 ? -1.0 : 1.0;
            const double n[3] = {(*normals)(v, 0), (*normals)(v, 1), (*normals)(v, 2)};
            fileNormals[v] = Vec3d{m[0] * n[0] + m[1] * n[1] + m[2] * n[2], m[3] * n[0] + m[4] * n[1] + m[5] * n[2],
                                   m[6] * n[0] + m[7] * n[1] + m[8] * n[2]} *
                             sign;
        }
    }

    // A target's offset moves with its vertex: p + d goes to T(p) + L(d), L the linear part of T.
    for (const FileOffsets& file : fileOffsets) {
        PrimitiveGeometry::Target& target = geometry.targets.emplace_back();
        target.index = file.target;
        for (std::size_t i = 0; i < file.vertices.size(); ++i) {
            const Vec3d d = transformVector(vertexTransform(file.vertices[i]), file.deltas[i]);
            const Vec3 offset{float(d.x), float(d.y), float(d.z)};
            if (!std::isfinite(offset.x) || !std::isfinite(offset.y) || !std::isfinite(offset.z))
                return m_reader.broken(use + " has a morph target offset that is not finite");
            if (offset.x == 0 && offset.y == 0 && offset.z == 0)
                continue;
            target.vertices.push_back(file.vertices[i]);
            target.offsets.push_back(offset);
        }
    }

    // Area-weighted face normals: used where the file has none (or a zero one).
    std::vector<Vec3d> faceSum(vertexCount);
    for (std::size_t t = 0; t < geometry.indices.size(); t += 3) {
        const std::uint32_t i0 = geometry.indices[t], i1 = geometry.indices[t + 1], i2 = geometry.indices[t + 2];
        const Vec3 a = geometry.positions[i0], b = geometry.positions[i1], c = geometry.positions[i2];
        const Vec3d e1{double(b.x) - a.x, double(b.y) - a.y, double(b.z) - a.z};
        const Vec3d e2{double(c.x) - a.x, double(c.y) - a.y, double(c.z) - a.z};
        const Vec3d cross{e1.y * e2.z - e1.z * e2.y, e1.z * e2.x - e1.x * e2.z, e1.x * e2.y - e1.y * e2.x};
        for (std::uint32_t i : {i0, i1, i2})
            faceSum[i] = faceSum[i] + cross; // |cross| = twice the area: area weighting
    }
    geometry.normals.resize(vertexCount);
    for (std::size_t v = 0; v < vertexCount; ++v) {
        const Vec3 fromFaces = normalizedOr(faceSum[v], Vec3{0, 1, 0});
        geometry.normals[v] = normals ? normalizedOr(fileNormals[v], fromFaces) : fromFaces;
    }
    return geometry;
}

std::string MeshBuilder::materialName(int material) const
{
    if (material < 0 || std::size_t(material) >= m_model.materials.size())
        return "default";
    const std::string& name = m_model.materials[std::size_t(material)].name;
    return name.empty() ? "material" + std::to_string(material) : name;
}

std::size_t MeshBuilder::builderFor(Key key, const std::string& baseName, const std::string& joint, const Mat4& frame,
                                    const SegmentSource& source)
{
    if (const auto found = m_builderByKey.find(key); found != m_builderByKey.end())
        return found->second;
    // Names stay unique: a second "Torso" (a mesh node and a joint of that name) gets "Torso#2".
    std::string name = baseName;
    for (int suffix = 2; std::any_of(m_builders.begin(), m_builders.end(),
                                     [&](const SegmentBuilder& b) { return b.segment.name == name; });
         ++suffix)
        name = baseName + "#" + std::to_string(suffix);
    SegmentBuilder builder;
    builder.segment.name = name;
    builder.segment.joint = joint;
    builder.segment.bindRotation = rotationOf(frame);
    builder.segment.bindTranslation = {frame[12], frame[13], frame[14]};
    builder.source = source;
    m_builders.push_back(std::move(builder));
    m_builderByKey.emplace(key, m_builders.size() - 1);
    return m_builders.size() - 1;
}

void MeshBuilder::append(std::size_t builderIndex, const PrimitiveGeometry& geometry,
                         std::span<const std::uint32_t> triangles, const SkinBind* skin, int material)
{
    SegmentBuilder& builder = m_builders[builderIndex];
    if (builder.positions.empty() && builder.indices.empty())
        builder.source.material = material;
    else if (builder.source.material != material)
        builder.source.mixedMaterials = true;
    m_hasTexcoords = m_hasTexcoords || !geometry.texcoords.empty();

    // Only the vertices these triangles use (all of them when the primitive is not split).
    const bool whole = triangles.size() == geometry.indices.size();
    std::vector<std::uint32_t> remap(geometry.positions.size(), kUnmapped);
    const std::uint32_t base = std::uint32_t(builder.positions.size());
    auto take = [&](std::uint32_t v) {
        if (remap[v] != kUnmapped)
            return base + remap[v];
        remap[v] = std::uint32_t(builder.positions.size()) - base;
        builder.positions.push_back(geometry.positions[v]);
        builder.normals.push_back(geometry.normals[v]);
        builder.texcoords.push_back(geometry.texcoords.empty() ? std::array<float, 2>{} : geometry.texcoords[v]);
        std::array<int, 8> nodes;
        nodes.fill(-1);
        std::array<float, 8> weights{};
        if (skin) {
            float total = 0;
            for (std::size_t k = 0; k < 8; ++k)
                if (geometry.weights[v][k] > 0) {
                    nodes[k] = skin->jointNodes[std::size_t(geometry.joints[v][k])];
                    weights[k] = geometry.weights[v][k];
                    total += weights[k];
                }
            if (!(total > 0)) { // as placed: with the skeleton's root
                nodes[0] = skin->rootNode;
                weights[0] = 1;
            }
        }
        builder.jointNodes.push_back(nodes);
        builder.weights.push_back(weights);
        return base + remap[v];
    };
    if (whole) // keep unused vertices and the file's vertex order
        for (std::uint32_t v = 0; v < geometry.positions.size(); ++v)
            take(v);
    for (std::uint32_t v : triangles)
        builder.indices.push_back(take(v));
    for (const PrimitiveGeometry::Target& target : geometry.targets)
        for (std::size_t i = 0; i < target.vertices.size(); ++i)
            if (const std::uint32_t v = target.vertices[i]; remap[v] != kUnmapped)
                builder.targetOffsets.push_back({target.index, base + remap[v], target.offsets[i]});
}

std::vector<int> MeshBuilder::targetsOf(const tinygltf::Mesh& mesh, int meshIndex)
{
    std::vector<int> targets;
    for (std::string& name : morphTargetNames(mesh, meshIndex)) {
        const auto [found, added] = m_targetByName.emplace(name, int(m_targetNames.size()));
        if (added)
            m_targetNames.push_back(std::move(name));
        targets.push_back(found->second);
    }
    return targets;
}

Result<void> MeshBuilder::addMeshNode(int nodeIndex)
{
    const tinygltf::Node& node = m_model.nodes[std::size_t(nodeIndex)];
    if (std::size_t(node.mesh) >= m_model.meshes.size())
        return m_reader.broken("node " + nodeName(m_model, nodeIndex) + " names mesh " + std::to_string(node.mesh) +
                               ", which does not exist");
    const tinygltf::Mesh& mesh = m_model.meshes[std::size_t(node.mesh)];
    const std::vector<double>& morphWeights = node.weights.empty() ? mesh.weights : node.weights;
    const std::vector<int> targets = targetsOf(mesh, node.mesh);

    std::optional<SkinBind> skin;
    if (node.skin >= 0) {
        Result<SkinBind> bind = skinBind(node.skin);
        if (!bind)
            return bind.error();
        skin = std::move(*bind);
    }
    const bool split = skin && m_options.splitSkinnedByJoint;
    const Mat4& frame = skin ? skin->placement : m_tree.world[std::size_t(nodeIndex)];
    const std::string& name = m_names[std::size_t(nodeIndex)];

    // Splitting by material: segments of a mesh with several materials are named "<name>/<material>".
    std::set<int> materials;
    for (const tinygltf::Primitive& primitive : mesh.primitives)
        materials.insert(primitive.material);
    const bool byMaterial = m_options.splitByMaterial && materials.size() > 1;
    auto keyMaterial = [&](int material) { return m_options.splitByMaterial ? material : -2; };
    auto withMaterial = [&](const std::string& base, int material) {
        return byMaterial ? base + "/" + materialName(material) : base;
    };

    for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
        const tinygltf::Primitive& primitive = mesh.primitives[p];
        const std::string use = "mesh \"" + (mesh.name.empty() ? nodeName(m_model, nodeIndex) : mesh.name) +
                                "\" primitive " + std::to_string(p);
        Result<PrimitiveGeometry> geometry = readPrimitive(primitive, use, morphWeights, targets,
                                                           skin ? &*skin : nullptr, m_tree.world[std::size_t(nodeIndex)]);
        if (!geometry)
            return geometry.error();
        if (!split) {
            const SegmentSource source{nodeIndex, skin ? skin->rootNode : nodeIndex, false, primitive.material, false};
            const std::size_t builder = builderFor({Kind::MeshNode, nodeIndex, keyMaterial(primitive.material)},
                                                   withMaterial(name, primitive.material), skin ? std::string() : name,
                                                   frame, source);
            append(builder, *geometry, geometry->indices, skin ? &*skin : nullptr, primitive.material);
            continue;
        }
        // Split: each triangle goes to the joint with the largest weight summed over its corners.
        const std::size_t jointCount = skin->jointNodes.size();
        std::vector<std::vector<std::uint32_t>> trianglesOfJoint(jointCount);
        std::vector<double> sum(jointCount);
        for (std::size_t t = 0; t < geometry->indices.size(); t += 3) {
            std::fill(sum.begin(), sum.end(), 0.0);
            for (std::size_t corner = 0; corner < 3; ++corner) {
                const std::uint32_t v = geometry->indices[t + corner];
                for (std::size_t k = 0; k < 8; ++k) // slots were checked against the skin when read
                    sum[std::size_t(geometry->joints[v][k])] += geometry->weights[v][k];
            }
            const std::size_t dominant = std::size_t(std::max_element(sum.begin(), sum.end()) - sum.begin());
            trianglesOfJoint[dominant].insert(trianglesOfJoint[dominant].end(),
                                              geometry->indices.begin() + std::ptrdiff_t(t),
                                              geometry->indices.begin() + std::ptrdiff_t(t + 3));
        }
        for (std::size_t j = 0; j < jointCount; ++j) {
            if (trianglesOfJoint[j].empty())
                continue;
            const int jointNode = skin->jointNodes[j];
            const std::string& jointName = m_names[std::size_t(jointNode)];
            const SegmentSource source{nodeIndex, jointNode, true, primitive.material, false};
            const std::size_t builder = builderFor({Kind::Joint, jointNode, keyMaterial(primitive.material)},
                                                   withMaterial(jointName, primitive.material), jointName,
                                                   m_tree.world[std::size_t(jointNode)], source);
            append(builder, *geometry, trianglesOfJoint[j], &*skin, primitive.material);
        }
    }
    // A mesh node with no primitives still names its segment.
    if (!split && mesh.primitives.empty())
        builderFor({Kind::MeshNode, nodeIndex, keyMaterial(-1)}, name, skin ? std::string() : name, frame,
                   SegmentSource{nodeIndex, skin ? skin->rootNode : nodeIndex, false, -1, false});
    return {};
}

MeshData MeshBuilder::finish()
{
    MeshData data;
    data.hasTexcoords = m_hasTexcoords;
    CharacterMesh& mesh = data.mesh;
    for (SegmentBuilder& builder : m_builders) {
        Segment segment = builder.segment;
        segment.firstVertex = std::uint32_t(mesh.positions.size());
        segment.vertexCount = std::uint32_t(builder.positions.size());
        segment.firstTriangle = std::uint32_t(mesh.triangleCount());
        segment.triangleCount = std::uint32_t(builder.indices.size() / 3);
        mesh.positions.insert(mesh.positions.end(), builder.positions.begin(), builder.positions.end());
        mesh.normals.insert(mesh.normals.end(), builder.normals.begin(), builder.normals.end());
        data.texcoords.insert(data.texcoords.end(), builder.texcoords.begin(), builder.texcoords.end());
        data.jointNodes.insert(data.jointNodes.end(), builder.jointNodes.begin(), builder.jointNodes.end());
        data.weights.insert(data.weights.end(), builder.weights.begin(), builder.weights.end());
        for (std::uint32_t index : builder.indices)
            mesh.indices.push_back(segment.firstVertex + index);
        mesh.segments.push_back(std::move(segment));
        data.sources.push_back(builder.source);
    }
    // Each target's vertices, ascending (a split primitive's vertices come in triangle order).
    std::vector<std::vector<std::pair<std::uint32_t, Vec3>>> offsets(m_targetNames.size());
    for (std::size_t b = 0; b < m_builders.size(); ++b)
        for (const SegmentBuilder::TargetOffset& entry : m_builders[b].targetOffsets)
            offsets[std::size_t(entry.target)].emplace_back(mesh.segments[b].firstVertex + entry.vertex, entry.offset);
    for (std::size_t t = 0; t < m_targetNames.size(); ++t) {
        std::sort(offsets[t].begin(), offsets[t].end(),
                  [](const auto& a, const auto& b) { return a.first < b.first; });
        MorphTarget& target = data.targets.emplace_back();
        target.name = m_targetNames[t];
        for (const auto& [vertex, offset] : offsets[t]) {
            target.vertices.push_back(vertex);
            target.offsets.push_back(offset);
        }
    }
    return data;
}

} // namespace

Result<MeshData> readMesh(const File& file, const NodeTree& tree, const GltfMeshOptions& options,
                          std::span<const std::string> names)
{
    const AccessorReader reader(file);
    MeshBuilder builder(file, reader, tree, options, names);
    Result<std::vector<int>> meshNodes = builder.meshNodesOfScene();
    if (!meshNodes)
        return meshNodes.error();
    if (meshNodes->empty())
        return makeError(ErrorCode::CorruptData, "The glTF file " + file.name + " has no mesh in its scene.");
    for (int node : *meshNodes)
        if (Result<void> ok = builder.addMeshNode(node); !ok)
            return ok.error();

    MeshData data = builder.finish();
    if (data.mesh.vertexCount() >= std::size_t(UINT32_MAX))
        return makeError(ErrorCode::CorruptData, "The glTF file " + file.name + " has too many vertices.");
    if (Result<void> ok = data.mesh.validate(); !ok)
        return makeError(ErrorCode::Internal, "The mesh read from " + file.name + " is inconsistent.",
                         ok.error().message);
    return data;
}

} // namespace gltf

Result<CharacterMesh> loadGltfMesh(const std::filesystem::path& path, const GltfMeshOptions& options)
{
    // Geometry only: images are not decoded (the renderer loads textures itself).
    Result<gltf::File> file = gltf::readFile(path, false);
    if (!file)
        return file.error();
    Result<gltf::NodeTree> tree = gltf::nodeTree(file->model, gltf::AccessorReader(*file));
    if (!tree)
        return tree.error();
    std::vector<std::string> names;
    for (std::size_t n = 0; n < file->model.nodes.size(); ++n)
        names.push_back(gltf::nodeName(file->model, int(n)));
    Result<gltf::MeshData> data = gltf::readMesh(*file, *tree, options, names);
    if (!data)
        return data.error();
    return std::move(data->mesh);
}

} // namespace thespis::core::scene
