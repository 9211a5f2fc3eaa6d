#include "scene/gltf_motion_export.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>

#include "anim/rig_orientation.h"
#include "scene/gltf_reader.h"
#include "scene/gltf_writing.h"
#include "util/file_io.h"
#include "util/text.h"

namespace thespis::core::scene {

namespace {

using anim::Quatd;
using gltf::Mat4;

Vec3d translationOf(const Mat4& m) { return {m[12], m[13], m[14]}; }
double scaleOf(const Mat4& m) { return std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]); }
double length(const Vec3d& v) { return std::sqrt(anim::dot(v, v)); }

/// The quarter turn import stood the rig up by: the one of the 24 that best takes the model's
/// rest joint positions onto the skeleton's, with the largest miss.
std::pair<Quatd, double> findTurn(std::span<const Vec3d> file, std::span<const Vec3d> skeleton)
{
    std::pair<Quatd, double> best{Quatd::identity(), std::numeric_limits<double>::infinity()};
    int permutation[3] = {0, 1, 2};
    do {
        const int inversions = (permutation[0] > permutation[1]) + (permutation[0] > permutation[2]) +
                               (permutation[1] > permutation[2]);
        for (int signs = 0; signs < 8; ++signs) {
            anim::AxisTurn turn;
            int sign = inversions % 2 ? -1 : 1;
            for (int row = 0; row < 3; ++row) {
                const int s = (signs >> row) & 1 ? -1 : 1;
                sign *= s;
                for (int column = 0; column < 3; ++column)
                    turn.matrix[row][column] = column == permutation[row] ? s : 0;
            }
            if (sign < 0)
                continue; // a mirror, not a turn
            double miss = 0;
            for (std::size_t j = 0; j < file.size(); ++j)
                miss = std::max(miss, length(turn.apply(file[j]) - skeleton[j]));
            if (miss < best.second)
                best = {anim::turnRotation(turn), miss};
        }
    } while (std::next_permutation(permutation, permutation + 3));
    return best;
}

const char* mimeTypeOf(const std::filesystem::path& file)
{
    const std::string extension = lowercase(file.extension().string());
    if (extension == ".png")
        return "image/png";
    if (extension == ".jpg" || extension == ".jpeg")
        return "image/jpeg";
    return "";
}

/// One buffer holding every buffer's bytes and every image the file named beside it, so that the
/// model travels as one .glb.
Result<void> gatherIntoOneBuffer(tinygltf::Model& model, const std::filesystem::path& source)
{
    std::vector<std::size_t> starts;
    std::vector<unsigned char> data;
    for (const tinygltf::Buffer& buffer : model.buffers) {
        data.resize((data.size() + 15) / 16 * 16, 0);
        starts.push_back(data.size());
        data.insert(data.end(), buffer.data.begin(), buffer.data.end());
    }
    for (tinygltf::BufferView& view : model.bufferViews) {
        view.byteOffset += starts.at(std::size_t(view.buffer));
        view.buffer = 0;
    }
    model.buffers.assign(1, tinygltf::Buffer{});
    model.buffers[0].data = std::move(data);
    for (tinygltf::Image& image : model.images) {
        if (image.bufferView >= 0 || image.uri.empty() || image.uri.starts_with("data:"))
            continue;
        const std::filesystem::path file = source.parent_path() / image.uri;
        auto bytes = readTextFile(file);
        if (!bytes)
            return makeError(ErrorCode::FileNotFound, "The image " + image.uri + " of " + source.string() +
                                                          " cannot be read, so it cannot go into the .glb.",
                             bytes.error().message);
        image.bufferView = gltf::addView(model, bytes->data(), bytes->size());
        image.mimeType = mimeTypeOf(file);
        image.uri.clear();
    }
    return {};
}

/// The model's node hierarchy alone: names and rest transforms, no meshes, skins or images.
tinygltf::Model nodesOnly(const tinygltf::Model& model)
{
    tinygltf::Model nodes;
    nodes.asset = model.asset;
    nodes.scenes = model.scenes;
    nodes.defaultScene = model.defaultScene;
    for (const tinygltf::Node& node : model.nodes) {
        tinygltf::Node copy;
        copy.name = node.name;
        copy.children = node.children;
        copy.translation = node.translation;
        copy.rotation = node.rotation;
        copy.scale = node.scale;
        copy.matrix = node.matrix;
        nodes.nodes.push_back(std::move(copy));
    }
    nodes.buffers.emplace_back();
    return nodes;
}

