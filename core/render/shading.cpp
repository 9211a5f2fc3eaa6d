#include "render/shading.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace thespis::core::render {

const char* shadingName(Shading shading)
{
    switch (shading) {
    case Shading::Prt: return "prt";
    case Shading::Phong: return "phong";
    case Shading::Unlit: return "unlit";
    }
    return "prt";
}

Result<Shading> parseShading(std::string_view name)
{
    for (Shading shading : {Shading::Prt, Shading::Phong, Shading::Unlit})
        if (name == shadingName(shading))
            return shading;
    return makeError(ErrorCode::InvalidArgument,
                     "Unknown shading \"" + std::string(name) + "\" (use prt, phong or unlit).");
}

DirectionalLight dominantLight(const lighting::ShRgb& light)
{
    using std::numbers::pi;
    const double y00 = 0.5 / std::sqrt(pi);
    DirectionalLight result;
    if (light.order < 1)
        return result;
    if (light.order >= 2) {
        // Y_1,−1 ∝ y, Y_1,0 ∝ z, Y_1,1 ∝ x: band 1 is a vector per channel; weigh the channels by luminance.
        constexpr std::array<double, 3> luminance{0.2126, 0.7152, 0.0722};
        anim::Vec3d axis;
        for (int c = 0; c < 3; ++c)
            axis = axis + anim::Vec3d{light.channel[c][3], light.channel[c][1], light.channel[c][2]} * luminance[c];
        const double length = std::sqrt(axis.x * axis.x + axis.y * axis.y + axis.z * axis.z);
        if (length > 0) {
            result.direction = axis * (1 / length);
            const double y1 = std::sqrt(3 / (4 * pi));
            for (int c = 0; c < 3; ++c) {
                const double band1 = light.channel[c][3] * result.direction.x + light.channel[c][1] * result.direction.y +
                                     light.channel[c][2] * result.direction.z;
                result.color[c] = std::max(0.0, 4 * pi / 3 * y1 * band1);
            }
        }
    }
    for (int c = 0; c < 3; ++c)
        result.ambientIrradiance[c] = std::max(0.0, pi * y00 * (light.channel[c][0] - result.color[c] * y00));
    return result;
}

std::array<double, 3> irradiance(const lighting::ShRgb& light, const anim::Vec3d& normal)
{
    std::array<double, 3> result{};
    if (light.order < 1)
        return result;
    std::array<double, lighting::kMaxShCoefficients> basis{};
    lighting::evaluateSh(light.order, normal, basis);
    for (int l = 0; l < light.order; ++l) {
        const double kernel = lighting::clampedCosineKernel(l);
        for (int i = l * l; i < (l + 1) * (l + 1); ++i)
            for (int c = 0; c < 3; ++c)
                result[c] += kernel * light.channel[c][i] * basis[i];
    }
    return result;
}

double encodeSrgb(double linear)
{
    const double c = std::clamp(linear, 0.0, 1.0);
    return c < 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1 / 2.4) - 0.055;
}

} // namespace thespis::core::render
