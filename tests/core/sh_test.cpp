// Spherical harmonics: basis, kernels and irradiance (sh.h), rotation (sh_rotation.h).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <span>
#include <vector>

#include "allocation_counter.h"
#include "lighting/sh.h"
#include "lighting/sh_rotation.h"
#include "util/quadrature.h"

using namespace thespis::core::lighting;
using thespis::core::anim::Quatd;

namespace {

constexpr double kPi = std::numbers::pi;

Vec3d normalized(Vec3d v)
{
    const double n = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    return {v.x / n, v.y / n, v.z / n};
}

/// Uniform random directions plus the poles and axes, where the recurrences have edge cases.
std::vector<Vec3d> testDirections(int randomCount, unsigned seed = 7)
{
    std::vector<Vec3d> directions = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0},
                                     normalized({1, 1, 1}), normalized({1e-9, -2e-9, 1})};
    std::mt19937 rng(seed);
    std::normal_distribution<double> gaussian;
    for (int i = 0; i < randomCount; ++i)
        directions.push_back(normalized({gaussian(rng), gaussian(rng), gaussian(rng)}));
    return directions;
}

struct QuadratureNode {
    Vec3d direction;
    double weight;
};

/// Product rule exact for polynomials of degree < 2·order on the sphere: Gauss–Legendre in
/// z = cos θ (order + 1 nodes) times a uniform grid in φ (2·order + 2 nodes).
std::vector<QuadratureNode> sphereQuadrature(int order)
{
    const int zCount = order + 1, phiCount = 2 * order + 2;
    std::vector<QuadratureNode> nodes;
    const auto rule = thespis::core::gaussLegendre(zCount);
    for (int i = 0; i < zCount; ++i) {
        const double z = rule.x[size_t(i)], zWeight = rule.w[size_t(i)];
        const double s = std::sqrt(1 - z * z);
        for (int j = 0; j < phiCount; ++j) {
            const double phi = 2 * kPi * (j + 0.5) / phiCount;
            nodes.push_back({{s * std::cos(phi), s * std::sin(phi), z}, zWeight * 2 * kPi / phiCount});
        }
    }
    return nodes;
}

} // namespace

TEST(ShBasis, FastEvaluationMatchesLegendreDefinitionToBand10)
{
    std::vector<double> fast(kMaxShCoefficients);
    for (int order = 1; order <= kMaxShOrder; ++order) {
        for (const Vec3d& d : testDirections(200)) {
            evaluateSh(order, d, fast);
            for (int l = 0; l < order; ++l)
                for (int m = -l; m <= l; ++m)
                    ASSERT_NEAR(fast[size_t(shIndex(l, m))], evaluateShReference(l, m, d), 1e-12)
                        << "order " << order << " l " << l << " m " << m << " at (" << d.x << ", " << d.y
                        << ", " << d.z << ")";
        }
    }
}

TEST(ShBasis, FloatEvaluationMatchesDouble)
{
    std::vector<double> expected(kMaxShCoefficients);
    std::vector<float> actual(kMaxShCoefficients);
    for (int order : {1, 2, 3, 4, 5, 8, 11}) {
        for (const Vec3d& d : testDirections(50)) {
            evaluateSh(order, d, expected);
            evaluateSh(order, Vec3{float(d.x), float(d.y), float(d.z)}, actual);
            for (int i = 0; i < order * order; ++i)
                ASSERT_NEAR(actual[size_t(i)], expected[size_t(i)], 2e-5) << "order " << order << " i " << i;
        }
    }
}

