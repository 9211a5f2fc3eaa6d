#include "util/crc32.h"

#include <array>

namespace thespis::core {

namespace {

// Slicing-by-4 tables: table[0] is the classic byte table, table[k] advances k more zero bytes,
// so four bytes are folded per step (bake files are megabytes).
using Crc32Tables = std::array<std::array<std::uint32_t, 256>, 4>;

constexpr Crc32Tables makeTables()
{
    Crc32Tables tables{};
    for (std::uint32_t byte = 0; byte < 256; ++byte) {
        std::uint32_t crc = byte;
        for (int bit = 0; bit < 8; ++bit)
            crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
        tables[0][byte] = crc;
    }
    for (std::uint32_t byte = 0; byte < 256; ++byte)
        for (int k = 1; k < 4; ++k)
            tables[k][byte] = (tables[k - 1][byte] >> 8) ^ tables[0][tables[k - 1][byte] & 0xffu];
    return tables;
}

constexpr Crc32Tables kTables = makeTables();

} // namespace

std::uint32_t crc32(std::string_view data, std::uint32_t crc)
{
    crc = ~crc;
    const auto* bytes = reinterpret_cast<const unsigned char*>(data.data());
    std::size_t size = data.size();
    for (; size >= 4; size -= 4, bytes += 4) {
        crc ^= std::uint32_t(bytes[0]) | std::uint32_t(bytes[1]) << 8 | std::uint32_t(bytes[2]) << 16
               | std::uint32_t(bytes[3]) << 24;
        crc = kTables[3][crc & 0xffu] ^ kTables[2][(crc >> 8) & 0xffu] ^ kTables[1][(crc >> 16) & 0xffu]
              ^ kTables[0][crc >> 24];
    }
    for (; size > 0; --size, ++bytes)
        crc = (crc >> 8) ^ kTables[0][(crc ^ *bytes) & 0xffu];
    return ~crc;
}

} // namespace thespis::core
