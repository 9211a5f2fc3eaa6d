#include "lighting/probe_preview.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "lighting/sh_rotation.h"

namespace thespis::core::lighting {

namespace {

std::uint8_t toSrgb(double linear)
{
    const double c = std::clamp(linear, 0.0, 1.0);
    const double s = c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
    return std::uint8_t(std::lround(s * 255.0));
}

// Fills a lat-long picture from a radiance function of the world direction.
template <class Radiance>
PreviewImage latLong(int width, double exposure, Radiance radiance)
{
    PreviewImage image;
    image.width = std::max(width, 2);
    image.height = std::max(image.width / 2, 1);
    image.rgba.resize(std::size_t(image.width) * std::size_t(image.height) * 4);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            Vec3d direction;
            directionOfPixel(ProbeLayout::LatLong, image.width, image.height, x + 0.5, y + 0.5, direction);
            const std::array<double, 3> rgb = radiance(direction);
            std::uint8_t* pixel = &image.rgba[(std::size_t(y) * std::size_t(image.width) + std::size_t(x)) * 4];
            for (int c = 0; c < 3; ++c)
                pixel[c] = toSrgb(rgb[std::size_t(c)] * exposure);
            pixel[3] = 255;
        }
    return image;
}

Quatd turn(double degrees)
{
    const double half = degrees * std::numbers::pi / 360.0;
    return {0.0, std::sin(half), 0.0, std::cos(half)};
}

} // namespace

ShRgb turnedLight(const ShRgb& light, double degrees, double intensity)
{
    ShRgb turned;
    ShRotation(light.order, turn(degrees)).applyRgb(light, turned);
    for (int c = 0; c < 3; ++c)
        for (double& coefficient : turned[c])
            coefficient *= intensity;
    return turned;
}

double previewExposure(const LightProbe& probe)
{
    const HdrImage& image = probe.image();
    double sum = 0;
    std::size_t count = 0;
    for (std::size_t p = 0; p + 2 < image.rgb.size(); p += 3) {
        const double luminance = 0.2126 * image.rgb[p] + 0.7152 * image.rgb[p + 1] + 0.0722 * image.rgb[p + 2];
        if (luminance > 0 && std::isfinite(luminance)) {
            sum += std::log(luminance);
            ++count;
        }
    }
    return count ? 0.18 / std::exp(sum / double(count)) : 1.0;
}

PreviewImage previewProbe(const LightProbe& probe, int width, double degrees, double intensity, double exposure)
{
    // The light from world direction d was the probe's from d turned back.
    const Quatd back = conjugate(turn(degrees));
    return latLong(width, exposure, [&](const Vec3d& d) {
        const std::array<float, 3> r = probe.radiance(rotate(back, d));
        return std::array<double, 3>{r[0] * intensity, r[1] * intensity, r[2] * intensity};
    });
}

PreviewImage previewLight(const ShRgb& light, int width, double exposure)
{
    return latLong(width, exposure, [&](const Vec3d& d) {
        return std::array<double, 3>{reconstructSh(light.order, light[0], d), reconstructSh(light.order, light[1], d),
                                     reconstructSh(light.order, light[2], d)};
    });
}

} // namespace thespis::core::lighting
