// Curves at their key points, their continuity (cubic kinds are C1), keyframed tangent modes, the
// coarticulation dominance against the paper's eq. 3.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "anim/curve.h"

using namespace thespis::core::anim;

namespace {

constexpr double kDuration = 3.0;

double slope(const Curve& c, double t, double h, double duration = kDuration)
{
    return (c.evaluate(t + h, duration) - c.evaluate(t, duration)) / h;
}

// Largest jump between neighbouring samples on [a, b] with step h: a continuous curve's jumps
// shrink with h, a discontinuous one's do not.
double largestJump(const Curve& c, double a, double b, double h)
{
    double worst = 0;
    for (double t = a; t < b; t += h)
        worst = std::max(worst, std::abs(c.evaluate(t + h, kDuration) - c.evaluate(t, kDuration)));
    return worst;
}

// The paper's eq. 3, written out here apart from the code under test: C_α(x) = e^(−α·2|x−0.5|) −
// 2|x−0.5|·e^(−α).
double paperDominance(double alpha, double x)
{
    const double distance = std::fabs(2 * x - 1);
    return std::exp(-alpha * distance) - distance / std::exp(alpha);
}

} // namespace

TEST(Curve, ConstantIsFlat)
{
    const Curve c = Curve::constant(0.25);
    EXPECT_DOUBLE_EQ(c.evaluate(-1), 0.25);
    EXPECT_DOUBLE_EQ(c.evaluate(100, kDuration), 0.25);
    EXPECT_TRUE(Curve().isIdentity());
    EXPECT_FALSE(c.isIdentity());
}

TEST(Curve, LinearFadeKeyPoints)
{
    const Curve c = Curve::linearFade(0.5, 1.0);
    EXPECT_DOUBLE_EQ(c.evaluate(-0.1, kDuration), 0.0);
    EXPECT_DOUBLE_EQ(c.evaluate(0.0, kDuration), 0.0);
    EXPECT_DOUBLE_EQ(c.evaluate(0.25, kDuration), 0.5);
    EXPECT_DOUBLE_EQ(c.evaluate(0.5, kDuration), 1.0);
    EXPECT_DOUBLE_EQ(c.evaluate(2.0, kDuration), 1.0);
    EXPECT_DOUBLE_EQ(c.evaluate(2.5, kDuration), 0.5);
    EXPECT_DOUBLE_EQ(c.evaluate(3.0, kDuration), 0.0);
    EXPECT_DOUBLE_EQ(c.evaluate(3.5, kDuration), 0.0);
    // Open-ended actions never fade out.
    EXPECT_DOUBLE_EQ(c.evaluate(1000.0), 1.0);
    EXPECT_LT(largestJump(c, -0.5, 3.5, 1e-4), 3e-4);
}

TEST(Curve, CubicFadeKeyPointsAndC1)
{
    const Curve c = Curve::cubicFade(0.5, 1.0, 0.8);
    EXPECT_DOUBLE_EQ(c.evaluate(0.0, kDuration), 0.0);
    EXPECT_DOUBLE_EQ(c.evaluate(0.25, kDuration), 0.4); // halfway up: 3u²−2u³ = 0.5
    EXPECT_DOUBLE_EQ(c.evaluate(0.5, kDuration), 0.8);
    EXPECT_DOUBLE_EQ(c.evaluate(2.5, kDuration), 0.4);
    EXPECT_DOUBLE_EQ(c.evaluate(3.0, kDuration), 0.0);
    // C1: the slope is 0 at both ends of each ramp, from either side.
    const double h = 1e-6;
    for (double knot : {0.0, 0.5, 2.0, 3.0}) {
        EXPECT_NEAR(slope(c, knot, h), 0.0, 1e-4) << "right slope at " << knot;
        EXPECT_NEAR(slope(c, knot - h, h), 0.0, 1e-4) << "left slope at " << knot;
    }
    // Slope continuous everywhere: neighbouring slopes differ little.
    double worst = 0;
    for (double t = -0.2; t < 3.2; t += 1e-3)
        worst = std::max(worst, std::abs(slope(c, t + 1e-3, 1e-5) - slope(c, t, 1e-5)));
    EXPECT_LT(worst, 0.02);
    // Linear fade is only C0: its slope jumps at the knots.
    EXPECT_GT(std::abs(slope(Curve::linearFade(0.5, 1.0), 0.5, h) - slope(Curve::linearFade(0.5, 1.0), 0.5 - 2 * h, h)), 1.0);
}

TEST(Curve, OverlappingFadesStayContinuous)
{
    const Curve c = Curve::cubicFade(2.0, 2.0);
    EXPECT_LT(c.evaluate(1.5, kDuration), 1.0); // never reaches the peak in a 3 s action
    EXPECT_LT(largestJump(c, 0, 3, 1e-4), 1e-3);
}

