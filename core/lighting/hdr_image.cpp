// HDR image files for light probes: OpenEXR through the OpenEXR library, Radiance .hdr (RGBE)
// with our own reader and writer.
//
// Radiance .hdr as read here (Greg Ward, "Real Pixels", Graphics Gems II, and the Radiance file
// format notes): a text header that starts with "#?RADIANCE" or "#?RGBE" and ends with an empty
// line, FORMAT=32-bit_rle_rgbe (XYZE is refused), then the resolution line, of which only the
// standard orientation "-Y H +X W" (rows from the top, pixels left to right) is accepted. Each
// scanline is either new-style run-length encoded (2, 2, W>>8, W&255, then the four byte planes,
// each as runs: n > 128 repeats the next byte n−128 times, otherwise n literal bytes) or flat
// (W × 4 bytes). Old-style runs (pixels 1,1,1,n of Radiance before 1991) are not supported.
// EXPOSURE lines are ignored, as Radiance's own tools and most readers do for display: the values
// are returned as stored. A byte mantissa m with exponent e decodes to (m + 0.5)·2^(e−136), as
// Radiance's colr_color does; e = 0 is black.

#include <algorithm>
#include <cmath>
#include <cstring>
#include <exception>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfStringAttribute.h>

#include "lighting/probe.h"
#include "util/file_io.h"

namespace thespis::core::lighting {

namespace {

Error corrupt(const std::filesystem::path& path, const std::string& what, std::string detail = {})
{
    return makeError(ErrorCode::CorruptData, path.string() + ": " + what, std::move(detail));
}

/// Refuses images whose size is zero or absurd (more than 2^28 pixels, 3 GB as floats).
Result<void> checkImageSize(const std::filesystem::path& path, long long width, long long height)
{
    if (width <= 0 || height <= 0 || width > 65536 || height > 65536 || width * height > (1LL << 28))
        return corrupt(path, "the image size " + std::to_string(width) + "×" + std::to_string(height)
                                 + " is not a valid light probe size.");
    return {};
}

/// Every pixel must be finite and non-negative radiance; names the first pixel that is not.
/// Lossy OpenEXR compression (DWA, B44) rings slightly below zero next to bright pixels: the
/// Blender probes have values down to −0.6% of their mean. Such undershoots, down to −2% of the
/// image's mean, are set to 0; anything more negative is refused.
Result<void> checkPixels(const std::filesystem::path& path, HdrImage& image)
{
    double sum = 0;
    for (float v : image.rgb)
        if (std::isfinite(v))
            sum += std::abs(double(v));
    const double undershoot = -0.02 * sum / double(std::max<size_t>(1, image.rgb.size()));
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            float* p = image.rgb.data() + 3 * (size_t(y) * size_t(image.width) + size_t(x));
            for (int c = 0; c < 3; ++c) {
                if (std::isfinite(p[c]) && p[c] >= 0.0f)
                    continue;
                if (std::isfinite(p[c]) && p[c] >= undershoot) {
                    p[c] = 0.0f;
                    continue;
                }
                return corrupt(path, "pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") has a "
                                         + (std::isfinite(p[c]) ? "negative" : "non-finite") + " value ("
                                         + std::to_string(p[c]) + ") in channel " + "RGB"[c]
                                         + "; radiance must be finite and ≥ 0.");
            }
        }
    return {};
}

