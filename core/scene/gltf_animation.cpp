// glTF animations for the character import (gltf_animation.h): reading the channels, sampling
// them the way glTF interpolates, and resampling them into clips on the skeleton's frame layout.

#include "scene/gltf_animation.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <memory>

#include "anim/keyframe_clip.h"

namespace thespis::core::scene::gltf {
namespace {

/// A node's rest rotation in its parent.
Quatd restRotation(const tinygltf::Node& node)
{
    if (node.matrix.size() == 16)
        return rotationOf(localMatrix(node));
    if (node.rotation.size() == 4)
        return anim::normalize(Quatd{node.rotation[0], node.rotation[1], node.rotation[2], node.rotation[3]});
    return {};
}

} // namespace

std::array<double, 4> Track::sample(double t) const
{
    std::array<double, 4> out{};
    const std::size_t n = times.size();
    auto keyValue = [&](std::size_t k) {
        std::array<double, 4> v{};
        for (int c = 0; c < components(); ++c)
            v[std::size_t(c)] = key(k, c);
        return v;
    };
    if (t <= times.front())
        return keyValue(0);
    if (t >= times.back())
        return keyValue(n - 1);
    const std::size_t k = std::size_t(std::upper_bound(times.begin(), times.end(), t) - times.begin()) - 1;
    const double span = times[k + 1] - times[k];
    if (!(span > 0))
        return keyValue(k + 1);
    const double u = (t - times[k]) / span;
    switch (interpolation) {
    case Interpolation::Step: return keyValue(k);
    case Interpolation::Linear: {
        const std::array<double, 4> a = keyValue(k), b = keyValue(k + 1);
        if (path == Path::Rotation) {
            const Quatd q = anim::slerp(anim::normalize(Quatd{a[0], a[1], a[2], a[3]}),
                                        anim::normalize(Quatd{b[0], b[1], b[2], b[3]}), u);
            return {q.x, q.y, q.z, q.w};
        }
        for (std::size_t c = 0; c < 4; ++c)
            out[c] = a[c] + (b[c] - a[c]) * u;
        return out;
    }
    case Interpolation::CubicSpline: {
        // Hermite: p(u) = h00·v_k + h10·Δ·b_k + h01·v_k+1 + h11·Δ·a_k+1 (glTF 2.0, Appendix C).
        const double u2 = u * u, u3 = u2 * u;
        const double h00 = 2 * u3 - 3 * u2 + 1, h10 = u3 - 2 * u2 + u, h01 = -2 * u3 + 3 * u2, h11 = u3 - u2;
        for (int c = 0; c < components(); ++c)
            out[std::size_t(c)] = h00 * values(3 * k + 1, c) + h10 * span * values(3 * k + 2, c) +
                                  h01 * values(3 * k + 4, c) + h11 * span * values(3 * k + 3, c);
        if (path == Path::Rotation) {
            const Quatd q = anim::normalize(Quatd{out[0], out[1], out[2], out[3]});
            return {q.x, q.y, q.z, q.w};
        }
        return out;
    }
    }
    return out;
}

Result<std::vector<Animation>> readAnimations(const tinygltf::Model& model, const AccessorReader& reader,
                                              std::span<const int> jointOfNode, IgnoredChannels& ignored)
{
    std::vector<Animation> animations;
    for (std::size_t a = 0; a < model.animations.size(); ++a) {
        const tinygltf::Animation& source = model.animations[a];
        Animation animation;
        animation.name = source.name.empty() ? "animation" + std::to_string(a) : source.name;
        const std::string use = "animation \"" + animation.name + "\"";
        for (std::size_t c = 0; c < source.channels.size(); ++c) {
            const tinygltf::AnimationChannel& channel = source.channels[c];
            const std::string channelUse = use + " channel " + std::to_string(c);
            if (channel.sampler < 0 || std::size_t(channel.sampler) >= source.samplers.size())
                return reader.broken(channelUse + " names a sampler that does not exist");
            if (channel.target_node < 0 || std::size_t(channel.target_node) >= model.nodes.size())
                continue; // no target node: the channel animates something outside the nodes (an extension)
            const std::string nodeLabel = nodeName(model, channel.target_node);
            const tinygltf::AnimationSampler& sampler = source.samplers[std::size_t(channel.sampler)];
            Result<AccessorData> input = reader.read(sampler.input, channelUse + " times");
            if (!input)
                return input.error();
            if (input->components != 1 || input->count == 0)
                return reader.broken(channelUse + " times are not a non-empty list of scalars");
            for (std::size_t k = 0; k < input->count; ++k)
                if (!std::isfinite(input->values[k]) || input->values[k] < 0 ||
                    (k > 0 && input->values[k] < input->values[k - 1]))
                    return reader.broken(channelUse + " has key times that are negative, not finite or out of order");
            animation.duration = std::max(animation.duration, input->values.back());

            Track track;
            if (channel.target_path == "rotation")
                track.path = Path::Rotation;
            else if (channel.target_path == "translation")
                track.path = Path::Translation;
            else {
                if (channel.target_path == "weights")
                    ignored.weights.insert(nodeLabel);
                else if (channel.target_path == "scale") {
                    // Files often key a constant scale (COLLADA2GLTF keys every channel): only a
                    // scale that changes the node is worth a warning.
                    Result<AccessorData> output = reader.read(sampler.output, channelUse + " values");
                    if (!output)
                        return output.error();
                    const std::vector<double>& rest = model.nodes[std::size_t(channel.target_node)].scale;
                    const bool cubic = sampler.interpolation == "CUBICSPLINE"; // keys between their tangents
                    for (std::size_t i = cubic ? 3 : 0; i < output->values.size(); i += cubic ? 9 : 3)
                        for (std::size_t axis = 0; axis < 3 && i + axis < output->values.size(); ++axis) {
                            const double expected = rest.size() == 3 ? rest[axis] : 1.0;
                            if (std::abs(output->values[i + axis] - expected) > 1e-4 * std::max(1.0, std::abs(expected)))
                                ignored.scale.insert(nodeLabel);
                        }
                }
                continue;
            }
            const int joint = jointOfNode[std::size_t(channel.target_node)];
            if (joint < 0) {
                ignored.outsideSkeleton.insert(nodeLabel);
                continue;
            }
            track.joint = joint;
            if (sampler.interpolation == "STEP")
                track.interpolation = Interpolation::Step;
            else if (sampler.interpolation == "CUBICSPLINE")
                track.interpolation = Interpolation::CubicSpline;
            else if (sampler.interpolation.empty() || sampler.interpolation == "LINEAR")
                track.interpolation = Interpolation::Linear;
            else
                return reader.broken(channelUse + " has an unknown interpolation \"" + sampler.interpolation + "\"");
            Result<AccessorData> output = reader.read(sampler.output, channelUse + " values");
            if (!output)
                return output.error();
            const int components = track.path == Path::Rotation ? 4 : 3;
            const std::size_t perKey = track.interpolation == Interpolation::CubicSpline ? 3 : 1;
            if (output->components != components || output->count != input->count * perKey)
                return reader.broken(channelUse + " values do not hold one " +
                                     (track.path == Path::Rotation ? std::string("quaternion") : "3D vector") +
                                     (perKey == 3 ? " and two tangents" : "") + " per key");
            for (double v : output->values)
                if (!std::isfinite(v))
                    return reader.broken(channelUse + " has a value that is not finite");
            track.times = std::move(input->values);
            track.values = std::move(*output);
            animation.tracks.push_back(std::move(track));
        }
        animations.push_back(std::move(animation));
    }

    // COLLADA2GLTF writes one unnamed animation per node: they are parts of one motion.
    const bool allUnnamed = std::all_of(model.animations.begin(), model.animations.end(),
                                        [](const tinygltf::Animation& a) { return a.name.empty(); });
    std::set<std::pair<int, std::string>> targets;
    bool disjoint = true;
    for (const tinygltf::Animation& animation : model.animations)
        for (const tinygltf::AnimationChannel& channel : animation.channels)
            disjoint = disjoint && targets.emplace(channel.target_node, channel.target_path).second;
    if (animations.size() > 1 && allUnnamed && disjoint) {
        Animation merged;
        merged.name = "animation";
        for (Animation& part : animations) {
            merged.duration = std::max(merged.duration, part.duration);
            std::move(part.tracks.begin(), part.tracks.end(), std::back_inserter(merged.tracks));
        }
        animations.assign(1, std::move(merged));
    }
    return animations;
}

bool movesJoint(const Track& track, const Vec3d& rest, const Mat4& parent, double tolerance)
{
    if (track.interpolation == Interpolation::CubicSpline)
        return true; // tangents may move it between keys
    for (std::size_t k = 0; k < track.times.size(); ++k) {
        const Vec3d key{track.key(k, 0), track.key(k, 1), track.key(k, 2)};
        const Vec3d offset = transformVector(parent, key - rest);
        if (std::sqrt(anim::dot(offset, offset)) > tolerance)
            return true;
    }
    return false;
}

Result<void> buildClips(const File& file, const NodeTree& tree, std::span<const int> jointNodes, double rate,
                        const std::vector<Animation>& animations, Character& character)
{
    const anim::Skeleton& skeleton = character.skeleton;
    const anim::FrameLayout& layout = *skeleton.frameLayout();
    const std::vector<float> rest = skeleton.restFrame();
    // Per joint: the rest world transform and rotation of its glTF parent, its own rest rotation.
    std::vector<Mat4> parentTransform;
    std::vector<Quatd> parentRotation, inverseRestRotation;
    for (int node : jointNodes) {
        parentTransform.push_back(parentWorld(tree, node));
        parentRotation.push_back(rotationOf(parentTransform.back()));
        inverseRestRotation.push_back(anim::conjugate(restRotation(file.model.nodes[std::size_t(node)])));
    }
    constexpr double kMaxClipFloats = double(std::size_t(1) << 26);
    for (const Animation& animation : animations) {
        if (animation.tracks.empty()) {
            character.warnings.push_back("Animation \"" + animation.name + "\" moves no joint and is left out.");
            continue;
        }
        const double frames = std::ceil(animation.duration * rate - 1e-9) + 1;
        if (frames * double(layout.floatCount()) > kMaxClipFloats) {
            character.warnings.push_back("Animation \"" + animation.name + "\" is too long (" +
                                         std::to_string(animation.duration) + " s) and is left out.");
            continue;
        }
        const auto frameCount = std::size_t(frames);
        std::vector<float> data;
        data.reserve(frameCount * layout.floatCount());
        for (std::size_t f = 0; f < frameCount; ++f) {
            const double t = double(f) / rate;
            const std::size_t base = data.size();
            data.insert(data.end(), rest.begin(), rest.end());
            for (const Track& track : animation.tracks) {
                const std::array<double, 4> v = track.sample(t);
                const auto j = std::size_t(track.joint);
                if (track.path == Path::Rotation) {
                    // Rw · r(t) · rrest⁻¹ · Rw⁻¹: the change from rest, in the world-aligned frame.
                    const Quatd r = anim::normalize(Quatd{v[0], v[1], v[2], v[3]});
                    const Quatd q = parentRotation[j] * r * inverseRestRotation[j] * anim::conjugate(parentRotation[j]);
                    float* out = data.data() + base + 4 * j;
                    out[0] = float(q.x);
                    out[1] = float(q.y);
                    out[2] = float(q.z);
                    out[3] = float(q.w);
                    continue;
                }
                const int element = skeleton.translationElement(track.joint);
                if (element < 0)
                    continue; // the channel holds the rest translation
                // The root's translation is its world position; another joint's, its offset in the world.
                const Vec3d local{v[0], v[1], v[2]};
                const Vec3d offset = j == 0 ? transformPoint(parentTransform[j], local)
                                            : transformVector(parentTransform[j], local);
                float* out = data.data() + base + layout.floatOffset(element);
                out[0] = float(offset.x);
                out[1] = float(offset.y);
                out[2] = float(offset.z);
            }
        }
        Result<std::shared_ptr<anim::KeyframeClip>> clip =
            anim::KeyframeClip::create(skeleton.frameLayout(), rate, std::move(data), animation.name);
        if (!clip)
            return makeError(ErrorCode::CorruptData,
                             "The glTF file " + file.name + " has an animation that cannot be imported: \"" +
                                 animation.name + "\".",
                             clip.error().message);
        character.clips.push_back(std::move(*clip));
    }
    return {};
}

} // namespace thespis::core::scene::gltf
