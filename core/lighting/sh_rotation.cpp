#include "lighting/sh_rotation.h"

#include <atomic>
#include <cassert>
#include <cstdint>
#include <cstring>
#include <utility>

#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace thespis::core::lighting {

namespace {

// Ivanic & Ruedenberg's recursion, with the 1998 errata (the V term for m < 0 uses
// P(1, m+1)·(1−δ(m,−1)) + P(−1, −m−1)·√(1+δ(m,−1))):
//   Rˡₘₙ = uₘₙ·Uₘₙ + vₘₙ·Vₘₙ + wₘₙ·Wₘₙ
// where u, v, w share the factor 1/√((l+n)(l−n)) (1/√(2l(2l−1)) when |n| = l), so they split
// into a row factor that depends on (l, m) and a column factor that depends on (l, n). U, V, W
// are sums of P(i, a, n) terms, each reading band 1 at row i and band l−1 at row a:
//   P(i, a, n) = r¹ᵢ₀·Rˡ⁻¹ₐₙ                                   for |n| < l
//   P(i, a, l) = r¹ᵢ₁·Rˡ⁻¹ₐ,ₗ₋₁ − r¹ᵢ,₋₁·Rˡ⁻¹ₐ,₋ₗ₊₁
//   P(i, a, −l) = r¹ᵢ₁·Rˡ⁻¹ₐ,₋ₗ₊₁ + r¹ᵢ,₋₁·Rˡ⁻¹ₐ,ₗ₋₁
// So row m of band l is a short linear combination (at most five terms) of rows of band l−1,
// scaled per column. The terms depend only on (l, m): they are tabulated once, at compile time.

struct RowTerm {
    int8_t band1Row = 0;   ///< i ∈ {−1, 0, 1}
    int8_t previousRow = 0; ///< a ∈ [−(l−1), l−1]
    double factor = 0;     ///< u, v or w without the column factor, times the δ factors
};

constexpr int kMaxBand = kMaxShOrder - 1;
constexpr int kMaxTermsPerRow = 5;

struct BandRecursion {
    int termCount[2 * kMaxBand + 1]{};                   ///< per row m + l
    RowTerm terms[2 * kMaxBand + 1][kMaxTermsPerRow]{};
    double interiorColumnFactor[2 * kMaxBand - 1]{};     ///< 1/√((l+n)(l−n)), n = −(l−1) … l−1
    double edgeColumnFactor = 0;                          ///< 1/√(2l(2l−1)), n = ±l
};

constexpr BandRecursion makeBandRecursion(int l)
{
    using detail::constexprSqrt;
    BandRecursion band;
    if (l < 2)
        return band;
    for (int m = -l; m <= l; ++m) {
        const int am = m < 0 ? -m : m;
        const long double delta = m == 0 ? 1 : 0;
        const long double u = constexprSqrt((long double)(l + m) * (l - m));
        const long double v = 0.5L * constexprSqrt((1 + delta) * (l + am - 1) * (l + am)) * (1 - 2 * delta);
        const long double w = -0.5L * constexprSqrt((long double)(l - am - 1) * (l - am)) * (1 - delta);
        const long double sqrt2 = constexprSqrt(2.0L);
        int count = 0;
        const auto add = [&](int i, int a, long double factor) {
            if (factor != 0)
                band.terms[m + l][count++] = {int8_t(i), int8_t(a), double(factor)};
        };
        add(0, m, u); // U = P(0, m, n)
        if (m == 0) { // V
            add(1, 1, v);
            add(-1, -1, v);
        } else if (m > 0) {
            add(1, m - 1, v * (m == 1 ? sqrt2 : 1));
            add(-1, -m + 1, m == 1 ? 0 : -v);
        } else {
            add(1, m + 1, m == -1 ? 0 : v);
            add(-1, -m - 1, v * (m == -1 ? sqrt2 : 1));
        }
        if (m > 0) { // W (w is zero for m = 0 and |m| ≥ l−1)
            add(1, m + 1, w);
            add(-1, -m - 1, w);
        } else if (m < 0) {
            add(1, m - 1, w);
            add(-1, -m + 1, -w);
        }
        band.termCount[m + l] = count;
    }
    for (int n = -(l - 1); n <= l - 1; ++n)
        band.interiorColumnFactor[n + l - 1] = double(1 / constexprSqrt((long double)(l + n) * (l - n)));
    band.edgeColumnFactor = double(1 / constexprSqrt(2.0L * l * (2 * l - 1)));
    return band;
}

constexpr auto kRecursion = [] {
    std::array<BandRecursion, kMaxShOrder> bands{};
    for (int l = 2; l < kMaxShOrder; ++l)
        bands[size_t(l)] = makeBandRecursion(l);
    return bands;
}();

constexpr int bandOffset(int l)
{
    int offset = 0;
    for (int k = 0; k < l; ++k)
        offset += (2 * k + 1) * (2 * k + 1);
    return offset;
}

constexpr auto kBandOffsets = [] {
    std::array<int, kMaxShOrder + 1> offsets{};
    for (int l = 0; l <= kMaxShOrder; ++l)
        offsets[size_t(l)] = bandOffset(l);
    return offsets;
}();

// Two doubles in one SSE2 register (GCC/Clang vector extension; plain code on other targets).
// The project builds without -march, so this is the widest vector every x86-64 has.
using Double2 = double __attribute__((vector_size(16)));

inline Double2 load2(const double* p)
{
    Double2 v;
    std::memcpy(&v, p, sizeof v);
    return v;
}

inline void store2(double* p, Double2 v) { std::memcpy(p, &v, sizeof v); }

/// What every row of band L reads, prepared once per band: band 1's middle column (the factor
/// of every interior P) and, for each band-1 row i and previous row a, the two edge values
/// (P(i, a, −l), P(i, a, l)), which the terms of several rows share.
template <int L>
struct BandInputs {
    const double* previous;    ///< band L−1, (2L−1)² row-major
    Double2 centre[3];         ///< (r¹ᵢ₀, r¹ᵢ₀) for i = −1, 0, 1
    Double2 edges[3][2 * L - 1]; ///< [i + 1][a + L − 1] = (P(i, a, −L), P(i, a, L))

