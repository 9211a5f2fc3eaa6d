#include "anim/curve.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace thespis::core::anim {
namespace {

// 0 before t = 0, 1 after t = length, a linear or cubic ramp between (a step when length = 0).
double rise(double t, double length, bool cubic)
{
    if (!(length > 0))
        return t >= 0 ? 1.0 : 0.0;
    const double u = std::clamp(t / length, 0.0, 1.0);
    return cubic ? smoothStep(u) : u;
}

} // namespace

Curve Curve::constant(double value)
{
    Curve curve;
    curve.m_envelope.peak = value;
    return curve;
}

Curve Curve::linearFade(double fadeIn, double fadeOut, double peak)
{
    Curve curve;
    curve.m_kind = CurveKind::LinearFade;
    curve.m_envelope = {fadeIn, 0, 1, fadeOut, peak};
    return curve;
}

Curve Curve::cubicFade(double fadeIn, double fadeOut, double peak)
{
    Curve curve = linearFade(fadeIn, fadeOut, peak);
    curve.m_kind = CurveKind::CubicFade;
    return curve;
}

Curve Curve::linearAdsr(double attack, double decay, double sustain, double release, double peak)
{
    Curve curve;
    curve.m_kind = CurveKind::LinearAdsr;
    curve.m_envelope = {attack, decay, sustain, release, peak};
    return curve;
}

Curve Curve::cubicAdsr(double attack, double decay, double sustain, double release, double peak)
{
    Curve curve = linearAdsr(attack, decay, sustain, release, peak);
    curve.m_kind = CurveKind::CubicAdsr;
    return curve;
}

Curve Curve::dominance(double alpha, double peak)
{
    Curve curve;
    curve.m_kind = CurveKind::Dominance;
    curve.m_envelope.peak = peak;
    curve.m_envelope.alpha = alpha;
    return curve;
}

double dominance(double alpha, double x)
{
    if (!(x >= 0 && x <= 1))
        return 0;
    const double distance = 2 * std::abs(x - 0.5);
    return std::exp(-alpha * distance) - distance * std::exp(-alpha);
}

Result<Curve> Curve::keyframed(std::vector<CurveKey> keys)
{
    if (keys.empty())
        return makeError(ErrorCode::InvalidArgument, "A keyframed curve needs at least one key.");
    std::stable_sort(keys.begin(), keys.end(),
                     [](const CurveKey& a, const CurveKey& b) { return a.time < b.time; });
    for (std::size_t i = 0; i < keys.size(); ++i) {
        const CurveKey& k = keys[i];
        if (!std::isfinite(k.time) || !std::isfinite(k.value) || !std::isfinite(k.inSlope)
            || !std::isfinite(k.outSlope))
            return makeError(ErrorCode::InvalidArgument,
                             "Curve key " + std::to_string(i) + " has a value that is not a finite number.");
        if (i > 0 && keys[i - 1].time == k.time)
            return makeError(ErrorCode::InvalidArgument,
                             "Two curve keys are at the same time (" + std::to_string(k.time) + " s).");
    }
    Curve curve;
    curve.m_kind = CurveKind::Keyframed;
    curve.m_keys = std::move(keys);
    curve.computeAutoSlopes();
    return curve;
}

Result<void> Curve::validate() const
{
    const EnvelopeParams& e = m_envelope;
    for (double v : {e.attack, e.decay, e.sustain, e.release, e.peak, e.alpha})
        if (!std::isfinite(v))
            return makeError(ErrorCode::InvalidArgument, "A curve parameter is not a finite number.");
    if (e.attack < 0 || e.decay < 0 || e.release < 0)
        return makeError(ErrorCode::InvalidArgument, "Curve times (attack, decay, release) must not be negative.");
    if (e.sustain < 0 || e.sustain > 1)
        return makeError(ErrorCode::InvalidArgument, "An ADSR sustain level must be between 0 and 1.");
    if (m_kind == CurveKind::Dominance && !(e.alpha > 0))
        return makeError(ErrorCode::InvalidArgument, "A dominance curve's alpha must be greater than 0.");
    if (m_kind == CurveKind::Keyframed && m_keys.empty())
        return makeError(ErrorCode::InvalidArgument, "A keyframed curve needs at least one key.");
    return {};
}

