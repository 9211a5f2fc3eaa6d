// libFuzzer target for the HDR image readers (core/lighting/probe.h: Radiance .hdr, our own
// reader, and OpenEXR through the library). The readers take files, so each input is written to
// a file in the temporary folder first. They must return an image or an error with a message,
// never crash, hang or allocate beyond what the header's (bounded) size allows; an accepted
// image has width × height × 3 finite, non-negative values.

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include "lighting/probe.h"

namespace lighting = thespis::core::lighting;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    static const std::filesystem::path path =
        std::filesystem::temp_directory_path() / ("fuzz_hdr_" + std::to_string(getpid()) + ".img");
    {
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
    }
    auto image = lighting::readHdrImage(path);
    if (!image) {
        if (image.error().message.empty()) {
            std::fprintf(stderr, "fuzz_hdr: an error without a message\n");
            std::abort();
        }
        return 0;
    }
    if (image->width <= 0 || image->height <= 0
        || image->rgb.size() != std::size_t(image->width) * std::size_t(image->height) * 3) {
        std::fprintf(stderr, "fuzz_hdr: the image's size does not match its pixels\n");
        std::abort();
    }
    for (float v : image->rgb)
        if (!std::isfinite(v) || v < 0) {
            std::fprintf(stderr, "fuzz_hdr: an accepted image holds %g\n", double(v));
            std::abort();
        }
    return 0;
}
