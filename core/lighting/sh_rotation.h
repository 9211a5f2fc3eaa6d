#pragma once
// Rotation of real SH coefficients (conventions in sh.h) by the recursive algorithm of Ivanic &
// Ruedenberg, J. Phys. Chem. 100 (1996) 6342, with the errata of J. Phys. Chem. A 102 (1998)
// 9099. The band-1 matrix comes from the 3×3 rotation (rows and columns in the order y, z, x,
// i.e. m = −1, 0, 1); band l is built from band l−1 and band 1 by the u, v, w recursion.
// This is what the paper uses to rotate the light into every segment's frame each frame.

#include <array>
#include <span>

#include "anim/quat.h"
#include "lighting/sh.h"

namespace thespis::core::lighting {

using anim::Quatd;

/// Row-major 3×3 rotation matrix.
using Matrix3d = std::array<double, 9>;

namespace detail {
/// Whether apply uses the AVX2/FMA kernels (chosen at run time where the processor has them).
bool shRotationUsesAvx2();
/// For tests: true makes apply use the baseline kernels everywhere, so both are checked.
void forceShRotationBaseline(bool force);
} // namespace detail

/// Rotation matrix of a unit quaternion (anim::rotate(q, v) == matrix · v).
Matrix3d rotationMatrix(const Quatd& q);

/// Block-diagonal SH rotation up to a given order: band l is a (2l+1)×(2l+1) row-major block.
/// Fixed storage, so building and applying never allocate. If f'(ω) = f(R⁻¹ω) (the function
/// turned by R), then coefficients(f') = apply(coefficients(f)).
class ShRotation {
public:
    ShRotation() = default;
    /// Builds bands 0 … order−1 from a rotation matrix or a unit quaternion.
    ShRotation(int order, const Matrix3d& rotation) { build(order, rotation); }
    ShRotation(int order, const Quatd& rotation) { build(order, rotationMatrix(rotation)); }

    void build(int order, const Matrix3d& rotation);

    int order() const { return m_order; }
    /// Band l's matrix, (2l+1)², row-major; rows and columns m = −l … l.
    std::span<const double> band(int l) const;

    /// out = R · in, for order² coefficients (in and out must not overlap).
    void apply(std::span<const double> in, std::span<double> out) const;
    void apply(std::span<const float> in, std::span<float> out) const;
    /// Three channels at once (the common case: an RGB light): rotates bands 0 … order()−1 of
    /// `in` (in.order ≥ order()) into `out`, a different object, and sets out.order = order().
    void applyRgb(const ShRgb& in, ShRgb& out) const;

private:
    static constexpr int kStorage = [] {
        int total = 0;
        for (int l = 0; l < kMaxShOrder; ++l)
            total += (2 * l + 1) * (2 * l + 1);
        return total;
    }();
    int m_order = 0;
    std::array<double, kStorage> m_bands{};
};

} // namespace thespis::core::lighting
