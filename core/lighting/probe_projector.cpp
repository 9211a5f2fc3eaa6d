// The ProbeProjector (probe.h): SH projection of a probe image with exact per-pixel solid angles.
//
// Solid angle of a pixel = the integral of the layout's Jacobian dω/dA over the pixel's footprint:
// - lat-long: Δφ·(cos θ₀ − cos θ₁), closed form;
// - cube face: the signed-area formula Ω = F(a₁,b₁) − F(a₀,b₁) − F(a₁,b₀) + F(a₀,b₀) with
//   F(a,b) = atan2(a·b, √(a²+b²+1)) on the face plane at distance 1, closed form;
// - mirror ball: dω/dA = 4 everywhere on the unit disc (θ = 2·asin r gives sin θ dθ = 4 r dr),
//   so Ω = 4 × area(pixel ∩ disc), closed form through ∫√(1−u²) du;
// - angular map: dω/dA = π·sin(πr)/r, integrated with Gauss–Legendre over pixel ∩ disc, the
//   outer integral split where the disc's edge crosses the pixel so that each piece is smooth.
// A pixel's basis values are taken at its centre, or, for a pixel that the disc's edge cuts, at
// the centroid of its part inside the disc (weighted by dω).

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <thread>

#include "lighting/probe.h"
#include "lighting/probe_layout.h"
#include "util/quadrature.h"

