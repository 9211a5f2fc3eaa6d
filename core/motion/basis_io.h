#pragma once
// One posture basis as a field of Thespis's binary motion files (posture_bases.h, idle_database.h).

#include <string>

#include "motion/posture_basis.h"
#include "util/byte_io.h"

namespace thespis::core::motion {

void writeBasis(ByteWriter& out, const PostureBasis& basis);
/// `field` names it in messages ("basis 1").
bool readBasis(ByteReader& in, const std::string& field, PostureBasis& basis, Error& error);

/// Checks the magic and the version; `document` is "posture bases file", "idle motion database".
Result<void> readHeader(ByteReader& in, std::string_view magic, std::uint32_t version, const std::filesystem::path& path,
                        const std::string& document);

/// After the last field: exactly the 4 bytes of the CRC-32 are left, and it matches.
Result<void> checkEnd(const ByteReader& in, std::string_view data, const std::filesystem::path& path,
                      const std::string& document);

} // namespace thespis::core::motion