Result<HdrImage> readOpenExr(const std::filesystem::path& path)
{
    try {
        Imf::InputFile file(path.c_str());
        const Imf::Header& header = file.header();
        std::string channels;
        for (auto it = header.channels().begin(); it != header.channels().end(); ++it)
            channels += std::string(channels.empty() ? "" : ", ") + it.name();
        for (const char* name : {"R", "G", "B"})
            if (!header.channels().findChannel(name))
                return corrupt(path, "the OpenEXR file has no R, G and B channels (it has: " + channels
                                         + "); a light probe must be an RGB image.");
        const Imath::Box2i window = header.dataWindow();
        const long long width = (long long)window.max.x - window.min.x + 1;
        const long long height = (long long)window.max.y - window.min.y + 1;
        if (auto sized = checkImageSize(path, width, height); !sized)
            return sized.error();
        HdrImage image;
        image.width = int(width);
        image.height = int(height);
        image.rgb.assign(size_t(width * height) * 3, 0.0f);
        // OpenEXR addresses the buffer by absolute pixel coordinates: shift the base so that the
        // data window's corner lands on rgb[0]. Computed in integers, the pointer is formed once.
        const std::ptrdiff_t origin = (std::ptrdiff_t(window.min.y) * width + window.min.x) * 3;
        char* base = reinterpret_cast<char*>(image.rgb.data()) - origin * std::ptrdiff_t(sizeof(float));
        Imf::FrameBuffer frame;
        const size_t xStride = 3 * sizeof(float);
        const size_t yStride = size_t(width) * xStride;
        frame.insert("R", Imf::Slice(Imf::FLOAT, base, xStride, yStride));
        frame.insert("G", Imf::Slice(Imf::FLOAT, base + sizeof(float), xStride, yStride));
        frame.insert("B", Imf::Slice(Imf::FLOAT, base + 2 * sizeof(float), xStride, yStride));
        file.setFrameBuffer(frame);
        file.readPixels(window.min.y, window.max.y);
        if (auto pixels = checkPixels(path, image); !pixels)
            return pixels.error();
        return image;
    } catch (const std::exception& e) {
        return corrupt(path, "the OpenEXR data cannot be read (truncated or damaged file).", e.what());
    }
}

/// A cursor over the file's bytes that never reads past the end.
struct ByteReader {
    std::string_view bytes;
    size_t at = 0;
    bool has(size_t n) const { return bytes.size() - at >= n; }
    uint8_t next() { return uint8_t(bytes[at++]); }
    /// Next header line without its newline; false at the end of the data.
    bool line(std::string_view& out)
    {
        if (at >= bytes.size())
            return false;
        const size_t end = bytes.find('\n', at);
        const size_t stop = end == std::string_view::npos ? bytes.size() : end;
        out = bytes.substr(at, stop - at);
        at = stop == bytes.size() ? stop : stop + 1;
        return true;
    }
};

float decodeRgbeChannel(uint8_t mantissa, uint8_t exponent)
{
    return exponent == 0 ? 0.0f : float(std::ldexp(double(mantissa) + 0.5, int(exponent) - 136));
}

