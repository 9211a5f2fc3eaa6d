#include "motion/posture_bases.h"

#include "motion/basis_io.h"
#include "util/crc32.h"
#include "util/file_io.h"

namespace thespis::core::motion {

namespace {
constexpr std::string_view kMagic{"THSPPCA\0", 8};
constexpr std::uint32_t kVersion = 1;
const std::string kDocument = "posture bases file";
} // namespace

std::string encodePostureBases(const PostureBases& bases)
{
    ByteWriter out;
    out.bytes(kMagic.data(), kMagic.size());
    out.u32(kVersion);
    out.u32(2);
    writeBasis(out, bases.whole);
    writeBasis(out, bases.upper);
    out.u32(crc32(out.data()));
    return std::move(out.data());
}

Result<PostureBases> parsePostureBases(std::string_view data, const std::filesystem::path& path)
{
    ByteReader in(data, path, kDocument);
    if (auto header = readHeader(in, kMagic, kVersion, path, kDocument); !header)
        return header.error();
    Error error;
    std::uint32_t count = 0;
    if (!in.u32("basis count", count, error))
        return error;
    if (count != 2)
        return in.corrupt("it holds " + std::to_string(count) + " bases, not 2 (whole body and upper body)");
    PostureBases bases;
    if (!readBasis(in, "basis 1", bases.whole, error) || !readBasis(in, "basis 2", bases.upper, error))
        return error;
    if (bases.whole.set() != PostureSet::WholeBody || bases.upper.set() != PostureSet::UpperBody)
        return in.corrupt("its bases are not the whole body's then the upper body's");
    if (auto end = checkEnd(in, data, path, kDocument); !end)
        return end.error();
    return bases;
}

Result<void> writePostureBasesFile(const std::filesystem::path& path, const PostureBases& bases)
{
    return writeFileAtomically(path, encodePostureBases(bases));
}

Result<PostureBases> readPostureBasesFile(const std::filesystem::path& path)
{
    auto data = readTextFile(path);
    if (!data)
        return data.error();
    return parsePostureBases(*data, path);
}

} // namespace thespis::core::motion
