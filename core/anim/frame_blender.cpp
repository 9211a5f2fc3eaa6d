#include "anim/frame_blender.h"

#include "anim/simd.h"

#include <algorithm>
#include <cmath>

namespace thespis::core::anim {
namespace {

// The loops below run input by input over all elements: the elements are independent, so the
// CPU overlaps their work (running per element over the inputs would chain every step).

// Σ wᵢ·xᵢ into out and Σ wᵢ into totals, for elements [first, first + count) of width floats.
void accumulateLinear(std::span<const BlendInput> inputs, float* __restrict out, float* __restrict totals,
                      int first, int count, std::size_t offset, int width)
{
    std::fill_n(out + offset, std::size_t(count) * std::size_t(width), 0.0f);
    for (const BlendInput& input : inputs) {
        const float* __restrict x = input.values + offset;
        const float* __restrict w = input.weights + first;
        for (int e = 0; e < count; ++e) {
            const float we = std::max(w[e], 0.0f);
            totals[first + e] += we;
            for (int c = 0; c < width; ++c)
                out[offset + std::size_t(e * width + c)] += we * x[e * width + c];
        }
    }
}

// Applies the normalized rule to accumulated sums: divide by W ≥ 1, else fill with rest (or,
// without filling, divide by any W > 0).
void finishLinear(std::span<const float> rest, float* __restrict out, const float* __restrict totals,
                  bool fill, int first, int count, std::size_t offset, int width)
{
    for (int e = 0; e < count; ++e) {
        const float total = totals[first + e];
        float* x = out + offset + std::size_t(e * width);
        const float* base = rest.data() + offset + std::size_t(e * width);
        if (total >= 1.0f || (!fill && total > 0.0f)) {
            const float inv = 1.0f / total;
            for (int c = 0; c < width; ++c)
                x[c] *= inv;
        } else {
            const float restWeight = 1.0f - total;
            for (int c = 0; c < width; ++c)
                x[c] += restWeight * base[c];
        }
    }
}

void blendLinearElements(std::span<const BlendInput> inputs, std::span<const float> rest, std::span<float> out,
                         float* totals, bool fill, int first, int count, std::size_t offset, int width)
{
    accumulateLinear(inputs, out.data(), totals, first, count, offset, width);
    finishLinear(rest, out.data(), totals, fill, first, count, offset, width);
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
    blendLinearElements(inputs, rest, out, totals, fill, r, t, layout.translationOffset(), 3);
    blendLinearElements(inputs, rest, out, totals, fill, r + t, layout.scalarCount(), layout.scalarOffset(), 1);
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

} // namespace

void QuaternionBlender::blend(const FrameLayout& layout, std::span<const BlendInput> inputs,
                              std::span<const float> rest, std::span<float> out, std::span<float> totals,
                              bool fill) const
{
    using namespace simd;
    const int rotations = layout.rotationCount();
    const int blocked = rotations / 4 * 4; // joints handled four at a time; the rest one by one
    float* __restrict acc = out.data();    // during accumulation: per block of 4 joints, x[4] y[4] z[4] w[4]
    float* __restrict total = totals.data();
    std::fill_n(acc, 4 * std::size_t(rotations), 0.0f);
    std::fill_n(total, std::size_t(layout.elementCount()), 0.0f);
    const I4 signBit = {int(0x80000000u), int(0x80000000u), int(0x80000000u), int(0x80000000u)};

    for (const BlendInput& input : inputs) {
        const float* __restrict q = input.values;
        const float* __restrict w = input.weights;
        for (int r = 0; r < blocked; r += 4) {
            float* a = acc + 4 * std::size_t(r);
            F4 x, y, z, qw;
            loadQuats(q + 4 * std::size_t(r), x, y, z, qw);
            const F4 weight = max(load(w + r), splat(0.0f));
            F4 ax = load(a), ay = load(a + 4), az = load(a + 8), aw = load(a + 12);
            // Align with the sum so far, so that q and −q (the same rotation) add up, not cancel.
            const F4 d = ax * x + ay * y + az * z + aw * qw;
            const F4 s = (F4)((I4)weight ^ ((d < 0.0f) & signBit));
            store(a, ax + s * x);
            store(a + 4, ay + s * y);
            store(a + 8, az + s * z);
            store(a + 12, aw + s * qw);
            store(total + r, load(total + r) + weight);
        }
        for (int r = blocked; r < rotations; ++r) {
            const std::size_t k = 4 * std::size_t(r);
            const float we = std::max(w[r], 0.0f);
            const float d = acc[k] * q[k] + acc[k + 1] * q[k + 1] + acc[k + 2] * q[k + 2] + acc[k + 3] * q[k + 3];
            const float s = d < 0.0f ? -we : we;
            for (int c = 0; c < 4; ++c)
                acc[k + std::size_t(c)] += s * q[k + std::size_t(c)];
            total[r] += we;
        }
    }

    // Rest fill (total < 1, or nothing at all without filling), normalization, back to x y z w.
    const F4 one = splat(1.0f), zero = splat(0.0f);
    for (int r = 0; r < blocked; r += 4) {
        float* a = acc + 4 * std::size_t(r);
        F4 ax = load(a), ay = load(a + 4), az = load(a + 8), aw = load(a + 12);
        const F4 t = load(total + r);
        const I4 needsRest = fill ? (t < one) : (t == zero);
        F4 rx, ry, rz, rw;
        loadQuats(rest.data() + 4 * std::size_t(r), rx, ry, rz, rw);
        if (any(needsRest)) { // most joints are fully driven: skip the fill for them
            const F4 d = ax * rx + ay * ry + az * rz + aw * rw;
            const F4 restWeight = select(needsRest, select(d < 0.0f, t - one, one - t), zero);
            ax += restWeight * rx;
            ay += restWeight * ry;
            az += restWeight * rz;
            aw += restWeight * rw;
        }
        const F4 norm2 = ax * ax + ay * ay + az * az + aw * aw;
        const I4 degenerate = norm2 < splat(1e-24f); // opposite inputs of equal weight: keep rest
        const F4 inv = one / simd::sqrt(select(degenerate, one, norm2));
        storeQuats(a, select(degenerate, rx, ax * inv), select(degenerate, ry, ay * inv),
                   select(degenerate, rz, az * inv), select(degenerate, rw, aw * inv));
    }
    for (int r = blocked; r < rotations; ++r) {
        const std::size_t k = 4 * std::size_t(r);
        const float t = total[r];
        const float* base = rest.data() + k;
        if (t < 1.0f && (fill || t == 0.0f)) {
            const float d = acc[k] * base[0] + acc[k + 1] * base[1] + acc[k + 2] * base[2] + acc[k + 3] * base[3];
            const float restWeight = d < 0.0f ? t - 1.0f : 1.0f - t;
            for (int c = 0; c < 4; ++c)
                acc[k + std::size_t(c)] += restWeight * base[c];
        }
        const float norm = std::sqrt(acc[k] * acc[k] + acc[k + 1] * acc[k + 1] + acc[k + 2] * acc[k + 2] + acc[k + 3] * acc[k + 3]);
        for (int c = 0; c < 4; ++c)
            acc[k + std::size_t(c)] = norm > 1e-12f ? acc[k + std::size_t(c)] / norm : base[c];
    }
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
    std::fill_n(totals.begin(), std::size_t(layout.elementCount()), 0.0f);
    blendLinearElements(inputs, rest, out, totals.data(), fill, 0, layout.rotationCount(), 0, 4);
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
