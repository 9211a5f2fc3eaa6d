#pragma once
// Four- and eight-float SIMD vectors through GCC/Clang vector extensions (SSE or AVX on x86-64,
// NEON on ARM, plain code elsewhere), for the engine's hot loops. Quaternions are stored x y z w
// per joint; the loops transpose four or eight joints at a time into one vector per component,
// so that dot products and accumulations are vertical operations.

#include <cmath>
#include <cstdint>
#include <cstring>
#if defined(__SSE__)
#include <xmmintrin.h>
#endif

#include "anim/simd_types.h"

namespace thespis::core::anim::simd {

/// Unaligned load and store of a whole vector, and a vector of one value (F4 unless told).
template <class V = F4>
inline V load(const float* p)
{
    V v;
    std::memcpy(&v, p, sizeof v);
    return v;
}
template <class V>
inline void store(float* p, V v)
{
    std::memcpy(p, &v, sizeof v);
}
template <class V = F4>
inline V splat(float x)
{
    // x − 0 is x for every x; V{} + x is not: 0 + (−0) is +0, which would lose a sign-bit mask.
    return x - V{};
}
template <class V>
inline V max(V a, V b)
{
    return a > b ? a : b;
}
inline F4 sqrt(F4 v)
{
#if defined(__SSE__)
    return F4(_mm_sqrt_ps(__m128(v)));
#else
    return F4{std::sqrt(v[0]), std::sqrt(v[1]), std::sqrt(v[2]), std::sqrt(v[3])};
#endif
}
/// True when any lane of a comparison mask is set.
inline bool any(I4 mask)
{
    return (mask[0] | mask[1] | mask[2] | mask[3]) != 0;
}
/// Lanes of `a` where mask is set (all bits), else lanes of `b`.
inline F4 select(I4 mask, F4 a, F4 b) { return mask ? a : b; }

/// Four x y z w quaternions (rows) ↔ four component vectors (columns).
inline void transpose(F4 a, F4 b, F4 c, F4 d, F4& x, F4& y, F4& z, F4& w)
{
    const F4 t0 = __builtin_shufflevector(a, b, 0, 4, 1, 5);
    const F4 t1 = __builtin_shufflevector(a, b, 2, 6, 3, 7);
    const F4 t2 = __builtin_shufflevector(c, d, 0, 4, 1, 5);
    const F4 t3 = __builtin_shufflevector(c, d, 2, 6, 3, 7);
    x = __builtin_shufflevector(t0, t2, 0, 1, 4, 5);
    y = __builtin_shufflevector(t0, t2, 2, 3, 6, 7);
    z = __builtin_shufflevector(t1, t3, 0, 1, 4, 5);
    w = __builtin_shufflevector(t1, t3, 2, 3, 6, 7);
}

/// Loads quaternions [4b, 4b + 4) of an x y z w array as component vectors.
inline void loadQuats(const float* quats, F4& x, F4& y, F4& z, F4& w)
{
    transpose(load(quats), load(quats + 4), load(quats + 8), load(quats + 12), x, y, z, w);
}
inline void storeQuats(float* quats, F4 x, F4 y, F4 z, F4 w)
{
    F4 a, b, c, d;
    transpose(x, y, z, w, a, b, c, d); // the transpose is its own inverse
    store(quats, a);
    store(quats + 4, b);
    store(quats + 8, c);
    store(quats + 12, d);
}

// ---- Eight lanes (one AVX register where the function is compiled for AVX) ------------------------

inline F8 select(I8 mask, F8 a, F8 b) { return mask ? a : b; }
inline bool any(I8 mask)
{
    const I4 half = __builtin_shufflevector(mask, mask, 0, 1, 2, 3) | __builtin_shufflevector(mask, mask, 4, 5, 6, 7);
    return any(half);
}
/// 1/√v to float rounding (a few ulps), from plain arithmetic only: an estimate read off the
/// float's bits (exponent halved and negated) refined by three Newton steps (relative error
/// 3.4e-2 → 1.8e-3 → 5e-6 → float rounding). Not the hardware's reciprocal-square-root estimate, whose
/// bits differ between CPU models (and so would poses, bakes and golden files); and several
/// times the throughput of a square root and a division. Every x86-64 CPU gives the same bits.
inline F8 reciprocalSqrt(F8 v)
{
    I8 bits;
    std::memcpy(&bits, &v, sizeof bits);
    bits = 0x5f375a86 - (bits >> 1);
    F8 estimate;
    std::memcpy(&estimate, &bits, sizeof estimate);
    const F8 halfV = splat<F8>(0.5f) * v;
    estimate = estimate * (splat<F8>(1.5f) - halfV * estimate * estimate);
    estimate = estimate * (splat<F8>(1.5f) - halfV * estimate * estimate);
    return estimate * (splat<F8>(1.5f) - halfV * estimate * estimate);
}
/// The same for one float, bit for bit as each lane of the vector one.
inline float reciprocalSqrt(float v)
{
    std::int32_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    bits = 0x5f375a86 - (bits >> 1);
    float estimate;
    std::memcpy(&estimate, &bits, sizeof estimate);
    const float halfV = 0.5f * v;
    estimate = estimate * (1.5f - halfV * estimate * estimate);
    estimate = estimate * (1.5f - halfV * estimate * estimate);
    return estimate * (1.5f - halfV * estimate * estimate);
}

/// The 4×4 transpose within each 128-bit half (AVX shuffles do not cross halves).
inline void transposeHalves(F8 a, F8 b, F8 c, F8 d, F8& x, F8& y, F8& z, F8& w)
{
    const F8 t0 = __builtin_shufflevector(a, b, 0, 8, 1, 9, 4, 12, 5, 13);
    const F8 t1 = __builtin_shufflevector(a, b, 2, 10, 3, 11, 6, 14, 7, 15);
    const F8 t2 = __builtin_shufflevector(c, d, 0, 8, 1, 9, 4, 12, 5, 13);
    const F8 t3 = __builtin_shufflevector(c, d, 2, 10, 3, 11, 6, 14, 7, 15);
    x = __builtin_shufflevector(t0, t2, 0, 1, 8, 9, 4, 5, 12, 13);
    y = __builtin_shufflevector(t0, t2, 2, 3, 10, 11, 6, 7, 14, 15);
    z = __builtin_shufflevector(t1, t3, 0, 1, 8, 9, 4, 5, 12, 13);
    w = __builtin_shufflevector(t1, t3, 2, 3, 10, 11, 6, 7, 14, 15);
}

/// Loads quaternions [8b, 8b + 8) of an x y z w array as component vectors whose lanes hold the
/// joints in the order 0 2 4 6 1 3 5 7 (what the in-half transpose gives); per-joint values
/// (weights) go through toQuatLanes to match, and back through toJointOrder.
inline void loadQuats8(const float* quats, F8& x, F8& y, F8& z, F8& w)
{
    transposeHalves(load<F8>(quats), load<F8>(quats + 8), load<F8>(quats + 16), load<F8>(quats + 24), x, y, z, w);
}
inline void storeQuats8(float* quats, F8 x, F8 y, F8 z, F8 w)
{
    F8 a, b, c, d;
    transposeHalves(x, y, z, w, a, b, c, d);
    store(quats, a);
    store(quats + 8, b);
    store(quats + 16, c);
    store(quats + 24, d);
}
inline F8 toQuatLanes(F8 v) { return __builtin_shufflevector(v, v, 0, 2, 4, 6, 1, 3, 5, 7); }
inline F8 toJointOrder(F8 v) { return __builtin_shufflevector(v, v, 0, 4, 1, 5, 2, 6, 3, 7); }

} // namespace thespis::core::anim::simd
