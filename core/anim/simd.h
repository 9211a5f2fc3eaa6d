#pragma once
// Four-float SIMD vectors through GCC/Clang vector extensions (SSE on x86-64, NEON on ARM, plain
// code elsewhere), for the engine's hot loops. Quaternions are stored x y z w per joint; the
// loops transpose four joints at a time into one vector per component, so that dot products and
// accumulations are vertical operations.

#include <cmath>
#include <cstring>
#if defined(__SSE__)
#include <xmmintrin.h>
#endif

namespace thespis::core::anim::simd {

using F4 = float __attribute__((vector_size(16)));
using I4 = int __attribute__((vector_size(16)));

inline F4 load(const float* p)
{
    F4 v;
    std::memcpy(&v, p, sizeof v);
    return v;
}
inline void store(float* p, F4 v) { std::memcpy(p, &v, sizeof v); }
inline F4 splat(float x) { return F4{x, x, x, x}; }
inline F4 max(F4 a, F4 b) { return a > b ? a : b; }
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

} // namespace thespis::core::anim::simd
