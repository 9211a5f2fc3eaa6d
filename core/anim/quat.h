#pragma once
// Small quaternion and vector math for the animation engine. Quaternions are (x, y, z, w) with
// w the scalar part, Hamilton product, and rotate vectors as q v q*. Templates so that file
// conversions can run in double while frames are stored in float.

#include <algorithm>
#include <cmath>

namespace thespis::core::anim {

template <class T>
struct Vec3T {
    T x = 0, y = 0, z = 0;
    friend Vec3T operator+(Vec3T a, Vec3T b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
    friend Vec3T operator-(Vec3T a, Vec3T b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
    friend Vec3T operator*(Vec3T a, T s) { return {a.x * s, a.y * s, a.z * s}; }
    friend bool operator==(const Vec3T&, const Vec3T&) = default;
};

template <class T>
struct QuatT {
    T x = 0, y = 0, z = 0, w = 1;

    static QuatT identity() { return {}; }
    /// Rotation of `angle` radians about a unit `axis`.
    static QuatT fromAxisAngle(Vec3T<T> axis, T angle)
    {
        const T s = std::sin(angle / 2);
        return {axis.x * s, axis.y * s, axis.z * s, std::cos(angle / 2)};
    }
    friend bool operator==(const QuatT&, const QuatT&) = default;
};

template <class T> inline T dot(const Vec3T<T>& a, const Vec3T<T>& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

using Vec3 = Vec3T<float>;
using Quat = QuatT<float>;
using Vec3d = Vec3T<double>;
using Quatd = QuatT<double>;

template <class T>
inline QuatT<T> operator*(const QuatT<T>& a, const QuatT<T>& b)
{
    return {a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
            a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
            a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w,
            a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z};
}

template <class T> inline QuatT<T> conjugate(const QuatT<T>& q) { return {-q.x, -q.y, -q.z, q.w}; }
template <class T> inline T dot(const QuatT<T>& a, const QuatT<T>& b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z + a.w * b.w;
}
template <class T> inline QuatT<T> negate(const QuatT<T>& q) { return {-q.x, -q.y, -q.z, -q.w}; }

template <class T>
inline QuatT<T> normalize(const QuatT<T>& q)
{
    const T n = std::sqrt(dot(q, q));
    if (!(n > T(0)))
        return QuatT<T>::identity();
    const T inv = T(1) / n;
    return {q.x * inv, q.y * inv, q.z * inv, q.w * inv};
}

template <class T>
inline Vec3T<T> rotate(const QuatT<T>& q, Vec3T<T> v)
{
    // v' = v + 2w (u × v) + 2 u × (u × v), u = vector part
    const Vec3T<T> u{q.x, q.y, q.z};
    const Vec3T<T> t{T(2) * (u.y * v.z - u.z * v.y), T(2) * (u.z * v.x - u.x * v.z),
                     T(2) * (u.x * v.y - u.y * v.x)};
    return {v.x + q.w * t.x + (u.y * t.z - u.z * t.y), v.y + q.w * t.y + (u.z * t.x - u.x * t.z),
            v.z + q.w * t.z + (u.x * t.y - u.y * t.x)};
}

/// Angle in radians of the rotation taking a to b (0 … π), sign-independent. Uses atan2 of the
/// relative rotation, which stays accurate for tiny angles (acos of a dot product does not).
template <class T>
inline T angleBetween(const QuatT<T>& a, const QuatT<T>& b)
{
    const QuatT<T> r = conjugate(a) * b;
    const T v = std::sqrt(r.x * r.x + r.y * r.y + r.z * r.z);
    return T(2) * std::atan2(v, std::abs(r.w));
}

/// Spherical linear interpolation along the shorter arc.
template <class T>
inline QuatT<T> slerp(const QuatT<T>& a, QuatT<T> b, T u)
{
    T d = dot(a, b);
    if (d < 0) {
        b = negate(b);
        d = -d;
    }
    T s0, s1;
    if (d > T(0.9995)) { // nearly parallel: linear is exact to float precision
        s0 = 1 - u;
        s1 = u;
    } else {
        const T theta = std::acos(d);
        const T inv = T(1) / std::sin(theta);
        s0 = std::sin((1 - u) * theta) * inv;
        s1 = std::sin(u * theta) * inv;
    }
    return normalize(QuatT<T>{s0 * a.x + s1 * b.x, s0 * a.y + s1 * b.y, s0 * a.z + s1 * b.z,
                              s0 * a.w + s1 * b.w});
}

/// q raised to the power s: the same axis, s times the angle (s may exceed 1).
template <class T>
inline QuatT<T> power(const QuatT<T>& q0, T s)
{
    const QuatT<T> q = q0.w < 0 ? negate(q0) : q0;
    const T vlen = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z);
    if (vlen < T(1e-12))
        return QuatT<T>::identity();
    const T half = std::atan2(vlen, q.w) * s;
    const T k = std::sin(half) / vlen;
    return {q.x * k, q.y * k, q.z * k, std::cos(half)};
}

} // namespace thespis::core::anim
