// libFuzzer target for the PRT bake file reader (core/lighting/transfer_bake.h).
//
// The fuzzed bytes are a bake file without its trailing CRC-32; the target appends the right
// checksum so that the reader's structure checks (counts, ranges, names, sizes against the file
// length) are what gets exercised, not only the checksum. The reader must return a bake or an
// error, never crash or allocate beyond the file's size; an accepted bake must be written and
// read back equal.

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "lighting/transfer_bake.h"
#include "util/crc32.h"

namespace lighting = thespis::core::lighting;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    std::string bytes(reinterpret_cast<const char*>(data), size);
    const std::uint32_t crc = thespis::core::crc32(bytes);
    for (int i = 0; i < 4; ++i)
        bytes.push_back(char((crc >> (8 * i)) & 0xff));
    auto bake = lighting::parseBakeBytes(bytes, "fuzz.prt");
    if (!bake) {
        if (bake.error().message.empty()) {
            std::fprintf(stderr, "fuzz_bake_file: an error without a message\n");
            std::abort();
        }
        return 0;
    }
    const std::filesystem::path path = std::filesystem::temp_directory_path() / "fuzz_bake_file_roundtrip.prt";
    if (!lighting::writeBakeFile(path, *bake))
        return 0; // a full disk is not the reader's fault
    auto again = lighting::readBakeFile(path);
    if (!again || !(*again == *bake)) {
        std::fprintf(stderr, "fuzz_bake_file: an accepted bake did not survive a write and read\n");
        std::abort();
    }
    return 0;
}