/// The weight the face gives each of its targets, frame after frame, and which targets any drive reaches.
struct FaceWeights {
    std::size_t targets = 0;
    std::vector<float> weights; ///< frames × targets
    std::vector<bool> driven;
};

FaceWeights faceWeights(const GltfMotion& motion, std::size_t frameCount)
{
    const FaceRig& rig = *motion.face;
    FaceWeights result;
    result.targets = rig.targets.size();
    result.driven.assign(rig.targets.size(), false);
    for (const MorphDrive& drive : rig.drives)
        result.driven[std::size_t(drive.target)] = true;
    // Each face channel's place in the motion's face frames (by its mpeg4Face name), or none.
    const anim::FrameLayout& layout = *motion.faceLayout;
    const std::vector<std::string>& channelNames = anim::FrameLayout::mpeg4Face()->scalarNames();
    std::vector<std::ptrdiff_t> placeOf(channelNames.size(), -1);
    for (std::size_t c = 0; c < channelNames.size(); ++c)
        for (std::size_t s = 0; s < layout.scalarNames().size(); ++s)
            if (layout.scalarNames()[s] == channelNames[c])
                placeOf[c] = std::ptrdiff_t(layout.scalarOffset() + s);
    const std::size_t floats = layout.floatCount();
    std::vector<float> face(kFaceChannelCount), channels(kFaceChannelCount), weights(rig.targets.size());
    result.weights.reserve(frameCount * rig.targets.size());
    for (std::size_t f = 0; f < frameCount; ++f) {
        for (std::size_t c = 0; c < face.size(); ++c)
            face[c] = placeOf[c] < 0 ? 0.0f : motion.faceFrames[f * floats + std::size_t(placeOf[c])];
        expandFaceChannels(rig, face, channels);
        morphTargetWeights(rig, channels, weights);
        result.weights.insert(result.weights.end(), weights.begin(), weights.end());
    }
    return result;
}

/// An animated node's transform must be TRS (glTF forbids animating a matrix).
void toTrs(tinygltf::Node& node)
{
    if (node.matrix.size() != 16)
        return;
    Mat4 m;
    std::copy(node.matrix.begin(), node.matrix.end(), m.begin());
    const Quatd r = gltf::rotationOf(m);
    const double sx = std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
    const double sy = std::sqrt(m[4] * m[4] + m[5] * m[5] + m[6] * m[6]);
    const double sz = std::sqrt(m[8] * m[8] + m[9] * m[9] + m[10] * m[10]);
    node.translation = {m[12], m[13], m[14]};
    node.rotation = {r.x, r.y, r.z, r.w};
    node.scale = {sx, sy, sz};
    node.matrix.clear();
}

} // namespace

