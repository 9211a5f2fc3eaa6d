#include "motion/idle_builder.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <Eigen/Eigenvalues>

namespace thespis::core::motion {

namespace {

constexpr std::size_t kRootX = 75; // the root's sideways place in a whole-body posture (+X: the body's left)

std::vector<std::string> categoryNames(int count)
{
    if (count == 3)
        return {"left", "both", "right"};
    std::vector<std::string> names;
    for (int i = 0; i < count; ++i)
        names.push_back("rest " + std::to_string(i + 1));
    return names;
}

// Runs of equal labels shorter than `minimum` frames take the label of their longer neighbour,
// shortest first, until none is left.
void mergeShortRuns(std::vector<int>& labels, int minimum)
{
    for (;;) {
        std::size_t bestStart = 0, bestLength = labels.size() + 1;
        for (std::size_t i = 0; i < labels.size();) {
            std::size_t j = i;
            while (j < labels.size() && labels[j] == labels[i])
                ++j;
            if (j - i < std::size_t(minimum) && j - i < bestLength && !(i == 0 && j == labels.size()))
                bestStart = i, bestLength = j - i;
            i = j;
        }
        if (bestLength > labels.size())
            return;
        const std::size_t end = bestStart + bestLength;
        std::size_t before = 0, after = 0;
        for (std::size_t k = bestStart; k > 0 && labels[k - 1] == labels[bestStart - 1]; --k)
            ++before;
        for (std::size_t k = end; k < labels.size() && labels[k] == labels[end]; ++k)
            ++after;
        const int label = bestStart == 0 ? labels[end] : end == labels.size() ? labels[bestStart - 1]
                          : before >= after                                    ? labels[bestStart - 1]
                                                                               : labels[end];
        std::fill(labels.begin() + std::ptrdiff_t(bestStart), labels.begin() + std::ptrdiff_t(end), label);
    }
}

Result<void> checkRecording(const IdleRecording& recording, std::size_t d)
{
    if (recording.postures.size() % d != 0 || recording.postures.size() < 2 * d)
        return makeError(ErrorCode::InvalidArgument,
                         "The recording " + recording.name + " does not hold at least two whole-body postures.");
    if (!recording.labels.empty() && recording.labels.size() != recording.postures.size() / d)
        return makeError(ErrorCode::InvalidArgument, "The recording " + recording.name + " has " +
                                                         std::to_string(recording.labels.size()) + " labels for " +
                                                         std::to_string(recording.postures.size() / d) + " frames.");
    return {};
}

// The columns `columns` of every whole-body posture, posture after posture.
std::vector<float> selectColumns(std::span<const float> wholePostures, const std::vector<std::size_t>& columns)
{
    const std::size_t d = std::size_t(PostureLayout::of(PostureSet::WholeBody).size()), frames = wholePostures.size() / d;
    std::vector<float> out;
    out.reserve(frames * columns.size());
    for (std::size_t f = 0; f < frames; ++f)
        for (const std::size_t column : columns)
            out.push_back(wholePostures[f * d + column]);
    return out;
}

// The whole-body posture's columns of the upper body's joints, or of the others.
std::vector<std::size_t> jointColumns(bool keepUpper)
{
    const PostureLayout& whole = PostureLayout::of(PostureSet::WholeBody);
    const PostureLayout& upper = PostureLayout::of(PostureSet::UpperBody);
    std::vector<std::size_t> columns;
    for (std::size_t j = 0; j < whole.joints.size(); ++j)
        if ((std::find(upper.joints.begin(), upper.joints.end(), whole.joints[j]) != upper.joints.end()) == keepUpper)
            for (std::size_t k = 0; k < 3; ++k)
                columns.push_back(3 * j + k);
    return columns;
}

// The root's rotation and translation and the legs' joints.
std::vector<float> lowerBodyOf(std::span<const float> wholePostures)
{
    std::vector<std::size_t> columns = jointColumns(false);
    for (std::size_t k = 0; k < 3; ++k)
        columns.push_back(std::size_t(PostureLayout::of(PostureSet::WholeBody).size()) - 3 + k);
    return selectColumns(wholePostures, columns);
}

} // namespace

std::vector<float> upperBodyOf(std::span<const float> wholePostures)
{
    // Upper-body joints come in the same order in both layouts (H-Anim order, parents first).
    return selectColumns(wholePostures, jointColumns(true));
}

std::vector<int> findRestCategories(const IdleRecording& recording, const IdleBuildOptions& options)
{
    const std::size_t d = std::size_t(PostureLayout::of(PostureSet::WholeBody).size()), n = recording.postures.size() / d;
    std::size_t k = std::size_t(std::clamp(options.clusterPcs, 1, int(d)));
    const int categories = std::max(1, options.categoryCount);
    std::vector<int> labels(n, 0);
    const bool allLabelled = !recording.labels.empty() &&
                             std::all_of(recording.labels.begin(), recording.labels.end(), [&](int l) { return l >= 0; });
    if (allLabelled || n == 0) {
        labels = recording.labels;
    } else {
        // Features: the leading PCs of the recording's own lower body (the root and the legs,
        // where balance shows), scaled by √eigenvalue so that squared Euclidean distance is eq. 1's.
        const std::vector<float> lower = lowerBodyOf(recording.postures);
        const std::size_t dl = lower.size() / n;
        Eigen::MatrixXd data = Eigen::Map<const Eigen::MatrixXf>(lower.data(), Eigen::Index(dl), Eigen::Index(n))
                                   .cast<double>()
                                   .transpose();
        data.rowwise() -= data.colwise().mean();
        const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(data.transpose() * data / double(n));
        const Eigen::Index kk = Eigen::Index(std::min(k, dl));
        const Eigen::MatrixXd leading = solver.eigenvectors().rightCols(kk); // unit vectors, ascending
        const Eigen::MatrixXd projected = data * leading;                     // n × k, PC values
        k = std::size_t(kk);
        std::vector<float> features(n * k);
        for (std::size_t f = 0; f < n; ++f)
            for (std::size_t i = 0; i < k; ++i)
                features[f * k + i] = float(projected(Eigen::Index(f), Eigen::Index(i)) *
                                            std::sqrt(std::max(0.0, solver.eigenvalues()[Eigen::Index(dl - k + i)])));
        // Deterministic start: the frames at the 1/2c, 3/2c … quantiles of where the weight is.
        std::vector<std::size_t> bySide(n);
        std::iota(bySide.begin(), bySide.end(), 0);
        std::sort(bySide.begin(), bySide.end(), [&](std::size_t a, std::size_t b) {
            return recording.postures[a * d + kRootX] < recording.postures[b * d + kRootX];
        });
        std::vector<float> centres(std::size_t(categories) * k);
        for (int c = 0; c < categories; ++c) {
            const std::size_t f = bySide[std::min(n - 1, std::size_t((double(c) + 0.5) / categories * double(n)))];
            std::copy_n(features.begin() + std::ptrdiff_t(f * k), k, centres.begin() + std::ptrdiff_t(std::size_t(c) * k));
        }
        std::vector<double> sums(centres.size());
        std::vector<std::size_t> counts(std::size_t(categories), 0);
        for (int iteration = 0; iteration < 50; ++iteration) {
            bool changed = false;
            for (std::size_t f = 0; f < n; ++f) {
                int best = 0;
                float bestDistance = std::numeric_limits<float>::max();
                for (int c = 0; c < categories; ++c) {
                    float distance = 0;
                    for (std::size_t i = 0; i < k; ++i) {
                        const float delta = features[f * k + i] - centres[std::size_t(c) * k + i];
                        distance += delta * delta;
                    }
                    if (distance < bestDistance)
                        bestDistance = distance, best = c;
                }
                changed = changed || labels[f] != best || iteration == 0;
                labels[f] = best;
            }
            if (!changed)
                break;
            std::fill(sums.begin(), sums.end(), 0.0);
            std::fill(counts.begin(), counts.end(), 0);
            for (std::size_t f = 0; f < n; ++f) {
                ++counts[std::size_t(labels[f])];
                for (std::size_t i = 0; i < k; ++i)
                    sums[std::size_t(labels[f]) * k + i] += features[f * k + i];
            }
            for (std::size_t c = 0; c < std::size_t(categories); ++c)
                if (counts[c] > 0)
                    for (std::size_t i = 0; i < k; ++i)
                        centres[c * k + i] = float(sums[c * k + i] / double(counts[c]));
        }
        // Clusters ordered by where the weight is: the root furthest to the body's left first.
        std::vector<double> side(std::size_t(categories), 0.0);
        std::fill(counts.begin(), counts.end(), 0);
        for (std::size_t f = 0; f < n; ++f) {
            side[std::size_t(labels[f])] += recording.postures[f * d + kRootX];
            ++counts[std::size_t(labels[f])];
        }
        std::vector<int> order(std::size_t(categories), 0);
        std::iota(order.begin(), order.end(), 0);
        std::sort(order.begin(), order.end(), [&](int a, int b) {
            const auto meanOf = [&](int c) {
                return counts[std::size_t(c)] ? side[std::size_t(c)] / double(counts[std::size_t(c)]) : 0.0;
            };
            return meanOf(a) > meanOf(b);
        });
        std::vector<int> rank(std::size_t(categories), 0);
        for (int r = 0; r < categories; ++r)
            rank[std::size_t(order[std::size_t(r)])] = r;
        for (std::size_t f = 0; f < n; ++f) {
            labels[f] = rank[std::size_t(labels[f])];
            if (!recording.labels.empty() && recording.labels[f] >= 0)
                labels[f] = recording.labels[f];
        }
    }
    mergeShortRuns(labels, std::max(1, int(std::lround(options.minimumRest * options.frameRate))));
    return labels;
}

Result<IdleDatabase> buildIdleDatabase(const std::vector<IdleRecording>& recordings, const IdleBuildOptions& options,
                                       IdleBuildReport* report)
{
    const std::size_t d = std::size_t(PostureLayout::of(PostureSet::WholeBody).size());
    if (recordings.empty())
        return makeError(ErrorCode::InvalidArgument, "An idle motion database needs at least one recording.");
    if (options.categoryCount < 2 || options.categoryCount > 16)
        return makeError(ErrorCode::InvalidArgument, "The number of rest-posture categories must be between 2 and 16.");
    if (!(options.frameRate > 0) || !(options.minimumRest >= 0))
        return makeError(ErrorCode::InvalidArgument, "The frame rate must be positive and the minimum rest not negative.");
    for (const IdleRecording& recording : recordings)
        if (auto checked = checkRecording(recording, d); !checked)
            return checked.error();

    // Every recording re-centred on the mean posture of all.
    std::vector<IdleRecording> centred = recordings;
    std::vector<double> overall(d, 0.0);
    std::size_t totalFrames = 0;
    for (const IdleRecording& recording : recordings) {
        for (std::size_t i = 0; i < recording.postures.size(); ++i)
            overall[i % d] += recording.postures[i];
        totalFrames += recording.postures.size() / d;
    }
    for (IdleRecording& recording : centred) {
        std::vector<double> own(d, 0.0);
        for (std::size_t i = 0; i < recording.postures.size(); ++i)
            own[i % d] += recording.postures[i];
        const double frames = double(recording.postures.size() / d);
        for (std::size_t i = 0; i < recording.postures.size(); ++i)
            recording.postures[i] += float(overall[i % d] / double(totalFrames) - own[i % d] / frames);
    }

    IdleDatabase database;
    database.frameRate = options.frameRate;
    database.categories = categoryNames(options.categoryCount);
    if (options.bases) {
        database.whole = options.bases->whole;
        database.upper = options.bases->upper;
    } else {
        std::vector<float> all;
        for (const IdleRecording& recording : centred)
            all.insert(all.end(), recording.postures.begin(), recording.postures.end());
        auto whole = PostureBasis::train(PostureSet::WholeBody, all);
        if (!whole)
            return whole.error();
        auto upper = PostureBasis::train(PostureSet::UpperBody, upperBodyOf(all));
        if (!upper)
            return upper.error();
        database.whole = std::move(whole).value();
        database.upper = std::move(upper).value();
    }

    IdleBuildReport local;
    IdleBuildReport& out = report ? *report : local;
    out = {};
    out.counts.assign(std::size_t(options.categoryCount), std::vector<int>(std::size_t(options.categoryCount), 0));
    const std::size_t variationPcs = std::size_t(std::clamp(options.variationPcs, 0, int(d)));
    std::vector<double> variationSum(variationPcs, 0.0);
    std::size_t variationFrames = 0;
    for (const IdleRecording& recording : centred) {
        const std::size_t n = recording.postures.size() / d;
        const std::vector<int> labels = findRestCategories(recording, options);
        IdleBuildReport::Recording summary{recording.name, int(n)};
        // Rests: runs of one category; a segment goes from the middle of one to the middle of the next.
        std::vector<std::pair<std::size_t, std::size_t>> runs;
        for (std::size_t i = 0; i < n;) {
            std::size_t j = i;
            while (j < n && labels[j] == labels[i])
                ++j;
            runs.emplace_back(i, j);
            i = j;
        }
        summary.rests = int(runs.size());
        for (std::size_t r = 0; r + 1 < runs.size(); ++r) {
            const std::size_t from = (runs[r].first + runs[r].second) / 2;
            const std::size_t to = (runs[r + 1].first + runs[r + 1].second) / 2;
            IdleSegment segment;
            segment.from = labels[runs[r].first];
            segment.to = labels[runs[r + 1].first];
            segment.first = std::uint32_t(database.postures.size() / d);
            segment.count = std::uint32_t(to - from + 1);
            segment.source = recording.name;
            segment.sourceStart = float(double(from) / options.frameRate);
            database.postures.insert(database.postures.end(), recording.postures.begin() + std::ptrdiff_t(from * d),
                                     recording.postures.begin() + std::ptrdiff_t((to + 1) * d));
            database.segments.push_back(std::move(segment));
            ++out.counts[std::size_t(database.segments.back().from)][std::size_t(database.segments.back().to)];
            ++summary.segments;
        }
        out.recordings.push_back(summary);

        // Small variations: what a one-second moving average of each PC leaves.
        std::vector<float> pcs(n * variationPcs);
        for (std::size_t f = 0; f < n; ++f)
            database.whole.project(std::span<const float>(recording.postures).subspan(f * d, d),
                                   std::span<float>(pcs).subspan(f * variationPcs, variationPcs));
        const std::ptrdiff_t half = std::ptrdiff_t(std::lround(options.frameRate / 2));
        for (std::size_t f = 0; f < n; ++f) {
            const std::size_t lo = std::size_t(std::max<std::ptrdiff_t>(0, std::ptrdiff_t(f) - half));
            const std::size_t hi = std::min(n, f + std::size_t(half) + 1);
            for (std::size_t i = 0; i < variationPcs; ++i) {
                double average = 0;
                for (std::size_t g = lo; g < hi; ++g)
                    average += pcs[g * variationPcs + i];
                average /= double(hi - lo);
                const double residual = pcs[f * variationPcs + i] - average;
                variationSum[i] += residual * residual;
            }
        }
        variationFrames += n;
    }
    for (double sum : variationSum)
        database.variation.push_back(float(std::sqrt(sum / double(std::max<std::size_t>(1, variationFrames)))));
    for (int a = 0; a < options.categoryCount; ++a)
        for (int b = 0; b < options.categoryCount; ++b)
            if (a != b && out.counts[std::size_t(a)][std::size_t(b)] == 0)
                out.missing.push_back(database.categories[std::size_t(a)] + " → " + database.categories[std::size_t(b)]);
    if (database.segments.empty())
        return makeError(ErrorCode::InvalidArgument,
                         "No transition between rest postures was found in the recordings: each stays in one "
                         "category. Give recordings in which the weight shifts, or label their rests by hand.");
    if (auto indexed = database.index(); !indexed)
        return indexed.error();
    return database;
}

} // namespace thespis::core::motion
