#include "motion/blink_synthesizer.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "scene/fap.h"

namespace thespis::core::motion {

namespace {

constexpr double kPeriod = 3600; // seconds of blinks drawn; later ones repeat them
constexpr double kShortestInterval = 0.4;
constexpr double kLowerLidShare = 0.12; // of the closing the lower lids take (they rise a little)

double uniform(std::mt19937_64& random) { return double(random() >> 11) * 0x1.0p-53; }
double exponential(std::mt19937_64& random) { return -std::log1p(-uniform(random)); }

} // namespace

Result<std::shared_ptr<BlinkSynthesizer>> BlinkSynthesizer::create(const BlinkOptions& options)
{
    if (!(options.ratePerMinute >= 1 && options.ratePerMinute <= 120))
        return makeError(ErrorCode::InvalidArgument, "blinks: the rate must be 1 to 120 a minute, not " +
                                                         std::to_string(options.ratePerMinute) + ".");
    const double blink = options.closeSeconds + options.shutSeconds + options.openSeconds;
    if (!(options.closeSeconds > 0 && options.shutSeconds >= 0 && options.openSeconds > 0) ||
        !(blink < kShortestInterval))
        return makeError(ErrorCode::InvalidArgument,
                         "blinks: closing and opening must take more than 0 s, and a whole blink less than " +
                             std::to_string(kShortestInterval) + " s.");
    std::shared_ptr<BlinkSynthesizer> self(new BlinkSynthesizer);
    self->m_options = options;
    self->m_layout = anim::FrameLayout::mpeg4Face();
    // Intervals: the shortest plus a gamma of shape 2 (two exponentials) with the rest of the mean.
    std::mt19937_64 random(options.seed);
    const double mean = 60 / options.ratePerMinute, scale = std::max(0.0, mean - kShortestInterval) / 2;
    for (double t = kShortestInterval * uniform(random) + scale * exponential(random); t < kPeriod;
         t += kShortestInterval + scale * (exponential(random) + exponential(random)))
        self->m_starts.push_back(t);
    return self;
}

double BlinkSynthesizer::closure(double t) const
{
    if (t < 0 || m_starts.empty())
        return 0;
    t = std::fmod(t, kPeriod);
    const auto next = std::upper_bound(m_starts.begin(), m_starts.end(), t);
    if (next == m_starts.begin())
        return 0;
    return blinkClosure(t - *(next - 1), m_options);
}

double blinkClosure(double into, const BlinkOptions& o)
{
    const double half = std::numbers::pi / 2;
    if (into < 0)
        return 0;
    if (into < o.closeSeconds)
        return std::pow(std::sin(half * into / o.closeSeconds), 2);
    if (into < o.closeSeconds + o.shutSeconds)
        return 1;
    if (into < o.closeSeconds + o.shutSeconds + o.openSeconds)
        return std::pow(std::cos(half * (into - o.closeSeconds - o.shutSeconds) / o.openSeconds), 2);
    return 0;
}

void BlinkSynthesizer::evaluate(double t, std::span<float> out) const
{
    std::fill(out.begin(), out.end(), 0.0f);
    closeLids(out, closure(t));
}

void closeLids(std::span<float> face, double shut)
{
    const float upper = float(1024 * (1 - kLowerLidShare) * shut), lower = float(1024 * kLowerLidShare * shut);
    for (const int fap : {19, 20})
        face[std::size_t(scene::fapChannel(fap))] = std::max(face[std::size_t(scene::fapChannel(fap))], upper);
    for (const int fap : {21, 22})
        face[std::size_t(scene::fapChannel(fap))] = std::max(face[std::size_t(scene::fapChannel(fap))], lower);
}

} // namespace thespis::core::motion
