#pragma once
// Private to the package reader and writer (package.cpp, package_export_job.cpp): a libzip
// archive owned by a unique_ptr, and the text of libzip's open errors.

#include <memory>
#include <string>

#include <zip.h>

namespace thespis::core::scenario::detail {

struct ZipDiscard {
    void operator()(zip_t* archive) const { zip_discard(archive); }
};
using ZipArchive = std::unique_ptr<zip_t, ZipDiscard>;

/// What zip_open's error code means ("Not a zip archive").
inline std::string zipOpenError(int code)
{
    zip_error_t error;
    zip_error_init_with_code(&error, code);
    std::string text = zip_error_strerror(&error);
    zip_error_fini(&error);
    return text;
}

} // namespace thespis::core::scenario::detail
