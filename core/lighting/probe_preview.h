#pragma once
// The light as a person sees it in the studio's probe picker: the probe's radiance and the
// band-limited light the characters are lit by (its SH projection), both as latitude–longitude
// pictures exposed alike, turned and scaled as the scenario asks (LightingSpec::rotation and
// intensity) — and that turn and scale applied to the light itself, for the renderer.

#include <cstdint>
#include <vector>

#include "lighting/probe.h"
#include "lighting/sh.h"

namespace thespis::core::lighting {

/// RGBA8 pixels, rows from the top.
struct PreviewImage {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;
};

/// The light turned about the vertical axis by `degrees` (the light that came from direction d
/// now comes from d turned by that angle) and multiplied by `intensity`.
ShRgb turnedLight(const ShRgb& light, double degrees, double intensity);

/// The exposure that shows a probe's typical radiance as mid-grey (0.18 over its log-average
/// luminance), so that a probe and its SH light are shown alike.
double previewExposure(const LightProbe& probe);

/// The probe as a width × width/2 latitude–longitude picture (centre: −Z, the probe's front),
/// turned and scaled like the light, exposed by `exposure`, sRGB.
PreviewImage previewProbe(const LightProbe& probe, int width, double degrees, double intensity, double exposure);

/// The SH light (already turned and scaled) as the same picture: what the characters receive.
PreviewImage previewLight(const ShRgb& light, int width, double exposure);

} // namespace thespis::core::lighting