Result<HdrImage> readRadiance(const std::filesystem::path& path, std::string_view bytes)
{
    ByteReader in{bytes};
    std::string_view line;
    in.line(line);
    if (line != "#?RADIANCE" && line != "#?RGBE")
        return makeError(ErrorCode::NotOurFormat,
                         path.string() + " is not a Radiance .hdr file (its first line is not #?RADIANCE or #?RGBE).");
    bool rgbe = false;
    for (;;) {
        if (!in.line(line))
            return corrupt(path, "the header ends before the empty line that closes it (truncated file).");
        if (line.empty())
            break;
        if (line.starts_with("FORMAT=")) {
            if (line != "FORMAT=32-bit_rle_rgbe")
                return corrupt(path, "the pixel format '" + std::string(line.substr(7))
                                         + "' is not supported; only 32-bit_rle_rgbe is.");
            rgbe = true;
        }
    }
    if (!rgbe)
        return corrupt(path, "the header has no FORMAT=32-bit_rle_rgbe line.");
    if (!in.line(line))
        return corrupt(path, "the resolution line is missing (truncated file).");
    char axisY[3] = {}, axisX[3] = {};
    long long height = 0, width = 0;
    char trailing = 0;
    const std::string resolution(line);
    if (std::sscanf(resolution.c_str(), "%2s %lld %2s %lld %c", axisY, &height, axisX, &width, &trailing) != 4)
        return corrupt(path, "the resolution line '" + resolution + "' is malformed.");
    if (std::strcmp(axisY, "-Y") != 0 || std::strcmp(axisX, "+X") != 0)
        return corrupt(path, "the image orientation '" + resolution
                                 + "' is not supported; only the standard '-Y height +X width' is.");
    if (auto sized = checkImageSize(path, width, height); !sized)
        return sized.error();

    HdrImage image;
    image.width = int(width);
    image.height = int(height);
    image.rgb.resize(size_t(width * height) * 3);
    std::vector<uint8_t> planes(size_t(width) * 4); // R…, G…, B…, E… of one scanline
    for (int y = 0; y < image.height; ++y) {
        const std::string where = "scanline " + std::to_string(y);
        const bool runLength = width >= 8 && width < 32768 && in.has(4) && uint8_t(bytes[in.at]) == 2
                               && uint8_t(bytes[in.at + 1]) == 2 && (uint8_t(bytes[in.at + 2]) & 0x80) == 0;
        if (runLength) {
            in.at += 2;
            const int declared = (int(in.next()) << 8) | in.next();
            if (declared != width)
                return corrupt(path, where + " declares a width of " + std::to_string(declared) + " instead of "
                                         + std::to_string(width) + ".");
            for (int plane = 0; plane < 4; ++plane) {
                uint8_t* out = planes.data() + size_t(plane) * size_t(width);
                int x = 0;
                while (x < width) {
                    if (!in.has(1))
                        return corrupt(path, where + " is cut short (truncated file).");
                    int count = in.next();
                    const bool run = count > 128;
                    if (run)
                        count -= 128;
                    if (count == 0 || count > width - x)
                        return corrupt(path, where + " has a run of " + std::to_string(count) + " bytes at pixel "
                                                 + std::to_string(x) + " that does not fit the width "
                                                 + std::to_string(width) + ".");
                    if (!in.has(run ? 1 : size_t(count)))
                        return corrupt(path, where + " is cut short (truncated file).");
                    if (run)
                        std::memset(out + x, in.next(), size_t(count));
                    else
                        for (int i = 0; i < count; ++i)
                            out[x + i] = in.next();
                    x += count;
                }
            }
        } else {
            if (!in.has(size_t(width) * 4))
                return corrupt(path, where + " is cut short (truncated file).");
            for (int x = 0; x < width; ++x)
                for (int plane = 0; plane < 4; ++plane)
                    planes[size_t(plane) * size_t(width) + size_t(x)] = in.next();
        }
        float* row = image.rgb.data() + size_t(y) * size_t(width) * 3;
        for (int x = 0; x < width; ++x) {
            const uint8_t exponent = planes[3 * size_t(width) + size_t(x)];
            for (int c = 0; c < 3; ++c)
                row[3 * x + c] = decodeRgbeChannel(planes[size_t(c) * size_t(width) + size_t(x)], exponent);
        }
    }
    return image; // RGBE cannot hold negative or non-finite values
}

/// Ward's float → RGBE: the largest channel keeps 8 significant bits.
std::array<uint8_t, 4> encodeRgbe(const float* rgb)
{
    const float largest = std::max({rgb[0], rgb[1], rgb[2]});
    if (!(largest > 1e-32f))
        return {0, 0, 0, 0};
    int exponent = 0;
    const float scale = std::frexp(largest, &exponent) * 256.0f / largest;
    return {uint8_t(std::max(0.0f, rgb[0]) * scale), uint8_t(std::max(0.0f, rgb[1]) * scale),
            uint8_t(std::max(0.0f, rgb[2]) * scale), uint8_t(exponent + 128)};
}

