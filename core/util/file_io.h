#pragma once
// Whole-file reads and atomic writes (write a temporary file beside the target, flush, rename),
// so that a crash or a full disk never leaves a half-written document.

#include <filesystem>
#include <string>
#include <string_view>

#include "util/error.h"

namespace thespis::core {

Result<std::string> readTextFile(const std::filesystem::path& path);
Result<void> writeFileAtomically(const std::filesystem::path& path, std::string_view content);

} // namespace thespis::core
