// The glTF reading that gltf_reader.h declares: affine matrices, opening a .gltf / .glb file,
// bound-checked accessors and the node hierarchy at rest. The mesh itself is built in
// gltf_mesh.cpp.

#include "scene/gltf_reader.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <exception>
#include <fstream>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "util/file_io.h"
#include "util/text.h"

namespace thespis::core::scene::gltf {

// ---- 4×4 affine matrices ---------------------------------------------------------------------

namespace {

double at(const Mat4& m, int row, int column) { return m[std::size_t(column * 4 + row)]; }

} // namespace

std::array<double, 9> normalMatrix(const Mat4& m)
{
    auto a = [&](int r, int c) { return at(m, r, c); };
    std::array<double, 9> n{}; // row-major
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) {
            const int r1 = (r + 1) % 3, r2 = (r + 2) % 3, c1 = (c + 1) % 3, c2 = (c + 2) % 3;
            n[std::size_t(r * 3 + c)] = a(r1, c1) * a(r2, c2) - a(r1, c2) * a(r2, c1);
        }
    return n;
}

Mat4 multiply(const Mat4& a, const Mat4& b)
{
    Mat4 c{};
    for (int column = 0; column < 4; ++column)
        for (int row = 0; row < 4; ++row) {
            double sum = 0;
            for (int k = 0; k < 4; ++k)
                sum += at(a, row, k) * at(b, k, column);
            c[std::size_t(column * 4 + row)] = sum;
        }
    return c;
}

Vec3d transformPoint(const Mat4& m, Vec3d p)
{
    return transformVector(m, p) + Vec3d{m[12], m[13], m[14]};
}

Vec3d transformVector(const Mat4& m, Vec3d v)
{
    return {m[0] * v.x + m[4] * v.y + m[8] * v.z, m[1] * v.x + m[5] * v.y + m[9] * v.z,
            m[2] * v.x + m[6] * v.y + m[10] * v.z};
}

double determinant3(const Mat4& m)
{
    return at(m, 0, 0) * (at(m, 1, 1) * at(m, 2, 2) - at(m, 1, 2) * at(m, 2, 1)) -
           at(m, 0, 1) * (at(m, 1, 0) * at(m, 2, 2) - at(m, 1, 2) * at(m, 2, 0)) +
           at(m, 0, 2) * (at(m, 1, 0) * at(m, 2, 1) - at(m, 1, 1) * at(m, 2, 0));
}

std::optional<Mat4> invertAffine(const Mat4& m)
{
    const double det = determinant3(m);
    if (!(std::abs(det) > 1e-300) || !std::isfinite(det))
        return std::nullopt;
    const std::array<double, 9> cof = normalMatrix(m); // cofactors; inverse = cofᵀ / det
    Mat4 inv = kIdentity;
    for (std::size_t r = 0; r < 3; ++r)
        for (std::size_t c = 0; c < 3; ++c)
            inv[c * 4 + r] = cof[c * 3 + r] / det;
    const Vec3d t = transformPoint(inv, {m[12], m[13], m[14]});
    inv[12] = -t.x;
    inv[13] = -t.y;
    inv[14] = -t.z;
    return inv;
}

Mat4 localMatrix(const tinygltf::Node& node)
{
    if (node.matrix.size() == 16) {
        Mat4 m;
        std::copy(node.matrix.begin(), node.matrix.end(), m.begin());
        return m;
    }
    const Vec3d t = node.translation.size() == 3 ? Vec3d{node.translation[0], node.translation[1], node.translation[2]}
                                                 : Vec3d{};
    const Vec3d s = node.scale.size() == 3 ? Vec3d{node.scale[0], node.scale[1], node.scale[2]} : Vec3d{1, 1, 1};
    Quatd q;
    if (node.rotation.size() == 4)
        q = anim::normalize(Quatd{node.rotation[0], node.rotation[1], node.rotation[2], node.rotation[3]});
    const Vec3d x = anim::rotate(q, Vec3d{s.x, 0, 0});
    const Vec3d y = anim::rotate(q, Vec3d{0, s.y, 0});
    const Vec3d z = anim::rotate(q, Vec3d{0, 0, s.z});
    return {x.x, x.y, x.z, 0, y.x, y.y, y.z, 0, z.x, z.y, z.z, 0, t.x, t.y, t.z, 1};
}

