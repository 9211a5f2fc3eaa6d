#pragma once
// HDR light probes (paper §6: distant natural light captured with a mirrored ball) and their
// projection onto spherical harmonics.
//
// Images are read from OpenEXR (OpenEXR library) or Radiance .hdr (RGBE, our own reader) into
// linear float RGB. A layout maps every pixel to a world direction (Thespis world: right-handed,
// y up; the probe's "forward", the centre of an angular map, of a mirror ball and of a lat-long
// map, is −z). No layout mirrors the world: each is a proper rotation of the published
// convention it names.
// - Angular map (Debevec; Ramamoorthi & Hanrahan): square, centre = −z, radius r ∈ [0,1] is the
//   angle θ = π·r from −z, the disc's up is +y and its right is −x. This is Debevec's definition
//   ("rotate (0,0,−1) by π·r about y, then by the disc angle about −z"): the disc is seen from
//   outside, like the mirror ball it is made from. It equals R&H's prefilter.c mapping (centre
//   +z, right +x, up +y) turned 180° about +y.
// - Latitude–longitude: 2:1, top row = +y, the centre column looks at −z, and going right in the
//   image turns towards +x (the panorama reads unmirrored from inside, as Poly Haven / Blender /
//   three.js maps do: it is three.js's equirectangular mapping turned 90° about +y).
// - Mirror ball: square photo of a chrome ball filling the image, taken by an orthographic camera
//   on the −z side looking along +z (image up +y, right −x), so the ball's centre reflects −z. A
//   pixel's direction is the camera ray reflected on the ball, which is the angular map with
//   r_angular = (2/π)·asin(r_ball).
// - Vertical cross cube map: 3:4 (w×h), faces of w/3 pixels as in Debevec's HDR Shop vertical
//   cross, seen from inside: row 0 centre +y, row 1 −x | −z | +x, row 2 centre −y, row 3 centre
//   +z. The unfolding goes on down the column, so the +z (back) face is stored upside down
//   (turned 180°: its +y at the bottom, +x on the right).
// Pixel (x, y) covers [x, x+1] × [y, y+1] of the image; directionOfPixel(x, y) is the direction of
// the point (x + ½, y + ½), the pixel's centre for integer x, y.
// Each layout documents its exact mapping in probe.cpp; directionOfPixel() is the one place.

#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <stop_token>
#include <string>
#include <string_view>
#include <vector>

#include "lighting/sh.h"
#include "util/error.h"

namespace thespis::core::lighting {

enum class ProbeLayout { Angular, LatLong, MirrorBall, VerticalCross };

/// "angular", "latlong", "mirrorball", "cross" (the CLI's and the scenario's spelling).
const char* probeLayoutName(ProbeLayout layout);
Result<ProbeLayout> parseProbeLayout(std::string_view name);

/// Linear float RGB, row-major from the top row, 3 floats per pixel.
struct HdrImage {
    int width = 0;
    int height = 0;
    std::vector<float> rgb;
    const float* pixel(int x, int y) const { return rgb.data() + 3 * (size_t(y) * width + x); }
};

/// Reads .exr or .hdr (by content, not extension). Refuses unreadable files, files that are not
/// EXR/HDR (NotOurFormat), truncated or malformed data (CorruptData, naming what is wrong) and
/// non-finite or negative pixels (CorruptData, naming the first bad pixel).
Result<HdrImage> readHdrImage(const std::filesystem::path& path);
/// Writes a Radiance .hdr (RGBE, run-length encoded); for tests and `thespis-cli` outputs.
Result<void> writeRadianceHdr(const std::filesystem::path& path, const HdrImage& image);

/// Writes an OpenEXR file (float R, G, B, ZIP compression); for tests and `thespis-cli` outputs.
/// Writes what it is given, non-finite values included (tests use it to make bad files).
Result<void> writeOpenExr(const std::filesystem::path& path, const HdrImage& image);

/// Checks that an image fits the layout (square, 2:1, 3:4) and says what is wrong if not.
Result<void> checkProbeSize(const HdrImage& image, ProbeLayout layout);

/// World direction of the centre of pixel (x, y), and whether the pixel lies on the sphere
/// (outside the disc of an angular map or mirror ball, or off the cross, it does not).
bool directionOfPixel(ProbeLayout layout, int width, int height, double x, double y, Vec3d& direction);

/// An environment map in a layout: radiance lookup by direction (bilinear), used by the
/// brute-force references (irradiance and fidelity tests) and by the renderer's background.
class LightProbe {
public:
    static Result<LightProbe> load(const std::filesystem::path& path, ProbeLayout layout);
    static Result<LightProbe> fromImage(HdrImage image, ProbeLayout layout);

    ProbeLayout layout() const { return m_layout; }
    const HdrImage& image() const { return m_image; }
    /// Radiance arriving from world direction d (unit), RGB.
    std::array<float, 3> radiance(const Vec3d& d) const;

private:
    ProbeLayout m_layout = ProbeLayout::LatLong;
    HdrImage m_image;
};

/// Precomputed per-pixel directions × solid angles × basis values for one layout, size and
/// order, so that re-projecting a live probe (the AR mirror ball) is one pass of multiply-adds.
/// Solid angles are exact per pixel (integrated over the pixel's footprint, not the centre
/// approximation), accumulation is in double.
///
/// Each pixel is a sample at its centre (directionOfPixel). The coefficients are the solid-angle
/// weighted least-squares fit to those samples, c = G⁻¹·Σ_p Ω_p·L_p·y(d_p) with the discrete Gram
/// matrix G = Σ_p Ω_p·y(d_p)·y(d_p)ᵀ (precomputed, applied in 3·n² multiply-adds). The plain sum
/// would be the midpoint rule, whose error G − I is about 1e-5 on a 1024×512 lat-long at order 5
/// and 4e-3 on a mirror ball, whose outer pixels each span degrees; the fit gives a band-limited
/// map's coefficients back to rounding. A mirror-ball or angular pixel cut by the disc's rim is
/// sampled only if its centre is on the disc: otherwise it shows mostly what surrounds the ball.
/// A map too coarse to pin every coefficient down (G singular) is refused.
class ProbeProjector {
public:
    static Result<ProbeProjector> create(ProbeLayout layout, int width, int height, int order);

    ProbeLayout layout() const { return m_layout; }
    int width() const { return m_width; }
    int height() const { return m_height; }
    int order() const { return m_order; }
    /// Solid angle the pixels cover, sampled or not (4π up to the layout's coverage), for tests.
    double totalSolidAngle() const;

    /// Projects an image of this projector's size; threads split the rows (the sum is made in a
    /// fixed order, so the result does not depend on the thread count). threads ≤ 0: one per
    /// hardware thread. A requested stop returns ErrorCode::Cancelled.
    Result<ShRgb> project(const HdrImage& image, std::stop_token stop = {}, int threads = 0) const;

private:
    ProbeLayout m_layout = ProbeLayout::LatLong;
    int m_width = 0, m_height = 0, m_order = 0;
    struct Table;
    std::shared_ptr<const Table> m_table;
};

} // namespace thespis::core::lighting
