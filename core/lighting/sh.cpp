#include "lighting/sh.h"

#include <cassert>
#include <cmath>
#include <numbers>
#include <utility>

#include "lighting/float4.h"

namespace thespis::core::lighting {

namespace {

// Normalised associated Legendre recurrence (no Condon–Shortley phase) in the form
// Yₗₘ = Qₗᵐ(z) · Cₘ (or Sₘ for m < 0), where Cₘ + i·Sₘ = (x + i·y)ᵐ = sinᵐθ·e^{imφ} and
// Qₗᵐ is a polynomial in z = cos θ that carries the normalisation:
//   Qₘᵐ = √2·Kₘₘ·(2m−1)!!            (√2 only for m > 0)
//   Qₗᵐ = aₗₘ·z·Qₗ₋₁ᵐ + bₗₘ·Qₗ₋₂ᵐ,   aₗₘ = √((4l²−1)/(l²−m²)),
//                                    bₗₘ = −√(((l−1)²−m²)(2l+1)/((2l−3)(l²−m²)))
// Both the Cₘ, Sₘ rotation and the z recurrence are stable and use no trigonometric call.
struct LegendreTables {
    double start[kMaxShOrder]{};                  // Qₘᵐ
    double a[kMaxShOrder][kMaxShOrder]{};         // [l][m]
    double b[kMaxShOrder][kMaxShOrder]{};
};

constexpr LegendreTables makeLegendreTables()
{
    LegendreTables t;
    for (int m = 0; m < kMaxShOrder; ++m) {
        long double doubleFactorial = 1; // (2m−1)!!
        for (int k = 2 * m - 1; k > 1; k -= 2)
            doubleFactorial *= k;
        t.start[m] = double(shNormalization(m, m) * doubleFactorial);
        for (int l = m + 1; l < kMaxShOrder; ++l) {
            const long double l2 = (long double)l * l, m2 = (long double)m * m;
            t.a[l][m] = double(detail::constexprSqrt((4 * l2 - 1) / (l2 - m2)));
            t.b[l][m] = l == m + 1 ? 0.0
                                   : double(-detail::constexprSqrt(((l - 1.0L) * (l - 1.0L) - m2) * (2 * l + 1) /
                                                           ((2 * l - 3.0L) * (l2 - m2))));
        }
    }
    return t;
}

constexpr LegendreTables kLegendre = makeLegendreTables();

// Constants of the explicit low bands: Qₗᵐ written as k·(polynomial in z with integer
// coefficients), k = √2·Kₗₘ times the rational factor of Pₗᵐ/sinᵐθ.
constexpr long double k00 = shNormalization(0, 0);
constexpr long double k1 = shNormalization(1, 0); // = √2·K₁₁ too
constexpr long double k20 = shNormalization(2, 0) / 2;  // P₂⁰ = (3z²−1)/2
constexpr long double k21 = shNormalization(2, 1) * 3;  // P₂¹ = 3z·sinθ
constexpr long double k22 = shNormalization(2, 2) * 3;  // P₂² = 3·sin²θ
constexpr long double k30 = shNormalization(3, 0) / 2;  // P₃⁰ = (5z³−3z)/2
constexpr long double k31 = shNormalization(3, 1) * 3 / 2; // P₃¹ = 3/2·(5z²−1)·sinθ
constexpr long double k32 = shNormalization(3, 2) * 15; // P₃² = 15z·sin²θ
constexpr long double k33 = shNormalization(3, 3) * 15; // P₃³ = 15·sin³θ
constexpr long double k40 = shNormalization(4, 0) / 8;  // P₄⁰ = (35z⁴−30z²+3)/8
constexpr long double k41 = shNormalization(4, 1) * 5 / 2;  // P₄¹ = 5/2·(7z³−3z)·sinθ
constexpr long double k42 = shNormalization(4, 2) * 15 / 2; // P₄² = 15/2·(7z²−1)·sin²θ
constexpr long double k43 = shNormalization(4, 3) * 105; // P₄³ = 105z·sin³θ
constexpr long double k44 = shNormalization(4, 4) * 105; // P₄⁴ = 105·sin⁴θ

constexpr int kFirstRecurrenceBand = 5;

// Bands 5 … Order−1 by the recurrence; Qₗᵐ of the lower bands are recomputed (a few
// multiplies) so the explicit part stays simple.
template <class T, int Order>
inline void evaluateHighBands(T z, const T* c, const T* s, T* out)
{
    for (int m = 0; m < Order; ++m) {
        T previous = 0;
        T current = T(kLegendre.start[m]);
        for (int l = m; l < Order; ++l) {
            if (l > m) {
                const T next = T(kLegendre.a[l][m]) * z * current + T(kLegendre.b[l][m]) * previous;
                previous = current;
                current = next;
            }
            if (l >= kFirstRecurrenceBand) {
                out[l * (l + 1) + m] = current * c[m];
                if (m > 0)
                    out[l * (l + 1) - m] = current * s[m];
            }
        }
    }
}

template <class T, int Order>
[[gnu::always_inline]] inline void evaluateFixed(T x, T y, T z, T* out)
{
    out[0] = T(k00);
    if constexpr (Order > 1) {
        out[1] = T(k1) * y;
        out[2] = T(k1) * z;
        out[3] = T(k1) * x;
    }
    if constexpr (Order > 2) {
        const T c2 = x * x - y * y, s2 = 2 * x * y;
        const T q21 = T(k21) * z;
        out[4] = T(k22) * s2;
        out[5] = q21 * y;
        out[6] = T(k20) * (3 * z * z - 1);
        out[7] = q21 * x;
        out[8] = T(k22) * c2;
        if constexpr (Order > 3) {
            const T c3 = x * c2 - y * s2, s3 = x * s2 + y * c2;
            const T z2 = z * z;
            const T q31 = T(k31) * (5 * z2 - 1);
            const T q32 = T(k32) * z;
            out[9] = T(k33) * s3;
            out[10] = q32 * s2;
            out[11] = q31 * y;
            out[12] = T(k30) * z * (5 * z2 - 3);
            out[13] = q31 * x;
            out[14] = q32 * c2;
            out[15] = T(k33) * c3;
            if constexpr (Order > 4) {
                const T c4 = x * c3 - y * s3, s4 = x * s3 + y * c3;
                const T q41 = T(k41) * z * (7 * z2 - 3);
                const T q42 = T(k42) * (7 * z2 - 1);
                const T q43 = T(k43) * z;
                out[16] = T(k44) * s4;
                out[17] = q43 * s3;
                out[18] = q42 * s2;
                out[19] = q41 * y;
                out[20] = T(k40) * ((35 * z2 - 30) * z2 + 3);
                out[21] = q41 * x;
                out[22] = q42 * c2;
                out[23] = q43 * c3;
                out[24] = T(k44) * c4;
            }
        }
    }
    if constexpr (Order > kFirstRecurrenceBand) {
        T c[Order], s[Order];
        c[0] = 1;
        s[0] = 0;
        for (int m = 1; m < Order; ++m) {
            c[m] = x * c[m - 1] - y * s[m - 1];
            s[m] = x * s[m - 1] + y * c[m - 1];
        }
        evaluateHighBands<T, Order>(z, c, s, out);
    }
}

template <class T>
void evaluateDispatch(int order, T x, T y, T z, T* out)
{
    switch (order) {
    case 1: return evaluateFixed<T, 1>(x, y, z, out);
    case 2: return evaluateFixed<T, 2>(x, y, z, out);
    case 3: return evaluateFixed<T, 3>(x, y, z, out);
    case 4: return evaluateFixed<T, 4>(x, y, z, out);
    case 5: return evaluateFixed<T, 5>(x, y, z, out);
    case 6: return evaluateFixed<T, 6>(x, y, z, out);
    case 7: return evaluateFixed<T, 7>(x, y, z, out);
    case 8: return evaluateFixed<T, 8>(x, y, z, out);
    case 9: return evaluateFixed<T, 9>(x, y, z, out);
    case 10: return evaluateFixed<T, 10>(x, y, z, out);
    case 11: return evaluateFixed<T, 11>(x, y, z, out);
    default: assert(false && "SH order must be 1 … kMaxShOrder");
    }
}

// Σ Y_i over the directions, evaluateFixed on four directions at once; the last 1–3 are padded
// with +z and weighed out by a 0/1 lane mask.
template <int Order>
[[gnu::always_inline]] inline void accumulateFixed(const float* x, const float* y, const float* z, std::size_t count, float* sums)
{
    constexpr int n = Order * Order;
    Float4 total[n];
    for (Float4& t : total)
        t = 0;
    Float4 basis[n];
    std::size_t k = 0;
    for (; k + 4 <= count; k += 4) {
        evaluateFixed<Float4, Order>(Float4::load(x + k), Float4::load(y + k), Float4::load(z + k), basis);
        for (int i = 0; i < n; ++i)
            total[i] += basis[i];
    }
    if (k < count) {
        float tailX[4] = {0, 0, 0, 0}, tailY[4] = {0, 0, 0, 0}, tailZ[4] = {1, 1, 1, 1}, weight[4] = {0, 0, 0, 0};
        for (std::size_t j = 0; k + j < count; ++j) {
            tailX[j] = x[k + j];
            tailY[j] = y[k + j];
            tailZ[j] = z[k + j];
            weight[j] = 1;
        }
        evaluateFixed<Float4, Order>(Float4::load(tailX), Float4::load(tailY), Float4::load(tailZ), basis);
        const Float4 w = Float4::load(weight);
        for (int i = 0; i < n; ++i)
            total[i] += basis[i] * w;
    }
    for (int i = 0; i < n; ++i)
        sums[i] += total[i].sum();
}

using AccumulateKernel = void (*)(const float*, const float*, const float*, std::size_t, float*);

template <int Order>
void accumulateBaseline(const float* x, const float* y, const float* z, std::size_t count, float* sums)
{
    accumulateFixed<Order>(x, y, z, count, sums);
}

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
// The same four-lane code with the AVX encoding: three-operand instructions and broadcast loads
// cut the instruction count by about a third (register copies, constant shuffles). No FMA, so
// the results are the baseline's bit for bit.
template <int Order>
__attribute__((target("avx"))) void accumulateAvx(const float* x, const float* y, const float* z, std::size_t count,
                                                 float* sums)
{
    accumulateFixed<Order>(x, y, z, count, sums);
}

bool hasAvx()
{
    static const bool supported = [] {
        __builtin_cpu_init();
        return __builtin_cpu_supports("avx");
    }();
    return supported;
}
#endif

template <int... Order>
constexpr std::array<AccumulateKernel, sizeof...(Order)> accumulateKernels(std::integer_sequence<int, Order...>,
                                                                          bool avx)
{
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
    if (avx)
        return {accumulateAvx<Order + 1>...};
#endif
    (void)avx;
    return {accumulateBaseline<Order + 1>...};
}

} // namespace

void accumulateShSums(int order, std::span<const float> x, std::span<const float> y, std::span<const float> z,
                      std::span<float> sums)
{
    assert(order >= 1 && order <= kMaxShOrder && sums.size() >= size_t(order * order));
    assert(x.size() == y.size() && x.size() == z.size());
    static const std::array<AccumulateKernel, kMaxShOrder> kernels =
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
        accumulateKernels(std::make_integer_sequence<int, kMaxShOrder>(), hasAvx());
#else
        accumulateKernels(std::make_integer_sequence<int, kMaxShOrder>(), false);
#endif
    kernels[std::size_t(order - 1)](x.data(), y.data(), z.data(), x.size(), sums.data());
}

void evaluateSh(int order, const Vec3d& d, std::span<double> out)
{
    assert(order >= 1 && order <= kMaxShOrder && out.size() >= size_t(order * order));
    evaluateDispatch(order, d.x, d.y, d.z, out.data());
}

void evaluateSh(int order, const Vec3& d, std::span<float> out)
{
    assert(order >= 1 && order <= kMaxShOrder && out.size() >= size_t(order * order));
    evaluateDispatch(order, d.x, d.y, d.z, out.data());
}

double evaluateShReference(int l, int m, const Vec3d& d)
{
    assert(l >= 0 && l < kMaxShOrder && std::abs(m) <= l);
    // Pₗ(z) = 2⁻ˡ Σₖ (−1)ᵏ C(l,k) C(2l−2k,l) z^(l−2k); Pₗᵐ = sinᵐθ · dᵐPₗ/dzᵐ (no (−1)ᵐ).
    const int am = std::abs(m);
    const long double z = d.z;
    const long double sinTheta = std::sqrt((long double)d.x * d.x + (long double)d.y * d.y);
    const auto binomial = [](int n, int k) {
        long double r = 1;
        for (int i = 1; i <= k; ++i)
            r = r * (n - k + i) / i;
        return r;
    };
    long double derivative = 0;
    for (int k = 0; 2 * k <= l; ++k) {
        const int power = l - 2 * k;
        if (power < am)
            continue;
        long double term = (k % 2 ? -1.0L : 1.0L) * binomial(l, k) * binomial(2 * l - 2 * k, l);
        for (int i = 0; i < am; ++i)
            term *= power - i; // dᵐ/dzᵐ z^power
        derivative += term * std::pow(z, power - am);
    }
    const long double legendre = derivative / std::pow(2.0L, l) * std::pow(sinTheta, am);
    const long double phi = std::atan2((long double)d.y, (long double)d.x);
    const long double azimuth = m > 0 ? std::cos(am * phi) : m < 0 ? std::sin(am * phi) : 1.0L;
    return double(shNormalization(l, am) * legendre * azimuth);
}

double reconstructSh(int order, std::span<const double> coefficients, const Vec3d& d)
{
    assert(coefficients.size() >= size_t(order * order));
    double basis[kMaxShCoefficients];
    evaluateSh(order, d, basis);
    double sum = 0;
    for (int i = 0; i < order * order; ++i)
        sum += coefficients[size_t(i)] * basis[i];
    return sum;
}

double clampedCosineKernel(int l)
{
    assert(l >= 0 && l < kMaxShOrder);
    constexpr double pi = std::numbers::pi;
    if (l == 0)
        return pi;
    if (l == 1)
        return 2 * pi / 3;
    if (l % 2 == 1)
        return 0.0;
    // Â_l = 2π·(−1)^(l/2−1) / ((l+2)(l−1)) · l! / (2^l ((l/2)!)²)   (Ramamoorthi & Hanrahan 2001)
    long double ratio = 1; // l! / (2^l ((l/2)!)²) = C(l, l/2) / 2^l
    for (int i = 1; i <= l / 2; ++i)
        ratio = ratio * (l / 2 + i) / i / 4;
    const long double sign = (l / 2 - 1) % 2 ? -1.0L : 1.0L;
    return double(2 * std::numbers::pi_v<long double> * sign / ((l + 2) * (l - 1)) * ratio);
}

void convolveZonal(int order, std::span<const double> kernelPerBand, std::span<double> coefficients)
{
    assert(kernelPerBand.size() >= size_t(order) && coefficients.size() >= size_t(order * order));
    for (int l = 0; l < order; ++l)
        for (int m = -l; m <= l; ++m)
            coefficients[size_t(shIndex(l, m))] *= kernelPerBand[size_t(l)];
}

void irradianceFromRadiance(int order, std::span<double> coefficients)
{
    double kernel[kMaxShOrder];
    for (int l = 0; l < order; ++l)
        kernel[l] = clampedCosineKernel(l);
    convolveZonal(order, {kernel, size_t(order)}, coefficients);
}

void accumulateShProjection(int order, const Vec3d& d, double weightedValue,
                            std::span<double> coefficients, std::span<double> scratch)
{
    assert(coefficients.size() >= size_t(order * order));
    evaluateSh(order, d, scratch);
    for (int i = 0; i < order * order; ++i)
        coefficients[size_t(i)] += weightedValue * scratch[size_t(i)];
}

} // namespace thespis::core::lighting