Result<GltfMotionResult> writeGltfMotion(const std::filesystem::path& output, const std::filesystem::path& model,
                                         const anim::Skeleton& skeleton, const GltfMotion& motion, bool animationOnly)
{
    if (output.extension() != ".glb")
        return makeError(ErrorCode::InvalidArgument, output.string() + ": glTF motion is written as a .glb file");
    const std::size_t floats = skeleton.frameLayout()->floatCount();
    if (!(motion.fps > 0) || motion.bodyFrames.empty() || motion.bodyFrames.size() % floats != 0)
        return makeError(ErrorCode::InvalidArgument, "The motion to write has no whole frames of its skeleton at a positive rate");
    const std::size_t frameCount = motion.bodyFrames.size() / floats;
    const std::size_t faceFloats = motion.faceLayout ? motion.faceLayout->floatCount() : 0;
    if (!motion.faceFrames.empty() && motion.faceFrames.size() != frameCount * faceFloats)
        return makeError(ErrorCode::InvalidArgument, "The face frames are not as many as the body's");

    Result<gltf::File> file = gltf::readFile(model, false);
    if (!file)
        return file.error();
    const gltf::AccessorReader reader(*file);
    Result<gltf::NodeTree> tree = gltf::nodeTree(file->model, reader);
    if (!tree)
        return tree.error();
    const tinygltf::Model& source = file->model;

    // Each joint's node, by the name the import gave it. Mesh nodes may share a joint's name
    // (FBX2glTF names a rigid part after its bone): skin joints first, then nodes without a mesh.
    std::vector<int> rank(source.nodes.size(), 2);
    for (std::size_t n = 0; n < source.nodes.size(); ++n)
        rank[n] = source.nodes[n].mesh < 0 ? 1 : 2;
    for (const tinygltf::Skin& skin : source.skins)
        for (int joint : skin.joints)
            if (joint >= 0 && std::size_t(joint) < rank.size())
                rank[std::size_t(joint)] = 0;
    std::map<std::string, int> nodeByName;
    for (std::size_t n = 0; n < source.nodes.size(); ++n) {
        const auto [it, added] = nodeByName.emplace(gltf::nodeName(source, int(n)), int(n));
        if (!added && rank[n] < rank[std::size_t(it->second)])
            it->second = int(n);
    }
    const int jointCount = skeleton.jointCount();
    std::vector<int> nodeOfJoint(std::size_t(jointCount), -1);
    std::vector<int> jointOfNode(source.nodes.size(), -1);
    for (int j = 0; j < jointCount; ++j) {
        const std::string& name = skeleton.joint(j).sourceName.empty() ? skeleton.joint(j).name : skeleton.joint(j).sourceName;
        const auto found = nodeByName.find(name);
        if (found == nodeByName.end())
            return makeError(ErrorCode::NotFound, "The glTF file " + model.string() + " has no node " + name +
                                                      " for the joint " + skeleton.joint(j).name +
                                                      ": the character was not read from this file.");
        nodeOfJoint[std::size_t(j)] = found->second;
        jointOfNode[std::size_t(found->second)] = j;
    }

    // The rig's turn, from the rest poses; a model that does not match is another file.
    std::vector<Vec3d> filePositions, restPositions = skeleton.worldPositions(skeleton.restFrame());
    double extent = 0;
    for (int j = 0; j < jointCount; ++j) {
        filePositions.push_back(translationOf(tree->world[std::size_t(nodeOfJoint[std::size_t(j)])]));
        extent = std::max(extent, length(restPositions[std::size_t(j)] - restPositions[0]));
    }
    const auto [turn, miss] = findTurn(filePositions, restPositions);
    if (miss > 1e-4 * std::max(1.0, extent))
        return makeError(ErrorCode::InvalidArgument, "The joints of " + model.string() + " do not stand where the character's do (" +
                                                         std::to_string(miss) + " apart): the character was not read from this file.");
    const Quatd unturn = anim::conjugate(turn);

    // Per frame, every joint node's local rotation and translation in the file's hierarchy.
    const auto joints = std::size_t(jointCount);
    std::vector<Vec3d> positions(joints);
    std::vector<Quatd> orientations(joints);
    std::vector<Quatd> nodeRotation(source.nodes.size());
    std::vector<Vec3d> nodePosition(source.nodes.size());
    std::vector<std::vector<float>> rotations(joints), translations(joints);
    std::vector<bool> moves(joints, false);
    std::vector<Quatd> restWorld(joints);
    for (std::size_t j = 0; j < joints; ++j)
        restWorld[j] = gltf::rotationOf(tree->world[std::size_t(nodeOfJoint[j])]);
    for (std::size_t f = 0; f < frameCount; ++f) {
        skeleton.worldTransforms(motion.bodyFrames.subspan(f * floats, floats), positions, orientations);
        for (int j = 0; j < jointCount; ++j) {
            const auto n = std::size_t(nodeOfJoint[std::size_t(j)]);
            nodeRotation[n] = anim::normalize(unturn * orientations[std::size_t(j)] * turn * restWorld[std::size_t(j)]);
            nodePosition[n] = anim::rotate(unturn, positions[std::size_t(j)]);
        }
        for (int j = 0; j < jointCount; ++j) {
            const auto n = std::size_t(nodeOfJoint[std::size_t(j)]);
            const int p = tree->parent[n];
            Quatd parentRotation = Quatd::identity();
            Vec3d parentPosition{0, 0, 0};
            double parentScale = 1;
            if (p >= 0) {
                const Mat4& rest = tree->world[std::size_t(p)];
                parentScale = scaleOf(rest);
                const bool animated = jointOfNode[std::size_t(p)] >= 0;
                parentRotation = animated ? nodeRotation[std::size_t(p)] : gltf::rotationOf(rest);
                parentPosition = animated ? nodePosition[std::size_t(p)] : translationOf(rest);
            }
            gltf::appendRotation(rotations[std::size_t(j)], anim::normalize(anim::conjugate(parentRotation) * nodeRotation[n]));
            const Vec3d t = anim::rotate(anim::conjugate(parentRotation), nodePosition[n] - parentPosition) * (1 / parentScale);
            translations[std::size_t(j)].insert(translations[std::size_t(j)].end(), {float(t.x), float(t.y), float(t.z)});
            const tinygltf::Node& node = source.nodes[n];
            const Vec3d rest = node.matrix.size() == 16 ? Vec3d{node.matrix[12], node.matrix[13], node.matrix[14]}
                               : node.translation.size() == 3 ? Vec3d{node.translation[0], node.translation[1], node.translation[2]}
                                                              : Vec3d{0, 0, 0};
            if (length(t - rest) > 1e-5 * std::max(1.0, extent / parentScale))
                moves[std::size_t(j)] = true;
        }
    }

    tinygltf::Model out = animationOnly ? nodesOnly(source) : source;
    // Every node named (as import names it): a node with nothing else left, a mesh's node in an
    // animation-only file, would be written as null, which no reader takes.
    for (std::size_t n = 0; n < out.nodes.size(); ++n)
        if (out.nodes[n].name.empty())
            out.nodes[n].name = gltf::nodeName(source, int(n));
    if (!animationOnly) {
        // The model's own animations give way to the bake, their data with them.
        out.animations.clear();
        if (auto gathered = gatherIntoOneBuffer(out, model); !gathered)
            return gathered.error();
        gltf::dropUnused(out);
    }
    out.asset.generator = "Thespis Studio (bake-motion)";
    tinygltf::Animation animation;
    animation.name = motion.name;
    const int timeAccessor = gltf::addFrameTimes(out, frameCount, motion.fps);
    GltfMotionResult result;
    for (int j = 0; j < jointCount; ++j) {
        const int n = nodeOfJoint[std::size_t(j)];
        toTrs(out.nodes[std::size_t(n)]);
        gltf::addChannel(out, animation, timeAccessor, n, "rotation", rotations[std::size_t(j)], TINYGLTF_TYPE_VEC4, 4);
        if (moves[std::size_t(j)])
            gltf::addChannel(out, animation, timeAccessor, n, "translation", translations[std::size_t(j)], TINYGLTF_TYPE_VEC3, 3);
        ++result.animatedNodes;
    }

    // Face tracks onto the model's morph targets, as its face mapping drives them (with the meshes only).
    if (!animationOnly && !motion.faceFrames.empty() && motion.face) {
        const FaceWeights face = faceWeights(motion, frameCount);
        std::map<std::string, std::size_t> targetByName;
        for (std::size_t t = 0; t < motion.face->targets.size(); ++t)
            if (face.driven[t])
                targetByName.emplace(motion.face->targets[t].name, t);
        for (std::size_t n = 0; n < out.nodes.size(); ++n) {
            const int meshIndex = source.nodes[n].mesh;
            if (meshIndex < 0 || std::size_t(meshIndex) >= source.meshes.size())
                continue;
            const tinygltf::Mesh& mesh = source.meshes[std::size_t(meshIndex)];
            const std::vector<std::string> names = gltf::morphTargetNames(mesh, meshIndex);
            const std::vector<double>& defaults = source.nodes[n].weights.empty() ? mesh.weights : source.nodes[n].weights;
            std::vector<std::ptrdiff_t> targetOf(names.size(), -1);
            for (std::size_t k = 0; k < names.size(); ++k)
                if (const auto found = targetByName.find(names[k]); found != targetByName.end())
                    targetOf[k] = std::ptrdiff_t(found->second);
            std::vector<float> weights;
            weights.reserve(frameCount * names.size());
            bool changes = false; // a face at rest all along needs no channel
            for (std::size_t f = 0; f < frameCount; ++f)
                for (std::size_t k = 0; k < names.size(); ++k) {
                    const float base = k < defaults.size() ? float(defaults[k]) : 0.0f;
                    const float driven = targetOf[k] < 0 ? 0.0f : face.weights[f * face.targets + std::size_t(targetOf[k])];
                    weights.push_back(base + driven);
                    changes = changes || driven != 0;
                }
            if (!changes)
                continue;
            for (std::size_t k = 0; k < names.size(); ++k)
                if (targetOf[k] >= 0)
                    result.morphTargets.push_back("mesh " + mesh.name + ": " + names[k]);
            gltf::addChannel(out, animation, timeAccessor, int(n), "weights", weights, TINYGLTF_TYPE_SCALAR, 1);
        }
    }
    out.animations.push_back(std::move(animation));

    if (auto written = gltf::writeGlb(out, output); !written)
        return written.error();
    return result;
}

} // namespace thespis::core::scene