// The bake's batched kernel: the sums of evaluateSh over the directions (in double, the kernel
// sums in float), for every order and for counts that leave 0–3 directions after the groups of
// four; the same input gives the same bits, and it adds to what `sums` held.
TEST(ShBasis, AccumulatedSumsMatchPerDirectionEvaluation)
{
    const std::vector<Vec3d> directions = testDirections(200);
    std::vector<float> x, y, z;
    for (const Vec3d& d : directions) {
        x.push_back(float(d.x));
        y.push_back(float(d.y));
        z.push_back(float(d.z));
    }
    std::vector<float> basis(kMaxShCoefficients);
    for (int order = 1; order <= kMaxShOrder; ++order) {
        for (std::size_t count : {std::size_t(0), std::size_t(1), std::size_t(2), std::size_t(3), std::size_t(4),
                                  std::size_t(7), std::size_t(9), directions.size()}) {
            std::vector<double> expected(kMaxShCoefficients, 0.5);
            for (std::size_t k = 0; k < count; ++k) {
                evaluateSh(order, Vec3{x[k], y[k], z[k]}, basis);
                for (int i = 0; i < order * order; ++i)
                    expected[size_t(i)] += basis[size_t(i)];
            }
            std::vector<float> sums(kMaxShCoefficients, 0.5f), again(kMaxShCoefficients, 0.5f);
            const auto first = [&](const std::vector<float>& v) { return std::span(v).first(count); };
            accumulateShSums(order, first(x), first(y), first(z), sums);
            accumulateShSums(order, first(x), first(y), first(z), again);
            EXPECT_EQ(sums, again) << "order " << order << " count " << count;
            for (int i = 0; i < order * order; ++i)
                ASSERT_NEAR(sums[size_t(i)], expected[size_t(i)], 1e-5 * double(count + 1))
                    << "order " << order << " count " << count << " i " << i;
            for (int i = order * order; i < kMaxShCoefficients; ++i)
                ASSERT_EQ(sums[size_t(i)], 0.5f) << "coefficients beyond order² are left alone";
        }
    }
}

// REFERENCE_SH.md §1 (prefilter.c): the 9 basis functions with their 6-digit constants.
TEST(ShBasis, MatchesRamamoorthiHanrahanTable)
{
    std::vector<double> y(9);
    for (const Vec3d& d : testDirections(50)) {
        evaluateSh(3, d, y);
        const double expected[9] = {0.282095,
                                    0.488603 * d.y,
                                    0.488603 * d.z,
                                    0.488603 * d.x,
                                    1.092548 * d.x * d.y,
                                    1.092548 * d.y * d.z,
                                    0.315392 * (3 * d.z * d.z - 1),
                                    1.092548 * d.x * d.z,
                                    0.546274 * (d.x * d.x - d.y * d.y)};
        for (int i = 0; i < 9; ++i)
            EXPECT_NEAR(y[size_t(i)], expected[i], 1.5e-6) << "index " << i;
    }
    // Full precision, not the rounded table: Y₀₀ = 1/(2√π), Y₁₀ = √(3/4π) at the pole.
    evaluateSh(3, Vec3d{0, 0, 1}, y);
    EXPECT_EQ(y[0], 0.5 / std::sqrt(kPi));
    EXPECT_NEAR(y[2], std::sqrt(3 / (4 * kPi)), 3e-16);
    EXPECT_NEAR(y[6], std::sqrt(5 / (4 * kPi)), 3e-16);
}


TEST(ShBasis, OrthonormalByQuadrature)
{
    constexpr int order = kMaxShOrder, n = order * order;
    std::vector<double> gram(size_t(n * n), 0.0);
    std::vector<double> y(static_cast<size_t>(n));
    for (const QuadratureNode& node : sphereQuadrature(order)) {
        evaluateSh(order, node.direction, y);
        for (int i = 0; i < n; ++i)
            for (int j = 0; j <= i; ++j)
                gram[size_t(i * n + j)] += node.weight * y[size_t(i)] * y[size_t(j)];
    }
    for (int i = 0; i < n; ++i)
        for (int j = 0; j <= i; ++j)
            ASSERT_NEAR(gram[size_t(i * n + j)], i == j ? 1.0 : 0.0, 1e-12) << "i " << i << " j " << j;
}

TEST(ShKernels, ClampedCosineClosedForm)
{
    EXPECT_DOUBLE_EQ(clampedCosineKernel(0), kPi);
    EXPECT_DOUBLE_EQ(clampedCosineKernel(1), 2 * kPi / 3);
    EXPECT_DOUBLE_EQ(clampedCosineKernel(2), kPi / 4);
    EXPECT_EQ(clampedCosineKernel(3), 0.0);
    EXPECT_DOUBLE_EQ(clampedCosineKernel(4), -kPi / 24);
    EXPECT_EQ(clampedCosineKernel(5), 0.0);
    EXPECT_DOUBLE_EQ(clampedCosineKernel(6), kPi / 64);
    EXPECT_DOUBLE_EQ(clampedCosineKernel(8), -kPi / 128);
    EXPECT_DOUBLE_EQ(clampedCosineKernel(10), 7 * kPi / 1536);
    EXPECT_EQ(clampedCosineKernel(9), 0.0);
}

