#include "anim/keyframe_clip.h"

#include "anim/simd.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace thespis::core::anim {
namespace {

// Slerp coefficients below this angle are computed for this angle instead: sin(uθ)/sin θ = u
// to within θ²/6 ≈ 2e-7 there, and it keeps the inner loop free of branches and divisions by 0.
constexpr float kMinSlerpAngle = 1e-3f;

// sin x for x in [0, π/2] (keys are hemisphere-aligned, so slerp angles never exceed π/2):
// Taylor series to x¹¹, error below 6e-8 on that range, cheaper than std::sin and vectorizable.
template <class T>
inline T sinHalfPi(T x)
{
    const T x2 = x * x;
    return x * (1.0f + x2 * (-1.0f / 6 + x2 * (1.0f / 120 + x2 * (-1.0f / 5040
           + x2 * (1.0f / 362880 + x2 * (-1.0f / 39916800))))));
}

} // namespace

Result<std::shared_ptr<KeyframeClip>> KeyframeClip::create(FrameLayoutPtr layout, double frameRate,
                                                           std::vector<float> frames, std::string name)
{
    if (!layout)
        return makeError(ErrorCode::InvalidArgument, "A clip needs a frame layout.");
    if (!(frameRate > 0) || !std::isfinite(frameRate))
        return makeError(ErrorCode::InvalidArgument,
                         "Clip '" + name + "' has frame rate " + std::to_string(frameRate) + "; it must be a positive number.");
    const std::size_t floats = layout->floatCount();
    if (floats == 0 || frames.empty() || frames.size() % floats != 0)
        return makeError(ErrorCode::InvalidArgument,
                         "Clip '" + name + "' has " + std::to_string(frames.size())
                             + " values, not a whole number of frames of " + std::to_string(floats) + " values.");
    const int frameCount = int(frames.size() / floats);
    const int rotations = layout->rotationCount();
    for (std::size_t i = 0; i < frames.size(); ++i)
        if (!std::isfinite(frames[i]))
            return makeError(ErrorCode::InvalidArgument,
                             "Clip '" + name + "' frame " + std::to_string(i / floats) + " holds a value that is not a finite number.");

    // Normalize rotations and align each key with the previous one, so that interpolation
    // always takes the short way and needs no sign test at run time.
    for (int f = 0; f < frameCount; ++f) {
        float* frame = frames.data() + std::size_t(f) * floats;
        for (int r = 0; r < rotations; ++r) {
            Quat& q = rotationAt(std::span<float>(frame, floats), r);
            if (dot(q, q) < 1e-12f)
                return makeError(ErrorCode::InvalidArgument,
                                 "Clip '" + name + "' frame " + std::to_string(f) + " has a zero rotation for '"
                                     + layout->name(r) + "'.");
            q = normalize(q);
            if (f > 0) {
                const Quat& previous = rotationAt(std::span<const float>(frame - floats, floats), r);
                if (dot(previous, q) < 0)
                    q = negate(q);
            }
        }
    }

    auto clip = std::shared_ptr<KeyframeClip>(new KeyframeClip());
    clip->m_layout = std::move(layout);
    clip->m_name = std::move(name);
    clip->m_frameRate = frameRate;
    clip->m_frameCount = frameCount;
    clip->m_frames = std::move(frames);
    const std::size_t intervals = std::size_t(std::max(0, frameCount - 1));
    clip->m_theta.resize(intervals * std::size_t(rotations));
    clip->m_invSinTheta.resize(intervals * std::size_t(rotations));
    for (std::size_t i = 0; i < intervals; ++i) {
        const std::span<const float> a(clip->m_frames.data() + i * floats, floats);
        const std::span<const float> b(clip->m_frames.data() + (i + 1) * floats, floats);
        for (int r = 0; r < rotations; ++r) {
            const double d = std::clamp(double(dot(rotationAt(a, r), rotationAt(b, r))), 0.0, 1.0);
            const double theta = std::max(std::acos(d), double(kMinSlerpAngle));
            clip->m_theta[i * std::size_t(rotations) + std::size_t(r)] = float(theta);
            clip->m_invSinTheta[i * std::size_t(rotations) + std::size_t(r)] = float(1.0 / std::sin(theta));
        }
    }
    return clip;
}

