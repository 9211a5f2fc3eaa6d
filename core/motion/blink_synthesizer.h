#pragma once
// Blinks (issue 31; paper §5.2's face track): an open-ended face synthesizer that closes and
// opens the eyelids at seeded random moments, for a Stage's face slot as idle motion is for the
// body. Rates as people blink: about 17 a minute at rest, 26 while talking (Bentivoglio et al.
// 1997); the lids close in about 100 ms and open more slowly. The intervals are a shifted gamma
// (shape 2): never two blinks within 0.4 s, most a few seconds apart. The same seed gives the
// same blinks on every machine (the random numbers are drawn by hand from a 64-bit Mersenne
// twister, not through the standard distributions, whose results differ between libraries).

#include <cstdint>
#include <memory>
#include <vector>

#include "anim/blendable.h"
#include "util/error.h"

namespace thespis::core::motion {

struct BlinkOptions {
    double ratePerMinute = 17;  ///< at rest 17, in conversation 26
    double closeSeconds = 0.10; ///< from open to shut
    double shutSeconds = 0.03;  ///< held shut
    double openSeconds = 0.25;  ///< from shut to open again
    std::uint64_t seed = 1;
    bool operator==(const BlinkOptions&) const = default;
};

/// How shut the eyes are `into` seconds after a blink starts, 0 … 1.
double blinkClosure(double into, const BlinkOptions& options = {});
/// Closes the lids of a face frame by `shut` (0 … 1): the upper lids (FAPs 19, 20) and, a little,
/// the lower ones (21, 22), in IRISD units; lids already closed further stay so.
void closeLids(std::span<float> face, double shut);

/// The people's rates: at rest and while talking (blinks a minute).
inline constexpr double kBlinkRateAtRest = 17, kBlinkRateTalking = 26;

class BlinkSynthesizer final : public anim::BlendableObject {
public:
    /// Errors: a rate outside 1 … 120 a minute, or a phase not longer than 0 (or too long for the
    /// rate: a blink must end before the next may start).
    static Result<std::shared_ptr<BlinkSynthesizer>> create(const BlinkOptions& options = {});

    const BlinkOptions& options() const { return m_options; }
    const anim::FrameLayoutPtr& layout() const override { return m_layout; }
    anim::TimeDomain domain() const override { return {0.0}; }
    /// The face frame at t: upper lids (FAPs 19, 20) and, a little, lower lids (21, 22) in IRISD
    /// units; 1024 in all between them shuts the eye. Nothing else moves.
    void evaluate(double t, std::span<float> out) const override;

    /// How shut the eyes are at t, 0 … 1.
    double closure(double t) const;
    /// When the blinks start, in the first hour (the pattern then repeats).
    const std::vector<double>& starts() const { return m_starts; }

private:
    BlinkSynthesizer() = default;

    BlinkOptions m_options;
    anim::FrameLayoutPtr m_layout;
    std::vector<double> m_starts; // ascending, over [0, kPeriod)
};

} // namespace thespis::core::motion
