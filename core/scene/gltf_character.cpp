// loadGltfCharacter (gltf_character.h): the skeleton of the skins' joints, the skin, materials
// and textures, and the assembly of the character. Joint names come from rig_naming.h, clips
// from gltf_animation.h.

#include "scene/gltf_character.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <vector>

#include "scene/face_naming.h"
#include "scene/gltf_animation.h"
#include "scene/gltf_reader.h"
#include "scene/rig_naming.h"
#include "scene/rig_repair.h"

namespace thespis::core::scene {
namespace {

using gltf::Mat4;
using rig_naming::joinedList;

// ==== the skeleton =================================================================================

/// The glTF nodes that become joints, parents first, and the way back.
struct SkeletonNodes {
    std::vector<int> nodes;       ///< joint → node
    std::vector<int> jointOfNode; ///< node → joint, -1 for other nodes
};

/// Every skin joint, the nodes between them and their nearest common node (the root).
Result<SkeletonNodes> skeletonNodes(const tinygltf::Model& model, const gltf::NodeTree& tree,
                                    const gltf::AccessorReader& reader)
{
    SkeletonNodes skeleton;
    skeleton.jointOfNode.assign(model.nodes.size(), -1);
    std::vector<bool> member(model.nodes.size(), false);
    std::vector<int> joints;
    for (std::size_t s = 0; s < model.skins.size(); ++s)
        for (int joint : model.skins[s].joints) {
            if (joint < 0 || std::size_t(joint) >= model.nodes.size())
                return reader.broken("skin " + std::to_string(s) + " names joint node " + std::to_string(joint) +
                                     ", which does not exist");
            if (!member[std::size_t(joint)])
                joints.push_back(joint);
            member[std::size_t(joint)] = true;
        }
    if (joints.empty())
        return skeleton;

    auto depth = [&](int n) {
        int d = 0;
        for (; tree.parent[std::size_t(n)] >= 0; n = tree.parent[std::size_t(n)])
            ++d;
        return d;
    };
    auto commonAncestor = [&](int a, int b) {
        int da = depth(a), db = depth(b);
        for (; da > db; --da)
            a = tree.parent[std::size_t(a)];
        for (; db > da; --db)
            b = tree.parent[std::size_t(b)];
        while (a != b && a >= 0) {
            a = tree.parent[std::size_t(a)];
            b = tree.parent[std::size_t(b)];
        }
        return a;
    };
    int root = joints.front();
    for (int joint : joints)
        if ((root = commonAncestor(root, joint)) < 0)
            return reader.broken("the joints of its skins are not under one common node");
    for (int joint : joints)
        for (int n = joint; n != root; n = tree.parent[std::size_t(n)])
            member[std::size_t(n)] = true;
    member[std::size_t(root)] = true;

    // Depth first from the root, children in file order: parents come first.
    std::vector<int> stack{root};
    while (!stack.empty()) {
        const int n = stack.back();
        stack.pop_back();
        skeleton.jointOfNode[std::size_t(n)] = int(skeleton.nodes.size());
        skeleton.nodes.push_back(n);
        const std::vector<int>& children = model.nodes[std::size_t(n)].children;
        for (auto c = children.rbegin(); c != children.rend(); ++c)
            if (member[std::size_t(*c)])
                stack.push_back(*c);
    }
    return skeleton;
}

Vec3d translationOf(const Mat4& m) { return {m[12], m[13], m[14]}; }

Vec3d restTranslation(const tinygltf::Node& node)
{
    if (node.matrix.size() == 16)
        return {node.matrix[12], node.matrix[13], node.matrix[14]};
    if (node.translation.size() == 3)
        return {node.translation[0], node.translation[1], node.translation[2]};
    return {};
}

// ==== materials and textures =====================================================================

/// A decoded glTF image as RGBA8, or nullopt when it holds no pixels we can read.
std::optional<TextureImage> textureOf(const tinygltf::Image& image, int index)
{
    const int channels = image.component;
    const int bytes = image.bits / 8;
    if (image.width <= 0 || image.height <= 0 || channels < 1 || channels > 4 || (bytes != 1 && bytes != 2))
        return std::nullopt;
    const std::size_t pixels = std::size_t(image.width) * std::size_t(image.height);
    if (image.image.size() != pixels * std::size_t(channels * bytes))
        return std::nullopt;
    TextureImage texture;
    texture.name = !image.name.empty() ? image.name : !image.uri.empty() ? image.uri : "image" + std::to_string(index);
    texture.width = image.width;
    texture.height = image.height;
    texture.rgba.resize(pixels * 4);
    for (std::size_t p = 0; p < pixels; ++p) {
        std::uint8_t value[4] = {0, 0, 0, 255};
        for (int c = 0; c < channels; ++c) // 16-bit samples are little endian: keep the high byte
            value[c] = image.image[(p * std::size_t(channels) + std::size_t(c)) * std::size_t(bytes) +
                                   std::size_t(bytes - 1)];
        if (channels <= 2) { // grey, grey + alpha
            value[3] = channels == 2 ? value[1] : 255;
            value[1] = value[2] = value[0];
        }
        std::copy(value, value + 4, texture.rgba.begin() + std::ptrdiff_t(p * 4));
    }
    return texture;
}

/// Every glTF material (same indices), with the base colour textures decoded into `character`.
void readMaterials(const tinygltf::Model& model, bool loadTextures, Character& character)
{
    std::map<int, int> textureOfImage;
    for (std::size_t m = 0; m < model.materials.size(); ++m) {
        const tinygltf::Material& source = model.materials[m];
        Material material;
        material.name = source.name.empty() ? "material" + std::to_string(m) : source.name;
        const std::vector<double>& factor = source.pbrMetallicRoughness.baseColorFactor;
        material.baseColor = {1, 1, 1, 1}; // glTF's default factor
        if (factor.size() == 4)
            for (std::size_t c = 0; c < 4; ++c)
                material.baseColor[c] = float(factor[c]);
        const int texture = source.pbrMetallicRoughness.baseColorTexture.index;
        if (loadTextures && texture >= 0) {
            const int image =
                std::size_t(texture) < model.textures.size() ? model.textures[std::size_t(texture)].source : -1;
            if (const auto found = textureOfImage.find(image); found != textureOfImage.end())
                material.baseColorTexture = found->second;
            else if (std::optional<TextureImage> decoded =
                         image >= 0 && std::size_t(image) < model.images.size()
                             ? textureOf(model.images[std::size_t(image)], image)
                             : std::nullopt) {
                material.baseColorTexture = int(character.textures.size());
                textureOfImage.emplace(image, material.baseColorTexture);
                character.textures.push_back(std::move(*decoded));
            } else
                character.warnings.push_back("Material \"" + material.name +
                                             "\" goes without its base colour texture, whose image could not be read.");
        }
        character.materials.push_back(std::move(material));
    }
}

// ==== assembling the character ===================================================================

/// What the import has read of the file, shared by the steps below.
struct Import {
    const gltf::File& file;
    const gltf::AccessorReader& reader;
    const gltf::NodeTree& tree;
    const SkeletonNodes& nodes;
    const GltfCharacterOptions& options;
    const tinygltf::Model& model() const { return file.model; }
};

/// The skeleton of the skin joints (named, see jointNames), with `translates` set for joints
/// whose animation moves them off their rest offsets.
Result<anim::Skeleton> buildSkeleton(const Import& import, const std::vector<gltf::Animation>& animations,
                                     std::vector<std::string>& warnings)
{
    const std::vector<int>& nodes = import.nodes.nodes;
    std::vector<std::string> sources;
    std::vector<int> parents;
    std::vector<Vec3d> positions;
    for (int node : nodes) {
        sources.push_back(gltf::nodeName(import.model(), node));
        const int parentNode = import.tree.parent[std::size_t(node)];
        parents.push_back(parentNode < 0 ? -1 : import.nodes.jointOfNode[std::size_t(parentNode)]);
        positions.push_back(translationOf(import.tree.world[std::size_t(node)]));
        const Vec3d& p = positions.back();
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            return import.reader.broken("joint " + sources.back() + " has a rest position that is not finite");
    }
    const std::vector<std::string> names = rig_naming::jointNames(sources, parents, positions, import.options, warnings);

    // Translation channels that keep a joint at its rest offset (COLLADA2GLTF keys every joint's
    // translation) leave it a fixed bone: they may differ from the rest by rounding only.
    double extent = 0;
    for (const Vec3d& p : positions)
        extent = std::max(extent, std::sqrt(anim::dot(p - positions[0], p - positions[0])));
    const double tolerance = 1e-5 * std::max(1.0, extent);
    std::vector<bool> translates(nodes.size(), false);
    for (const gltf::Animation& animation : animations)
        for (const gltf::Track& track : animation.tracks) {
            const int node = nodes[std::size_t(track.joint)];
            if (track.path == gltf::Path::Translation &&
                gltf::movesJoint(track, restTranslation(import.model().nodes[std::size_t(node)]),
                           gltf::parentWorld(import.tree, node), tolerance))
                translates[std::size_t(track.joint)] = true;
        }

    std::vector<anim::Joint> joints;
    for (std::size_t j = 0; j < nodes.size(); ++j) {
        anim::Joint joint;
        joint.name = names[j];
        joint.sourceName = sources[j];
        joint.parent = parents[j];
        joint.offset = parents[j] < 0 ? positions[j] : positions[j] - positions[std::size_t(parents[j])];
        joint.translates = translates[j];
        joints.push_back(std::move(joint));
    }
    Result<anim::Skeleton> skeleton = anim::Skeleton::create(std::move(joints));
    if (!skeleton)
        return makeError(ErrorCode::Internal, "The skeleton read from " + import.file.name + " is inconsistent.",
                         skeleton.error().message);
    return skeleton;
}

/// Points every segment at the skeleton joint at or above the node it follows (the root when
/// none is); returns the joint of each segment.
std::vector<int> followJoints(const Import& import, const std::vector<gltf::SegmentSource>& sources,
                              Character& character)
{
    std::vector<int> segmentJoint(character.mesh.segments.size(), 0);
    std::vector<std::string> mixed;
    for (std::size_t s = 0; s < character.mesh.segments.size(); ++s) {
        for (int n = sources[s].jointNode; n >= 0; n = import.tree.parent[std::size_t(n)])
            if (const int joint = import.nodes.jointOfNode[std::size_t(n)]; joint >= 0) {
                segmentJoint[s] = joint;
                break;
            }
        Segment& segment = character.mesh.segments[s];
        segment.joint = character.skeleton.joint(segmentJoint[s]).name;
        if (sources[s].mixedMaterials)
            mixed.push_back(segment.name);
    }
    if (!mixed.empty())
        character.warnings.push_back("These segments mix several materials and show the first one only: " +
                                     joinedList(mixed) + ".");
    return segmentJoint;
}

/// The Skin: the file's normalized weights for skinned vertices (a joint named twice counts once),
/// weight 1 on the segment's joint for the vertices of rigid mesh nodes. Empty when nothing is
/// skinned.
Skin buildSkin(const Import& import, const gltf::MeshData& data, const std::vector<int>& segmentJoint,
               const CharacterMesh& mesh)
{
    Skin skin;
    if (std::none_of(data.jointNodes.begin(), data.jointNodes.end(),
                     [](const std::array<int, 8>& slots) { return slots[0] >= 0; }))
        return skin;
    const std::size_t vertexCount = mesh.vertexCount();
    std::vector<std::array<std::uint16_t, kMaxInfluences>> vertexJoints(vertexCount);
    std::vector<std::array<double, kMaxInfluences>> vertexWeights(vertexCount);
    std::vector<int> influenceCount(vertexCount, 0);
    int influences = 1;
    for (std::size_t s = 0; s < mesh.segments.size(); ++s) {
        const Segment& segment = mesh.segments[s];
        for (std::size_t v = segment.firstVertex; v < segment.firstVertex + segment.vertexCount; ++v) {
            auto& joints = vertexJoints[v];
            int& count = influenceCount[v];
            for (std::size_t k = 0; k < 8; ++k) {
                const int node = data.jointNodes[v][k];
                if (node < 0 || !(data.weights[v][k] > 0))
                    continue;
                const auto joint = std::uint16_t(import.nodes.jointOfNode[std::size_t(node)]);
                const auto same = std::find(joints.begin(), joints.begin() + count, joint);
                if (same == joints.begin() + count)
                    joints[std::size_t(count++)] = joint;
                vertexWeights[v][std::size_t(same - joints.begin())] += data.weights[v][k];
            }
            if (count == 0) { // a rigid mesh node's vertex
                joints[0] = std::uint16_t(segmentJoint[s]);
                vertexWeights[v][0] = 1;
                count = 1;
            }
            influences = std::max(influences, count);
        }
    }
    skin.influences = influences <= 4 ? 4 : kMaxInfluences;
    const auto stride = std::size_t(skin.influences);
    skin.joints.assign(vertexCount * stride, 0);
    skin.weights.assign(vertexCount * stride, 0.0f);
    for (std::size_t v = 0; v < vertexCount; ++v) {
        const auto count = std::size_t(influenceCount[v]);
        double total = 0;
        for (std::size_t k = 0; k < count; ++k)
            total += vertexWeights[v][k];
        for (std::size_t k = 0; k < count; ++k) {
            skin.joints[v * stride + k] = vertexJoints[v][k];
            skin.weights[v * stride + k] = float(vertexWeights[v][k] / total);
        }
    }
    return skin;
}

void warnAboutIgnoredChannels(const gltf::IgnoredChannels& ignored, std::vector<std::string>& warnings)
{
    auto warn = [&](const std::set<std::string>& nodes, const std::string& what) {
        if (!nodes.empty())
            warnings.push_back(what + ": " + joinedList(std::vector<std::string>(nodes.begin(), nodes.end())) + ".");
    };
    warn(ignored.scale, "Scale animation is not imported (clips rotate and translate joints)");
    warn(ignored.weights, "Morph target animation is not imported");
    warn(ignored.outsideSkeleton, "Animation of nodes that are not joints of the skin is not imported");
}

} // namespace

// ==== the public functions =========================================================================

Result<Character> loadGltfCharacter(const std::filesystem::path& path, const GltfCharacterOptions& options)
{
    if (!(options.clipFrameRate > 0) || !std::isfinite(options.clipFrameRate))
        return makeError(ErrorCode::InvalidArgument,
                         "The clip frame rate must be a positive number of frames per second.");
    Result<gltf::File> file = gltf::readFile(path, options.loadTextures);
    if (!file)
        return file.error();
    const gltf::AccessorReader reader(*file);
    Result<gltf::NodeTree> tree = gltf::nodeTree(file->model, reader);
    if (!tree)
        return tree.error();
    Result<SkeletonNodes> nodes = skeletonNodes(file->model, *tree, reader);
    if (!nodes)
        return nodes.error();
    const Import import{*file, reader, *tree, *nodes, options};

    Character character;
    character.name = path.stem().string();
    character.warnings = file->imageWarnings;

    gltf::IgnoredChannels ignored;
    std::vector<gltf::Animation> animations;
    Result<anim::Skeleton> skeleton = anim::Skeleton{};
    if (nodes->nodes.empty()) {
        // No skin: one joint that every segment follows rigidly.
        anim::Joint root;
        root.name = "humanoid_root";
        skeleton = anim::Skeleton::create({root});
        if (!file->model.animations.empty())
            character.warnings.push_back("The file has no skin: its " + std::to_string(file->model.animations.size()) +
                                         " animations are not imported.");
    } else {
        if (nodes->nodes.size() > std::numeric_limits<std::uint16_t>::max())
            return makeError(ErrorCode::CorruptData, "The glTF file " + file->name + " has too many joints.");
        Result<std::vector<gltf::Animation>> read = gltf::readAnimations(file->model, reader, nodes->jointOfNode, ignored);
        if (!read)
            return read.error();
        animations = std::move(*read);
        skeleton = buildSkeleton(import, animations, character.warnings);
    }
    if (!skeleton)
        return skeleton.error();
    character.skeleton = std::move(*skeleton);

    // The mesh: split segments take their joint's name.
    std::vector<std::string> names;
    for (std::size_t n = 0; n < file->model.nodes.size(); ++n) {
        const int joint = nodes->jointOfNode[n];
        names.push_back(joint >= 0 ? character.skeleton.joint(joint).name : gltf::nodeName(file->model, int(n)));
    }
    Result<gltf::MeshData> data = gltf::readMesh(*file, *tree, options.mesh, names);
    if (!data)
        return data.error();
    character.mesh = std::move(data->mesh);
    character.face.targets = std::move(data->targets);
    const std::vector<int> segmentJoint = followJoints(import, data->sources, character);
    character.skin = buildSkin(import, *data, segmentJoint, character.mesh);
    if (data->hasTexcoords)
        character.texcoords = std::move(data->texcoords);

    readMaterials(file->model, options.loadTextures, character);
    if (!character.materials.empty())
        for (const gltf::SegmentSource& source : data->sources)
            character.segmentMaterials.push_back(source.material < int(character.materials.size()) ? source.material
                                                                                                   : -1);

    if (Result<void> built = gltf::buildClips(*file, *tree, nodes->nodes, options.clipFrameRate, animations, character); !built)
        return built.error();
    warnAboutIgnoredChannels(ignored, character.warnings);
    if (options.standardRig) {
        for (const std::string& foot : attachIkFeet(character, &automaticHAnimName))
            character.warnings.push_back("The IK foot " + foot + " now hangs from its knee, so that motion made for other bodies moves it.");
        if (const std::string was = turnToFaceForward(character); !was.empty())
            character.warnings.push_back("The model stood " + was + "; it is turned to stand +Y up facing +Z, as H-Anim does.");
    }
    // The face's joints are found by their final names, on the rig as it finally stands.
    const FaceMapping mapping = options.faceMapping ? *options.faceMapping : recogniseFaceMapping(character);
    for (std::string& warning : applyFaceMapping(mapping, character))
        character.warnings.push_back(std::move(warning));

    if (Result<void> valid = character.validate(); !valid)
        return makeError(ErrorCode::Internal, "The character read from " + file->name + " is inconsistent.",
                         valid.error().message);
    return character;
}

} // namespace thespis::core::scene
