#include "motion/posture_basis.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <Eigen/Eigenvalues>

namespace thespis::core::motion {

Result<PostureBasis> PostureBasis::train(PostureSet set, std::span<const float> postures)
{
    const std::size_t d = std::size_t(PostureLayout::of(set).size());
    if (postures.size() % d != 0)
        return makeError(ErrorCode::InvalidArgument, "The postures are not whole " + std::string(postureSetName(set)) +
                                                         " postures of " + std::to_string(d) + " numbers.");
    const std::size_t n = postures.size() / d;
    if (n <= d)
        return makeError(ErrorCode::InvalidArgument,
                         "Too few postures to train a " + std::string(postureSetName(set)) + " PCA: " + std::to_string(n) +
                             " frames for " + std::to_string(d) + " dimensions (it needs more frames than dimensions; "
                             "give longer or more clips).");
    if (const auto bad = std::find_if(postures.begin(), postures.end(), [](float v) { return !std::isfinite(v); });
        bad != postures.end())
        return makeError(ErrorCode::InvalidArgument, "Posture " + std::to_string((bad - postures.begin()) / d) +
                                                         " holds a value that is not a finite number.");

    // Mean and covariance in double: the data has 10⁴–10⁵ frames of values near each other.
    Eigen::VectorXd mean = Eigen::VectorXd::Zero(Eigen::Index(d));
    for (std::size_t i = 0; i < n; ++i)
        mean += Eigen::Map<const Eigen::VectorXf>(postures.data() + i * d, Eigen::Index(d)).cast<double>();
    mean /= double(n);
    Eigen::MatrixXd covariance = Eigen::MatrixXd::Zero(Eigen::Index(d), Eigen::Index(d));
    Eigen::VectorXd centred = Eigen::VectorXd::Zero(Eigen::Index(d));
    for (std::size_t i = 0; i < n; ++i) {
        centred = Eigen::Map<const Eigen::VectorXf>(postures.data() + i * d, Eigen::Index(d)).cast<double>() - mean;
        covariance.selfadjointView<Eigen::Lower>().rankUpdate(centred);
    }
    covariance = covariance.selfadjointView<Eigen::Lower>();
    covariance /= double(n - 1);
    if (covariance.trace() <= 0)
        return makeError(ErrorCode::InvalidArgument,
                         "The postures do not vary: every frame is the same posture, so there is nothing to analyse.");

    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(covariance);
    if (solver.info() != Eigen::Success)
        return makeError(ErrorCode::Internal, "The PCA's eigen decomposition did not converge.");
    // Eigen sorts ascending; PCs go largest first. Each vector's sign is fixed (its largest
    // coefficient positive) so that the same data always gives the same basis.
    PostureBasis basis;
    basis.m_set = set;
    basis.m_samples = n;
    basis.m_mean.assign(mean.data(), mean.data() + d);
    basis.m_eigenvalues.resize(d);
    basis.m_components.resize(d * d);
    for (std::size_t i = 0; i < d; ++i) {
        const Eigen::Index source = Eigen::Index(d - 1 - i);
        basis.m_eigenvalues[i] = float(std::max(0.0, solver.eigenvalues()[source]));
        Eigen::VectorXd v = solver.eigenvectors().col(source);
        Eigen::Index largest = 0;
        v.cwiseAbs().maxCoeff(&largest);
        if (v[largest] < 0)
            v = -v;
        for (std::size_t k = 0; k < d; ++k)
            basis.m_components[i * d + k] = float(v[Eigen::Index(k)]);
    }
    return basis;
}

Result<PostureBasis> PostureBasis::fromParts(PostureSet set, std::uint64_t sampleCount, std::vector<float> mean,
                                             std::vector<float> eigenvalues, std::vector<float> components)
{
    const std::size_t d = std::size_t(PostureLayout::of(set).size());
    if (mean.size() != d || eigenvalues.size() != d || components.size() != d * d)
        return makeError(ErrorCode::InvalidArgument, "A " + std::string(postureSetName(set)) + " basis has " +
                                                         std::to_string(d) + " dimensions.");
    const auto finite = [](const std::vector<float>& values) {
        return std::all_of(values.begin(), values.end(), [](float v) { return std::isfinite(v); });
    };
    if (!finite(mean) || !finite(eigenvalues) || !finite(components))
        return makeError(ErrorCode::InvalidArgument, "The basis holds a value that is not a finite number.");
    for (std::size_t i = 0; i < d; ++i) {
        if (eigenvalues[i] < 0 || (i > 0 && eigenvalues[i] > eigenvalues[i - 1]))
            return makeError(ErrorCode::InvalidArgument,
                             "The basis's eigenvalues are not non-negative and largest first (at PC " +
                                 std::to_string(i + 1) + ").");
        const float* row = components.data() + i * d;
        const double norm = std::sqrt(std::inner_product(row, row + d, row, 0.0));
        if (std::abs(norm - 1) > 1e-3)
            return makeError(ErrorCode::InvalidArgument,
                             "PC " + std::to_string(i + 1) + "'s vector is not of unit length (" + std::to_string(norm) + ").");
    }
    PostureBasis basis;
    basis.m_set = set;
    basis.m_samples = sampleCount;
    basis.m_mean = std::move(mean);
    basis.m_eigenvalues = std::move(eigenvalues);
    basis.m_components = std::move(components);
    return basis;
}

std::span<const float> PostureBasis::component(int i) const
{
    const std::size_t d = m_mean.size();
    return {m_components.data() + std::size_t(i) * d, d};
}

void PostureBasis::project(std::span<const float> posture, std::span<float> pcs) const
{
    const std::size_t d = m_mean.size();
    const std::size_t k = std::min(pcs.size(), d);
    for (std::size_t i = 0; i < k; ++i) {
        const float* row = m_components.data() + i * d;
        float sum = 0;
        for (std::size_t j = 0; j < d; ++j)
            sum += row[j] * (posture[j] - m_mean[j]);
        pcs[i] = sum;
    }
}

void PostureBasis::reconstruct(std::span<const float> pcs, std::span<float> posture) const
{
    const std::size_t d = m_mean.size();
    const std::size_t k = std::min(pcs.size(), d);
    std::copy(m_mean.begin(), m_mean.end(), posture.begin());
    for (std::size_t i = 0; i < k; ++i) {
        const float* row = m_components.data() + i * d;
        const float value = pcs[i];
        for (std::size_t j = 0; j < d; ++j)
            posture[j] += value * row[j];
    }
}

double PostureBasis::explainedVariance(int k) const
{
    const double total = std::accumulate(m_eigenvalues.begin(), m_eigenvalues.end(), 0.0);
    const std::size_t n = std::min(std::size_t(std::max(k, 0)), m_eigenvalues.size());
    return total > 0 ? std::accumulate(m_eigenvalues.begin(), m_eigenvalues.begin() + std::ptrdiff_t(n), 0.0) / total : 0;
}

float PostureBasis::distance(std::span<const float> p, std::span<const float> q, int k) const
{
    float sum = 0;
    for (int i = 0; i < k; ++i) {
        const float d = p[std::size_t(i)] - q[std::size_t(i)];
        sum += m_eigenvalues[std::size_t(i)] * d * d;
    }
    return std::sqrt(sum);
}

} // namespace thespis::core::motion