TEST(Curve, LinearAdsrKeyPoints)
{
    const Curve c = Curve::linearAdsr(0.5, 0.5, 0.6, 1.0);
    EXPECT_DOUBLE_EQ(c.evaluate(0.0, kDuration), 0.0);
    EXPECT_DOUBLE_EQ(c.evaluate(0.25, kDuration), 0.5);
    EXPECT_DOUBLE_EQ(c.evaluate(0.5, kDuration), 1.0);
    EXPECT_DOUBLE_EQ(c.evaluate(0.75, kDuration), 0.8);
    EXPECT_DOUBLE_EQ(c.evaluate(1.0, kDuration), 0.6);
    EXPECT_DOUBLE_EQ(c.evaluate(1.5, kDuration), 0.6);
    EXPECT_DOUBLE_EQ(c.evaluate(2.0, kDuration), 0.6);
    EXPECT_DOUBLE_EQ(c.evaluate(2.5, kDuration), 0.3);
    EXPECT_DOUBLE_EQ(c.evaluate(3.0, kDuration), 0.0);
    EXPECT_DOUBLE_EQ(c.evaluate(50.0), 0.6); // open-ended: sustains
    EXPECT_LT(largestJump(c, -0.5, 3.5, 1e-4), 3e-4);
}

TEST(Curve, CubicAdsrKeyPointsAndC1)
{
    const Curve c = Curve::cubicAdsr(0.5, 0.5, 0.6, 1.0);
    for (auto [t, v] : {std::pair{0.0, 0.0}, {0.25, 0.5}, {0.5, 1.0}, {0.75, 0.8}, {1.0, 0.6}, {2.0, 0.6}, {2.5, 0.3}, {3.0, 0.0}})
        EXPECT_NEAR(c.evaluate(t, kDuration), v, 1e-12) << "t = " << t;
    const double h = 1e-6;
    for (double knot : {0.0, 0.5, 1.0, 2.0, 3.0}) {
        EXPECT_NEAR(slope(c, knot, h), 0.0, 1e-4) << "right slope at " << knot;
        EXPECT_NEAR(slope(c, knot - h, h), 0.0, 1e-4) << "left slope at " << knot;
    }
}

TEST(Curve, ValidateRejectsBadParameters)
{
    EXPECT_FALSE(Curve::linearFade(-1, 0).validate());
    EXPECT_FALSE(Curve::linearAdsr(0.1, 0.1, 1.5, 0.1).validate());
    EXPECT_FALSE(Curve::constant(std::nan("")).validate());
    EXPECT_TRUE(Curve::cubicAdsr(0.1, 0.2, 0.5, 0.3).validate());
}

TEST(KeyframedCurve, LinearAndConstantModes)
{
    auto linear = Curve::keyframed({{0, 0, TangentMode::Linear}, {1, 1, TangentMode::Linear}, {3, 0, TangentMode::Linear}});
    ASSERT_TRUE(linear);
    EXPECT_NEAR(linear->evaluate(0.5), 0.5, 1e-12);
    EXPECT_NEAR(linear->evaluate(2.0), 0.5, 1e-12);
    EXPECT_DOUBLE_EQ(linear->evaluate(-1), 0.0); // holds its ends
    EXPECT_DOUBLE_EQ(linear->evaluate(9), 0.0);

    auto step = Curve::keyframed({{0, 0.2, TangentMode::Constant}, {1, 0.7, TangentMode::Constant}});
    ASSERT_TRUE(step);
    EXPECT_DOUBLE_EQ(step->evaluate(0.999), 0.2);
    EXPECT_DOUBLE_EQ(step->evaluate(1.0), 0.7);
}

TEST(KeyframedCurve, AutoClampedNeverOvershoots)
{
    // Monotone keys: an unclamped spline overshoots around the sharp corner; auto-clamped must not.
    auto c = Curve::keyframed({{0, 0}, {1, 0.05}, {1.2, 1.0}, {3, 1.0}});
    ASSERT_TRUE(c);
    for (double t = 0; t <= 3; t += 1e-3) {
        EXPECT_GE(c->evaluate(t), -1e-12) << t;
        EXPECT_LE(c->evaluate(t), 1.0 + 1e-12) << t;
    }
    // Extremum keys get a flat tangent.
    auto peak = Curve::keyframed({{0, 0}, {1, 1}, {2, 0}});
    EXPECT_NEAR(slope(*peak, 1.0, 1e-6, Curve::Infinite), 0.0, 1e-4);
}