    BandInputs(const double* band1, const double* previousBand) : previous(previousBand)
    {
        constexpr int previousSize = 2 * L - 1;
        for (int i = 0; i < 3; ++i)
            centre[i] = Double2{band1[3 * i + 1], band1[3 * i + 1]};
        for (int a = 0; a < previousSize; ++a) {
            const double first = previous[previousSize * a], last = previous[previousSize * a + previousSize - 1];
            const Double2 firstLast = {first, last}, lastMinusFirst = {last, -first};
            for (int i = 0; i < 3; ++i) {
                const double positive = band1[3 * i + 2], negative = band1[3 * i];
                edges[i][a] = Double2{positive, positive} * firstLast + Double2{negative, negative} * lastMinusFirst;
            }
        }
    }
};

/// Adds term K of row Row of band L to the row's interior columns and its two edge columns.
template <int L, int Row, int K>
inline void addRowTerm(const BandInputs<L>& inputs, Double2* interior, double& interiorLast, Double2& edges)
{
    constexpr int previousSize = 2 * L - 1;
    constexpr RowTerm term = kRecursion[L].terms[Row][K];
    constexpr Double2 factor = {term.factor, term.factor};
    const double* previousRow = inputs.previous + previousSize * (term.previousRow + L - 1);
    const Double2 scale = factor * inputs.centre[term.band1Row + 1];
    for (int j = 0; j < L - 1; ++j)
        interior[j] += scale * load2(previousRow + 2 * j);
    interiorLast += scale[0] * previousRow[previousSize - 1];
    edges += factor * inputs.edges[term.band1Row + 1][term.previousRow + L - 1];
}

/// Row Row of band L. Everything the recursion needs besides the two matrices is a
/// compile-time constant here.
template <int L, int Row, int... K>
inline void buildRow(const BandInputs<L>& inputs, double* __restrict out, std::integer_sequence<int, K...>)
{
    constexpr int size = 2 * L + 1, previousSize = 2 * L - 1;
    constexpr const BandRecursion& table = kRecursion[L];
    Double2 interior[L - 1] = {};
    double interiorLast = 0;
    Double2 edges = {};
    (addRowTerm<L, Row, K>(inputs, interior, interiorLast, edges), ...);
    double* outRow = out + size * Row;
    outRow[0] = table.edgeColumnFactor * edges[0];
    for (int j = 0; j < L - 1; ++j)
        store2(outRow + 1 + 2 * j, load2(table.interiorColumnFactor + 2 * j) * interior[j]);
    outRow[previousSize] = table.interiorColumnFactor[previousSize - 1] * interiorLast;
    outRow[size - 1] = table.edgeColumnFactor * edges[1];
}

template <int L, int... Row>
inline void buildRows(const BandInputs<L>& inputs, double* __restrict out, std::integer_sequence<int, Row...>)
{
    (buildRow<L, Row>(inputs, out, std::make_integer_sequence<int, kRecursion[L].termCount[Row]>{}), ...);
}

/// Band L from band L−1 (`previous`) and band 1 (`band1`, 3×3, rows/cols m = −1…1); `out`
/// overlaps neither.
template <int L>
void buildBand(const double* band1, const double* previous, double* __restrict out)
{
    const BandInputs<L> inputs(band1, previous);
    buildRows<L>(inputs, out, std::make_integer_sequence<int, 2 * L + 1>{});
}

template <int... L>
void buildBands(int order, const double* band1, double* bands, std::integer_sequence<int, L...>)
{
    // Bands 2 … order−1 in sequence, each from the one before.
    (void)((L + 2 < order ? (buildBand<L + 2>(band1, bands + kBandOffsets[L + 1], bands + kBandOffsets[L + 2]), true)
                          : false) &&
           ...);
}

/// Each channel's coefficient 0, by value so the compiler knows stores cannot change them.
template <class T, int Channels>
using ChannelPointers = std::array<T*, Channels>;

/// out[c] = M·in[c] for band L and Channels channels; M is (2L+1)² row-major and in[c], out[c]
/// point at a channel's coefficient 0. Two rows at a time: each pair of matrix elements is
/// loaded once and used for every channel, and the two rows' partial sums reduce into one pair
/// of outputs.
template <int L, int Channels>
inline void applyBand(const double* matrix, ChannelPointers<const double, Channels> in,
                      ChannelPointers<double, Channels> out)
{
    constexpr int size = 2 * L + 1, first = L * L;
    constexpr int last = size - 1; // the odd column and the odd row
    for (int row = 0; row + 1 < size; row += 2) {
        const double* upper = matrix + size * row;
        const double* lower = upper + size;
        Double2 sumUpper[Channels] = {}, sumLower[Channels] = {};
        for (int column = 0; column < last; column += 2) {
            const Double2 a = load2(upper + column), b = load2(lower + column);
            for (int c = 0; c < Channels; ++c) {
                const Double2 x = load2(in[c] + first + column);
                sumUpper[c] += a * x;
                sumLower[c] += b * x;
            }
        }
        const Double2 lastColumn = {upper[last], lower[last]};
        for (int c = 0; c < Channels; ++c) {
            const Double2 lows = __builtin_shufflevector(sumUpper[c], sumLower[c], 0, 2);
            const Double2 highs = __builtin_shufflevector(sumUpper[c], sumLower[c], 1, 3);
            const double x = in[c][first + last];
            store2(out[c] + first + row, lows + highs + lastColumn * Double2{x, x});
        }
    }
    const double* bottom = matrix + size * last;
    Double2 sum[Channels] = {};
    for (int column = 0; column < last; column += 2) {
        const Double2 a = load2(bottom + column);
        for (int c = 0; c < Channels; ++c)
            sum[c] += a * load2(in[c] + first + column);
    }
    for (int c = 0; c < Channels; ++c)
        out[c][first + last] = sum[c][0] + sum[c][1] + bottom[last] * in[c][first + last];
}

template <int Channels, int... L>
void applyBands(int order, const double* bands, ChannelPointers<const double, Channels> in,
                ChannelPointers<double, Channels> out, std::integer_sequence<int, L...>)
{
    (void)((L < order ? (applyBand<L, Channels>(bands + kBandOffsets[L], in, out), true) : false) && ...);
}

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define THESPIS_SH_AVX2 1

/// Adds columns `column` … `column + 3` of rows `row` … `row + Rows − 1` to their sums; with
/// Masked, only the lanes of `mask` are read.
template <int L, int Channels, int Rows, bool Masked>
__attribute__((target("avx2,fma"))) inline void accumulateChunkAvx2(const double* matrix, int row, int column,
                                                                     __m256i mask,
                                                                     ChannelPointers<const double, Channels> in,
                                                                     __m256d (&sum)[Rows][Channels])
{
    constexpr int size = 2 * L + 1, first = L * L;
    __m256d x[Channels];
    for (int c = 0; c < Channels; ++c)
        x[c] = Masked ? _mm256_maskload_pd(in[c] + first + column, mask) : _mm256_loadu_pd(in[c] + first + column);
    for (int r = 0; r < Rows; ++r) {
        const double* p = matrix + size * (row + r) + column;
        const __m256d a = Masked ? _mm256_maskload_pd(p, mask) : _mm256_loadu_pd(p);
        for (int c = 0; c < Channels; ++c)
            sum[r][c] = _mm256_fmadd_pd(a, x[c], sum[r][c]);
    }
}

/// Rows `row` … `row + Rows − 1` of band L (Rows = 1, 2 or 4): one multiply-add per matrix
/// element and channel, then each row's four partial sums reduce into one output.
template <int L, int Channels, int Rows>
__attribute__((target("avx2,fma"))) inline void applyRowsAvx2(const double* matrix, int row,
                                                               ChannelPointers<const double, Channels> in,
                                                               ChannelPointers<double, Channels> out)
{
    constexpr int size = 2 * L + 1, fullChunks = size / 4, tail = size % 4;
    __m256d sum[Rows][Channels];
    for (int r = 0; r < Rows; ++r)
        for (int c = 0; c < Channels; ++c)
            sum[r][c] = _mm256_setzero_pd();
    const __m256i mask = _mm256_setr_epi64x(-1, tail > 1 ? -1 : 0, tail > 2 ? -1 : 0, 0);
    for (int k = 0; k < fullChunks; ++k)
        accumulateChunkAvx2<L, Channels, Rows, false>(matrix, row, 4 * k, mask, in, sum);
    if constexpr (tail > 0)
        accumulateChunkAvx2<L, Channels, Rows, true>(matrix, row, 4 * fullChunks, mask, in, sum);
    for (int c = 0; c < Channels; ++c) {
        double* target = out[c] + L * L + row;
        if constexpr (Rows == 4) {
            const __m256d h01 = _mm256_hadd_pd(sum[0][c], sum[1][c]); // (r0, r1) partial sums, twice
            const __m256d h23 = _mm256_hadd_pd(sum[2][c], sum[3][c]);
            _mm256_storeu_pd(target, _mm256_add_pd(_mm256_permute2f128_pd(h01, h23, 0x20),
                                                   _mm256_permute2f128_pd(h01, h23, 0x31)));
        } else {
            const __m256d h = _mm256_hadd_pd(sum[0][c], sum[Rows - 1][c]);
            const __m128d sums = _mm_add_pd(_mm256_castpd256_pd128(h), _mm256_extractf128_pd(h, 1));
            if constexpr (Rows == 2)
                _mm_storeu_pd(target, sums);
            else
                *target = _mm_cvtsd_f64(sums);
        }
    }
}

/// The same product as applyBand with AVX2 and FMA, four columns at a time, for the processors
/// that have them (chosen at run time: the project is built for baseline x86-64). The odd tail
/// of each row is a masked load, so nothing outside the band is read.
template <int L, int Channels>
__attribute__((target("avx2,fma"))) inline void applyBandAvx2(const double* matrix,
                                                               ChannelPointers<const double, Channels> in,
                                                               ChannelPointers<double, Channels> out)
{
    constexpr int size = 2 * L + 1;
    int row = 0;
    for (; row + 4 <= size; row += 4)
        applyRowsAvx2<L, Channels, 4>(matrix, row, in, out);
    if constexpr (size % 4 == 3) {
        applyRowsAvx2<L, Channels, 2>(matrix, row, in, out);
        row += 2;
    }
    applyRowsAvx2<L, Channels, 1>(matrix, row, in, out);
}

template <int Channels, int... L>
__attribute__((target("avx2,fma"))) void applyBandsAvx2(int order, const double* bands,
                                                         ChannelPointers<const double, Channels> in,
                                                         ChannelPointers<double, Channels> out,
                                                         std::integer_sequence<int, L...>)
{
    (void)((L < order ? (applyBandAvx2<L, Channels>(bands + kBandOffsets[L], in, out), true) : false) && ...);
}

bool hasAvx2AndFma()
{
    static const bool supported = [] {
        __builtin_cpu_init();
        return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
    }();
    return supported;
}
#endif

std::atomic<bool> gBaselineForced{false};

template <int Channels>
void applyAllBands(int order, const double* bands, ChannelPointers<const double, Channels> in,
                   ChannelPointers<double, Channels> out)
{
#ifdef THESPIS_SH_AVX2
    if (hasAvx2AndFma() && !gBaselineForced.load(std::memory_order_relaxed))
        return applyBandsAvx2<Channels>(order, bands, in, out, std::make_integer_sequence<int, kMaxShOrder>{});
#endif
    applyBands<Channels>(order, bands, in, out, std::make_integer_sequence<int, kMaxShOrder>{});
}

} // namespace