Quatd rotationOf(const Mat4& m)
{
    auto normalized = [](Vec3d v) {
        const double n = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
        return n > 0 ? v * (1 / n) : v;
    };
    auto dot3 = [](Vec3d a, Vec3d b) { return a.x * b.x + a.y * b.y + a.z * b.z; };
    const double sign = determinant3(m) < 0 ? -1.0 : 1.0;
    Vec3d x = normalized(Vec3d{m[0], m[1], m[2]} * sign);
    Vec3d y = Vec3d{m[4], m[5], m[6]} * sign;
    y = normalized(y - x * dot3(x, y));
    const Vec3d z{x.y * y.z - x.z * y.y, x.z * y.x - x.x * y.z, x.x * y.y - x.y * y.x};
    // Shepperd's method on the orthonormal basis (columns x, y, z).
    const double trace = x.x + y.y + z.z;
    Quatd q;
    if (trace > 0) {
        const double s = std::sqrt(trace + 1) * 2;
        q = {(y.z - z.y) / s, (z.x - x.z) / s, (x.y - y.x) / s, s / 4};
    } else if (x.x > y.y && x.x > z.z) {
        const double s = std::sqrt(1 + x.x - y.y - z.z) * 2;
        q = {s / 4, (y.x + x.y) / s, (z.x + x.z) / s, (y.z - z.y) / s};
    } else if (y.y > z.z) {
        const double s = std::sqrt(1 + y.y - x.x - z.z) * 2;
        q = {(y.x + x.y) / s, s / 4, (z.y + y.z) / s, (z.x - x.z) / s};
    } else {
        const double s = std::sqrt(1 + z.z - x.x - y.y) * 2;
        q = {(z.x + x.z) / s, (z.y + y.z) / s, s / 4, (x.y - y.x) / s};
    }
    return anim::normalize(q);
}

// ---- the file ----------------------------------------------------------------------------------

namespace {

/// Extensions that may be required without changing the geometry we read. Anything else that a
/// file requires (Draco, meshopt, GPU instancing, …) is refused.
bool extensionKeepsGeometry(const std::string& name)
{
    return name == "KHR_mesh_quantization" || name == "KHR_texture_transform" || name == "KHR_lights_punctual" ||
           name == "KHR_texture_basisu" || name == "EXT_texture_webp" || name.starts_with("KHR_materials_");
}

/// Extensions that compress geometry, which Thespis cannot decode. A file may use one without
/// requiring it when it also holds the geometry uncompressed, which is what is read then.
constexpr const char* kCompressions[] = {"KHR_draco_mesh_compression", "EXT_meshopt_compression",
                                         "KHR_meshopt_compression"};

Error cannotDecode(const std::string& file, const std::string& what, const std::string& extension,
                   const std::string& detail = {})
{
    return makeError(ErrorCode::NotOurFormat,
                     "The glTF file " + file + " " + what + " " + extension +
                         ", which Thespis cannot decode; export it without " + extension + ".",
                     detail);
}

/// A compressed part the file holds no uncompressed copy of: a Draco primitive whose attributes
/// or indices have no data of their own, a meshopt buffer view whose own buffer is a placeholder.
std::optional<Error> compressedOnly(const File& file)
{
    const tinygltf::Model& model = file.model;
    const auto hasData = [&](int accessor) {
        if (accessor < 0 || std::size_t(accessor) >= model.accessors.size())
            return true; // not this check's to refuse: the reader names it
        const tinygltf::Accessor& a = model.accessors[std::size_t(accessor)];
        return a.bufferView >= 0 || a.sparse.isSparse;
    };
    for (std::size_t m = 0; m < model.meshes.size(); ++m)
        for (const tinygltf::Primitive& primitive : model.meshes[m].primitives) {
            const char* draco = kCompressions[0];
            if (!primitive.extensions.contains(draco))
                continue;
            bool whole = hasData(primitive.indices) || primitive.indices < 0;
            for (const auto& [name, accessor] : primitive.attributes)
                whole = whole && hasData(accessor);
            if (!whole)
                return cannotDecode(file.name,
                                    "holds mesh " + (model.meshes[m].name.empty() ? std::to_string(m)
                                                                                  : inQuotes(model.meshes[m].name)) +
                                        " only compressed with",
                                    draco);
        }
    for (const tinygltf::BufferView& view : model.bufferViews)
        for (const char* meshopt : {kCompressions[1], kCompressions[2]})
            if (view.extensions.contains(meshopt) &&
                (view.buffer < 0 || std::size_t(view.buffer) >= model.buffers.size() ||
                 model.buffers[std::size_t(view.buffer)].data.size() < view.byteOffset + view.byteLength))
                return cannotDecode(file.name, "holds buffer views only compressed with", meshopt);
    return std::nullopt;
}

bool startsWithGlbMagic(const std::filesystem::path& path)
{
    std::ifstream in(path, std::ios::binary);
    char magic[4] = {};
    in.read(magic, 4);
    return in.gcount() == 4 && std::memcmp(magic, "glTF", 4) == 0;
}

// Image loaders for tinygltf. The decoding one keeps the file loading when an image cannot be
// decoded (an unknown format, a broken JPEG): the character then goes without that texture.
bool skipImage(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*)
{
    return true;
}

bool decodeImage(tinygltf::Image* image, const int index, std::string*, std::string* warning, int width, int height,
                 const unsigned char* bytes, int size, void* imageWarnings)
{
    std::string why;
    if (!tinygltf::LoadImageData(image, index, &why, warning, width, height, bytes, size, nullptr)) {
        image->image.clear();
        static_cast<std::vector<std::string>*>(imageWarnings)
            ->push_back("Image " + std::to_string(index) + (image->name.empty() ? "" : " (\"" + image->name + "\")") +
                        " cannot be decoded and is left out: " + (why.empty() ? "unknown format" : why));
    }
    return true;
}

} // namespace