TEST(ShKernels, ClampedCosineIsTheProjectionOfMaxCos)
{
    // Â_l = √(4π/(2l+1)) · ∫ max(cos θ, 0) Y_l0 dω = √(4π/(2l+1)) · 2π ∫₀¹ z Y_l0(z) dz (midpoint rule).
    constexpr int steps = 20000;
    std::vector<double> integral(kMaxShOrder, 0.0), y(kMaxShCoefficients);
    for (int t = 0; t < steps; ++t) {
        const double z = (t + 0.5) / steps;
        evaluateSh(kMaxShOrder, Vec3d{std::sqrt(1 - z * z), 0, z}, y);
        for (int l = 0; l < kMaxShOrder; ++l)
            integral[size_t(l)] += 2 * kPi * z * y[size_t(shIndex(l, 0))] / steps;
    }
    for (int l = 0; l < kMaxShOrder; ++l)
        EXPECT_NEAR(clampedCosineKernel(l), std::sqrt(4 * kPi / (2 * l + 1)) * integral[size_t(l)], 1e-7) << "l " << l;
}

TEST(ShKernels, ConvolveZonalScalesEachBand)
{
    std::vector<double> coefficients(16, 1.0);
    const double kernel[4] = {1, 2, 3, 4};
    convolveZonal(4, kernel, coefficients);
    for (int l = 0; l < 4; ++l)
        for (int m = -l; m <= l; ++m)
            EXPECT_EQ(coefficients[size_t(shIndex(l, m))], l + 1.0);
}

namespace {
// REFERENCE_SH.md §2: Grace Cathedral, prefilter.c output (R, G, B per coefficient).
constexpr double kGrace[9][3] = {{0.078908, 0.043710, 0.054161},    {0.039499, 0.034989, 0.060488},
                                 {-0.033974, -0.018236, -0.026940}, {-0.029213, -0.005562, 0.000944},
                                 {-0.011141, -0.005090, -0.012231}, {-0.026240, -0.022401, -0.047479},
                                 {-0.015570, -0.009471, -0.014733}, {0.056014, 0.021444, 0.013915},
                                 {0.021205, -0.005432, -0.030374}};
// §3: Eucalyptus Grove and St. Peter's (scaled by 1/10; irradiance is linear so scale does not matter).
constexpr double kEucalyptus[9][3] = {
    {0.3783264, 0.4260425, 0.4504587},    {0.2887813, 0.3586803, 0.4147053},   {0.0379030, 0.0295216, 0.0098567},
    {-0.1033028, -0.1031690, -0.0884924}, {-0.0621750, -0.0554432, -0.0396779}, {0.0077820, -0.0148312, -0.0471301},
    {-0.0935561, -0.1254260, -0.1525629}, {-0.0572703, -0.0502192, -0.0363410}, {0.0203348, -0.0044201, -0.0452180}};
constexpr double kStPeters[9][3] = {
    {0.3623915, 0.2624130, 0.2326261},    {0.1759130, 0.1436267, 0.1260569},    {-0.0247311, -0.0101253, -0.0010745},
    {0.0346500, 0.0223184, 0.0101350},    {0.0198140, 0.0144073, 0.0043987},    {-0.0469596, -0.0254485, -0.0117786},
    {-0.0898667, -0.0760911, -0.0740964}, {0.0050194, 0.0038841, 0.0001374},    {-0.0818750, -0.0321501, 0.0033399}};
// The printed M matrices for Grace (rows of n^T M n with n = (x, y, z, 1)).
constexpr double kGraceMatrix[3][4][4] = {
    {{0.009098, -0.004780, 0.024033, -0.014947}, {-0.004780, -0.009098, -0.011258, 0.020210},
     {0.024033, -0.011258, -0.011570, -0.017383}, {-0.014947, 0.020210, -0.017383, 0.073787}},
    {{-0.002331, -0.002184, 0.009201, -0.002846}, {-0.002184, 0.002331, -0.009611, 0.017903},
     {0.009201, -0.009611, -0.007038, -0.009331}, {-0.002846, 0.017903, -0.009331, 0.041083}},
    {{-0.013032, -0.005248, 0.005970, 0.000483}, {-0.005248, 0.013032, -0.020370, 0.030949},
     {0.005970, -0.020370, -0.010948, -0.013784}, {0.000483, 0.030949, -0.013784, 0.051648}}};

/// Ramamoorthi & Hanrahan's polynomial form (their c1 … c5 with 6 digits).
double irradiancePolynomial(const double (&L)[9][3], int c, const Vec3d& n)
{
    constexpr double c1 = 0.429043, c2 = 0.511664, c3 = 0.743125, c4 = 0.886227, c5 = 0.247708;
    const auto l = [&](int i) { return L[i][c]; };
    return c1 * l(8) * (n.x * n.x - n.y * n.y) + c3 * l(6) * n.z * n.z + c4 * l(0) - c5 * l(6) +
           2 * c1 * (l(4) * n.x * n.y + l(7) * n.x * n.z + l(5) * n.y * n.z) +
           2 * c2 * (l(3) * n.x + l(1) * n.y + l(2) * n.z);
}
} // namespace

