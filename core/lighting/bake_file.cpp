// The bake file (format version 2), little-endian, in this order:
//
//   char[8]  magic "THSPPRT\0"
//   u32      format version (2; 1 has no geometry hash)
//   u32      order (1 … kMaxShOrder)
//   u32      transfer kind (0 du, 1 ds, 2 dsm)
//   u32      rays per vertex
//   f32      ε (metres)
//   u64      seed
//   u64      vertex count of the character mesh
//   u64      geometry hash of the mesh (meshGeometryHash; format 2 on)
//   u32      segment count, then per segment:
//              u32 name length, name bytes (UTF-8), u32 first vertex, u32 vertex count,
//              u64 transfer offset, u8 role (0 none, 1 receiver, 2 occluder), u8 baked (0/1)
//   u64      float count (Σ over baked segments of vertex count × order²)
//   f32[]    the transfer
//   u32      CRC-32 (util/crc32.h) of every byte before it
//
// The reader checks every count against the bytes that are left before it allocates, so a
// corrupt header cannot make it reserve gigabytes; truncation and inconsistent counts are
// reported naming the field, then the checksum catches any other change.

#include <algorithm>
#include <bit>
#include <cmath>

#include "lighting/transfer_bake.h"
#include "util/byte_io.h"
#include "util/crc32.h"
#include "util/file_io.h"