namespace thespis::core::lighting {

namespace {

double cubeAreaTerm(double a, double b) { return std::atan2(a * b, std::sqrt(a * a + b * b + 1.0)); }

// ---- Quadrature over a pixel cut by the unit disc ----------------------------------------------

using GaussRule = GaussLegendreRule;

/// Splits [u0, u1] where the disc's edge meets the lines v = v0, v = v1 and at u = ±1, so that on
/// each piece the clipped v-range has one smooth formula; calls piece(a, b) for each piece with
/// part of the disc.
template <class Piece>
void forEachDiscPiece(double u0, double u1, double v0, double v1, Piece&& piece)
{
    // Unused cuts stay at u0 and make empty pieces.
    std::array<double, 8> cuts{u0, u1, -1.0, 1.0, u0, u0, u0, u0};
    size_t count = 4;
    for (double v : {v0, v1})
        if (std::abs(v) < 1.0)
            for (double sign : {-1.0, 1.0})
                cuts[count++] = sign * std::sqrt(1.0 - v * v);
    std::sort(cuts.begin(), cuts.end());
    for (size_t i = 0; i + 1 < cuts.size(); ++i) {
        const double a = std::max(cuts[i], u0), b = std::min(cuts[i + 1], u1);
        if (!(b > a) || std::abs(0.5 * (a + b)) >= 1.0)
            continue;
        const double s = std::sqrt(1.0 - 0.25 * (a + b) * (a + b));
        if (std::min(v1, s) > std::max(v0, -s))
            piece(a, b);
    }
}
/// ∫∫ f over [u0,u1]×[v0,v1] ∩ unit disc.
template <class F>
double integrateOverDisc(double u0, double u1, double v0, double v1, const GaussRule& rule, F&& f)
{
    double sum = 0;
    forEachDiscPiece(u0, u1, v0, v1, [&](double a, double b) {
        for (size_t i = 0; i < rule.x.size(); ++i) {
            const double u = 0.5 * (a + b) + 0.5 * (b - a) * rule.x[i];
            const double s = std::sqrt(std::max(0.0, 1.0 - u * u));
            const double lo = std::max(v0, -s), hi = std::min(v1, s);
            if (!(hi > lo))
                continue;
            for (size_t j = 0; j < rule.x.size(); ++j) {
                const double v = 0.5 * (lo + hi) + 0.5 * (hi - lo) * rule.x[j];
                sum += 0.25 * (b - a) * (hi - lo) * rule.w[i] * rule.w[j] * f(u, v);
            }
        }
    });
    return sum;
}
/// Exact area of [u0,u1]×[v0,v1] ∩ unit disc.
double discArea(double u0, double u1, double v0, double v1)
{
    const auto arc = [](double u) { return 0.5 * (u * std::sqrt(std::max(0.0, 1.0 - u * u)) + std::asin(u)); };
    double area = 0;
    forEachDiscPiece(u0, u1, v0, v1, [&](double a, double b) {
        const double m = 0.5 * (a + b), s = std::sqrt(1.0 - m * m);
        // On this piece the upper bound is either v1 or √(1−u²), the lower v0 or −√(1−u²).
        area += (v1 < s ? v1 * (b - a) : arc(b) - arc(a)) - (v0 > -s ? v0 * (b - a) : -(arc(b) - arc(a)));
    });
    return area;
}

} // namespace

// ---- ProbeProjector -----------------------------------------------------------------------------

/// Lat-long (separable): on row j every basis function is a trigonometric polynomial of degree
/// ≤ l in φ, Y_i(θ_j, φ) = Σ_k T_j[i][k]·trig_k(φ) with trig = (1, cos φ, sin φ, cos 2φ, …), so a
/// row projects as Fourier sums Σ_x L(x)·trig_k(φ_x) followed by the small matrix Ω_j·T_j. The
/// sums use the columns' symmetry (see foldLatLongRow), so the trig table covers a quarter row.
/// Other layouts (dense): one entry per pixel on the sphere with Ω·Y_i in float, or, above
/// kDenseTableBytes, the pixel's direction and Ω and the basis evaluated while projecting.
struct ProbeProjector::Table {
    int coefficientCount = 0;
    int trigCount = 0;
    double totalSolidAngle = 0;
    // Lat-long
    int quarterCount = 0;          ///< columns of the first quarter row, ⌈W/4⌉ (see foldLatLongRow)
    int quarterStride = 0;         ///< quarterCount rounded up to kLanes, zero-padded
    std::vector<double> trig;      ///< trigCount × quarterStride: trig_k(φ_q) of the first quarter's columns
    std::vector<double> rowMatrix; ///< height × trigCount × coefficientCount, Ω_j folded in
    // Dense layouts
    std::vector<uint32_t> pixelIndex; ///< y·width + x of each entry, in row order
    std::vector<size_t> rowStart;     ///< first entry of each row, height + 1 values
    std::vector<float> weightedBasis; ///< entries × coefficientCount (Ω·Y), empty when too large
    std::vector<double> solidAngle;   ///< per entry
    std::vector<Vec3d> direction;     ///< per entry
    // Both
    std::vector<double> inverseGram; ///< coefficientCount², G⁻¹ with G = Σ Ω·y·yᵀ over the sampled pixels
};

namespace {

constexpr size_t kDenseTableBytes = size_t(256) << 20;
constexpr int kRowsPerChunk = 8; // fixed work unit, so the sum order does not depend on threads
constexpr int kGramRowsPerChunk = 64; // the same for the Gram matrix, whose partial sums are n² each
constexpr double kSingularPivot = 1e-10; // Cholesky pivot / diagonal below which the Gram matrix counts as singular
constexpr int kLanes = 4;        // independent partial sums per dot product (vectorisable, fixed order)

/// The four folds of a lat-long row (see foldLatLongRow), one array per fold and channel.
enum RowFold { CosEven, CosOdd, SinEven, SinOdd, kRowFolds };

// Portable SIMD through the vector extensions of GCC and Clang (SSE2 here, NEON elsewhere).
using Float4 = float __attribute__((vector_size(16)));
using Double2 = double __attribute__((vector_size(16)));
using Double4 = double __attribute__((vector_size(32))); // only to convert a Float4, as two Double2

Float4 loadFloat4(const float* p)
{
    Float4 v;
    std::memcpy(&v, p, sizeof v);
    return v;
}
Double2 loadDouble2(const double* p)
{
    Double2 v;
    std::memcpy(&v, p, sizeof v);
    return v;
}
void store(double* p, double v) { *p = v; }
void store(double* p, Double2 v) { std::memcpy(p, &v, sizeof v); }

/// One channel of 4 consecutive RGB pixels, in pixel order or reversed.
Float4 channelOfPixels4(const float* p, int channel, bool reversed)
{
    // v0 = r0 g0 b0 r1, v1 = g1 b1 r2 g2, v2 = b2 r3 g3 b3. Every shuffle takes two lanes from
    // each operand (one SSE2 shufps): other patterns compile to slow scalar code.
    const Float4 v0 = loadFloat4(p), v1 = loadFloat4(p + 4), v2 = loadFloat4(p + 8);
    switch (channel) {
    case 0: {
        const Float4 r2r2r3r3 = __builtin_shufflevector(v1, v2, 2, 2, 5, 5);
        return reversed ? __builtin_shufflevector(r2r2r3r3, v0, 2, 0, 7, 4) : __builtin_shufflevector(v0, r2r2r3r3, 0, 3, 4, 6);
    }
    case 1: {
        const Float4 g0g0g1g1 = __builtin_shufflevector(v0, v1, 1, 1, 4, 4);
        const Float4 g2g2g3g3 = __builtin_shufflevector(v1, v2, 3, 3, 6, 6);
        return reversed ? __builtin_shufflevector(g2g2g3g3, g0g0g1g1, 2, 0, 6, 4)
                        : __builtin_shufflevector(g0g0g1g1, g2g2g3g3, 0, 2, 4, 6);
    }
    default: {
        const Float4 b0b0b1b1 = __builtin_shufflevector(v0, v1, 2, 2, 5, 5);
        return reversed ? __builtin_shufflevector(v2, b0b0b1b1, 3, 0, 6, 4) : __builtin_shufflevector(b0b0b1b1, v2, 0, 2, 4, 7);
    }
    }
}
/// The two halves of a Float4, in double.
std::array<Double2, 2> toDouble(Float4 v)
{
    const Double4 wide = __builtin_convertvector(v, Double4);
    return {__builtin_shufflevector(wide, wide, 0, 1), __builtin_shufflevector(wide, wide, 2, 3)};
}

/// Stores the four folds of one channel at quarter column q from the values of its columns q
/// (a), W−1−q (b), W/2−1−q (c) and W/2+q (d); T is double or Double2 (columns q, q+1).
template <class T>
void storeFolds(double* fold, int stride, int channel, int q, T a, T b, T c, T d)
{
    const T sum = a + b, difference = a - b, sum2 = c + d, difference2 = c - d;
    const auto at = [&](RowFold which) { return fold + size_t(which * 3 + channel) * size_t(stride) + size_t(q); };
    store(at(CosEven), sum + sum2);
    store(at(CosOdd), sum - sum2);
    store(at(SinEven), difference - difference2);
    store(at(SinOdd), difference + difference2);
}

/// Folds a lat-long row (RGB floats) for its Fourier sums. Column q (angle φ), W−1−q (−φ),
/// W/2−1−q (π−φ) and W/2+q (φ+π) have cos mφ and sin mφ up to signs set by m's parity:
/// with s = L(q)+L(W−1−q), d = L(q)−L(W−1−q) and s′, d′ the same for the other two columns,
/// Σ_x L(x)·cos mφ_x = Σ_q cos mφ_q·(s ± s′) and Σ_x L(x)·sin mφ_x = Σ_q sin mφ_q·(d ∓ d′),
/// upper signs for even m. So each row is four folds on a quarter of the columns, and the
/// multiply-adds drop fourfold. When W/2 is odd, the last quarter column (φ = −π/2) is its own
/// π−φ partner and is folded as a pair alone. Sums of two floats are exact in double, so
/// folding loses nothing. fold holds kRowFolds × 3 arrays of stride doubles; its padding past
/// quarterCount must be zero.
void foldLatLongRow(const float* row, int width, int quarterCount, int stride, double* fold)
{
    const int half = width / 2, fullQuarter = width / 4;
    const auto pixel = [&](int x) { return row + 3 * size_t(x); };
    int q = 0;
    for (; q + 4 <= fullQuarter; q += 4) {
        for (int channel = 0; channel < 3; ++channel) {
            const auto a = toDouble(channelOfPixels4(pixel(q), channel, false));
            const auto b = toDouble(channelOfPixels4(pixel(width - 4 - q), channel, true));
            const auto c = toDouble(channelOfPixels4(pixel(half - 4 - q), channel, true));
            const auto d = toDouble(channelOfPixels4(pixel(half + q), channel, false));
            for (int i = 0; i < 2; ++i)
                storeFolds(fold, stride, channel, q + 2 * i, a[size_t(i)], b[size_t(i)], c[size_t(i)], d[size_t(i)]);
        }
    }
    for (; q < fullQuarter; ++q)
        for (int channel = 0; channel < 3; ++channel)
            storeFolds(fold, stride, channel, q, double(pixel(q)[channel]), double(pixel(width - 1 - q)[channel]),
                       double(pixel(half - 1 - q)[channel]), double(pixel(half + q)[channel]));
    if (quarterCount > fullQuarter)
        for (int channel = 0; channel < 3; ++channel)
            storeFolds(fold, stride, channel, q, double(pixel(q)[channel]), double(pixel(width - 1 - q)[channel]), 0.0, 0.0);
}

/// sums[c·trigCount + k] = Σ_x L_c(x)·trig_k(φ_x) from a folded row, in kLanes partial sums.
void latLongRowSums(const double* fold, const double* trig, int trigCount, int stride, double* sums)
{
    static_assert(kLanes == 4, "two Double2 per sum");
    for (int k = 0; k < trigCount; ++k) {
        const int m = (k + 1) / 2; // k = 0: 1; k = 2m − 1: cos mφ; k = 2m: sin mφ
        const bool cosine = k == 0 || k % 2 == 1;
        const RowFold which = cosine ? (m % 2 == 0 ? CosEven : CosOdd) : (m % 2 == 0 ? SinEven : SinOdd);
        const double* t = trig + size_t(k) * size_t(stride);
        const double* channels = fold + size_t(which * 3) * size_t(stride);
        Double2 lanes[3][2] = {};
        for (int q = 0; q < stride; q += kLanes) {
            const Double2 t0 = loadDouble2(t + q), t1 = loadDouble2(t + q + 2);
            for (int c = 0; c < 3; ++c) {
                lanes[c][0] += t0 * loadDouble2(channels + size_t(c) * size_t(stride) + size_t(q));
                lanes[c][1] += t1 * loadDouble2(channels + size_t(c) * size_t(stride) + size_t(q) + 2);
            }
        }
        for (int c = 0; c < 3; ++c) {
            const Double2 pair = lanes[c][0] + lanes[c][1];
            sums[c * trigCount + k] = pair[0] + pair[1];
        }
    }
}

/// dω/dA on the unit disc: π·sin(πr)/r for the angular map, 4 for the mirror ball.
double discJacobian(ProbeLayout layout, double u, double v)
{
    if (layout == ProbeLayout::MirrorBall)
        return 4.0;
    const double r = std::hypot(u, v);
    return r < 1e-8 ? kPi * kPi : kPi * std::sin(kPi * r) / r;
}

/// Solid angle of the part of the sphere that pixel (x, y) covers (0 off the sphere).
double pixelSolidAngle(ProbeLayout layout, int width, int height, int x, int y, const GaussRule& fine)
{
    switch (layout) {
    case ProbeLayout::LatLong: return 2.0 * kPi / width * (std::cos(kPi * y / height) - std::cos(kPi * (y + 1) / height));
    case ProbeLayout::VerticalCross: {
        const int faceSize = width / 3;
        if (!crossFaceAt(x / faceSize, y / faceSize))
            return 0;
        const double a0 = 2.0 * (x % faceSize) / faceSize - 1.0, a1 = a0 + 2.0 / faceSize;
        const double b0 = 2.0 * (y % faceSize) / faceSize - 1.0, b1 = b0 + 2.0 / faceSize;
        return cubeAreaTerm(a1, b1) - cubeAreaTerm(a0, b1) - cubeAreaTerm(a1, b0) + cubeAreaTerm(a0, b0);
    }
    case ProbeLayout::Angular:
    case ProbeLayout::MirrorBall: {
        const double scale = 2.0 / width;
        const double u0 = x * scale - 1.0, u1 = u0 + scale;
        const double v1 = 1.0 - y * scale, v0 = v1 - scale;
        const auto inside = [](double u, double v) { return u * u + v * v <= 1.0; };
        if (inside(u0, v0) && inside(u0, v1) && inside(u1, v0) && inside(u1, v1)) {
            // Inside the disc the Jacobian is smooth: a 2×2 Gauss rule (exact to degree 3) on a
            // pixel a few thousandths wide is exact to rounding.
            const double centreU = 0.5 * (u0 + u1), centreV = 0.5 * (v0 + v1), offset = 0.5 * scale / std::sqrt(3.0);
            double solidAngle = 0;
            for (double a : {-1.0, 1.0})
                for (double b : {-1.0, 1.0})
                    solidAngle += 0.25 * scale * scale * discJacobian(layout, centreU + a * offset, centreV + b * offset);
            return solidAngle;
        }
        if (layout == ProbeLayout::MirrorBall)
            return 4.0 * discArea(u0, u1, v0, v1);
        return integrateOverDisc(u0, u1, v0, v1, fine, [&](double u, double v) { return discJacobian(layout, u, v); });
    }
    }
    return 0;
}

/// Runs work(chunk) for every chunk of rows on a few threads; false if stopped.
template <class Work>
bool forEachChunk(int chunks, int threads, std::stop_token stop, Work&& work)
{
    std::atomic<int> next{0};
    std::atomic<bool> stopped{false};
    const auto run = [&] {
        for (int chunk = next++; chunk < chunks; chunk = next++) {
            if (stop.stop_requested()) {
                stopped = true;
                return;
            }
            work(chunk);
        }
    };
    {
        std::vector<std::jthread> helpers;
        for (int t = 1; t < threads; ++t)
            helpers.emplace_back(run);
        run();
    }
    return !stopped && !stop.stop_requested();
}

/// gram (n×n, lower triangle) += weight·y·yᵀ.
void addOuterProduct(double* gram, int n, const double* y, double weight)
{
    for (int i = 0; i < n; ++i) {
        const double scaled = weight * y[i];
        double* row = gram + size_t(i) * size_t(n);
        for (int j = 0; j <= i; ++j)
            row[j] += scaled * y[j];
    }
}

/// Replaces the symmetric matrix whose lower triangle is in gram (n×n) by its full inverse,
/// through a Cholesky factor; false when a pivot shows it (numerically) singular: the samples do
/// not pin every basis function down.
bool invertGram(std::vector<double>& gram, int n)
{
    const auto at = [n](std::vector<double>& m, int i, int j) -> double& { return m[size_t(i) * size_t(n) + size_t(j)]; };
    std::vector<double> factor(gram.size(), 0.0); // L, lower, with G = L·Lᵀ
    for (int j = 0; j < n; ++j) {
        double pivot = at(gram, j, j);
        for (int k = 0; k < j; ++k)
            pivot -= at(factor, j, k) * at(factor, j, k);
        if (!(pivot > kSingularPivot * at(gram, j, j)))
            return false;
        at(factor, j, j) = std::sqrt(pivot);
        for (int i = j + 1; i < n; ++i) {
            double value = at(gram, i, j);
            for (int k = 0; k < j; ++k)
                value -= at(factor, i, k) * at(factor, j, k);
            at(factor, i, j) = value / at(factor, j, j);
        }
    }
    // Column c of G⁻¹ solves L·Lᵀ·x = e_c.
    std::vector<double> column(static_cast<size_t>(n));
    for (int c = 0; c < n; ++c) {
        for (int i = 0; i < n; ++i) {
            double value = i == c ? 1.0 : 0.0;
            for (int k = 0; k < i; ++k)
                value -= at(factor, i, k) * column[size_t(k)];
            column[size_t(i)] = value / at(factor, i, i);
        }
        for (int i = n - 1; i >= 0; --i) {
            double value = column[size_t(i)];
            for (int k = i + 1; k < n; ++k)
                value -= at(factor, k, i) * column[size_t(k)];
            column[size_t(i)] = value / at(factor, i, i);
        }
        for (int i = 0; i < n; ++i)
            at(gram, i, c) = column[size_t(i)];
    }
    return true;
}

} // namespace

Result<ProbeProjector> ProbeProjector::create(ProbeLayout layout, int width, int height, int order)
{
    if (order < 1 || order > kMaxShOrder)
        return makeError(ErrorCode::InvalidArgument,
                         "The SH order must be 1 to " + std::to_string(kMaxShOrder) + "; got " + std::to_string(order) + ".");
    if (auto sized = checkSize(layout, width, height); !sized)
        return sized.error();
    // Fewer rows than bands cannot tell the zonal functions apart (nor, then, can the fit).
    if (layout == ProbeLayout::LatLong && height < order)
        return makeError(ErrorCode::InvalidArgument, "A latitude–longitude map of " + std::to_string(width) + "×" + std::to_string(height)
                                                         + " has too few rows for SH order " + std::to_string(order) + "; it needs at least "
                                                         + std::to_string(order) + ".");
    auto table = std::make_shared<Table>();
    const int n = shCoefficientCount(order);
    const size_t nn = size_t(n) * size_t(n);
    table->coefficientCount = n;
    const GaussRule fine = gaussLegendre(16);
    std::vector<double> gram(nn, 0.0); // lower triangle of Σ Ω·y·yᵀ over the sampled pixels
    if (layout == ProbeLayout::LatLong) {
        const int bands = order - 1;
        const int trigCount = 2 * bands + 1;
        table->trigCount = trigCount;
        table->quarterCount = (width / 2 + 1) / 2;
        table->quarterStride = (table->quarterCount + kLanes - 1) / kLanes * kLanes;
        const size_t stride = size_t(table->quarterStride);
        table->trig.assign(size_t(trigCount) * stride, 0.0);
        for (int q = 0; q < table->quarterCount; ++q) {
            const double phi = 2.0 * kPi * ((q + 0.5) / width - 0.5);
            table->trig[size_t(q)] = 1.0;
            for (int m = 1; m <= bands; ++m) {
                table->trig[size_t(2 * m - 1) * stride + size_t(q)] = std::cos(m * phi);
                table->trig[size_t(2 * m) * stride + size_t(q)] = std::sin(m * phi);
            }
        }
        // Fourier coefficients of each basis function along the row, exact from trigCount
        // equally spaced samples (a trigonometric polynomial of degree ≤ bands).
        table->rowMatrix.assign(size_t(height) * size_t(n) * size_t(trigCount), 0.0);
        std::vector<double> basis(static_cast<size_t>(n));
        std::vector<double> trigAtSample(size_t(trigCount), 1.0); // 1, 2·cos φ, 2·sin φ, …: the DFT weights
        for (int y = 0; y < height; ++y) {
            const double theta = kPi * (y + 0.5) / height;
            const double rowSolidAngle = pixelSolidAngle(layout, width, height, 0, y, fine);
            table->totalSolidAngle += rowSolidAngle * width;
            double* matrix = table->rowMatrix.data() + size_t(y) * size_t(n) * size_t(trigCount);
            for (int s = 0; s < trigCount; ++s) {
                const double phi = 2.0 * kPi * s / trigCount;
                evaluateSh(order, Vec3d{std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi)}, basis);
                for (int m = 1; m <= bands; ++m) {
                    trigAtSample[size_t(2 * m - 1)] = 2.0 * std::cos(m * phi);
                    trigAtSample[size_t(2 * m)] = 2.0 * std::sin(m * phi);
                }
                for (int k = 0; k < trigCount; ++k)
                    for (int i = 0; i < n; ++i)
                        matrix[size_t(k) * size_t(n) + size_t(i)] += basis[size_t(i)] * rowSolidAngle / trigCount * trigAtSample[size_t(k)];
            }
            // Row k of the matrix is Ω·a_k, a_k the Fourier coefficients of trig_k; over the W
            // equally spaced columns Σ_x trig_k·trig_k′ = W·δ_kk′ (½·W for k > 0), exactly, since
            // every product has degree ≤ 2·bands < W.
            for (int k = 0; k < trigCount; ++k)
                addOuterProduct(gram.data(), n, matrix + size_t(k) * size_t(n), (k == 0 ? 1.0 : 0.5) * width / rowSolidAngle);
        }
    } else {
        table->rowStart.assign(size_t(height) + 1, 0);
        for (int y = 0; y < height; ++y) {
            table->rowStart[size_t(y)] = table->pixelIndex.size();
            for (int x = 0; x < width; ++x) {
                const double solidAngle = pixelSolidAngle(layout, width, height, x, y, fine);
                table->totalSolidAngle += solidAngle;
                Vec3d direction;
                if (!(solidAngle > 0) || !directionOfPixel(layout, width, height, x, y, direction))
                    continue;
                table->pixelIndex.push_back(uint32_t(size_t(y) * size_t(width) + size_t(x)));
                table->solidAngle.push_back(solidAngle);
                table->direction.push_back(direction);
            }
        }
        table->rowStart[size_t(height)] = table->pixelIndex.size();
        const size_t entries = table->pixelIndex.size();
        if (entries * size_t(n) * sizeof(float) <= kDenseTableBytes)
            table->weightedBasis.resize(entries * size_t(n));
        // Σ Ω·y·yᵀ costs n²/2 multiply-adds a pixel (a second at order 11 on a 1000² mirror
        // ball): threads take chunks of rows, each its own partial sum, added in chunk order.
        const int chunks = (height + kGramRowsPerChunk - 1) / kGramRowsPerChunk;
        std::vector<double> partialGram(size_t(chunks) * nn, 0.0);
        const int threads = std::min(chunks, int(std::max(1u, std::thread::hardware_concurrency())));
        forEachChunk(chunks, threads, {}, [&](int chunk) {
            std::array<double, kMaxShCoefficients> basis{};
            const size_t first = table->rowStart[size_t(chunk * kGramRowsPerChunk)];
            const size_t last = table->rowStart[size_t(std::min(height, (chunk + 1) * kGramRowsPerChunk))];
            double* partial = partialGram.data() + size_t(chunk) * nn;
            for (size_t e = first; e < last; ++e) {
                evaluateSh(order, table->direction[e], basis);
                if (!table->weightedBasis.empty())
                    for (int i = 0; i < n; ++i)
                        table->weightedBasis[e * size_t(n) + size_t(i)] = float(basis[size_t(i)] * table->solidAngle[e]);
                addOuterProduct(partial, n, basis.data(), table->solidAngle[e]);
            }
        });
        for (int chunk = 0; chunk < chunks; ++chunk)
            for (size_t i = 0; i < nn; ++i)
                gram[i] += partialGram[size_t(chunk) * nn + i];
    }
    if (!invertGram(gram, n))
        return makeError(ErrorCode::InvalidArgument, "A " + std::to_string(width) + "×" + std::to_string(height) + " "
                                                         + probeLayoutName(layout) + " map samples the sphere too coarsely for SH order "
                                                         + std::to_string(order) + "; use a larger map or a lower order.");
    table->inverseGram = std::move(gram);
    ProbeProjector projector;
    projector.m_layout = layout;
    projector.m_width = width;
    projector.m_height = height;
    projector.m_order = order;
    projector.m_table = std::move(table);
    return projector;
}

