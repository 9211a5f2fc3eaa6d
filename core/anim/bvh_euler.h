#pragma once
// Private to the BVH reader and writer: BVH Euler angles. They are intrinsic, the first channel
// outermost: "Zrotation Xrotation Yrotation" means R = Rz·Rx·Ry, applied to column vectors in
// the parent's frame, so the quaternion is qz·qx·qy (Hamilton product, q v q*).

#include <array>

#include "anim/quat.h"

namespace thespis::core::anim::bvh {

/// The rotation of one channel: `degrees` about axis 0, 1 or 2 (X, Y, Z).
Quatd axisRotation(int axis, double degrees);

using Matrix3 = std::array<std::array<double, 3>, 3>;

Matrix3 toMatrix(const Quatd& q);

/// Euler angles (radians) of R = R_i(a)·R_j(b)·R_k(c) for a permutation (i, j, k) of the axes.
/// b is in [−π/2, π/2]. In gimbal lock (|b| = π/2) only a ± c is defined: c is then kept at
/// `lockedC` (the previous frame's value, so curves stay continuous) and a takes the rest.
std::array<double, 3> decompose(const Matrix3& r, int i, int j, int k, double lockedC);

/// `angle` plus the whole turns that bring it nearest to `reference`.
double unwrapNear(double angle, double reference);

} // namespace thespis::core::anim::bvh
