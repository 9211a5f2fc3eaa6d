#pragma once
// Four floats processed together, one SIMD register (SSE on x86-64, NEON on arm64), through the
// GCC/Clang vector extension. It has just the operations the bake's hot loops need, so that the
// same template code (sh.cpp's polynomial SH forms, the bake's sampler) handles four directions
// at once. Every operation is the IEEE one lane by lane: results equal scalar code bit for bit.

#include <bit>
#include <cmath>
#include <cstring>
#include <type_traits>

#if defined(__SSE__)
#include <xmmintrin.h>
#endif

namespace thespis::core::lighting {

struct Mask4;

struct Float4 {
    using Vector = float __attribute__((vector_size(16)));
    using Bits = int __attribute__((vector_size(16)));
    Vector v;

    Float4() = default;
    Float4(Vector vector) : v(vector) {}
    /// Broadcast: implicit, so constants mix with vectors as in scalar code (2 * x, T(k) …).
    template <class Scalar>
        requires std::is_arithmetic_v<Scalar>
    Float4(Scalar s) : v{float(s), float(s), float(s), float(s)}
    {
    }

    static Float4 load(const float* p)
    {
        Vector loaded;
        std::memcpy(&loaded, p, sizeof loaded);
        return loaded;
    }
    void store(float* p) const { std::memcpy(p, &v, sizeof v); }
    float operator[](int lane) const { return v[lane]; }
    /// ((v0 + v1) + (v2 + v3)): a fixed order, so the result only depends on the lanes.
    float sum() const { return (v[0] + v[1]) + (v[2] + v[3]); }

    friend Float4 operator+(Float4 a, Float4 b) { return a.v + b.v; }
    friend Float4 operator-(Float4 a, Float4 b) { return a.v - b.v; }
    friend Float4 operator*(Float4 a, Float4 b) { return a.v * b.v; }
    friend Float4 operator/(Float4 a, Float4 b) { return a.v / b.v; }
    Float4& operator+=(Float4 b)
    {
        v += b.v;
        return *this;
    }
    friend Mask4 operator>(Float4 a, Float4 b);
    friend Mask4 operator==(Float4 a, Float4 b);
};

/// Per-lane booleans (all bits set or clear), from comparisons.
struct Mask4 {
    Float4::Bits bits;
};

inline Mask4 operator>(Float4 a, Float4 b) { return {a.v > b.v}; }
inline Mask4 operator==(Float4 a, Float4 b) { return {a.v == b.v}; }

/// Lane by lane: mask ? a : b.
inline Float4 select(Mask4 mask, Float4 a, Float4 b)
{
    const Float4::Bits bits = (mask.bits & std::bit_cast<Float4::Bits>(a.v)) | (~mask.bits & std::bit_cast<Float4::Bits>(b.v));
    return std::bit_cast<Float4::Vector>(bits);
}

inline Float4 abs(Float4 a) { return std::bit_cast<Float4::Vector>(std::bit_cast<Float4::Bits>(a.v) & 0x7fffffff); }

/// std::max(b, a) of each lane, i.e. a > b ? a : b (NaN in a gives b, as std::max(b, a)).
inline Float4 max(Float4 b, Float4 a) { return select(a > b, a, b); }

inline Float4 sqrt(Float4 a)
{
#if defined(__SSE__)
    return Float4::Vector(_mm_sqrt_ps(a.v));
#else
    return Float4::Vector{std::sqrt(a.v[0]), std::sqrt(a.v[1]), std::sqrt(a.v[2]), std::sqrt(a.v[3])};
#endif
}

} // namespace thespis::core::lighting
