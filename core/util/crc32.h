#pragma once
// CRC-32 as in zlib, PNG and gzip (IEEE 802.3 polynomial, reflected: 0xEDB88320, initial and
// final XOR 0xFFFFFFFF). crc32("123456789") == 0xCBF43926. Used as the checksum of binary files.

#include <cstdint>
#include <string_view>

namespace thespis::core {

/// CRC-32 of `data`; pass a previous result as `crc` to continue over several pieces
/// (crc32(b, crc32(a)) == crc32(a + b)).
std::uint32_t crc32(std::string_view data, std::uint32_t crc = 0);

} // namespace thespis::core