namespace detail {
bool shRotationUsesAvx2()
{
#ifdef THESPIS_SH_AVX2
    return hasAvx2AndFma() && !gBaselineForced.load(std::memory_order_relaxed);
#else
    return false;
#endif
}

void forceShRotationBaseline(bool force) { gBaselineForced.store(force, std::memory_order_relaxed); }
} // namespace detail

Matrix3d rotationMatrix(const Quatd& q)
{
    const double xx = q.x * q.x, yy = q.y * q.y, zz = q.z * q.z;
    const double xy = q.x * q.y, xz = q.x * q.z, yz = q.y * q.z;
    const double wx = q.w * q.x, wy = q.w * q.y, wz = q.w * q.z;
    return {1 - 2 * (yy + zz), 2 * (xy - wz),     2 * (xz + wy),
            2 * (xy + wz),     1 - 2 * (xx + zz), 2 * (yz - wx),
            2 * (xz - wy),     2 * (yz + wx),     1 - 2 * (xx + yy)};
}

void ShRotation::build(int order, const Matrix3d& rotation)
{
    assert(order >= 1 && order <= kMaxShOrder);
    m_order = order;
    m_bands[0] = 1;
    if (order < 2)
        return;
    // Band 1 is the rotation itself with rows and columns in the SH order (y, z, x).
    constexpr int axis[3] = {1, 2, 0};
    double* band1 = m_bands.data() + 1;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            band1[3 * i + j] = rotation[size_t(3 * axis[i] + axis[j])];
    buildBands(order, band1, m_bands.data(), std::make_integer_sequence<int, kMaxShOrder - 2>{});
}

