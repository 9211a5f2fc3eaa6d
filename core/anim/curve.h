#pragma once
// Parametrizable curves that drive blending weights and scales over an action's local time
// (paper §4.2, Fig. 3). A curve is a value: cheap to copy, compare and serialize.
//
// Fades and ADSR envelopes are defined relative to the action's duration d, so that trimming
// an action keeps its fades at the ends:
//   fade:  rises 0 → peak over [0, fadeIn], holds, falls peak → 0 over [d − fadeOut, d]
//   ADSR:  rises 0 → peak over attack, decays to sustain·peak over decay, holds, releases to 0
//          over [d − release, d]
// "Linear" ramps are straight; "cubic" ramps use 3u² − 2u³, so the curve is C1 everywhere.
// An open-ended action (d = ∞) never releases. Keyframed curves are cubic Hermite splines with a
// tangent mode per key, in the local time of the action (d is ignored).
// The dominance curve is the paper's coarticulation weight (§5.2, eq. 3) over the action's
// duration: with x = t/d, C_α(x) = e^(−α·2|x−0.5|) − 2|x−0.5|·e^(−α), times the peak. It is 0 at
// both ends, 1·peak in the middle, and α sets how sharply it peaks (a viseme's dominance).

#include <limits>
#include <vector>

#include "util/error.h"

namespace thespis::core::anim {

enum class CurveKind { Constant, LinearFade, CubicFade, LinearAdsr, CubicAdsr, Keyframed, Dominance };

enum class TangentMode {
    AutoClamped, ///< smooth (Catmull-Rom slope), flattened at extrema so it never overshoots
    Linear,      ///< straight line towards the neighbouring keys
    Constant,    ///< step: holds the key's value until the next key
    Free,        ///< user slope, the same on both sides (smooth)
    Broken,      ///< user slopes, independent in and out
};

struct CurveKey {
    double time = 0;
    double value = 0;
    TangentMode mode = TangentMode::AutoClamped;
    double inSlope = 0;  ///< value per second, used by Free and Broken
    double outSlope = 0; ///< used by Broken (Free uses inSlope on both sides)
    bool operator==(const CurveKey&) const = default;
};

struct EnvelopeParams {
    double attack = 0;  ///< fade-in time for fades, attack time for ADSR (seconds)
    double decay = 0;   ///< ADSR only
    double sustain = 1; ///< ADSR only: level after decay, fraction of peak
    double release = 0; ///< fade-out time for fades, release time for ADSR
    double peak = 1;    ///< level reached after the attack (the dominance curve's maximum)
    double alpha = 0;   ///< dominance only: its α (> 0; larger peaks more sharply)
    bool operator==(const EnvelopeParams&) const = default;
};

class Curve {
public:
    static constexpr double Infinite = std::numeric_limits<double>::infinity();

    Curve() = default; ///< constant 1
    static Curve constant(double value);
    static Curve linearFade(double fadeIn, double fadeOut, double peak = 1);
    static Curve cubicFade(double fadeIn, double fadeOut, double peak = 1);
    static Curve linearAdsr(double attack, double decay, double sustain, double release, double peak = 1);
    static Curve cubicAdsr(double attack, double decay, double sustain, double release, double peak = 1);
    /// The coarticulation dominance C_α over the action's duration (α > 0), scaled by `peak`.
    static Curve dominance(double alpha, double peak = 1);
    /// Keys are sorted by time; two keys at the same time are an error.
    static Result<Curve> keyframed(std::vector<CurveKey> keys);

    /// Checks parameters: finite, non-negative times, sustain in [0, 1], a dominance's α > 0.
    Result<void> validate() const;

    CurveKind kind() const { return m_kind; }
    const EnvelopeParams& envelope() const { return m_envelope; }
    double constantValue() const { return m_envelope.peak; }
    const std::vector<CurveKey>& keys() const { return m_keys; }

    /// Value at local time t of an action lasting `duration` seconds (may be Infinite).
    double evaluate(double t, double duration = Infinite) const;
    /// True when the curve is the constant 1 (lets the engine skip work).
    bool isIdentity() const { return m_kind == CurveKind::Constant && m_envelope.peak == 1.0; }

    bool operator==(const Curve&) const = default;

private:
    double evaluateKeys(double t) const;
    void computeAutoSlopes();

    CurveKind m_kind = CurveKind::Constant;
    EnvelopeParams m_envelope;
    std::vector<CurveKey> m_keys;
    std::vector<double> m_outSlopes, m_inSlopes; // resolved slopes per key
};

/// The paper's eq. 3 at x in [0, 1]: e^(−α·2|x−0.5|) − 2|x−0.5|·e^(−α); 0 outside [0, 1].
double dominance(double alpha, double x);

/// 3u² − 2u³ for u in [0, 1]: the cubic fade used by cubic curves and cut-offs.
inline double smoothStep(double u)
{
    u = u < 0 ? 0 : u > 1 ? 1 : u;
    return u * u * (3.0 - 2.0 * u);
}

} // namespace thespis::core::anim