double Curve::evaluate(double t, double duration) const
{
    const EnvelopeParams& e = m_envelope;
    switch (m_kind) {
    case CurveKind::Constant:
        return e.peak;
    case CurveKind::Keyframed:
        return evaluateKeys(t);
    case CurveKind::Dominance:
        // Open-ended, it has no middle: it holds its peak, as a fade with no ends would.
        return e.peak * (std::isfinite(duration) ? (duration > 0 ? anim::dominance(e.alpha, t / duration) : 0.0) : 1.0);
    case CurveKind::LinearFade:
    case CurveKind::CubicFade: {
        const bool cubic = m_kind == CurveKind::CubicFade;
        return e.peak * rise(t, e.attack, cubic) * rise(duration - t, e.release, cubic);
    }
    case CurveKind::LinearAdsr:
    case CurveKind::CubicAdsr: {
        const bool cubic = m_kind == CurveKind::CubicAdsr;
        // Attack and decay, then the release multiplies whatever level the envelope has: the
        // product of C1 pieces stays C1 for the cubic kinds, even when the phases overlap.
        const double decayed = 1.0 - (1.0 - e.sustain) * rise(t - e.attack, e.decay, cubic);
        const double level = t < e.attack ? rise(t, e.attack, cubic) : decayed;
        return e.peak * level * rise(duration - t, e.release, cubic);
    }
    }
    return 0;
}

void Curve::computeAutoSlopes()
{
    const std::size_t n = m_keys.size();
    m_inSlopes.assign(n, 0.0);
    m_outSlopes.assign(n, 0.0);
    auto secant = [&](std::size_t a, std::size_t b) {
        return (m_keys[b].value - m_keys[a].value) / (m_keys[b].time - m_keys[a].time);
    };
    for (std::size_t i = 0; i < n; ++i) {
        const CurveKey& k = m_keys[i];
        const double left = i > 0 ? secant(i - 1, i) : (i + 1 < n ? secant(i, i + 1) : 0.0);
        const double right = i + 1 < n ? secant(i, i + 1) : left;
        switch (k.mode) {
        case TangentMode::AutoClamped: {
            double slope = 0.0;
            if (i > 0 && i + 1 < n) {
                const double prev = m_keys[i - 1].value, next = m_keys[i + 1].value;
                const bool extremum = (k.value >= prev && k.value >= next) || (k.value <= prev && k.value <= next);
                slope = extremum ? 0.0 : (next - prev) / (m_keys[i + 1].time - m_keys[i - 1].time);
                // Clamp so that neither neighbouring segment overshoots its end values.
                const double limit = 3.0 * std::min(std::abs(left), std::abs(right));
                slope = std::clamp(slope, -limit, limit);
            }
            m_inSlopes[i] = m_outSlopes[i] = slope;
            break;
        }
        case TangentMode::Linear:
            m_inSlopes[i] = left;
            m_outSlopes[i] = right;
            break;
        case TangentMode::Constant:
            m_inSlopes[i] = m_outSlopes[i] = 0.0;
            break;
        case TangentMode::Free:
            m_inSlopes[i] = m_outSlopes[i] = k.inSlope;
            break;
        case TangentMode::Broken:
            m_inSlopes[i] = k.inSlope;
            m_outSlopes[i] = k.outSlope;
            break;
        }
    }
}

double Curve::evaluateKeys(double t) const
{
    const auto& keys = m_keys;
    if (t <= keys.front().time)
        return keys.front().value;
    if (t >= keys.back().time)
        return keys.back().value;
    const auto next = std::upper_bound(keys.begin(), keys.end(), t,
                                       [](double time, const CurveKey& k) { return time < k.time; });
    const std::size_t i1 = std::size_t(next - keys.begin());
    const std::size_t i0 = i1 - 1;
    const CurveKey& a = keys[i0];
    const CurveKey& b = keys[i1];
    if (a.mode == TangentMode::Constant)
        return a.value;
    const double h = b.time - a.time;
    const double u = (t - a.time) / h;
    const double u2 = u * u, u3 = u2 * u;
    // Cubic Hermite basis.
    const double h00 = 2 * u3 - 3 * u2 + 1, h10 = u3 - 2 * u2 + u, h01 = -2 * u3 + 3 * u2, h11 = u3 - u2;
    return h00 * a.value + h10 * h * m_outSlopes[i0] + h01 * b.value + h11 * h * m_inSlopes[i1];
}

} // namespace thespis::core::anim
