#include "speech/resample.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <numbers>
#include <random>

namespace thespis::core::speech {
namespace {

constexpr int kZeroCrossings = 12;   // each side: the filter's length, and its sharpness
constexpr int kTableSteps = 512;     // kernel values per zero crossing, linearly interpolated
constexpr double kPassband = 0.95;   // of the lower Nyquist frequency: room for the transition

// The windowed sinc at u zero crossings from its centre, u in [0, kZeroCrossings].
const std::array<float, kZeroCrossings * kTableSteps + 2>& kernelTable()
{
    static const auto table = [] {
        std::array<float, kZeroCrossings * kTableSteps + 2> t{};
        for (std::size_t i = 0; i < t.size(); ++i) {
            const double u = double(i) / kTableSteps;
            if (u >= kZeroCrossings)
                continue;
            const double x = std::numbers::pi * u;
            const double sinc = i == 0 ? 1.0 : std::sin(x) / x;
            const double phase = std::numbers::pi * u / kZeroCrossings;
            const double blackman = 0.42 + 0.5 * std::cos(phase) + 0.08 * std::cos(2 * phase);
            t[i] = float(sinc * blackman);
        }
        return t;
    }();
    return table;
}

} // namespace

std::vector<float> resampled(std::span<const float> samples, int from, int to)
{
    assert(from > 0 && to > 0);
    if (from == to)
        return {samples.begin(), samples.end()};
    const auto& table = kernelTable();
    // In input samples: the cut-off (as a fraction of the input's Nyquist frequency) and the reach.
    const double cutoff = kPassband * std::min(1.0, double(to) / from);
    const double reach = kZeroCrossings / cutoff;
    const std::size_t count = std::size_t(double(samples.size()) * to / from);
    const long last = long(samples.size()) - 1;
    std::vector<float> out(count);
    for (std::size_t n = 0; n < count; ++n) {
        const double t = double(n) * from / to; // exact enough: n·from < 2^53
        const long first = std::max(0L, long(std::ceil(t - reach)));
        const long end = std::min(last, long(std::floor(t + reach)));
        double sum = 0;
        for (long k = first; k <= end; ++k) {
            const double u = std::abs(t - double(k)) * cutoff * kTableSteps;
            const std::size_t i = std::size_t(u);
            const double f = u - double(i);
            sum += samples[std::size_t(k)] * (table[i] + f * (table[i + 1] - table[i]));
        }
        out[n] = float(sum * cutoff);
    }
    return out;
}

std::vector<std::int16_t> dithered16(std::span<const float> samples)
{
    std::minstd_rand random(1);
    std::vector<std::int16_t> pcm(samples.size());
    for (std::size_t i = 0; i < samples.size(); ++i) {
        const long value = std::lround(std::clamp(samples[i], -1.0f, 1.0f) * 32766.0f) + (random() & 1 ? 1 : -1);
        pcm[i] = std::int16_t(value);
    }
    return pcm;
}

} // namespace thespis::core::speech