/// One byte plane of a scanline as new-style runs: runs of ≥ 3 equal bytes, literals otherwise.
void appendRuns(std::string& out, const uint8_t* data, int count)
{
    int x = 0;
    while (x < count) {
        int run = 1;
        while (x + run < count && run < 127 && data[x + run] == data[x])
            ++run;
        if (run >= 3) {
            out.push_back(char(128 + run));
            out.push_back(char(data[x]));
            x += run;
            continue;
        }
        // A literal stretch up to the next run of 3 (or 128 bytes).
        int literal = 0;
        while (x + literal < count && literal < 128
               && !(x + literal + 2 < count && data[x + literal] == data[x + literal + 1]
                    && data[x + literal] == data[x + literal + 2]))
            ++literal;
        out.push_back(char(literal));
        out.append(reinterpret_cast<const char*>(data + x), size_t(literal));
        x += literal;
    }
}

} // namespace

Result<HdrImage> readHdrImage(const std::filesystem::path& path)
{
    auto bytes = readTextFile(path);
    if (!bytes)
        return bytes.error();
    const std::string& data = *bytes;
    static constexpr unsigned char kExrMagic[4] = {0x76, 0x2f, 0x31, 0x01};
    if (data.size() >= 4 && std::memcmp(data.data(), kExrMagic, 4) == 0)
        return readOpenExr(path);
    if (data.starts_with("#?"))
        return readRadiance(path, data);
    return makeError(ErrorCode::NotOurFormat,
                     path.string() + " is neither an OpenEXR nor a Radiance .hdr image.");
}

Result<void> writeRadianceHdr(const std::filesystem::path& path, const HdrImage& image)
{
    assert(image.width > 0 && image.height > 0 && image.rgb.size() == size_t(image.width) * size_t(image.height) * 3);
    std::string out = "#?RADIANCE\n# written by Thespis Studio\nFORMAT=32-bit_rle_rgbe\n\n-Y "
                      + std::to_string(image.height) + " +X " + std::to_string(image.width) + "\n";
    const bool runLength = image.width >= 8 && image.width < 32768;
    std::vector<uint8_t> planes(size_t(image.width) * 4);
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const auto rgbe = encodeRgbe(image.pixel(x, y));
            for (int plane = 0; plane < 4; ++plane)
                planes[size_t(plane) * size_t(image.width) + size_t(x)] = rgbe[size_t(plane)];
        }
        if (runLength) {
            out += {char(2), char(2), char(image.width >> 8), char(image.width & 255)};
            for (int plane = 0; plane < 4; ++plane)
                appendRuns(out, planes.data() + size_t(plane) * size_t(image.width), image.width);
        } else {
            for (int x = 0; x < image.width; ++x)
                for (int plane = 0; plane < 4; ++plane)
                    out.push_back(char(planes[size_t(plane) * size_t(image.width) + size_t(x)]));
        }
    }
    return writeFileAtomically(path, out);
}

Result<void> writeOpenExr(const std::filesystem::path& path, const HdrImage& image)
{
    assert(image.width > 0 && image.height > 0 && image.rgb.size() == size_t(image.width) * size_t(image.height) * 3);
    try {
        Imf::Header header(image.width, image.height);
        header.compression() = Imf::ZIP_COMPRESSION;
        for (const char* name : {"R", "G", "B"})
            header.channels().insert(name, Imf::Channel(Imf::FLOAT));
        Imf::OutputFile file(path.c_str(), header);
        Imf::FrameBuffer frame;
        char* base = const_cast<char*>(reinterpret_cast<const char*>(image.rgb.data()));
        const size_t xStride = 3 * sizeof(float);
        const size_t yStride = size_t(image.width) * xStride;
        static constexpr const char* kNames[3] = {"R", "G", "B"};
        for (int c = 0; c < 3; ++c)
            frame.insert(kNames[c], Imf::Slice(Imf::FLOAT, base + size_t(c) * sizeof(float), xStride, yStride));
        file.setFrameBuffer(frame);
        file.writePixels(image.height);
        return {};
    } catch (const std::exception& e) {
        return makeError(ErrorCode::IoError, "Writing " + path.string() + " failed.", e.what());
    }
}

} // namespace thespis::core::lighting
