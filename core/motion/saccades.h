#pragma once
// Saccades while fixating, after "Eyes Alive" (Lee, Badler and Badler, SIGGRAPH 2002): the eyes
// leave the person looked at and come back in quick jumps. From their statistics of people in
// conversation —
//   - amplitude A (degrees): P(A) = 15.7·e^(−A/6.9) per cent, so A = −6.9·ln(P/15.7) with P
//     drawn uniformly from (0, 15];
//   - direction: one of eight, up and down or sideways most often (their table);
//   - duration: 25 ms + 2.4 ms per degree;
//   - how long the eyes stay: in mutual gaze and away, each a normal distribution fitted
//     separately for the talking and the listening mode — a speaker looks away more often.
// Seeded: the same seed gives the same saccades (numbers drawn by hand from a 64-bit Mersenne
// twister, as the blink generator does, so that no library's distribution changes them).

#include <cstdint>
#include <random>

namespace thespis::core::motion {

/// One saccade: from an eye offset to another (degrees: heading + left, pitch + down).
struct Saccade {
    double start = 0, duration = 0;             ///< seconds
    double fromHeading = 0, fromPitch = 0;
    double toHeading = 0, toPitch = 0;
    double amplitude() const;                   ///< degrees
};

/// Eyes Alive's duration of a saccade of `amplitude` degrees: 25 ms + 2.4 ms per degree.
double saccadeDuration(double amplitudeDegrees);
/// The minimum-jerk share 10τ³ − 15τ⁴ + 6τ⁵ of a movement done at τ ∈ [0, 1]: smooth at both ends.
double minimumJerk(double tau);

class SaccadeGenerator {
public:
    explicit SaccadeGenerator(std::uint64_t seed = 1);

    /// Starts over at `t` in mutual gaze (offset 0): the fixation begins.
    void restart(double t, bool talking);
    /// Talking or listening from now on (the next interval drawn uses it).
    void setTalking(bool talking) { m_talking = talking; }
    /// The eye offset from the target at `t` (t never going back between restarts).
    void offset(double t, double& heading, double& pitch);
    /// The saccade playing or last played.
    const Saccade& current() const { return m_current; }
    /// Saccades started since the last restart.
    int count() const { return m_count; }

private:
    double uniform();
    double normal(double mean, double deviation);
    void next(double t); // the next saccade, starting at t

    std::mt19937_64 m_random;
    Saccade m_current;
    double m_nextStart = 0;
    bool m_away = false, m_talking = false;
    int m_count = 0;
};

} // namespace thespis::core::motion
