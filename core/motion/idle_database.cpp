#include "motion/idle_database.h"

#include <algorithm>
#include <cmath>

#include "motion/basis_io.h"
#include "util/crc32.h"
#include "util/file_io.h"

namespace thespis::core::motion {

namespace {
constexpr std::string_view kMagic{"THSPIDL\0", 8};
constexpr std::uint32_t kVersion = 1;
const std::string kDocument = "idle motion database";
constexpr std::uint32_t kMaxCategories = 64;
constexpr std::size_t kSegmentFixedBytes = 4 * 5 + 4;
} // namespace

Result<void> IdleDatabase::index()
{
    auto invalid = [](const std::string& what) {
        return makeError(ErrorCode::InvalidArgument, "The idle motion database is inconsistent: " + what + ".");
    };
    if (whole.set() != PostureSet::WholeBody || whole.dimension() != postureSize() || upper.set() != PostureSet::UpperBody ||
        upper.dimension() != PostureLayout::of(PostureSet::UpperBody).size())
        return invalid("its bases are not a whole-body and an upper-body basis");
    if (!(frameRate > 0) || !std::isfinite(frameRate))
        return invalid("its frame rate is not a positive number");
    if (categories.empty() || categories.size() > kMaxCategories)
        return invalid("it has " + std::to_string(categories.size()) + " categories");
    if (segments.empty())
        return invalid("it has no segments");
    if (variation.size() > std::size_t(postureSize()) ||
        std::any_of(variation.begin(), variation.end(), [](float v) { return !(v >= 0) || !std::isfinite(v); }))
        return invalid("its variation spreads are not non-negative numbers, at most one per PC");
    const std::size_t frames = postures.size() / std::size_t(postureSize());
    if (postures.size() % std::size_t(postureSize()) != 0)
        return invalid("its postures are not whole postures");
    if (std::any_of(postures.begin(), postures.end(), [](float v) { return !std::isfinite(v); }))
        return invalid("a posture holds a value that is not a finite number");
    for (std::size_t s = 0; s < segments.size(); ++s) {
        const IdleSegment& segment = segments[s];
        const std::string name = "segment " + std::to_string(s + 1);
        if (segment.from < 0 || segment.to < 0 || std::size_t(segment.from) >= categories.size() ||
            std::size_t(segment.to) >= categories.size())
            return invalid(name + " goes between unknown categories");
        if (segment.count < 2 || std::uint64_t(segment.first) + segment.count > frames)
            return invalid(name + " has " + std::to_string(segment.count) + " frames from frame " +
                           std::to_string(segment.first) + " of " + std::to_string(frames));
    }
    alignment.assign(frames * kAlignmentPcs, 0.0f);
    for (std::size_t f = 0; f < frames; ++f)
        whole.project(posture(std::uint32_t(f)), std::span<float>(alignment).subspan(f * kAlignmentPcs, kAlignmentPcs));
    return {};
}

std::string encodeIdleDatabase(const IdleDatabase& database)
{
    ByteWriter out;
    out.data().reserve(64 + database.postures.size() * 4 + 2 * 4 * 78 * 78);
    out.bytes(kMagic.data(), kMagic.size());
    out.u32(kVersion);
    writeBasis(out, database.whole);
    writeBasis(out, database.upper);
    out.f32(database.frameRate);
    out.u32(std::uint32_t(database.categories.size()));
    for (const std::string& name : database.categories)
        out.text(name);
    out.u32(std::uint32_t(database.variation.size()));
    out.f32s(database.variation);
    out.u32(std::uint32_t(database.segments.size()));
    for (const IdleSegment& segment : database.segments) {
        out.u32(std::uint32_t(segment.from));
        out.u32(std::uint32_t(segment.to));
        out.u32(segment.first);
        out.u32(segment.count);
        out.text(segment.source);
        out.f32(segment.sourceStart);
    }
    out.u64(database.postures.size());
    out.f32s(database.postures);
    out.u32(crc32(out.data()));
    return std::move(out.data());
}

Result<IdleDatabase> parseIdleDatabase(std::string_view data, const std::filesystem::path& path)
{
    ByteReader in(data, path, kDocument);
    if (auto header = readHeader(in, kMagic, kVersion, path, kDocument); !header)
        return header.error();
    Error error;
    IdleDatabase database;
    if (!readBasis(in, "whole-body basis", database.whole, error) ||
        !readBasis(in, "upper-body basis", database.upper, error))
        return error;
    if (database.whole.set() != PostureSet::WholeBody || database.upper.set() != PostureSet::UpperBody)
        return in.corrupt("its bases are not the whole body's then the upper body's");
    std::uint32_t categories = 0;
    if (!in.f32("frame rate", database.frameRate, error) || !in.u32("category count", categories, error))
        return error;
    if (categories == 0 || categories > kMaxCategories)
        return in.corrupt("its category count " + std::to_string(categories) + " is not between 1 and " +
                          std::to_string(kMaxCategories));
    database.categories.resize(categories);
    for (std::uint32_t c = 0; c < categories; ++c)
        if (!in.text("category " + std::to_string(c + 1) + " name", database.categories[c], error, 256))
            return error;
    std::uint32_t variations = 0;
    if (!in.u32("variation count", variations, error))
        return error;
    if (variations > std::uint32_t(database.postureSize()))
        return in.corrupt("its variation count " + std::to_string(variations) + " exceeds the PCs");
    database.variation.resize(variations);
    std::uint32_t segments = 0;
    if (!in.f32s("variations", database.variation, error) || !in.u32("segment count", segments, error))
        return error;
    if (segments > in.left() / kSegmentFixedBytes)
        return in.corrupt("its segment count " + std::to_string(segments) + " does not fit in the file");
    database.segments.resize(segments);
    for (std::uint32_t s = 0; s < segments; ++s) {
        IdleSegment& segment = database.segments[s];
        const std::string field = "segment " + std::to_string(s + 1);
        std::uint32_t from = 0, to = 0;
        if (!in.u32(field + " from", from, error) || !in.u32(field + " to", to, error) ||
            !in.u32(field + " first frame", segment.first, error) || !in.u32(field + " frame count", segment.count, error) ||
            !in.text(field + " source", segment.source, error) || !in.f32(field + " source start", segment.sourceStart, error))
            return error;
        if (from >= categories || to >= categories)
            return in.corrupt(field + " goes between unknown categories " + std::to_string(from) + " and " + std::to_string(to));
        segment.from = int(from);
        segment.to = int(to);
    }
    std::uint64_t floats = 0;
    if (!in.u64("posture float count", floats, error))
        return error;
    if (floats > in.left() / 4)
        return in.truncated("postures");
    database.postures.resize(floats);
    if (!in.f32s("postures", database.postures, error))
        return error;
    if (auto end = checkEnd(in, data, path, kDocument); !end)
        return end.error();
    if (auto indexed = database.index(); !indexed)
        return makeError(ErrorCode::CorruptData, path.string() + ": " + indexed.error().message);
    return database;
}

Result<void> writeIdleDatabaseFile(const std::filesystem::path& path, const IdleDatabase& database)
{
    return writeFileAtomically(path, encodeIdleDatabase(database));
}

Result<IdleDatabase> readIdleDatabaseFile(const std::filesystem::path& path)
{
    auto data = readTextFile(path);
    if (!data)
        return data.error();
    return parseIdleDatabase(*data, path);
}

} // namespace thespis::core::motion
