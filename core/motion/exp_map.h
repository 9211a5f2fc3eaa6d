#pragma once
// The exponential map of rotations (Grassia 1998, the paper's §4.1 posture representation): a
// rotation of θ radians about a unit axis a is the 3-vector θ·a. Unlike quaternions it has no
// sign ambiguity and no unit constraint, so postures become plain vectors that PCA can take
// apart. logMap returns θ in [0, π] (the quaternion's sign does not matter); both directions are
// accurate near 0 (series) and near π (the axis comes from the vector part, never from θ).

#include <cmath>
#include <type_traits>

#include "anim/quat.h"

namespace thespis::core::motion {

template <class T>
inline anim::Vec3T<T> logMap(anim::QuatT<T> q)
{
    if (q.w < 0)
        q = anim::negate(q);
    const T s = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z);
    // θ/s with θ = 2·atan2(s, w); for tiny s, 2/w (1 − s²/3w²) is exact to rounding.
    const T k = s > T(1e-4) ? T(2) * std::atan2(s, q.w) / s : (T(2) / q.w) * (T(1) - s * s / (T(3) * q.w * q.w));
    return {q.x * k, q.y * k, q.z * k};
}

template <class T>
inline anim::QuatT<T> expMap(anim::Vec3T<T> v)
{
    const T theta2 = v.x * v.x + v.y * v.y + v.z * v.z;
    const T theta = std::sqrt(theta2);
    // One call for both (postures turn into frames 25 joints at a time, every frame).
    T sine, cosine;
    if constexpr (std::is_same_v<T, float>)
        ::sincosf(theta / 2, &sine, &cosine);
    else
        ::sincos(theta / 2, &sine, &cosine);
    // sin(θ/2)/θ, by its series where θ is tiny: 1/2 − θ²/48.
    const T k = theta > T(1e-4) ? sine / theta : T(0.5) - theta2 / T(48);
    return {v.x * k, v.y * k, v.z * k, cosine};
}

} // namespace thespis::core::motion
