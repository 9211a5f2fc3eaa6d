#include "speech/boundary_refinement.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "speech/sphinx_decoder.h"

namespace thespis::core::speech {
namespace {

constexpr int kStepsPerSecond = 400;  // 2.5 ms
constexpr int kReachSteps = 6;        // 15 ms each way
constexpr double kHalfWindow = 0.030; // compared on each side
constexpr double kShortest = 0.010;   // a phoneme's least length

// How much the sound changes at a time: the distance between the mean cepstra of the frames
// centred in the half window before it and in the half window after it.
class SpectralChange {
public:
    explicit SpectralChange(std::span<const std::int16_t> samples)
    {
        const auto cepstra = sphinxCepstra(samples, kStepsPerSecond);
        m_sums.resize(cepstra.size() + 1);
        for (std::size_t k = 0; k < cepstra.size(); ++k)
            for (std::size_t d = 0; d < 13; ++d)
                m_sums[k + 1][d] = m_sums[k][d] + cepstra[k][d];
    }

    double at(double time) const
    {
        const std::size_t before = frameCentredFrom(time - kHalfWindow), middle = frameCentredFrom(time),
                          after = frameCentredFrom(time + kHalfWindow);
        if (before == middle || middle == after)
            return 0;
        double distance = 0;
        for (std::size_t d = 0; d < 13; ++d) {
            const double left = (m_sums[middle][d] - m_sums[before][d]) / double(middle - before);
            const double right = (m_sums[after][d] - m_sums[middle][d]) / double(after - middle);
            distance += (left - right) * (left - right);
        }
        return std::sqrt(distance);
    }

private:
    // The first frame whose window is centred at `time` or later.
    std::size_t frameCentredFrom(double time) const
    {
        const double frame = std::ceil((time - kSphinxWindow / 2) * kStepsPerSecond - 1e-9);
        return std::size_t(std::clamp(frame, 0.0, double(m_sums.size() - 1)));
    }

    std::vector<std::array<double, 13>> m_sums; // m_sums[k]: the sum of frames [0, k)
};

} // namespace

void refineBoundaries(std::vector<PhonemeTiming>& phonemes, std::span<const std::int16_t> samples)
{
    const SpectralChange change(samples);
    for (std::size_t i = 1; i < phonemes.size(); ++i) {
        const double boundary = phonemes[i].start;
        const double earliest = phonemes[i - 1].start + kShortest, latest = phonemes[i].end - kShortest;
        double best = boundary, bestChange = -1;
        for (int step = -kReachSteps; step <= kReachSteps; ++step) {
            const double time = boundary + double(step) / kStepsPerSecond;
            if (time < earliest || time > latest)
                continue;
            if (const double c = change.at(time); c > bestChange) {
                bestChange = c;
                best = time;
            }
        }
        phonemes[i - 1].end = phonemes[i].start = best;
    }
}

} // namespace thespis::core::speech