std::span<const float> KeyframeClip::frame(int index) const
{
    const std::size_t floats = m_layout->floatCount();
    return {m_frames.data() + std::size_t(index) * floats, floats};
}

void KeyframeClip::evaluate(double t, std::span<float> out) const
{
    const std::size_t floats = m_layout->floatCount();
    const double position = t * m_frameRate;
    if (!(position > 0) || m_frameCount == 1) { // also catches NaN
        std::copy_n(m_frames.data(), floats, out.data());
        return;
    }
    if (position >= double(m_frameCount - 1)) {
        std::copy_n(m_frames.data() + std::size_t(m_frameCount - 1) * floats, floats, out.data());
        return;
    }
    const auto interval = std::size_t(position);
    const float u = float(position - double(interval));
    const float* a = m_frames.data() + interval * floats;
    const float* b = a + floats;
    const auto rotations = std::size_t(m_layout->rotationCount());
    const float* theta = m_theta.data() + interval * rotations;
    const float* invSin = m_invSinTheta.data() + interval * rotations;
    float* o = out.data();
    // slerp = sin((1−u)θ)/sin θ · a + sin(uθ)/sin θ · b, coefficients for four joints at a time.
    using namespace simd;
    const std::size_t blocked = rotations / 4 * 4;
    const F4 u4 = splat(u), v4 = splat(1.0f - u);
    for (std::size_t r = 0; r < blocked; r += 4) {
        const F4 th = load(theta + r), inv = load(invSin + r);
        const F4 s0 = sinHalfPi(v4 * th) * inv;
        const F4 s1 = sinHalfPi(u4 * th) * inv;
        for (std::size_t j = 0; j < 4; ++j) {
            const std::size_t k = 4 * (r + j);
            store(o + k, splat(s0[j]) * load(a + k) + splat(s1[j]) * load(b + k));
        }
    }
    for (std::size_t r = blocked; r < rotations; ++r) {
        const float s0 = sinHalfPi((1.0f - u) * theta[r]) * invSin[r];
        const float s1 = sinHalfPi(u * theta[r]) * invSin[r];
        const std::size_t k = 4 * r;
        store(o + k, splat(s0) * load(a + k) + splat(s1) * load(b + k));
    }
    for (std::size_t k = 4 * rotations; k < floats; ++k)
        o[k] = a[k] + u * (b[k] - a[k]);
}

Result<std::shared_ptr<KeyframeClip>> remapClip(const KeyframeClip& clip, FrameLayoutPtr target,
                                                std::span<const float> rest, std::vector<std::string>* dropped)
{
    if (!target || rest.size() != target->floatCount())
        return makeError(ErrorCode::InvalidArgument, "Remapping needs a target layout and a rest frame of that layout.");
    const FrameLayout& source = *clip.layout();
    // For each target element: the source element it copies, or -1 to take the rest value.
    std::vector<int> from(std::size_t(target->elementCount()), -1);
    for (int e = 0; e < target->elementCount(); ++e)
        from[std::size_t(e)] = source.find(target->name(e), target->kind(e));
    if (dropped) {
        dropped->clear();
        for (int e = 0; e < source.elementCount(); ++e)
            if (target->find(source.name(e), source.kind(e)) < 0)
                dropped->push_back(source.name(e));
    }
    const std::size_t floats = target->floatCount();
    std::vector<float> frames(floats * std::size_t(clip.frameCount()));
    for (int f = 0; f < clip.frameCount(); ++f) {
        const std::span<const float> in = clip.frame(f);
        float* out = frames.data() + std::size_t(f) * floats;
        for (int e = 0; e < target->elementCount(); ++e) {
            const int n = floatsPerElement(target->kind(e));
            const int s = from[std::size_t(e)];
            const float* value = s >= 0 ? in.data() + source.floatOffset(s) : rest.data() + target->floatOffset(e);
            std::copy_n(value, n, out + target->floatOffset(e));
        }
    }
    return KeyframeClip::create(std::move(target), clip.frameRate(), std::move(frames), clip.name());
}

} // namespace thespis::core::anim
