#include "scene/gltf_writing.h"

#include <algorithm>
#include <limits>
#include <sstream>

#include "util/file_io.h"

namespace thespis::core::scene::gltf {

int addView(tinygltf::Model& model, const void* bytes, std::size_t size, int target)
{
    std::vector<unsigned char>& data = model.buffers[0].data;
    data.resize((data.size() + 3) / 4 * 4, 0);
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = data.size();
    view.byteLength = size;
    view.target = target;
    const auto* first = static_cast<const unsigned char*>(bytes);
    data.insert(data.end(), first, first + size);
    model.bufferViews.push_back(std::move(view));
    return int(model.bufferViews.size()) - 1;
}

int addAccessor(tinygltf::Model& model, const std::vector<float>& values, int type, int components, bool withBounds,
                int target)
{
    tinygltf::Accessor accessor;
    accessor.bufferView = addView(model, values.data(), values.size() * sizeof(float), target);
    accessor.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
    accessor.type = type;
    accessor.count = values.size() / std::size_t(components);
    if (withBounds && !values.empty()) {
        accessor.minValues.assign(std::size_t(components), std::numeric_limits<double>::infinity());
        accessor.maxValues.assign(std::size_t(components), -std::numeric_limits<double>::infinity());
        for (std::size_t i = 0; i < values.size(); ++i) {
            double& low = accessor.minValues[i % std::size_t(components)];
            double& high = accessor.maxValues[i % std::size_t(components)];
            low = std::min(low, double(values[i]));
            high = std::max(high, double(values[i]));
        }
    }
    model.accessors.push_back(std::move(accessor));
    return int(model.accessors.size()) - 1;
}

int addIntegerAccessor(tinygltf::Model& model, const void* bytes, std::size_t size, int componentType, int type,
                       std::size_t count, int target)
{
    tinygltf::Accessor accessor;
    accessor.bufferView = addView(model, bytes, size, target);
    accessor.componentType = componentType;
    accessor.type = type;
    accessor.count = count;
    model.accessors.push_back(std::move(accessor));
    return int(model.accessors.size()) - 1;
}

int addFrameTimes(tinygltf::Model& model, std::size_t frames, double fps)
{
    std::vector<float> times(frames);
    for (std::size_t f = 0; f < frames; ++f)
        times[f] = float(double(f) / fps);
    return addAccessor(model, times, TINYGLTF_TYPE_SCALAR, 1, true);
}

void addChannel(tinygltf::Model& model, tinygltf::Animation& animation, int times, int node, const char* path,
                const std::vector<float>& values, int type, int components)
{
    tinygltf::AnimationSampler sampler;
    sampler.input = times;
    sampler.output = addAccessor(model, values, type, components, false);
    sampler.interpolation = "LINEAR";
    animation.samplers.push_back(std::move(sampler));
    tinygltf::AnimationChannel channel;
    channel.sampler = int(animation.samplers.size()) - 1;
    channel.target_node = node;
    channel.target_path = path;
    animation.channels.push_back(std::move(channel));
}

void appendRotation(std::vector<float>& values, anim::Quatd q)
{
    const std::size_t n = values.size();
    if (n >= 4 && double(values[n - 4]) * q.x + double(values[n - 3]) * q.y + double(values[n - 2]) * q.z +
                          double(values[n - 1]) * q.w < 0)
        q = {-q.x, -q.y, -q.z, -q.w};
    values.insert(values.end(), {float(q.x), float(q.y), float(q.z), float(q.w)});
}

void dropUnused(tinygltf::Model& model)
{
    // What is referred to: accessors by meshes, skins and animations; views by accessors
    // (sparse parts too) and images.
    std::vector<char> accessorUsed(model.accessors.size(), 0), viewUsed(model.bufferViews.size(), 0);
    auto useAccessor = [&](int a) {
        if (a >= 0 && std::size_t(a) < accessorUsed.size())
            accessorUsed[std::size_t(a)] = 1;
    };
    for (const tinygltf::Mesh& mesh : model.meshes)
        for (const tinygltf::Primitive& primitive : mesh.primitives) {
            for (const auto& [name, accessor] : primitive.attributes)
                useAccessor(accessor);
            useAccessor(primitive.indices);
            for (const auto& target : primitive.targets)
                for (const auto& [name, accessor] : target)
                    useAccessor(accessor);
        }
    for (const tinygltf::Skin& skin : model.skins)
        useAccessor(skin.inverseBindMatrices);
    for (const tinygltf::Animation& animation : model.animations)
        for (const tinygltf::AnimationSampler& sampler : animation.samplers) {
            useAccessor(sampler.input);
            useAccessor(sampler.output);
        }
    auto useView = [&](int v) {
        if (v >= 0 && std::size_t(v) < viewUsed.size())
            viewUsed[std::size_t(v)] = 1;
    };
    for (std::size_t a = 0; a < model.accessors.size(); ++a)
        if (accessorUsed[a]) {
            const tinygltf::Accessor& accessor = model.accessors[a];
            useView(accessor.bufferView);
            if (accessor.sparse.isSparse) {
                useView(accessor.sparse.indices.bufferView);
                useView(accessor.sparse.values.bufferView);
            }
        }
    for (const tinygltf::Image& image : model.images)
        useView(image.bufferView);

    // The kept views' bytes, in order, into a new buffer; then every index renumbered.
    std::vector<int> newView(model.bufferViews.size(), -1), newAccessor(model.accessors.size(), -1);
    std::vector<tinygltf::BufferView> views;
    std::vector<unsigned char> data;
    const std::vector<unsigned char>& old = model.buffers[0].data;
    for (std::size_t v = 0; v < model.bufferViews.size(); ++v) {
        if (!viewUsed[v])
            continue;
        tinygltf::BufferView view = model.bufferViews[v];
        data.resize((data.size() + 15) / 16 * 16, 0); // keeps every accessor's alignment
        const auto begin = old.begin() + std::ptrdiff_t(view.byteOffset);
        data.insert(data.end(), begin, begin + std::ptrdiff_t(view.byteLength));
        view.byteOffset = data.size() - view.byteLength;
        newView[v] = int(views.size());
        views.push_back(std::move(view));
    }
    auto renumberView = [&](int& v) { v = v >= 0 ? newView[std::size_t(v)] : v; };
    std::vector<tinygltf::Accessor> accessors;
    for (std::size_t a = 0; a < model.accessors.size(); ++a) {
        if (!accessorUsed[a])
            continue;
        tinygltf::Accessor accessor = model.accessors[a];
        renumberView(accessor.bufferView);
        if (accessor.sparse.isSparse) {
            renumberView(accessor.sparse.indices.bufferView);
            renumberView(accessor.sparse.values.bufferView);
        }
        newAccessor[a] = int(accessors.size());
        accessors.push_back(std::move(accessor));
    }
    auto renumberAccessor = [&](int& a) { a = a >= 0 ? newAccessor[std::size_t(a)] : a; };
    for (tinygltf::Mesh& mesh : model.meshes)
        for (tinygltf::Primitive& primitive : mesh.primitives) {
            for (auto& [name, accessor] : primitive.attributes)
                renumberAccessor(accessor);
            renumberAccessor(primitive.indices);
            for (auto& target : primitive.targets)
                for (auto& [name, accessor] : target)
                    renumberAccessor(accessor);
        }
    for (tinygltf::Skin& skin : model.skins)
        renumberAccessor(skin.inverseBindMatrices);
    for (tinygltf::Animation& animation : model.animations)
        for (tinygltf::AnimationSampler& sampler : animation.samplers) {
            renumberAccessor(sampler.input);
            renumberAccessor(sampler.output);
        }
    for (tinygltf::Image& image : model.images)
        renumberView(image.bufferView);
    model.accessors = std::move(accessors);
    model.bufferViews = std::move(views);
    model.buffers[0].data = std::move(data);
}

Result<void> writeGlb(const tinygltf::Model& model, const std::filesystem::path& output)
{
    tinygltf::TinyGLTF writer;
    std::ostringstream bytes;
    // tinygltf's writer takes a non-const model but does not change it.
    if (!writer.WriteGltfSceneToStream(const_cast<tinygltf::Model*>(&model), bytes, false, true))
        return makeError(ErrorCode::Internal, "The glTF writer could not write " + output.string() + ".");
    return writeFileAtomically(output, bytes.str());
}

} // namespace thespis::core::scene::gltf
