#pragma once
// Little-endian binary fields for Thespis's binary files (bakes, posture bases, idle databases).
// The writer appends to a string; the reader takes fields in order and names each one, so a
// short or damaged file says which field it ends in and at which byte.

#include <bit>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>

#include "util/error.h"

namespace thespis::core {

class ByteWriter {
public:
    void bytes(const void* data, std::size_t size) { m_out.append(static_cast<const char*>(data), size); }
    void u8(std::uint8_t value) { m_out.push_back(char(value)); }
    void u32(std::uint32_t value)
    {
        for (int i = 0; i < 4; ++i)
            m_out.push_back(char((value >> (8 * i)) & 0xffu));
    }
    void u64(std::uint64_t value)
    {
        for (int i = 0; i < 8; ++i)
            m_out.push_back(char((value >> (8 * i)) & 0xffu));
    }
    void f32(float value) { u32(std::bit_cast<std::uint32_t>(value)); }
    void f32s(std::span<const float> values)
    {
        for (float value : values)
            f32(value);
    }
    /// u32 length, then the bytes.
    void text(std::string_view value)
    {
        u32(std::uint32_t(value.size()));
        bytes(value.data(), value.size());
    }
    std::string& data() { return m_out; }

private:
    std::string m_out;
};

/// Reads fields in order; every read names its field. `document` names the kind of file in
/// messages ("bake file"): "The bake file F is damaged: it ends inside the seed."
class ByteReader {
public:
    ByteReader(std::string_view data, const std::filesystem::path& path, std::string document)
        : m_data(data), m_path(path), m_document(std::move(document)) {}

    std::size_t left() const { return m_data.size() - m_position; }
    std::size_t position() const { return m_position; }

    Error corrupt(const std::string& what) const;
    Error truncated(const std::string& field) const { return corrupt("it ends inside the " + field); }

    bool take(std::size_t size, const std::string& field, std::string_view& out, Error& error);
    bool u8(const std::string& field, std::uint8_t& value, Error& error);
    bool u32(const std::string& field, std::uint32_t& value, Error& error);
    bool u64(const std::string& field, std::uint64_t& value, Error& error);
    bool f32(const std::string& field, float& value, Error& error);
    /// `values.size()` floats.
    bool f32s(const std::string& field, std::span<float> values, Error& error);
    /// u32 length (at most `maxLength`), then the bytes.
    bool text(const std::string& field, std::string& value, Error& error, std::size_t maxLength = 4096);

private:
    std::string_view m_data;
    std::filesystem::path m_path;
    std::string m_document;
    std::size_t m_position = 0;
};

/// Checks the CRC-32 (util/crc32.h) in the last 4 bytes of `data` against everything before it.
Result<void> checkTrailingCrc(std::string_view data, const std::filesystem::path& path, const std::string& document);

} // namespace thespis::core
