#pragma once
// Real spherical harmonics (paper §6), the one convention used everywhere in Thespis:
//
// - Order n means the bands l = 0 … n−1 and n² coefficients (Sloan's convention: "order 5" is
//   25 coefficients). Bands go up to l = 10 (order 11).
// - Coefficient index i = l(l+1)+m for m = −l … l.
// - Real basis without the Condon–Shortley phase, as in graphics (Sloan 2002, Ramamoorthi &
//   Hanrahan 2001): Y₁₋₁ = c·y, Y₁₀ = c·z, Y₁₁ = c·x with c = √(3/4π); Yₗₘ for m > 0 ∝ cos(mφ),
//   m < 0 ∝ sin(|m|φ), with φ measured from +x towards +y and θ from +z.
// - Directions are unit vectors in world axes (Thespis world: right-handed, y up, metres).
//   Nothing in this file depends on which axis is up.
// - Projection: L_i = ∫ L(ω) Y_i(ω) dω (radiance, no cosine). Reconstruction: L(ω) = Σ L_i Y_i(ω).

#include <array>
#include <cstddef>
#include <span>

#include "anim/quat.h"

namespace thespis::core::lighting {

using anim::Vec3d;
using anim::Vec3;

inline constexpr int kMaxShOrder = 11; ///< bands l = 0 … 10
inline constexpr int kMaxShCoefficients = kMaxShOrder * kMaxShOrder;

constexpr int shCoefficientCount(int order) { return order * order; }
constexpr int shIndex(int l, int m) { return l * (l + 1) + m; }

namespace detail {
/// √v at compile time, in long double (Newton from above; std::sqrt is not constexpr).
constexpr long double constexprSqrt(long double v)
{
    if (!(v > 0))
        return 0;
    long double x = v > 1 ? v : 1;
    for (int i = 0; i < 1000; ++i) {
        const long double next = (x + v / x) / 2;
        if (!(next < x))
            break;
        x = next;
    }
    return x;
}
} // namespace detail

/// The factor of Yₗₘ in front of Pₗ^|m|(cos θ)·cos(mφ) (or sin(|m|φ)), in full precision:
/// √((2l+1)/4π · (l−|m|)!/(l+|m|)!), times √2 when m ≠ 0.
constexpr long double shNormalization(int l, int m)
{
    const int am = m < 0 ? -m : m;
    long double factorialRatio = 1; // (l−|m|)! / (l+|m|)!
    for (int k = l - am + 1; k <= l + am; ++k)
        factorialRatio /= k;
    constexpr long double pi = 3.141592653589793238462643383279502884L;
    const long double k = detail::constexprSqrt((2 * l + 1) / (4 * pi) * factorialRatio);
    return am == 0 ? k : k * detail::constexprSqrt(2.0L);
}

/// Evaluates every basis function of bands 0 … order−1 at the unit direction `d` into
/// `out[0 … order²)`. Polynomial forms for the low bands, the stable recurrence above.
/// Requires 1 ≤ order ≤ kMaxShOrder and out.size() ≥ order². No allocation.
void evaluateSh(int order, const Vec3d& d, std::span<double> out);
void evaluateSh(int order, const Vec3& d, std::span<float> out);

/// Adds Σₖ Y_i(dₖ) over the unit directions dₖ = (x[k], y[k], z[k]) to sums[i] for i < order²:
/// the transfer bake's inner loop. Four directions at a time in float SIMD, with evaluateSh's
/// forms. The summation order is fixed (lane k mod 4 in k order, then the lanes pairwise), so
/// the same inputs give the same bits. Requires x, y, z of equal size, 1 ≤ order ≤ kMaxShOrder
/// and sums.size() ≥ order². No allocation.
void accumulateShSums(int order, std::span<const float> x, std::span<const float> y, std::span<const float> z,
                      std::span<float> sums);

/// One basis function Yₗₘ(d), computed directly from the associated Legendre definition
/// (slow, for tests and reference code).
double evaluateShReference(int l, int m, const Vec3d& d);

/// Σ coefficients[i]·Y_i(d): the band-limited function at a direction.
double reconstructSh(int order, std::span<const double> coefficients, const Vec3d& d);

/// Â_l, the SH coefficient of the clamped cosine max(cos θ, 0) as a zonal kernel, in the form
/// used for irradiance: E_lm = Â_l · L_lm. Â₀ = π, Â₁ = 2π/3, Â₂ = π/4, Â₃ = 0, Â₄ = −π/24, …
/// (odd l > 1 are zero). Exact closed form, any l ≤ 10.
double clampedCosineKernel(int l);

/// Convolution of a function with a zonal (rotation-symmetric about +z) kernel given by its
/// per-band factors: coefficients[l(l+1)+m] *= kernelPerBand[l]. For irradiance pass
/// clampedCosineKernel(l) per band (see irradianceFromRadiance).
void convolveZonal(int order, std::span<const double> kernelPerBand, std::span<double> coefficients);

/// Irradiance coefficients E = Â_l·L per band, from radiance coefficients (in place).
void irradianceFromRadiance(int order, std::span<double> coefficients);

/// Projection of a function given by samples: accumulates weight·value·Y_i(d) in double.
/// Used by the probe projector and by tests; `scratch` receives Y(d) (size ≥ order²).
void accumulateShProjection(int order, const Vec3d& d, double weightedValue,
                            std::span<double> coefficients, std::span<double> scratch);

/// RGB coefficients of a light, channel-major: r[0 … n²), g[…], b[…].
struct ShRgb {
    int order = 0;
    std::array<std::array<double, kMaxShCoefficients>, 3> channel{};
    std::span<double> operator[](int c) { return {channel[c].data(), size_t(order * order)}; }
    std::span<const double> operator[](int c) const { return {channel[c].data(), size_t(order * order)}; }
};

} // namespace thespis::core::lighting