TEST(ShIrradiance, MatchesRamamoorthiHanrahanPolynomialAndMatrix)
{
    for (const auto* probe : {&kGrace, &kEucalyptus, &kStPeters}) {
        for (int c = 0; c < 3; ++c) {
            std::vector<double> coefficients(9);
            for (int i = 0; i < 9; ++i)
                coefficients[size_t(i)] = (*probe)[i][c];
            irradianceFromRadiance(3, coefficients);
            for (const Vec3d& n : testDirections(100)) {
                const double expected = irradiancePolynomial(*probe, c, n);
                // 6-digit c constants: relative 1e-6 of the largest term.
                EXPECT_NEAR(reconstructSh(3, coefficients, n), expected, 2e-6) << "channel " << c;
                if (probe == &kGrace) {
                    const double v[4] = {n.x, n.y, n.z, 1};
                    double quadratic = 0;
                    for (int i = 0; i < 4; ++i)
                        for (int j = 0; j < 4; ++j)
                            quadratic += v[i] * kGraceMatrix[c][i][j] * v[j];
                    EXPECT_NEAR(reconstructSh(3, coefficients, n), quadratic, 1e-5) << "channel " << c;
                }
            }
        }
    }
}

TEST(ShProjection, AccumulateRecoversABandLimitedFunction)
{
    // Project f = Σ cᵢYᵢ with an exact quadrature: the coefficients come back.
    constexpr int order = 6, n = order * order;
    std::vector<double> truth(n), recovered(n, 0.0), scratch(n);
    for (int i = 0; i < n; ++i)
        truth[size_t(i)] = std::sin(1.0 + i);
    for (const QuadratureNode& node : sphereQuadrature(order))
        accumulateShProjection(order, node.direction, node.weight * reconstructSh(order, truth, node.direction),
                               recovered, scratch);
    for (int i = 0; i < n; ++i)
        EXPECT_NEAR(recovered[size_t(i)], truth[size_t(i)], 1e-12) << "i " << i;
}

namespace {

Quatd randomRotation(std::mt19937& rng)
{
    std::normal_distribution<double> gaussian;
    return normalize(Quatd{gaussian(rng), gaussian(rng), gaussian(rng), gaussian(rng)});
}

/// Determinant by LU with partial pivoting.
double determinant(std::vector<double> a, int n)
{
    double det = 1;
    for (int k = 0; k < n; ++k) {
        int pivot = k;
        for (int i = k + 1; i < n; ++i)
            if (std::abs(a[size_t(i * n + k)]) > std::abs(a[size_t(pivot * n + k)]))
                pivot = i;
        if (pivot != k) {
            for (int j = 0; j < n; ++j)
                std::swap(a[size_t(k * n + j)], a[size_t(pivot * n + j)]);
            det = -det;
        }
        det *= a[size_t(k * n + k)];
        for (int i = k + 1; i < n; ++i) {
            const double f = a[size_t(i * n + k)] / a[size_t(k * n + k)];
            for (int j = k; j < n; ++j)
                a[size_t(i * n + j)] -= f * a[size_t(k * n + j)];
        }
    }
    return det;
}

} // namespace

TEST(ShRotation, RotationMatrixMatchesQuaternionRotate)
{
    std::mt19937 rng(1);
    for (int trial = 0; trial < 20; ++trial) {
        const Quatd q = randomRotation(rng);
        const Matrix3d m = rotationMatrix(q);
        for (const Vec3d& v : testDirections(5)) {
            const Vec3d expected = rotate(q, v);
            EXPECT_NEAR(m[0] * v.x + m[1] * v.y + m[2] * v.z, expected.x, 1e-15);
            EXPECT_NEAR(m[3] * v.x + m[4] * v.y + m[5] * v.z, expected.y, 1e-15);
            EXPECT_NEAR(m[6] * v.x + m[7] * v.y + m[8] * v.z, expected.z, 1e-15);
        }
    }
}