Result<File> readFile(const std::filesystem::path& path, bool decodeImages)
{
    File file;
    file.name = path.string();
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        return makeError(ErrorCode::FileNotFound, "The glTF file " + file.name + " does not exist.");

    std::string error;
    std::string warning;
    tinygltf::TinyGLTF loader;
    if (decodeImages)
        loader.SetImageLoader(decodeImage, &file.imageWarnings);
    else
        loader.SetImageLoader(skipImage, nullptr);
    bool loaded = false;
    try {
        loaded = startsWithGlbMagic(path) ? loader.LoadBinaryFromFile(&file.model, &error, &warning, file.name)
                                          : loader.LoadASCIIFromFile(&file.model, &error, &warning, file.name);
    } catch (const std::exception& e) {
        error = e.what();
    }
    if (!loaded) {
        // tinygltf stops at what it cannot take (a meshopt placeholder buffer has no "uri"): when
        // the file names a compression, that is the likelier cause, and the one to tell.
        if (Result<std::string> text = readTextFile(path))
            for (const char* extension : kCompressions)
                if (text->find("\"" + std::string(extension) + "\"") != std::string::npos)
                    return cannotDecode(file.name, "cannot be read: it uses", extension, error);
        return makeError(ErrorCode::CorruptData, "The glTF file " + file.name + " cannot be read.", error);
    }

    for (const std::string& extension : file.model.extensionsRequired)
        if (!extensionKeepsGeometry(extension))
            return makeError(ErrorCode::NotOurFormat,
                             "The glTF file " + file.name + " requires the extension " + extension +
                                 ", which Thespis does not support; export it without " + extension + ".");
    if (std::optional<Error> compressed = compressedOnly(file))
        return *compressed;
    return file;
}

// ---- reading accessors ------------------------------------------------------------------------

namespace {

// Upper bound on one accessor's element count: keeps a lying file from asking for gigabytes.
constexpr std::size_t kMaxAccessorCount = std::size_t(1) << 26;

double readComponent(const unsigned char* bytes, int componentType, bool normalized)
{
    auto load = [bytes]<class T>(T) {
        T value;
        std::memcpy(&value, bytes, sizeof value);
        return value;
    };
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
        const double v = load(std::int8_t{});
        return normalized ? std::max(v / 127.0, -1.0) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
        const double v = load(std::uint8_t{});
        return normalized ? v / 255.0 : v;
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
        const double v = load(std::int16_t{});
        return normalized ? std::max(v / 32767.0, -1.0) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        const double v = load(std::uint16_t{});
        return normalized ? v / 65535.0 : v;
    }
    case TINYGLTF_COMPONENT_TYPE_INT: return load(std::int32_t{});
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return load(std::uint32_t{});
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return load(float{});
    default: return 0; // refused before reading
    }
}

} // namespace

Error AccessorReader::broken(const std::string& what) const
{
    return makeError(ErrorCode::CorruptData, "The glTF file " + m_file + " is broken: " + what + ".");
}

