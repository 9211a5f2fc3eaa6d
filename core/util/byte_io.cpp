#include "util/byte_io.h"

#include "util/crc32.h"

namespace thespis::core {

Error ByteReader::corrupt(const std::string& what) const
{
    return makeError(ErrorCode::CorruptData, "The " + m_document + " " + m_path.string() + " is damaged: " + what + ".",
                     "at byte " + std::to_string(m_position));
}

bool ByteReader::take(std::size_t size, const std::string& field, std::string_view& out, Error& error)
{
    if (left() < size) {
        error = truncated(field);
        return false;
    }
    out = m_data.substr(m_position, size);
    m_position += size;
    return true;
}

bool ByteReader::u8(const std::string& field, std::uint8_t& value, Error& error)
{
    std::string_view raw;
    if (!take(1, field, raw, error))
        return false;
    value = std::uint8_t(raw[0]);
    return true;
}

bool ByteReader::u32(const std::string& field, std::uint32_t& value, Error& error)
{
    std::string_view raw;
    if (!take(4, field, raw, error))
        return false;
    value = 0;
    for (int i = 0; i < 4; ++i)
        value |= std::uint32_t(std::uint8_t(raw[i])) << (8 * i);
    return true;
}

bool ByteReader::u64(const std::string& field, std::uint64_t& value, Error& error)
{
    std::string_view raw;
    if (!take(8, field, raw, error))
        return false;
    value = 0;
    for (int i = 0; i < 8; ++i)
        value |= std::uint64_t(std::uint8_t(raw[i])) << (8 * i);
    return true;
}

bool ByteReader::f32(const std::string& field, float& value, Error& error)
{
    std::uint32_t bits = 0;
    if (!u32(field, bits, error))
        return false;
    value = std::bit_cast<float>(bits);
    return true;
}

bool ByteReader::f32s(const std::string& field, std::span<float> values, Error& error)
{
    if (left() / 4 < values.size()) {
        error = truncated(field);
        return false;
    }
    for (float& value : values)
        (void)f32(field, value, error); // length checked above
    return true;
}

bool ByteReader::text(const std::string& field, std::string& value, Error& error, std::size_t maxLength)
{
    std::uint32_t length = 0;
    if (!u32(field + " length", length, error))
        return false;
    if (length > maxLength) {
        error = corrupt("its " + field + " is " + std::to_string(length) + " bytes long");
        return false;
    }
    std::string_view raw;
    if (!take(length, field, raw, error))
        return false;
    value = std::string(raw);
    return true;
}

Result<void> checkTrailingCrc(std::string_view data, const std::filesystem::path& path, const std::string& document)
{
    constexpr std::size_t kChecksumBytes = 4;
    if (data.size() < kChecksumBytes)
        return makeError(ErrorCode::CorruptData, "The " + document + " " + path.string() + " is damaged: it is too short.");
    std::uint32_t stored = 0;
    for (std::size_t i = 0; i < kChecksumBytes; ++i)
        stored |= std::uint32_t(std::uint8_t(data[data.size() - kChecksumBytes + i])) << (8 * i);
    if (const std::uint32_t computed = crc32(data.substr(0, data.size() - kChecksumBytes)); computed != stored)
        return makeError(ErrorCode::CorruptData,
                         "The " + document + " " + path.string() +
                             " is damaged: its checksum does not match (the file was changed after it was written).",
                         "CRC-32 stored " + std::to_string(stored) + ", computed " + std::to_string(computed));
    return {};
}

} // namespace thespis::core
