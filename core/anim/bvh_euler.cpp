// BVH Euler angles ↔ quaternions (bvh_euler.h).

#include "anim/bvh_euler.h"

#include <cmath>
#include <numbers>

namespace thespis::core::anim::bvh {
namespace {

Matrix3 multiply(const Matrix3& a, const Matrix3& b)
{
    Matrix3 m{};
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            m[r][c] = a[r][0] * b[0][c] + a[r][1] * b[1][c] + a[r][2] * b[2][c];
    return m;
}

Matrix3 axisMatrix(int axis, double radians)
{
    return toMatrix(axisRotation(axis, radians * 180.0 / std::numbers::pi));
}

} // namespace

Quatd axisRotation(int axis, double degrees)
{
    const double half = std::fmod(degrees, 360.0) * (std::numbers::pi / 360.0);
    Quatd q{0, 0, 0, std::cos(half)};
    (axis == 0 ? q.x : axis == 1 ? q.y : q.z) = std::sin(half);
    return q;
}

Matrix3 toMatrix(const Quatd& q0)
{
    const Quatd q = normalize(q0);
    const double x = q.x, y = q.y, z = q.z, w = q.w;
    return {{{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
             {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
             {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}}};
}

std::array<double, 3> decompose(const Matrix3& r, int i, int j, int k, double lockedC)
{
    const double s = (j - i + 3) % 3 == 1 ? 1.0 : -1.0; // +1 for cyclic orders (XYZ, YZX, ZXY)
    const double cosB = std::hypot(r[i][i], r[i][j]);
    const double b = std::atan2(s * r[i][k], cosB);
    if (cosB > 1e-9) {
        const double a = std::atan2(-s * r[j][k], r[k][k]);
        const double c = std::atan2(-s * r[i][j], r[i][i]);
        return {a, b, c};
    }
    const Matrix3 m = multiply(r, axisMatrix(k, -lockedC)); // = R_i(a)·R_j(b)
    const double a = std::atan2(s * m[k][j], m[j][j]);
    return {a, b, lockedC};
}

double unwrapNear(double angle, double reference)
{
    const double turn = 2 * std::numbers::pi;
    return angle + turn * std::round((reference - angle) / turn);
}

} // namespace thespis::core::anim::bvh
