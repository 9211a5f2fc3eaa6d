// The light turned and scaled as a scenario asks (lighting/probe_preview.h), and the probe
// picker's pictures, on a real probe: the sun moves round by the angle asked, in the light the
// characters get and in the picture of the probe alike.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "lighting/probe_preview.h"
#include "lighting/probe_projection_job.h"
#include "lighting/sh.h"
#include "test_support.h"

namespace thespis::core::lighting {
namespace {

// Where the light comes from most: the band-1 coefficients' direction (y, z, x order in the
// real basis, index l(l+1)+m), of the luminance.
Vec3d dominant(const ShRgb& light)
{
    Vec3d d{};
    for (int c = 0; c < 3; ++c) {
        const double w = c == 0 ? 0.2126 : c == 1 ? 0.7152 : 0.0722;
        d = d + Vec3d{light[c][3], light[c][1], light[c][2]} * w;
    }
    return d;
}

double azimuthDegrees(const Vec3d& d)
{
    return std::atan2(d.x, d.z) * 180.0 / std::numbers::pi;
}

// The column of a picture's brightest pixel.
int brightestColumn(const PreviewImage& image)
{
    int best = 0, bestValue = -1;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const std::uint8_t* p = &image.rgba[(std::size_t(y) * std::size_t(image.width) + std::size_t(x)) * 4];
            if (const int v = p[0] + p[1] + p[2]; v > bestValue) {
                bestValue = v;
                best = x;
            }
        }
    return best;
}

TEST(ProbePreview, TurningTheLightMovesTheSunRound)
{
    auto probe = LightProbe::load(test::sharedData("probes/polyhaven_1k/venice_sunset_1k.hdr"), ProbeLayout::LatLong);
    ASSERT_TRUE(probe.ok()) << describe(probe.error());
    auto projected = projectProbeFile(test::sharedData("probes/polyhaven_1k/venice_sunset_1k.hdr"), ProbeLayout::LatLong, 3);
    ASSERT_TRUE(projected.ok());
    const double before = azimuthDegrees(dominant(*projected));
    const ShRgb turned = turnedLight(*projected, 90.0, 1.0);
    double moved = azimuthDegrees(dominant(turned)) - before;
    moved = std::remainder(moved, 360.0);
    EXPECT_NEAR(moved, 90.0, 0.01);
    // Intensity scales every coefficient.
    const ShRgb doubled = turnedLight(*projected, 0.0, 2.0);
    EXPECT_NEAR(doubled[1][0], 2.0 * (*projected)[1][0], 1e-12);
    EXPECT_NEAR(doubled[2][5], 2.0 * (*projected)[2][5], 1e-12);

    // The pictures: the sun's column moves by a quarter of the width when turned 90°, in the
    // probe's picture and in the light's (its broad lobe) alike, the way the light moved.
    const double exposure = previewExposure(*probe);
    const int width = 256;
    const PreviewImage still = previewProbe(*probe, width, 0.0, 1.0, exposure);
    const PreviewImage round = previewProbe(*probe, width, 90.0, 1.0, exposure);
    ASSERT_EQ(still.width, width);
    ASSERT_EQ(still.height, width / 2);
    // The azimuth a picture's column looks towards (its middle row, the horizon).
    const auto columnAzimuth = [&](int column) {
        Vec3d d;
        directionOfPixel(ProbeLayout::LatLong, width, width / 2, column + 0.5, width / 4 + 0.5, d);
        return azimuthDegrees(d);
    };
    const auto turnOf = [&](const PreviewImage& a, const PreviewImage& b) {
        return std::remainder(columnAzimuth(brightestColumn(b)) - columnAzimuth(brightestColumn(a)), 360.0);
    };
    EXPECT_NEAR(turnOf(still, round), 90.0, 3.0);
    const PreviewImage lightStill = previewLight(*projected, width, exposure);
    const PreviewImage lightRound = previewLight(turned, width, exposure);
    EXPECT_NEAR(turnOf(lightStill, lightRound), 90.0, 3.0);
}

} // namespace
} // namespace thespis::core::lighting