TEST(KeyframedCurve, FreeAndBrokenTangents)
{
    CurveKey a{0, 0, TangentMode::Free, 2.0, 0};
    CurveKey b{1, 1, TangentMode::Broken, 3.0, -1.0};
    CurveKey c{2, 0, TangentMode::Free, 0.5, 0};
    auto curve = Curve::keyframed({a, b, c});
    ASSERT_TRUE(curve);
    const double h = 1e-7;
    EXPECT_NEAR(slope(*curve, 0.0, h, Curve::Infinite), 2.0, 1e-4);      // free: its slope
    EXPECT_NEAR(slope(*curve, 1.0 - h, h, Curve::Infinite), 3.0, 1e-4);  // broken: in-slope
    EXPECT_NEAR(slope(*curve, 1.0, h, Curve::Infinite), -1.0, 1e-4);     // broken: out-slope
    EXPECT_NEAR(slope(*curve, 2.0 - h, h, Curve::Infinite), 0.5, 1e-4);
}

TEST(KeyframedCurve, RefusesBadKeys)
{
    EXPECT_FALSE(Curve::keyframed({}));
    auto duplicate = Curve::keyframed({{1, 0}, {1, 1}});
    ASSERT_FALSE(duplicate);
    EXPECT_NE(duplicate.error().message.find("same time"), std::string::npos);
    EXPECT_FALSE(Curve::keyframed({{0, std::nan("")}}));
    // Keys are sorted on creation.
    auto sorted = Curve::keyframed({{2, 1, TangentMode::Linear}, {0, 0, TangentMode::Linear}});
    ASSERT_TRUE(sorted);
    EXPECT_DOUBLE_EQ(sorted->keys().front().time, 0.0);
    EXPECT_NEAR(sorted->evaluate(1.0), 0.5, 1e-12);
}

TEST(DominanceCurve, FollowsEquation3)
{
    std::mt19937 random(3);
    std::uniform_real_distribution<double> anywhere(0.0, 1.0);
    for (double alpha : {2.0, 5.0}) {
        std::vector<double> xs;
        for (int i = 0; i <= 10; ++i)
            xs.push_back(i / 10.0);
        for (int i = 0; i < 50; ++i)
            xs.push_back(anywhere(random));
        const Curve c = Curve::dominance(alpha, 0.7);
        for (double x : xs) {
            EXPECT_NEAR(dominance(alpha, x), paperDominance(alpha, x), 1e-12) << "alpha " << alpha << ", x " << x;
            EXPECT_NEAR(c.evaluate(x * kDuration, kDuration), 0.7 * paperDominance(alpha, x), 1e-12)
                << "alpha " << alpha << ", x " << x;
        }
    }
    // α sets the sharpness: halfway to the middle, the larger α has fallen further.
    EXPECT_LT(dominance(5, 0.25), dominance(2, 0.25));
}

TEST(DominanceCurve, PeaksInTheMiddleIsZeroAtTheEndsAndSymmetric)
{
    for (double alpha : {0.1, 2.0, 5.0, 50.0}) {
        SCOPED_TRACE(alpha);
        const Curve c = Curve::dominance(alpha, 0.8);
        EXPECT_DOUBLE_EQ(c.evaluate(kDuration / 2, kDuration), 0.8);
        EXPECT_NEAR(c.evaluate(0, kDuration), 0.0, 1e-15);
        EXPECT_NEAR(c.evaluate(kDuration, kDuration), 0.0, 1e-15);
        EXPECT_EQ(c.evaluate(-0.1, kDuration), 0.0); // nothing outside the action
        EXPECT_EQ(c.evaluate(kDuration + 0.1, kDuration), 0.0);
        for (double t = 0; t <= kDuration / 2; t += 0.01) {
            EXPECT_NEAR(c.evaluate(t, kDuration), c.evaluate(kDuration - t, kDuration), 1e-12) << "t = " << t;
            EXPECT_LE(c.evaluate(t, kDuration), 0.8);
            EXPECT_GE(c.evaluate(t, kDuration), 0.0);
        }
    }
}

TEST(DominanceCurve, OpenEndedHoldsThePeak)
{
    const Curve c = Curve::dominance(5, 0.6);
    for (double t : {0.0, 1.0, 1000.0})
        EXPECT_EQ(c.evaluate(t), 0.6) << "t = " << t;
    EXPECT_EQ(c.evaluate(0, 0), 0.0); // an action of no length has no middle to peak in
}

TEST(DominanceCurve, ValidateRefusesAlphaNotAboveZero)
{
    EXPECT_TRUE(Curve::dominance(0.1).validate());
    EXPECT_TRUE(Curve::dominance(50, 2).validate());
    for (double alpha : {0.0, -1.0, std::nan(""), std::numeric_limits<double>::infinity()}) {
        SCOPED_TRACE(alpha);
        EXPECT_FALSE(Curve::dominance(alpha).validate());
    }
    EXPECT_NE(Curve::dominance(0).validate().error().message.find("alpha"), std::string::npos);
}