namespace thespis::core::lighting {

namespace {

std::size_t firstNonFinite(const std::vector<float>& values)
{
    return std::size_t(std::find_if(values.begin(), values.end(), [](float v) { return !std::isfinite(v); }) -
                       values.begin());
}

constexpr char kMagic[8] = {'T', 'H', 'S', 'P', 'P', 'R', 'T', '\0'};
constexpr std::uint32_t kFormatVersion = 2;
constexpr std::uint32_t kFirstWithGeometryHash = 2;
constexpr std::size_t kSegmentFixedBytes = 4 + 4 + 4 + 8 + 1 + 1; // everything but the name
constexpr std::size_t kChecksumBytes = 4;

} // namespace

Result<TransferBake> parseBakeBytes(std::string_view data, const std::filesystem::path& path)
{
    ByteReader in(data, path, "bake file");
    Error error;
    std::string_view magic;
    if (!in.take(sizeof kMagic, "magic", magic, error) || magic != std::string_view(kMagic, sizeof kMagic))
        return makeError(ErrorCode::NotOurFormat, path.string() + " is not a Thespis bake file.",
                         "the file does not start with THSPPRT");

    std::uint32_t version = 0;
    if (!in.u32("format version", version, error))
        return error;
    if (version > kFormatVersion)
        return makeError(ErrorCode::NewerVersion,
                         "The bake file " + path.string() + " was written by a newer Thespis (bake format " +
                             std::to_string(version) + "). Update Thespis, or bake again.",
                         "this build reads bake format " + std::to_string(kFormatVersion));
    if (version == 0)
        return in.corrupt("its format version is 0");

    TransferBake bake;
    std::uint32_t order = 0, kind = 0, rays = 0, segmentCount = 0;
    if (!in.u32("order", order, error) || !in.u32("transfer kind", kind, error) ||
        !in.u32("rays per vertex", rays, error) || !in.f32("epsilon", bake.epsilon, error) ||
        !in.u64("seed", bake.seed, error) || !in.u64("vertex count", bake.vertexCount, error) ||
        (version >= kFirstWithGeometryHash && !in.u64("geometry hash", bake.geometryHash, error)) ||
        !in.u32("segment count", segmentCount, error))
        return error;
    if (order < 1 || order > std::uint32_t(kMaxShOrder))
        return in.corrupt("its SH order " + std::to_string(order) + " is not between 1 and " +
                          std::to_string(kMaxShOrder));
    if (kind > std::uint32_t(TransferKind::DiffuseShadowedMerged))
        return in.corrupt("its transfer kind " + std::to_string(kind) + " is unknown");
    if (rays < 1 || rays > std::uint32_t(INT32_MAX))
        return in.corrupt("its rays per vertex " + std::to_string(rays) + " is out of range");
    if (bake.vertexCount > UINT32_MAX)
        return in.corrupt("its vertex count " + std::to_string(bake.vertexCount) + " is out of range");
    if (segmentCount > in.left() / kSegmentFixedBytes)
        return in.corrupt("its segment count " + std::to_string(segmentCount) + " does not fit in the file");
    bake.order = int(order);
    bake.transferKind = TransferKind(kind);
    bake.raysPerVertex = int(rays);

    const std::uint64_t perVertex = std::uint64_t(order) * order;
    std::uint64_t expectedFloats = 0;
    bake.segments.resize(segmentCount);
    for (std::uint32_t s = 0; s < segmentCount; ++s) {
        BakedSegment& segment = bake.segments[s];
        const std::string field = "segment " + std::to_string(s);
        std::uint32_t nameLength = 0;
        std::string_view name;
        std::uint8_t role = 0, baked = 0;
        if (!in.u32(field + " name length", nameLength, error) || !in.take(nameLength, field + " name", name, error) ||
            !in.u32(field + " first vertex", segment.firstVertex, error) ||
            !in.u32(field + " vertex count", segment.vertexCount, error) ||
            !in.u64(field + " transfer offset", segment.transferOffset, error) || !in.u8(field + " role", role, error) ||
            !in.u8(field + " baked flag", baked, error))
            return error;
        segment.name = std::string(name);
        if (std::uint64_t(segment.firstVertex) + segment.vertexCount > bake.vertexCount)
            return in.corrupt(field + " (\"" + segment.name + "\") reaches past the vertex count");
        if (role > std::uint8_t(scene::SegmentRole::Occluder))
            return in.corrupt(field + " (\"" + segment.name + "\") has an unknown role " + std::to_string(role));
        if (baked > 1)
            return in.corrupt(field + " (\"" + segment.name + "\") has a baked flag of " + std::to_string(baked));
        segment.role = scene::SegmentRole(role);
        segment.baked = baked == 1;
        if (segment.baked) {
            if (segment.transferOffset != expectedFloats)
                return in.corrupt(field + " (\"" + segment.name + "\") has transfer offset " +
                                  std::to_string(segment.transferOffset) + ", expected " + std::to_string(expectedFloats));
            expectedFloats += segment.vertexCount * perVertex;
        } else if (segment.transferOffset != 0) {
            return in.corrupt(field + " (\"" + segment.name + "\") is not baked but has a transfer offset");
        }
    }

    std::uint64_t floatCount = 0;
    if (!in.u64("transfer float count", floatCount, error))
        return error;
    if (floatCount != expectedFloats)
        return in.corrupt("its transfer float count " + std::to_string(floatCount) + " does not match its segments (" +
                          std::to_string(expectedFloats) + ")");
    if (floatCount > (in.left() - std::min(in.left(), kChecksumBytes)) / 4)
        return in.truncated("transfer");
    if (in.left() != floatCount * 4 + kChecksumBytes)
        return in.corrupt("it has " + std::to_string(in.left() - floatCount * 4 - kChecksumBytes) +
                          " unexpected bytes at its end");
    bake.transfer.resize(floatCount);
    for (float& value : bake.transfer)
        (void)in.f32("transfer", value, error); // length checked above
    // Last, the checksum over everything before it: a flipped byte the checks above let through.
    if (auto checksum = checkTrailingCrc(data, path, "bake file"); !checksum)
        return checksum.error();
    // Values the checksum cannot vouch for: a writer that went wrong before checksumming.
    if (!std::isfinite(bake.epsilon) || bake.epsilon < 0)
        return in.corrupt("its epsilon " + std::to_string(bake.epsilon) + " is not a distance");
    if (const std::size_t bad = firstNonFinite(bake.transfer); bad < bake.transfer.size())
        return in.corrupt("transfer value " + std::to_string(bad) + " (baked vertex " + std::to_string(bad / perVertex) +
                          ", coefficient " + std::to_string(bad % perVertex) + ") is not a finite number");
    return bake;
}

Result<std::string> bakeFileBytes(const TransferBake& bake, const std::filesystem::path& path)
{
    const std::uint64_t perVertex = std::uint64_t(bake.order) * bake.order;
    std::uint64_t expectedFloats = 0;
    for (const BakedSegment& segment : bake.segments)
        if (segment.baked)
            expectedFloats += segment.vertexCount * perVertex;
    if (bake.order < 1 || bake.order > kMaxShOrder || expectedFloats != bake.transfer.size())
        return makeError(ErrorCode::InvalidArgument,
                         "Cannot write " + path.string() + ": the bake is inconsistent (order " +
                             std::to_string(bake.order) + ", " + std::to_string(bake.transfer.size()) +
                             " transfer floats for " + std::to_string(expectedFloats) + " expected).");
    if (!std::isfinite(bake.epsilon) || bake.epsilon < 0 || firstNonFinite(bake.transfer) < bake.transfer.size())
        return makeError(ErrorCode::InvalidArgument,
                         "Cannot write " + path.string() + ": the bake holds a value that is not a finite number.");

    ByteWriter out;
    out.data().reserve(64 + bake.segments.size() * 48 + bake.transfer.size() * 4);
    out.bytes(kMagic, sizeof kMagic);
    out.u32(kFormatVersion);
    out.u32(std::uint32_t(bake.order));
    out.u32(std::uint32_t(bake.transferKind));
    out.u32(std::uint32_t(bake.raysPerVertex));
    out.f32(bake.epsilon);
    out.u64(bake.seed);
    out.u64(bake.vertexCount);
    out.u64(bake.geometryHash);
    out.u32(std::uint32_t(bake.segments.size()));
    for (const BakedSegment& segment : bake.segments) {
        out.u32(std::uint32_t(segment.name.size()));
        out.bytes(segment.name.data(), segment.name.size());
        out.u32(segment.firstVertex);
        out.u32(segment.vertexCount);
        out.u64(segment.transferOffset);
        out.u8(std::uint8_t(segment.role));
        out.u8(segment.baked ? 1 : 0);
    }
    out.u64(bake.transfer.size());
    for (float value : bake.transfer)
        out.f32(value);
    out.u32(crc32(out.data()));
    return std::move(out.data());
}

Result<void> writeBakeFile(const std::filesystem::path& path, const TransferBake& bake)
{
    auto bytes = bakeFileBytes(bake, path);
    if (!bytes)
        return bytes.error();
    return writeFileAtomically(path, *bytes);
}

Result<TransferBake> readBakeFile(const std::filesystem::path& path)
{
    Result<std::string> data = readTextFile(path);
    if (!data)
        return data.error();
    return parseBakeBytes(*data, path);
}

std::uint64_t meshGeometryHash(const scene::CharacterMesh& mesh)
{
    // FNV-1a over the bits of every value, in a fixed order.
    std::uint64_t hash = 0xcbf29ce484222325ULL;
    const auto add = [&hash](std::uint64_t value) {
        for (int i = 0; i < 8; ++i) {
            hash ^= (value >> (8 * i)) & 0xffu;
            hash *= 0x100000001b3ULL;
        }
    };
    for (const auto* list : {&mesh.positions, &mesh.normals})
        for (const auto& v : *list) {
            add(std::bit_cast<std::uint32_t>(v.x));
            add(std::bit_cast<std::uint32_t>(v.y));
            add(std::bit_cast<std::uint32_t>(v.z));
        }
    for (const std::uint32_t index : mesh.indices)
        add(index);
    for (const scene::Segment& segment : mesh.segments)
        add(std::uint64_t(segment.firstVertex) << 32 | segment.vertexCount);
    return hash == 0 ? 1 : hash; // 0 means "not recorded"
}

Result<void> checkBakeMatchesMesh(const TransferBake& bake, const scene::CharacterMesh& mesh)
{
    auto mismatch = [](const std::string& what) {
        return makeError(ErrorCode::InvalidArgument,
                         "The lighting bake does not belong to this mesh: " + what + ". Bake the character again.");
    };
    if (bake.vertexCount != mesh.vertexCount())
        return mismatch("it has " + std::to_string(bake.vertexCount) + " vertices, the mesh " +
                        std::to_string(mesh.vertexCount()));
    if (bake.segments.size() != mesh.segments.size())
        return mismatch("it has " + std::to_string(bake.segments.size()) + " segments, the mesh " +
                        std::to_string(mesh.segments.size()));
    for (std::size_t s = 0; s < bake.segments.size(); ++s) {
        const BakedSegment& baked = bake.segments[s];
        const scene::Segment& segment = mesh.segments[s];
        if (baked.name != segment.name)
            return mismatch("segment " + std::to_string(s) + " is \"" + baked.name + "\" in the bake and \"" +
                            segment.name + "\" in the mesh");
        if (baked.firstVertex != segment.firstVertex || baked.vertexCount != segment.vertexCount)
            return mismatch("segment \"" + segment.name + "\" has vertices " + std::to_string(baked.firstVertex) +
                            "+" + std::to_string(baked.vertexCount) + " in the bake and " +
                            std::to_string(segment.firstVertex) + "+" + std::to_string(segment.vertexCount) +
                            " in the mesh");
        // Roles shape M′ only in DSM; a changed tag makes a DSM bake stale.
        if (bake.transferKind == TransferKind::DiffuseShadowedMerged && baked.role != segment.role)
            return mismatch("segment \"" + segment.name + "\" was baked as " + scene::segmentRoleName(baked.role) +
                            " and is now tagged " + scene::segmentRoleName(segment.role));
    }
    if (bake.geometryHash != 0 && bake.geometryHash != meshGeometryHash(mesh))
        return mismatch("the mesh's shape changed since it was baked (its vertices, normals or triangles differ)");
    return {};
}

} // namespace thespis::core::lighting
