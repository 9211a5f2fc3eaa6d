#include "anim/frame_blender.h"

#include "anim/simd.h"

#include <algorithm>
#include <cmath>

namespace thespis::core::anim {
namespace {

// The loops below run input by input over all elements: the elements are independent, so the
// CPU overlaps their work (running per element over the inputs would chain every step).

// Σ wᵢ·xᵢ into out and Σ wᵢ into totals, for elements [first, first + count) of Width floats.
template <int Width>
void accumulateLinear(std::span<const BlendInput> inputs, float* __restrict out, float* __restrict totals,
                      int first, int count, std::size_t offset)
{
    float* __restrict sum = out + offset;
    float* __restrict total = totals + first;
    if (inputs.empty()) {
        std::fill_n(sum, std::size_t(count) * Width, 0.0f);
        std::fill_n(total, std::size_t(count), 0.0f);
        return;
    }
    for (std::size_t i = 0; i < inputs.size(); ++i) {
        const float* __restrict x = inputs[i].values + offset;
        const float* __restrict w = inputs[i].weights + first;
        for (int e = 0; e < count; ++e) {
            const float we = std::max(w[e], 0.0f);
            total[e] = i == 0 ? we : total[e] + we; // the first input starts the sums
            for (int c = 0; c < Width; ++c)
                sum[e * Width + c] = i == 0 ? we * x[e * Width + c] : sum[e * Width + c] + we * x[e * Width + c];
        }
    }
}

// Applies the normalized rule to accumulated sums: divide by W ≥ 1, else fill with rest (or,
// without filling, divide by any W > 0).
template <int Width>
void finishLinear(std::span<const float> rest, float* __restrict out, const float* __restrict totals,
                  bool fill, int first, int count, std::size_t offset)
{
    for (int e = 0; e < count; ++e) {
        const float total = totals[first + e];
        float* x = out + offset + std::size_t(e * Width);
        const float* base = rest.data() + offset + std::size_t(e * Width);
        if (total >= 1.0f || (!fill && total > 0.0f)) {
            const float inv = 1.0f / total;
            for (int c = 0; c < Width; ++c)
                x[c] *= inv;
        } else {
            const float restWeight = 1.0f - total;
            for (int c = 0; c < Width; ++c)
                x[c] += restWeight * base[c];
        }
    }
}

template <int Width>
void blendLinearElements(std::span<const BlendInput> inputs, std::span<const float> rest, std::span<float> out,
                         float* totals, bool fill, int first, int count, std::size_t offset)
{
    accumulateLinear<Width>(inputs, out.data(), totals, first, count, offset);
    finishLinear<Width>(rest, out.data(), totals, fill, first, count, offset);
}

void overlayLinear(const BlendInput& input, std::span<float> out, int firstElement, int elementCount,
                   std::size_t offset, int width)
{
    for (int e = 0; e < elementCount; ++e) {
        const float w = input.weights[firstElement + e];
        if (!(w > 0))
            continue;
        const std::size_t base = offset + std::size_t(e) * std::size_t(width);
        for (int c = 0; c < width; ++c) {
            float& o = out[base + std::size_t(c)];
            o = w >= 1.0f ? input.values[base + std::size_t(c)] : o + w * (input.values[base + std::size_t(c)] - o);
        }
    }
}

void addLinear(const BlendInput& input, std::span<const float> reference, std::span<float> out,
               int firstElement, int elementCount, std::size_t offset, int width)
{
    for (int e = 0; e < elementCount; ++e) {
        const float w = input.weights[firstElement + e];
        if (!(w > 0))
            continue;
        const std::size_t base = offset + std::size_t(e) * std::size_t(width);
        for (int c = 0; c < width; ++c)
            out[base + std::size_t(c)] += w * (input.values[base + std::size_t(c)] - reference[base + std::size_t(c)]);
    }
}

// Translations and scalars are linear in both blenders.
void blendTail(const FrameLayout& layout, std::span<const BlendInput> inputs, std::span<const float> rest,
               std::span<float> out, float* totals, bool fill)
{
    const int r = layout.rotationCount(), t = layout.translationCount();
    blendLinearElements<3>(inputs, rest, out, totals, fill, r, t, layout.translationOffset());
    blendLinearElements<1>(inputs, rest, out, totals, fill, r + t, layout.scalarCount(), layout.scalarOffset());
}

void overlayTail(const FrameLayout& layout, const BlendInput& input, std::span<float> out)
{
    const int r = layout.rotationCount(), t = layout.translationCount();
    overlayLinear(input, out, r, t, layout.translationOffset(), 3);
    overlayLinear(input, out, r + t, layout.scalarCount(), layout.scalarOffset(), 1);
}

void addTail(const FrameLayout& layout, const BlendInput& input, std::span<const float> reference, std::span<float> out)
{
    const int r = layout.rotationCount(), t = layout.translationCount();
    addLinear(input, reference, out, r, t, layout.translationOffset(), 3);
    addLinear(input, reference, out, r + t, layout.scalarCount(), layout.scalarOffset(), 1);
}

// Function multiversioning: the blend's eight-joint loop gets an AVX2 build, chosen at load time
// on CPUs that have it, and a baseline build for the others (the only one without
// THESPIS_CPU_DISPATCH, which is how the sanitizer build tests it). Both round alike: this file
// is built without contracting a·b + c into FMA, and 1/√x comes from plain arithmetic
// (simd::reciprocalSqrt), not a hardware estimate, so a pose is the same bit for bit on every
// x86-64 CPU (tested against a scalar reference). GCC only: Clang 14 refuses
// the AVX clone's calls to the inline simd helpers, which it compiles without AVX.
#if defined(__x86_64__) && defined(THESPIS_CPU_DISPATCH) && !defined(__clang__)
#define THESPIS_AVX2_CLONE [[gnu::target_clones("arch=x86-64-v3", "default")]]
#else
#define THESPIS_AVX2_CLONE
#endif

/// Adds one input's rotations into the accumulator (see blendRotations); the first input
/// initializes it.
template <bool First>
[[gnu::always_inline]] inline void accumulateRotations(const BlendInput& input, float* __restrict acc, float* __restrict totals,
                                                       int blocked, int rotations)
{
    using namespace simd;
    const F8 zero = splat<F8>(0.0f);
    const I8 signBit = (I8)splat<F8>(-0.0f);
    for (int r = 0; r < blocked; r += 8) {
        float* a = acc + 4 * std::size_t(r);
        F8 x, y, z, qw;
        loadQuats8(input.values + 4 * std::size_t(r), x, y, z, qw);
        const F8 weight = max(toQuatLanes(load<F8>(input.weights + r)), zero);
        if constexpr (First) {
            store(a, weight * x);
            store(a + 8, weight * y);
            store(a + 16, weight * z);
            store(a + 24, weight * qw);
            store(totals + r, weight);
        } else {
            const F8 ax = load<F8>(a), ay = load<F8>(a + 8), az = load<F8>(a + 16), aw = load<F8>(a + 24);
            // Align with the sum so far, so that q and −q (the same rotation) add up, not cancel.
            const F8 d = (ax * x + ay * y) + (az * z + aw * qw);
            const F8 s = (F8)((I8)weight ^ ((I8)d & signBit)); // weight with d's sign
            store(a, ax + s * x);
            store(a + 8, ay + s * y);
            store(a + 16, az + s * z);
            store(a + 24, aw + s * qw);
            store(totals + r, load<F8>(totals + r) + weight);
        }
    }
    for (int r = blocked; r < rotations; ++r) {
        const std::size_t k = 4 * std::size_t(r);
        const float* q = input.values + k;
        const float weight = std::max(input.weights[r], 0.0f);
        if constexpr (First) {
            for (int c = 0; c < 4; ++c)
                acc[k + std::size_t(c)] = weight * q[c];
            totals[r] = weight;
        } else {
            const float d = (acc[k] * q[0] + acc[k + 1] * q[1]) + (acc[k + 2] * q[2] + acc[k + 3] * q[3]);
            const float s = std::signbit(d) ? -weight : weight; // as the lanes flip it
            for (int c = 0; c < 4; ++c)
                acc[k + std::size_t(c)] += s * q[c];
            totals[r] += weight;
        }
    }
}

/// The quaternion blend of all joints. out serves as the accumulator: per block of eight joints
/// x[8] y[8] z[8] w[8] (simd::loadQuats8's lanes), then the joints left over as x y z w; totals
/// are in the same lanes until the end. Input by input over all joints, since the joints are
/// independent and the CPU overlaps their work (joint by joint over the inputs would chain every
/// step); then, per joint, the rest fill (total < 1, or nothing at all without filling),
/// normalization, and back to x y z w in joint order.
THESPIS_AVX2_CLONE
void blendRotations(std::span<const BlendInput> inputs, const float* __restrict rest, float* __restrict out,
                    float* __restrict totals, int rotations, bool fill)
{
    using namespace simd;
    const int blocked = rotations / 8 * 8;
    if (inputs.empty()) {
        std::fill_n(out, 4 * std::size_t(rotations), 0.0f);
        std::fill_n(totals, std::size_t(rotations), 0.0f);
    } else {
        accumulateRotations<true>(inputs.front(), out, totals, blocked, rotations);
        for (const BlendInput& input : inputs.subspan(1))
            accumulateRotations<false>(input, out, totals, blocked, rotations);
    }

    const F8 one = splat<F8>(1.0f), zero = splat<F8>(0.0f);
    for (int r = 0; r < blocked; r += 8) {
        float* a = out + 4 * std::size_t(r);
        F8 ax = load<F8>(a), ay = load<F8>(a + 8), az = load<F8>(a + 16), aw = load<F8>(a + 24);
        const F8 t = load<F8>(totals + r);
        F8 rx, ry, rz, rw;
        loadQuats8(rest + 4 * std::size_t(r), rx, ry, rz, rw);
        const I8 needsRest = fill ? (t < one) : (t == zero);
        if (any(needsRest)) { // most joints are fully driven: skip the fill for them
            const F8 d = (ax * rx + ay * ry) + (az * rz + aw * rw);
            const F8 restWeight = select(needsRest, select(d < 0.0f, t - one, one - t), zero);
            ax += restWeight * rx;
            ay += restWeight * ry;
            az += restWeight * rz;
            aw += restWeight * rw;
        }
        const F8 norm2 = (ax * ax + ay * ay) + (az * az + aw * aw);
        // The rest pose exactly where nothing drives the joint, and where opposite inputs of
        // equal weight cancel.
        const I8 keepRest = (norm2 < splat<F8>(1e-24f)) | (t == zero);
        const F8 inv = reciprocalSqrt(select(keepRest, one, norm2));
        storeQuats8(a, select(keepRest, rx, ax * inv), select(keepRest, ry, ay * inv), select(keepRest, rz, az * inv),
                    select(keepRest, rw, aw * inv));
        store(totals + r, toJointOrder(t));
    }
    for (int r = blocked; r < rotations; ++r) {
        float* q = out + 4 * std::size_t(r);
        const float* base = rest + 4 * std::size_t(r);
        const float t = totals[r];
        if (t < 1.0f && (fill || t == 0.0f)) {
            const float d = (q[0] * base[0] + q[1] * base[1]) + (q[2] * base[2] + q[3] * base[3]);
            const float restWeight = d < 0.0f ? t - 1.0f : 1.0f - t;
            for (int c = 0; c < 4; ++c)
                q[c] += restWeight * base[c];
        }
        // The same operations as the eight-joint lanes, so that every joint rounds alike.
        const float norm2 = (q[0] * q[0] + q[1] * q[1]) + (q[2] * q[2] + q[3] * q[3]);
        const bool keepRest = norm2 < 1e-24f || t == 0.0f;
        const float inv = keepRest ? 1.0f : simd::reciprocalSqrt(norm2);
        for (int c = 0; c < 4; ++c)
            q[c] = keepRest ? base[c] : q[c] * inv;
    }
}

} // namespace

void QuaternionBlender::blend(const FrameLayout& layout, std::span<const BlendInput> inputs,
                              std::span<const float> rest, std::span<float> out, std::span<float> totals,
                              bool fill) const
{
    const int rotations = layout.rotationCount();
    blendRotations(inputs, rest.data(), out.data(), totals.data(), rotations, fill);
    blendTail(layout, inputs, rest, out, totals.data(), fill);
}

void QuaternionBlender::overlay(const FrameLayout& layout, const BlendInput& input, std::span<float> out) const
{
    for (int r = 0; r < layout.rotationCount(); ++r) {
        const float w = input.weights[r];
        if (!(w > 0))
            continue;
        Quat& o = rotationAt(out, r);
        const Quat& q = rotationAt(std::span<const float>(input.values, layout.floatCount()), r);
        o = w >= 1.0f ? q : slerp(o, q, w);
    }
    overlayTail(layout, input, out);
}

void QuaternionBlender::add(const FrameLayout& layout, const BlendInput& input, std::span<const float> reference,
                            std::span<float> out) const
{
    const std::span<const float> values(input.values, layout.floatCount());
    for (int r = 0; r < layout.rotationCount(); ++r) {
        const float w = input.weights[r];
        if (!(w > 0))
            continue;
        // The local change from the reference pose, applied after the current rotation.
        const Quat delta = conjugate(rotationAt(reference, r)) * rotationAt(values, r);
        Quat& o = rotationAt(out, r);
        o = normalize(o * (w == 1.0f ? delta : power(delta, w)));
    }
    addTail(layout, input, reference, out);
}

void LinearBlender::blend(const FrameLayout& layout, std::span<const BlendInput> inputs, std::span<const float> rest,
                          std::span<float> out, std::span<float> totals, bool fill) const
{
    blendLinearElements<4>(inputs, rest, out, totals.data(), fill, 0, layout.rotationCount(), 0);
    blendTail(layout, inputs, rest, out, totals.data(), fill);
}

void LinearBlender::overlay(const FrameLayout& layout, const BlendInput& input, std::span<float> out) const
{
    overlayLinear(input, out, 0, layout.rotationCount(), 0, 4);
    overlayTail(layout, input, out);
}

void LinearBlender::add(const FrameLayout& layout, const BlendInput& input, std::span<const float> reference,
                        std::span<float> out) const
{
    addLinear(input, reference, out, 0, layout.rotationCount(), 0, 4);
    addTail(layout, input, reference, out);
}

std::shared_ptr<const FrameBlender> defaultBlender()
{
    static const auto blender = std::make_shared<const QuaternionBlender>();
    return blender;
}

} // namespace thespis::core::anim
