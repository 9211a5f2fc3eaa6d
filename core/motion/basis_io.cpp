#include "motion/basis_io.h"

namespace thespis::core::motion {

void writeBasis(ByteWriter& out, const PostureBasis& basis)
{
    out.u8(std::uint8_t(basis.set()));
    out.u64(basis.sampleCount());
    out.u32(std::uint32_t(basis.dimension()));
    out.f32s(basis.mean());
    out.f32s(basis.eigenvalues());
    out.f32s(basis.components());
}

bool readBasis(ByteReader& in, const std::string& field, PostureBasis& basis, Error& error)
{
    std::uint8_t set = 0;
    std::uint64_t samples = 0;
    std::uint32_t dimension = 0;
    if (!in.u8(field + " set", set, error) || !in.u64(field + " sample count", samples, error) ||
        !in.u32(field + " dimension", dimension, error))
        return false;
    if (set > std::uint8_t(PostureSet::UpperBody)) {
        error = in.corrupt(field + " is of an unknown posture set " + std::to_string(set));
        return false;
    }
    const int expected = PostureLayout::of(PostureSet(set)).size();
    if (dimension != std::uint32_t(expected)) {
        error = in.corrupt(field + " has " + std::to_string(dimension) + " dimensions; a " +
                           std::string(postureSetName(PostureSet(set))) + " posture has " + std::to_string(expected) +
                           " (the file was made for another skeleton)");
        return false;
    }
    std::vector<float> mean(dimension), eigenvalues(dimension), components(std::size_t(dimension) * dimension);
    if (!in.f32s(field + " mean", mean, error) || !in.f32s(field + " eigenvalues", eigenvalues, error) ||
        !in.f32s(field + " components", components, error))
        return false;
    auto made = PostureBasis::fromParts(PostureSet(set), samples, std::move(mean), std::move(eigenvalues),
                                        std::move(components));
    if (!made) {
        error = in.corrupt(field + ": " + made.error().message);
        return false;
    }
    basis = std::move(made).value();
    return true;
}

Result<void> readHeader(ByteReader& in, std::string_view magic, std::uint32_t version, const std::filesystem::path& path,
                        const std::string& document)
{
    Error error;
    std::string_view found;
    if (!in.take(magic.size(), "magic", found, error) || found != magic)
        return makeError(ErrorCode::NotOurFormat, path.string() + " is not a Thespis " + document + ".",
                         "the file does not start with " + std::string(magic.substr(0, magic.size() - 1)));
    std::uint32_t fileVersion = 0;
    if (!in.u32("format version", fileVersion, error))
        return error;
    if (fileVersion > version)
        return makeError(ErrorCode::NewerVersion,
                         "The " + document + " " + path.string() + " was written by a newer Thespis (format " +
                             std::to_string(fileVersion) + "). Update Thespis, or make the file again.",
                         "this build reads format " + std::to_string(version));
    if (fileVersion == 0)
        return in.corrupt("its format version is 0");
    return {};
}

Result<void> checkEnd(const ByteReader& in, std::string_view data, const std::filesystem::path& path,
                      const std::string& document)
{
    if (in.left() < 4)
        return in.truncated("checksum");
    if (in.left() > 4)
        return in.corrupt("it has " + std::to_string(in.left() - 4) + " unexpected bytes at its end");
    return checkTrailingCrc(data, path, document);
}

} // namespace thespis::core::motion