std::span<const double> ShRotation::band(int l) const
{
    assert(l >= 0 && l < m_order);
    return {m_bands.data() + kBandOffsets[size_t(l)], size_t((2 * l + 1) * (2 * l + 1))};
}

void ShRotation::apply(std::span<const double> in, std::span<double> out) const
{
    assert(in.size() >= size_t(m_order * m_order) && out.size() >= size_t(m_order * m_order));
    applyAllBands<1>(m_order, m_bands.data(), {in.data()}, {out.data()});
}

void ShRotation::apply(std::span<const float> in, std::span<float> out) const
{
    // The matrix is double: widen once, rotate in double, narrow once.
    assert(in.size() >= size_t(m_order * m_order) && out.size() >= size_t(m_order * m_order));
    const int n = m_order * m_order;
    double wide[kMaxShCoefficients], rotated[kMaxShCoefficients];
    for (int i = 0; i < n; ++i)
        wide[i] = in[size_t(i)];
    apply({wide, size_t(n)}, {rotated, size_t(n)});
    for (int i = 0; i < n; ++i)
        out[size_t(i)] = float(rotated[i]);
}

void ShRotation::applyRgb(const ShRgb& in, ShRgb& out) const
{
    assert(in.order >= m_order && &in != &out);
    out.order = m_order;
    applyAllBands<3>(m_order, m_bands.data(), {in.channel[0].data(), in.channel[1].data(), in.channel[2].data()},
                     {out.channel[0].data(), out.channel[1].data(), out.channel[2].data()});
}

} // namespace thespis::core::lighting