Result<AccessorData> AccessorReader::read(int index, const std::string& use) const
{
    if (index < 0 || std::size_t(index) >= m_model.accessors.size())
        return broken(use + " names accessor " + std::to_string(index) + ", which does not exist");
    const tinygltf::Accessor& accessor = m_model.accessors[std::size_t(index)];
    const std::string where = "accessor " + std::to_string(index) + " (" + use + ")";
    const int componentSize = tinygltf::GetComponentSizeInBytes(std::uint32_t(accessor.componentType));
    const int components = tinygltf::GetNumComponentsInType(std::uint32_t(accessor.type));
    if (componentSize <= 0 || componentSize > 4 || components <= 0)
        return broken(where + " has an unknown component or element type");
    if (accessor.count > kMaxAccessorCount)
        return broken(where + " claims " + std::to_string(accessor.count) + " elements");

    // Matrix columns of 1- and 2-byte components are padded to 4 bytes.
    const int columns = accessor.type == TINYGLTF_TYPE_MAT2   ? 2
                        : accessor.type == TINYGLTF_TYPE_MAT3 ? 3
                        : accessor.type == TINYGLTF_TYPE_MAT4 ? 4
                                                              : 1;
    const int rows = components / columns;
    const std::size_t columnBytes = std::size_t(rows * componentSize);
    const std::size_t columnStride = columns > 1 ? (columnBytes + 3) / 4 * 4 : columnBytes;
    const std::size_t elementSize = columnStride * std::size_t(columns);

    AccessorData data;
    data.components = components;
    data.count = accessor.count;
    data.values.assign(accessor.count * std::size_t(components), 0.0); // no buffer view: zeros

    auto readElement = [&](const unsigned char* element, std::size_t to) {
        for (int c = 0; c < columns; ++c)
            for (int r = 0; r < rows; ++r)
                data.values[to * std::size_t(components) + std::size_t(c * rows + r)] =
                    readComponent(element + std::size_t(c) * columnStride + std::size_t(r * componentSize),
                                  accessor.componentType, accessor.normalized);
    };

    if (accessor.bufferView >= 0 && accessor.count > 0) {
        Result<std::span<const unsigned char>> view = viewBytes(accessor.bufferView, where);
        if (!view)
            return view.error();
        const std::size_t byteStride = m_model.bufferViews[std::size_t(accessor.bufferView)].byteStride;
        const std::size_t stride = byteStride != 0 ? byteStride : elementSize;
        if (stride < elementSize)
            return broken(where + " has a byte stride smaller than its elements");
        if (accessor.byteOffset > view->size() || (accessor.count - 1) > (view->size() - accessor.byteOffset) / stride ||
            accessor.byteOffset + (accessor.count - 1) * stride + elementSize > view->size())
            return broken(where + " reads past the end of its buffer view");
        for (std::size_t i = 0; i < accessor.count; ++i)
            readElement(view->data() + accessor.byteOffset + i * stride, i);
    }

    if (accessor.sparse.isSparse) {
        const auto& sparse = accessor.sparse;
        const std::string sparseWhere = "the sparse part of " + where;
        if (sparse.count < 0 || std::size_t(sparse.count) > accessor.count)
            return broken(sparseWhere + " has more elements than the accessor");
        const std::size_t count = std::size_t(sparse.count);
        const int indexSize = tinygltf::GetComponentSizeInBytes(std::uint32_t(sparse.indices.componentType));
        if (sparse.indices.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
            sparse.indices.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
            sparse.indices.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
            return broken(sparseWhere + " has indices that are not unsigned integers");
        Result<std::span<const unsigned char>> indices =
            viewRange(sparse.indices.bufferView, sparse.indices.byteOffset, count * std::size_t(indexSize), sparseWhere);
        if (!indices)
            return indices.error();
        Result<std::span<const unsigned char>> values =
            viewRange(sparse.values.bufferView, sparse.values.byteOffset, count * elementSize, sparseWhere);
        if (!values)
            return values.error();
        for (std::size_t i = 0; i < count; ++i) {
            const double target =
                readComponent(indices->data() + i * std::size_t(indexSize), sparse.indices.componentType, false);
            if (target >= double(accessor.count))
                return broken(sparseWhere + " replaces element " + std::to_string(std::uint64_t(target)) + " of " +
                              std::to_string(accessor.count));
            readElement(values->data() + i * elementSize, std::size_t(target));
        }
    }
    return data;
}

Result<std::span<const unsigned char>> AccessorReader::viewBytes(int viewIndex, const std::string& where) const
{
    if (viewIndex < 0 || std::size_t(viewIndex) >= m_model.bufferViews.size())
        return broken(where + " names buffer view " + std::to_string(viewIndex) + ", which does not exist");
    const tinygltf::BufferView& view = m_model.bufferViews[std::size_t(viewIndex)];
    if (view.buffer < 0 || std::size_t(view.buffer) >= m_model.buffers.size())
        return broken("buffer view " + std::to_string(viewIndex) + " names a buffer that does not exist");
    const std::vector<unsigned char>& buffer = m_model.buffers[std::size_t(view.buffer)].data;
    if (view.byteOffset > buffer.size() || view.byteLength > buffer.size() - view.byteOffset)
        return broken("buffer view " + std::to_string(viewIndex) + " reaches past the end of its buffer (" +
                      std::to_string(buffer.size()) + " bytes)");
    return std::span<const unsigned char>(buffer.data() + view.byteOffset, view.byteLength);
}

Result<std::span<const unsigned char>> AccessorReader::viewRange(int viewIndex, int offset, std::size_t length,
                                                                 const std::string& where) const
{
    Result<std::span<const unsigned char>> view = viewBytes(viewIndex, where);
    if (!view)
        return view.error();
    if (offset < 0 || std::size_t(offset) > view->size() || length > view->size() - std::size_t(offset))
        return broken(where + " reads past the end of its buffer view");
    return view->subspan(std::size_t(offset), length);
}

// ---- the node hierarchy -------------------------------------------------------------------------

Result<NodeTree> nodeTree(const tinygltf::Model& model, const AccessorReader& reader)
{
    const std::size_t count = model.nodes.size();
    NodeTree tree;
    tree.parent.assign(count, -1);
    for (std::size_t n = 0; n < count; ++n)
        for (int child : model.nodes[n].children) {
            if (child < 0 || std::size_t(child) >= count)
                return reader.broken("node " + std::to_string(n) + " has a child " + std::to_string(child) +
                                     " that does not exist");
            if (tree.parent[std::size_t(child)] >= 0 || std::size_t(child) == n)
                return reader.broken("node " + std::to_string(child) + " has more than one parent");
            tree.parent[std::size_t(child)] = int(n);
        }
    tree.world.assign(count, kIdentity);
    std::vector<int> stack;
    for (std::size_t n = 0; n < count; ++n)
        if (tree.parent[n] < 0)
            stack.push_back(int(n));
    std::size_t reached = 0;
    while (!stack.empty()) {
        const auto n = std::size_t(stack.back());
        stack.pop_back();
        const Mat4 local = localMatrix(model.nodes[n]);
        tree.world[n] = tree.parent[n] < 0 ? local : multiply(tree.world[std::size_t(tree.parent[n])], local);
        ++reached;
        for (int child : model.nodes[n].children)
            stack.push_back(child);
    }
    if (reached != count)
        return reader.broken("its node hierarchy has a cycle");
    return tree;
}

std::string nodeName(const tinygltf::Model& model, int index)
{
    const tinygltf::Node& node = model.nodes[std::size_t(index)];
    if (!node.name.empty())
        return node.name;
    if (node.mesh >= 0 && std::size_t(node.mesh) < model.meshes.size() &&
        !model.meshes[std::size_t(node.mesh)].name.empty())
        return model.meshes[std::size_t(node.mesh)].name;
    return "node" + std::to_string(index);
}

std::vector<std::string> morphTargetNames(const tinygltf::Mesh& mesh, int meshIndex)
{
    std::size_t count = 0;
    for (const tinygltf::Primitive& primitive : mesh.primitives)
        count = std::max(count, primitive.targets.size());
    const tinygltf::Value& names = mesh.extras.Get("targetNames");
    const bool named = names.IsArray() && std::size_t(names.ArrayLen()) == count;
    std::vector<std::string> result;
    for (std::size_t t = 0; t < count; ++t) {
        const tinygltf::Value& name = named ? names.Get(int(t)) : tinygltf::Value();
        if (name.IsString() && !name.Get<std::string>().empty())
            result.push_back(name.Get<std::string>());
        else
            result.push_back((mesh.name.empty() ? "mesh" + std::to_string(meshIndex) : mesh.name) + ":" +
                             std::to_string(t));
    }
    return result;
}

Mat4 parentWorld(const NodeTree& tree, int node)
{
    const int parent = tree.parent[std::size_t(node)];
    return parent < 0 ? kIdentity : tree.world[std::size_t(parent)];
}

} // namespace thespis::core::scene::gltf
