#pragma once
// PCA of a posture database (paper §4.1): the mean posture, and the eigenvectors of the
// postures' covariance ordered by eigenvalue, so that low principal components (PCs) hold what
// the data does most and high ones what it hardly ever does. Projection both ways, the variance
// a number of PCs explains, and the paper's weighted PC distance (eq. 1):
//   d(p, q) = sqrt( Σ_{i<k} w_i (p_i − q_i)² ),  w_i = the eigenvalues,
// which with all PCs equals the distance of the postures under their covariance, and with a
// few PCs is a cheap approximation of it.
//
// Components are stored row after row (one PC's coefficients contiguous), so projecting onto k
// PCs and reconstructing from them are k dot products and k multiply-adds over flat memory.

#include <cstdint>
#include <span>
#include <vector>

#include "motion/posture.h"
#include "util/error.h"

namespace thespis::core::motion {

class PostureBasis {
public:
    PostureBasis() = default;
    /// PCA of `postures`: frameCount × layout.size() floats, posture after posture. Needs more
    /// postures than dimensions, all finite, and a set that varies (errors say so).
    static Result<PostureBasis> train(PostureSet set, std::span<const float> postures);
    /// A basis from stored parts (a file): `components` is dimension² floats, row by row.
    static Result<PostureBasis> fromParts(PostureSet set, std::uint64_t sampleCount, std::vector<float> mean,
                                          std::vector<float> eigenvalues, std::vector<float> components);

    PostureSet set() const { return m_set; }
    const PostureLayout& layout() const { return PostureLayout::of(m_set); }
    int dimension() const { return int(m_mean.size()); }
    std::uint64_t sampleCount() const { return m_samples; }
    const std::vector<float>& mean() const { return m_mean; }
    /// Variances along each PC, largest first.
    const std::vector<float>& eigenvalues() const { return m_eigenvalues; }
    /// PC i's unit eigenvector (dimension() floats).
    std::span<const float> component(int i) const;
    const std::vector<float>& components() const { return m_components; }

    /// The first pcs.size() PC values of a posture: pcs_i = v_iᵀ (posture − mean).
    void project(std::span<const float> posture, std::span<float> pcs) const;
    /// The posture of PC values (missing higher PCs are 0): mean + Σ pcs_i v_i.
    void reconstruct(std::span<const float> pcs, std::span<float> posture) const;
    /// The fraction of the data's variance the first k PCs explain.
    double explainedVariance(int k) const;
    /// Eq. 1 over the first k PCs of two PC vectors (each at least k long).
    float distance(std::span<const float> p, std::span<const float> q, int k) const;

private:
    PostureSet m_set = PostureSet::WholeBody;
    std::uint64_t m_samples = 0;
    std::vector<float> m_mean, m_eigenvalues, m_components;
};

} // namespace thespis::core::motion