TEST(ShRotation, BandOneIsThePermutedMatrix)
{
    std::mt19937 rng(2);
    const Matrix3d m = rotationMatrix(randomRotation(rng));
    const ShRotation rotation(2, m);
    const int axis[3] = {1, 2, 0}; // m = −1, 0, 1 ↔ y, z, x
    EXPECT_EQ(rotation.band(0)[0], 1.0);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            EXPECT_EQ(rotation.band(1)[size_t(3 * i + j)], m[size_t(3 * axis[i] + axis[j])]);
}

TEST(ShRotation, BandsAreOrthonormalWithDeterminantOne)
{
    std::mt19937 rng(3);
    for (int trial = 0; trial < 10; ++trial) {
        const ShRotation rotation(kMaxShOrder, randomRotation(rng));
        for (int l = 0; l < kMaxShOrder; ++l) {
            const int size = 2 * l + 1;
            const std::span<const double> band = rotation.band(l);
            for (int i = 0; i < size; ++i)
                for (int j = 0; j < size; ++j) {
                    double dot = 0;
                    for (int k = 0; k < size; ++k)
                        dot += band[size_t(i * size + k)] * band[size_t(j * size + k)];
                    ASSERT_NEAR(dot, i == j ? 1.0 : 0.0, 1e-12) << "band " << l << " rows " << i << ", " << j;
                }
            if (l <= 6) {
                EXPECT_NEAR(determinant({band.begin(), band.end()}, size), 1.0, 1e-11) << "band " << l;
            }
        }
    }
}

TEST(ShRotation, IsAHomomorphism)
{
    std::mt19937 rng(4);
    for (int trial = 0; trial < 10; ++trial) {
        const Quatd q1 = randomRotation(rng), q2 = randomRotation(rng);
        const ShRotation r1(kMaxShOrder, q1), r2(kMaxShOrder, q2), r12(kMaxShOrder, q1 * q2),
            inverse(kMaxShOrder, conjugate(q1));
        for (int l = 0; l < kMaxShOrder; ++l) {
            const int size = 2 * l + 1;
            const auto a = r1.band(l), b = r2.band(l), ab = r12.band(l), aInverse = inverse.band(l);
            for (int i = 0; i < size; ++i)
                for (int j = 0; j < size; ++j) {
                    double product = 0;
                    for (int k = 0; k < size; ++k)
                        product += a[size_t(i * size + k)] * b[size_t(k * size + j)];
                    ASSERT_NEAR(ab[size_t(i * size + j)], product, 1e-12) << "R(q1·q2), band " << l;
                    ASSERT_NEAR(aInverse[size_t(i * size + j)], a[size_t(j * size + i)], 1e-12)
                        << "R(q⁻¹) = R(q)ᵀ, band " << l;
                }
        }
    }
}

TEST(ShRotation, RotateThenEvaluateEqualsEvaluateAtRotatedDirection)
{
    // f'(ω) = f(R⁻¹ω) and coefficients(f') = apply(coefficients(f)), so
    // reconstruct(apply(c), ω) == reconstruct(c, R⁻¹ω).
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> uniform(-1, 1);
    for (int order = 1; order <= kMaxShOrder; ++order) {
        const int n = order * order;
        std::vector<double> c(static_cast<size_t>(n)), rotated(static_cast<size_t>(n));
        std::vector<float> cFloat(static_cast<size_t>(n)), rotatedFloat(static_cast<size_t>(n));
        for (int trial = 0; trial < 5; ++trial) {
            for (int i = 0; i < n; ++i) {
                c[size_t(i)] = uniform(rng);
                cFloat[size_t(i)] = float(c[size_t(i)]);
            }
            const Quatd q = randomRotation(rng);
            const ShRotation rotation(order, q);
            rotation.apply(c, rotated);
            rotation.apply(cFloat, rotatedFloat);
            for (const Vec3d& omega : testDirections(20)) {
                const double expected = reconstructSh(order, c, rotate(conjugate(q), omega));
                ASSERT_NEAR(reconstructSh(order, rotated, omega), expected, 1e-10) << "order " << order;
                std::vector<double> fromFloat(rotatedFloat.begin(), rotatedFloat.end());
                ASSERT_NEAR(reconstructSh(order, fromFloat, omega), expected, 2e-4 * order) << "order " << order;
            }
        }
    }
}

