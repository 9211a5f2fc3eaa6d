#pragma once
// How characters are shaded, and the light quantities the shaders take from the scene's SH light.
//
// - Prt (paper §6): per vertex, radiance = Σ t_i · L_seg,i with t the vertex's transfer in its
//   segment's bind frame and L_seg the world light rotated into the segment's current frame;
//   colour = albedo · radiance.
// - Phong (paper Fig. 16, the comparison): one directional light taken from the light's band 1
//   (its dominant direction), an ambient term from what remains of the DC band, Lambert diffuse
//   and a small normalised Blinn-Phong highlight, per pixel.
// - Unlit: the albedo alone.
// Lit colours are linear radiance; the display value is sRGB(clamp(exposure · radiance)).

#include <array>
#include <string_view>

#include "anim/quat.h"
#include "lighting/sh.h"
#include "util/error.h"

namespace thespis::core::render {

enum class Shading { Prt, Phong, Unlit };

const char* shadingName(Shading shading); ///< "prt", "phong", "unlit" (the CLI's spelling)
Result<Shading> parseShading(std::string_view name);

/// The directional light and ambient term Phong shading uses in place of an SH light. For a
/// light of colour c from direction d projected to SH (L_i = c·Y_i(d)) it gives back d, c and
/// no ambient; for a constant light, no directional part and the constant's irradiance.
struct DirectionalLight {
    anim::Vec3d direction{0, 1, 0};       ///< unit, world, towards the light
    std::array<double, 3> color{};         ///< irradiance on a surface facing the light (RGB)
    std::array<double, 3> ambientIrradiance{}; ///< irradiance from every direction (RGB)
};

/// Sloan's extraction ("Stupid SH tricks", 2008): the direction is band 1's luminance-weighted
/// axis, the colour c = (4π/3)·Σ_m L_1m·Y_1m(d) per channel (the directional light whose band 1
/// is closest to L's), and the ambient is the irradiance π·Y_00·(L_00 − c·Y_00) of the rest of
/// the DC band, clamped at 0.
DirectionalLight dominantLight(const lighting::ShRgb& light);

/// Irradiance E(n) = Σ Â_l·L_lm·Y_lm(n) of an SH light on a surface with unit normal n (RGB).
std::array<double, 3> irradiance(const lighting::ShRgb& light, const anim::Vec3d& normal);

/// The sRGB transfer function of a linear value clamped to [0, 1] (what the shaders apply last).
double encodeSrgb(double linear);

} // namespace thespis::core::render
