#pragma once
// Sample-rate conversion of mono sound by band-limited interpolation (a Blackman-windowed sinc),
// so that a recogniser made for one rate (pocketsphinx: 16 kHz) hears recordings made at any.

#include <span>
#include <vector>

namespace thespis::core::speech {

/// `samples` at `from` Hz as the same sound at `to` Hz (both > 0). Going down, what lies above
/// the new Nyquist frequency is filtered out rather than folded back.
std::vector<float> resampled(std::span<const float> samples, int from, int to);

} // namespace thespis::core::speech
