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

/// Noise at x for one channel of a seed: 0 at every integer, slopes in [−1, 1] there, values
/// within about ±0.5 between. Two octaves make its spectrum fuller.
inline float gradientNoise(std::uint64_t seed, std::uint32_t channel, double x)
{
    const double cell = std::floor(x);
    const float f = float(x - cell);
    const std::uint64_t base = mixBits(seed ^ (std::uint64_t(channel) << 40));
    const auto slope = [base](std::int64_t i) {
        return float(mixBits(base ^ std::uint64_t(i)) >> 40) * (2.0f / 16777216.0f) - 1.0f;
    };
    const std::int64_t i = std::int64_t(cell);
    const float u = f * f * f * (f * (f * 6 - 15) + 10);
    return (1 - u) * slope(i) * f + u * slope(i + 1) * (f - 1);
}

} // namespace thespis::core::motion
