#include "util/file_io.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace thespis::core {

Result<std::string> readTextFile(const std::filesystem::path& path)
{
    std::error_code ec;
    if (!std::filesystem::exists(path, ec))
        return makeError(ErrorCode::FileNotFound, "The file " + path.string() + " does not exist.");
    if (std::filesystem::is_directory(path, ec))
        return makeError(ErrorCode::IoError, path.string() + " is a folder, not a file.");
    std::ifstream in(path, std::ios::binary);
    if (!in)
        return makeError(ErrorCode::FileNotFound, "Cannot open " + path.string() + ".", std::strerror(errno));
    std::ostringstream buffer;
    buffer << in.rdbuf();
    if (in.bad())
        return makeError(ErrorCode::IoError, "Reading " + path.string() + " failed.");
    return buffer.str();
}

Result<void> writeFileAtomically(const std::filesystem::path& path, std::string_view content)
{
    const std::filesystem::path temporary = path.string() + ".tmp-" + std::to_string(::getpid());
    std::FILE* file = std::fopen(temporary.c_str(), "wb");
    if (!file)
        return makeError(ErrorCode::IoError, "Cannot write " + path.string() + ".", std::strerror(errno));
    const bool written = std::fwrite(content.data(), 1, content.size(), file) == content.size()
                         && std::fflush(file) == 0 && ::fsync(fileno(file)) == 0;
    const int writeErrno = errno;
    if (std::fclose(file) != 0 || !written) {
        std::remove(temporary.c_str());
        return makeError(ErrorCode::IoError, "Writing " + path.string() + " failed.", std::strerror(writeErrno));
    }
    if (std::rename(temporary.c_str(), path.c_str()) != 0) {
        const int renameErrno = errno;
        std::remove(temporary.c_str());
        return makeError(ErrorCode::IoError, "Cannot replace " + path.string() + ".", std::strerror(renameErrno));
    }
    return {};
}

} // namespace thespis::core
