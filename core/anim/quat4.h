#pragma once
// One quaternion (x y z w) or vector (x y z 0) in one four-float SIMD register (anim/simd.h),
// for chains of products walked every frame (the gaze's forward kinematics): the scalar
// Hamilton product is 16 multiplications in a long dependency chain, this is four vector
// multiplications whose shuffles of the right-hand side stay off the chain.

#include <cstring>

#include "anim/quat.h"
#include "anim/simd.h"

namespace thespis::core::anim::quat4 {

using simd::F4;

template <int X, int Y, int Z, int W>
inline F4 shuffle(F4 v)
{
    return __builtin_shufflevector(v, v, X, Y, Z, W);
}
template <int Lane>
inline F4 broadcast(F4 v)
{
    return shuffle<Lane, Lane, Lane, Lane>(v);
}

inline F4 load(const Quat& q) { return simd::load(&q.x); }
inline F4 identity() { return F4{0, 0, 0, 1}; }
inline F4 vector(const Vec3d& v) { return F4{float(v.x), float(v.y), float(v.z), 0}; }
inline Vec3d toVec3d(F4 v) { return {v[0], v[1], v[2]}; }
inline Quatd toQuatd(F4 q) { return {q[0], q[1], q[2], q[3]}; }
inline Quat toQuat(F4 q) { return {q[0], q[1], q[2], q[3]}; }
inline F4 conjugate(F4 q) { return q * F4{-1, -1, -1, 1}; }

/// The Hamilton product a b (anim/quat.h's, lane by lane).
inline F4 multiply(F4 a, F4 b)
{
    const F4 bx = shuffle<3, 2, 1, 0>(b) * F4{1, -1, 1, -1};
    const F4 by = shuffle<2, 3, 0, 1>(b) * F4{1, 1, -1, -1};
    const F4 bz = shuffle<1, 0, 3, 2>(b) * F4{-1, 1, 1, -1};
    return (broadcast<3>(a) * b + broadcast<0>(a) * bx) + (broadcast<1>(a) * by + broadcast<2>(a) * bz);
}

/// a × b of the x y z lanes; the w lane is 0.
inline F4 cross(F4 a, F4 b)
{
    return shuffle<1, 2, 0, 3>(a) * shuffle<2, 0, 1, 3>(b) - shuffle<2, 0, 1, 3>(a) * shuffle<1, 2, 0, 3>(b);
}

/// q v q* for a vector v (w lane 0), as anim::rotate: v + 2w (u × v) + u × 2(u × v).
inline F4 rotate(F4 q, F4 v)
{
    const F4 t = cross(q, v) * 2.0f;
    return v + broadcast<3>(q) * t + cross(q, t);
}

} // namespace thespis::core::anim::quat4