TEST(ShRotation, ApplyRgbMatchesPerChannelApply)
{
    std::mt19937 rng(6);
    std::uniform_real_distribution<double> uniform(-1, 1);
    for (int order = 1; order <= kMaxShOrder; ++order) {
        ShRgb in, out;
        in.order = order;
        for (auto& channel : in.channel)
            for (double& v : channel)
                v = uniform(rng);
        const ShRotation rotation(order, randomRotation(rng));
        rotation.applyRgb(in, out);
        EXPECT_EQ(out.order, order);
        for (int c = 0; c < 3; ++c) {
            std::vector<double> expected(size_t(order * order));
            rotation.apply(in[c], expected);
            for (int i = 0; i < order * order; ++i)
                ASSERT_NEAR(out[c][size_t(i)], expected[size_t(i)], 1e-14) << "order " << order << " channel " << c;
        }
    }
}

TEST(ShRotation, AboutZMatchesClosedForm)
{
    // A turn by α about z maps the pair (cos mφ, sin mφ) with: c'₊ = cos(mα)·c₊ − sin(mα)·c₋,
    // c'₋ = sin(mα)·c₊ + cos(mα)·c₋ (c₊ = coefficient of m > 0, c₋ of −m).
    for (double alpha : {0.3, -1.2, 2.5, 3.14159}) {
        const ShRotation rotation(kMaxShOrder, Quatd::fromAxisAngle({0, 0, 1}, alpha));
        for (int l = 0; l < kMaxShOrder; ++l) {
            const int size = 2 * l + 1;
            const auto band = rotation.band(l);
            std::vector<double> expected(size_t(size * size), 0.0);
            const auto at = [&](int m, int n) -> double& { return expected[size_t((m + l) * size + n + l)]; };
            at(0, 0) = 1;
            for (int m = 1; m <= l; ++m) {
                at(m, m) = std::cos(m * alpha);
                at(m, -m) = -std::sin(m * alpha);
                at(-m, m) = std::sin(m * alpha);
                at(-m, -m) = std::cos(m * alpha);
            }
            for (int i = 0; i < size * size; ++i)
                ASSERT_NEAR(band[size_t(i)], expected[size_t(i)], 1e-13) << "band " << l << " alpha " << alpha;
        }
    }
}

TEST(ShRotation, BuildAndApplyDoNotAllocate)
{
    std::mt19937 rng(7);
    const Quatd q = randomRotation(rng);
    ShRgb in, out;
    in.order = kMaxShOrder;
    std::array<double, kMaxShCoefficients> c{}, rotated{};
    std::array<float, kMaxShCoefficients> cFloat{}, rotatedFloat{};
    ShRotation rotation;
    const long before = thespis::test::allocationCount();
    for (int order = 1; order <= kMaxShOrder; ++order) {
        rotation.build(order, rotationMatrix(q));
        rotation.apply(c, rotated);
        rotation.apply(cFloat, rotatedFloat);
        rotation.applyRgb(in, out);
    }
    EXPECT_EQ(thespis::test::allocationCount(), before);
}

TEST(ShRotation, BaselineAndAvx2KernelsAgree)
{
    // apply picks AVX2/FMA kernels at run time where it can; the baseline kernels must give the
    // same rotation (to rounding), and both must be exercised on a machine with AVX2.
    std::mt19937 rng(8);
    std::uniform_real_distribution<double> uniform(-1, 1);
    for (int order = 1; order <= kMaxShOrder; ++order) {
        const ShRotation rotation(order, randomRotation(rng));
        ShRgb in, fast, baseline;
        in.order = order;
        for (auto& channel : in.channel)
            for (double& v : channel)
                v = uniform(rng);
        rotation.applyRgb(in, fast);
        thespis::core::lighting::detail::forceShRotationBaseline(true);
        EXPECT_FALSE(thespis::core::lighting::detail::shRotationUsesAvx2());
        rotation.applyRgb(in, baseline);
        std::vector<double> single(size_t(order * order));
        rotation.apply(in[0], single);
        thespis::core::lighting::detail::forceShRotationBaseline(false);
        for (int c = 0; c < 3; ++c)
            for (int i = 0; i < order * order; ++i)
                ASSERT_NEAR(fast[c][size_t(i)], baseline[c][size_t(i)], 1e-14) << "order " << order;
        for (int i = 0; i < order * order; ++i)
            ASSERT_NEAR(single[size_t(i)], baseline[0][size_t(i)], 1e-14) << "order " << order;
    }
}
