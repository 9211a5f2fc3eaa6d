#pragma once
// The posture bases file (.pca): the whole-body and upper-body PCA of one posture database, as
// `thespis-cli train-pca` writes it and the dependent-joint filter and idle motion read it.
// Binary, little-endian:
//
//   char[8]  magic "THSPPCA\0"
//   u32      format version (1)
//   u32      basis count, then per basis (basis_io.h):
//              u8 set (0 whole body, 1 upper body), u64 samples, u32 dimension d,
//              f32[d] mean, f32[d] eigenvalues, f32[d·d] components (row by row)
//   u32      CRC-32 of every byte before it
//
// The reader refuses another format, a newer version, a basis whose dimension is not its set's,
// truncation and any changed byte, naming the field.

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "motion/posture_basis.h"
#include "util/error.h"

namespace thespis::core::motion {

struct PostureBases {
    PostureBasis whole;
    PostureBasis upper;
};

std::string encodePostureBases(const PostureBases& bases);
/// `path` names the file in messages.
Result<PostureBases> parsePostureBases(std::string_view data, const std::filesystem::path& path);
Result<void> writePostureBasesFile(const std::filesystem::path& path, const PostureBases& bases);
Result<PostureBases> readPostureBasesFile(const std::filesystem::path& path);

} // namespace thespis::core::motion
