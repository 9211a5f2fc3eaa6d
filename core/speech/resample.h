#pragma once
// Sample-rate conversion of mono sound by band-limited interpolation (a Blackman-windowed sinc),
// so that a recogniser made for one rate (pocketsphinx: 16 kHz) hears recordings made at any.

#include <cstdint>
#include <span>
#include <vector>

namespace thespis::core::speech {

/// `samples` at `from` Hz as the same sound at `to` Hz (both > 0). Going down, what lies above
/// the new Nyquist frequency is filtered out rather than folded back.
std::vector<float> resampled(std::span<const float> samples, int from, int to);

/// `samples` (−1 … 1, clamped) as 16-bit samples, dithered by one step either way from a fixed
/// seed (results repeat): digital silence, as in espeak-ng's pauses, has no log energy for a
/// recogniser.
std::vector<std::int16_t> dithered16(std::span<const float> samples);

} // namespace thespis::core::speech
