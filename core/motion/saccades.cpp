#include "motion/saccades.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace thespis::core::motion {

namespace {

// Eyes Alive's saccade directions: per cent of saccades towards 0° (right), 45°, 90° (up) …
constexpr std::array<double, 8> kDirectionShare = {15.54, 6.46, 17.69, 7.44, 16.80, 7.89, 20.38, 7.79};
// How long the eyes stay (their fits, in frames at 30 a second): mean and deviation of mutual
// gaze and of gaze away, talking and listening.
struct Stay {
    double mean, deviation;
};
constexpr Stay kMutualTalking{93.9 / 30, 94.9 / 30}, kAwayTalking{27.8 / 30, 24.0 / 30};
constexpr Stay kMutualListening{237.5 / 30, 47.1 / 30}, kAwayListening{13.0 / 30, 7.1 / 30};
// A conversational saccade stays small: beyond this the head turns as well (a gaze shift).
constexpr double kLargestAmplitude = 15;
constexpr double kShortestStay = 0.1; // seconds between the end of one saccade and the next

} // namespace

double Saccade::amplitude() const { const double h = toHeading - fromHeading, p = toPitch - fromPitch;
    return std::sqrt(h * h + p * p); }

double saccadeDuration(double amplitudeDegrees) { return 0.025 + 0.0024 * amplitudeDegrees; }

double minimumJerk(double tau)
{
    tau = std::clamp(tau, 0.0, 1.0);
    return tau * tau * tau * (10 + tau * (-15 + 6 * tau));
}

SaccadeGenerator::SaccadeGenerator(std::uint64_t seed) : m_random(seed) {}

double SaccadeGenerator::uniform() { return double(m_random() >> 11) * 0x1.0p-53; }

double SaccadeGenerator::normal(double mean, double deviation)
{
    // Box–Muller by hand: the same numbers everywhere.
    const double u = 1 - uniform(), v = uniform();
    return mean + deviation * std::sqrt(-2 * std::log(u)) * std::cos(2 * std::numbers::pi * v);
}

void SaccadeGenerator::restart(double t, bool talking)
{
    m_talking = talking;
    m_away = false;
    m_current = Saccade{t, 0, 0, 0, 0, 0};
    m_count = 0;
    const Stay stay = m_talking ? kMutualTalking : kMutualListening;
    m_nextStart = t + std::max(kShortestStay, normal(stay.mean, stay.deviation));
}

void SaccadeGenerator::next(double t)
{
    Saccade saccade;
    saccade.start = t;
    saccade.fromHeading = m_current.toHeading;
    saccade.fromPitch = m_current.toPitch;
    if (!m_away) {
        const double share = 1 - uniform(); // (0, 1]
        const double amplitude = std::min(kLargestAmplitude, -6.9 * std::log(15 * share / 15.7));
        double pick = uniform() * 99.99, direction = 0;
        for (std::size_t i = 0; i < kDirectionShare.size(); ++i) {
            direction = double(i) * std::numbers::pi / 4;
            if ((pick -= kDirectionShare[i]) < 0)
                break;
        }
        // 0° is to the right (heading −), 90° up (pitch −).
        saccade.toHeading = -amplitude * std::cos(direction);
        saccade.toPitch = -amplitude * std::sin(direction);
    }
    saccade.duration = saccadeDuration(saccade.amplitude());
    m_current = saccade;
    m_away = !m_away;
    ++m_count;
    const Stay stay = m_away ? (m_talking ? kAwayTalking : kAwayListening)
                             : (m_talking ? kMutualTalking : kMutualListening);
    m_nextStart = t + saccade.duration + std::max(kShortestStay, normal(stay.mean, stay.deviation));
}

void SaccadeGenerator::offset(double t, double& heading, double& pitch)
{
    while (t >= m_nextStart)
        next(m_nextStart);
    const Saccade& s = m_current;
    const double done = s.duration > 0 ? minimumJerk((t - s.start) / s.duration) : 1;
    heading = s.fromHeading + (s.toHeading - s.fromHeading) * done;
    pitch = s.fromPitch + (s.toPitch - s.fromPitch) * done;
}

} // namespace thespis::core::motion