double ProbeProjector::totalSolidAngle() const { return m_table->totalSolidAngle; }

Result<ShRgb> ProbeProjector::project(const HdrImage& image, std::stop_token stop, int threads) const
{
    if (image.width != m_width || image.height != m_height || image.rgb.size() != size_t(m_width) * size_t(m_height) * 3)
        return makeError(ErrorCode::InvalidArgument,
                         "The probe image is " + std::to_string(image.width) + "×" + std::to_string(image.height)
                             + " but the projector was made for " + std::to_string(m_width) + "×" + std::to_string(m_height) + ".");
    const Table& table = *m_table;
    const int n = table.coefficientCount;
    const size_t stride = 3 * size_t(n);
    const int chunks = (m_height + kRowsPerChunk - 1) / kRowsPerChunk;
    std::vector<double> partial(size_t(chunks) * stride, 0.0);
    if (threads <= 0)
        threads = int(std::max(1u, std::thread::hardware_concurrency()));
    threads = std::min(threads, chunks);

    const auto projectLatLongChunk = [&](int chunk) {
        const int k = table.trigCount;
        double* out = partial.data() + size_t(chunk) * stride;
        std::vector<double> sums(3 * size_t(k));
        std::vector<double> fold(size_t(kRowFolds) * 3 * size_t(table.quarterStride), 0.0);
        for (int y = chunk * kRowsPerChunk; y < std::min(m_height, (chunk + 1) * kRowsPerChunk); ++y) {
            foldLatLongRow(image.rgb.data() + size_t(y) * size_t(m_width) * 3, m_width, table.quarterCount,
                           table.quarterStride, fold.data());
            latLongRowSums(fold.data(), table.trig.data(), k, table.quarterStride, sums.data());
            // Column by column, so that the coefficients are independent multiply-adds.
            const double* matrix = table.rowMatrix.data() + size_t(y) * size_t(k) * size_t(n);
            for (int c = 0; c < 3; ++c)
                for (int j = 0; j < k; ++j) {
                    const double* column = matrix + size_t(j) * size_t(n);
                    const double sum = sums[size_t(c) * size_t(k) + size_t(j)];
                    double* coefficients = out + size_t(c) * size_t(n);
                    for (int i = 0; i < n; ++i)
                        coefficients[i] += column[i] * sum;
                }
        }
    };
    const auto projectDenseChunk = [&](int chunk) {
        double* out = partial.data() + size_t(chunk) * stride;
        double* outR = out;
        double* outG = out + n;
        double* outB = out + 2 * n;
        std::array<double, kMaxShCoefficients> basis{};
        const size_t first = table.rowStart[size_t(chunk * kRowsPerChunk)];
        const size_t last = table.rowStart[size_t(std::min(m_height, (chunk + 1) * kRowsPerChunk))];
        for (size_t e = first; e < last; ++e) {
            const float* pixel = image.rgb.data() + 3 * size_t(table.pixelIndex[e]);
            const double r = pixel[0], g = pixel[1], b = pixel[2];
            if (!table.weightedBasis.empty()) {
                const float* w = table.weightedBasis.data() + e * size_t(n);
                for (int i = 0; i < n; ++i) {
                    outR[i] += r * w[i];
                    outG[i] += g * w[i];
                    outB[i] += b * w[i];
                }
            } else {
                evaluateSh(m_order, table.direction[e], basis);
                const double solidAngle = table.solidAngle[e];
                for (int i = 0; i < n; ++i) {
                    const double w = basis[size_t(i)] * solidAngle;
                    outR[i] += r * w;
                    outG[i] += g * w;
                    outB[i] += b * w;
                }
            }
        }
    };
    const bool finished = m_layout == ProbeLayout::LatLong ? forEachChunk(chunks, threads, stop, projectLatLongChunk)
                                                           : forEachChunk(chunks, threads, stop, projectDenseChunk);
    if (!finished)
        return makeError(ErrorCode::Cancelled, "The probe projection was cancelled.");
    std::array<std::array<double, kMaxShCoefficients>, 3> sums{};
    for (int chunk = 0; chunk < chunks; ++chunk)
        for (int c = 0; c < 3; ++c)
            for (int i = 0; i < n; ++i)
                sums[size_t(c)][size_t(i)] += partial[size_t(chunk) * stride + size_t(c) * size_t(n) + size_t(i)];
    ShRgb result;
    result.order = m_order;
    for (int c = 0; c < 3; ++c)
        for (int i = 0; i < n; ++i) {
            const double* row = table.inverseGram.data() + size_t(i) * size_t(n);
            double value = 0;
            for (int j = 0; j < n; ++j)
                value += row[j] * sums[size_t(c)][size_t(j)];
            result.channel[size_t(c)][size_t(i)] = value;
        }
    return result;
}

} // namespace thespis::core::lighting
