// Blinks (core/motion/blink_synthesizer.h, issue 31): over ten minutes the rate and the lids'
// closing and opening times are the ones asked for, within 10 %; the same seed gives the same
// blinks, another seed others; a blink shuts the eye (the lids' FAPs add up to the iris
// diameter, 1024 units) and evaluating allocates nothing.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "allocation_counter.h"
#include "motion/blink_synthesizer.h"
#include "scene/fap.h"

namespace thespis::core::motion {
namespace {

struct Measured {
    int blinks = 0;
    double closing = 0, opening = 0; // mean seconds from 5 % to 95 % shut and back
};

// Samples every millisecond: a blink starts where the closure leaves 0.
Measured measure(const BlinkSynthesizer& blinks, double seconds)
{
    Measured m;
    constexpr double Step = 0.001;
    double previous = 0, closeStart = -1, shutAt = -1, openStart = -1;
    int closings = 0, openings = 0;
    for (double t = 0; t < seconds; t += Step) {
        const double c = blinks.closure(t);
        if (previous == 0 && c > 0)
            ++m.blinks;
        if (previous < 0.05 && c >= 0.05)
            closeStart = t;
        if (previous < 0.95 && c >= 0.95 && closeStart >= 0)
            m.closing += t - closeStart, ++closings, shutAt = t;
        if (previous > 0.95 && c <= 0.95)
            openStart = t;
        if (previous > 0.05 && c <= 0.05 && openStart >= 0 && shutAt >= 0)
            m.opening += t - openStart, ++openings;
        previous = c;
    }
    m.closing /= closings;
    m.opening /= openings;
    return m;
}

TEST(Blinks, RateAndTimesOverTenMinutesAreTheOnesAskedFor)
{
    for (const double rate : {kBlinkRateAtRest, kBlinkRateTalking}) {
        SCOPED_TRACE(rate);
        BlinkOptions options;
        options.ratePerMinute = rate;
        options.seed = 11;
        const auto blinks = BlinkSynthesizer::create(options);
        ASSERT_TRUE(blinks.ok());
        const Measured m = measure(**blinks, 600);
        EXPECT_NEAR(m.blinks, rate * 10, rate * 10 * 0.10);
        // sin² from 5 % to 95 % takes 0.713 of the phase (2·(asin √0.95 − asin √0.05) / π).
        const double share = 2 * (std::asin(std::sqrt(0.95)) - std::asin(std::sqrt(0.05))) / M_PI;
        EXPECT_NEAR(m.closing, share * options.closeSeconds, 0.10 * share * options.closeSeconds);
        EXPECT_NEAR(m.opening, share * options.openSeconds, 0.10 * share * options.openSeconds);
        EXPECT_GT(m.opening, m.closing) << "the lids open more slowly than they close";
    }
}

TEST(Blinks, TheSameSeedGivesTheSameBlinks)
{
    BlinkOptions options;
    options.seed = 4;
    const auto a = BlinkSynthesizer::create(options), b = BlinkSynthesizer::create(options);
    options.seed = 5;
    const auto c = BlinkSynthesizer::create(options);
    ASSERT_TRUE(a.ok() && b.ok() && c.ok());
    EXPECT_EQ((*a)->starts(), (*b)->starts());
    EXPECT_NE((*a)->starts(), (*c)->starts());
    EXPECT_GT((*a)->starts().size(), 900u); // an hour at 17 a minute
    for (std::size_t i = 1; i < (*a)->starts().size(); ++i)
        EXPECT_GE((*a)->starts()[i] - (*a)->starts()[i - 1], 0.4);
}

TEST(Blinks, ABlinkShutsTheEyeAndMovesOnlyTheLids)
{
    const auto blinks = BlinkSynthesizer::create({});
    ASSERT_TRUE(blinks.ok());
    const BlinkSynthesizer& b = **blinks;
    const double shut = b.starts()[3] + b.options().closeSeconds + 0.5 * b.options().shutSeconds;
    std::vector<float> frame(b.layout()->floatCount());
    const long before = thespis::test::allocationCount();
    b.evaluate(shut, frame);
    EXPECT_EQ(thespis::test::allocationCount(), before);
    using scene::fapChannel;
    EXPECT_FLOAT_EQ(frame[std::size_t(fapChannel(19))] + frame[std::size_t(fapChannel(21))], 1024.0f);
    EXPECT_FLOAT_EQ(frame[std::size_t(fapChannel(20))] + frame[std::size_t(fapChannel(22))], 1024.0f);
    EXPECT_GT(frame[std::size_t(fapChannel(19))], 800.0f) << "mostly the upper lid";
    for (std::size_t i = 0; i < frame.size(); ++i) {
        if (i < 18 || i > 21) {
            EXPECT_EQ(frame[i], 0.0f) << i;
        }
    }
    b.evaluate(b.starts()[3] - 0.01, frame);
    EXPECT_EQ(frame[std::size_t(fapChannel(19))], 0.0f);
}

TEST(Blinks, RefusesRatesAndTimesOutOfRange)
{
    EXPECT_FALSE(BlinkSynthesizer::create({.ratePerMinute = 0}).ok());
    EXPECT_FALSE(BlinkSynthesizer::create({.ratePerMinute = 500}).ok());
    EXPECT_FALSE(BlinkSynthesizer::create({.closeSeconds = 0}).ok());
    EXPECT_FALSE(BlinkSynthesizer::create({.openSeconds = 0.5}).ok());
}

} // namespace
} // namespace thespis::core::motion
