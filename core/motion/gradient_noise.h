#pragma once
// Perlin's gradient noise in one dimension (Perlin 1985, with his 2002 quintic fade), the paper's
// §4.3.2 source of small posture variations: smooth, band-limited, and a pure function of
// (seed, channel, x), so that an idle scrubbed backwards gives the same frames.

#include <cmath>
#include <cstdint>

namespace thespis::core::motion {

/// A well-mixed 64-bit hash (SplitMix64's finaliser).
inline std::uint64_t mixBits(std::uint64_t x)
{
    x += 0x9e3779b97f4a7c15ULL;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
}

/// One channel of a seed's noise (what gradientNoise() takes).
inline std::uint64_t noiseChannel(std::uint64_t seed, std::uint32_t channel)
{
    return mixBits(seed ^ (std::uint64_t(channel) << 40));
}

/// The slope of a channel's noise at the integer i, in [−1, 1].
inline float noiseSlope(std::uint64_t channel, std::int64_t i)
{
    return float(mixBits(channel ^ std::uint64_t(i)) >> 40) * (2.0f / 16777216.0f) - 1.0f;
}

/// Noise at f ∈ [0, 1) into a cell whose ends have slopes `a` and `b`.
inline float gradientNoiseIn(float a, float b, float f)
{
    const float u = f * f * f * (f * (f * 6 - 15) + 10);
    return (1 - u) * a * f + u * b * (f - 1);
}

/// Noise at x on a channel: 0 at every integer, slopes in [−1, 1] there, values within about
/// ±0.5 between.
inline float gradientNoise(std::uint64_t channel, double x)
{
    const double cell = std::floor(x);
    const auto i = std::int64_t(cell);
    return gradientNoiseIn(noiseSlope(channel, i), noiseSlope(channel, i + 1), float(x - cell));
}

} // namespace thespis::core::motion
