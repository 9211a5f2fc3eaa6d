#pragma once
// BlendableObject (paper §4.2): an animation A: t → frame over a time domain [ts, te], or
// open-ended for motion synthesizers. Clips, modifiers and schedules are all blendables.

#include <algorithm>
#include <cstdint>
#include <limits>
#include <memory>
#include <span>

#include "anim/frame.h"

namespace thespis::core::anim {

struct TimeDomain {
    double start = 0;
    double end = std::numeric_limits<double>::infinity(); ///< ∞ when open-ended

    bool openEnded() const { return end == std::numeric_limits<double>::infinity(); }
    double duration() const { return end - start; }
    bool contains(double t) const { return t >= start && t <= end; }
    bool operator==(const TimeDomain&) const = default;
};

class BlendableObject {
public:
    virtual ~BlendableObject() = default;

    virtual const FrameLayoutPtr& layout() const = 0;
    virtual TimeDomain domain() const = 0;
    /// Writes the frame at time t (seconds) into `out`, which holds layout()->floatCount()
    /// floats. Times outside the domain give the nearest frame in it (clips hold their ends).
    /// Must not allocate: it runs every frame.
    virtual void evaluate(double t, std::span<float> out) const = 0;
    /// True for blendables that drive only part of each element some of the time (schedules):
    /// a parent then calls evaluateWithCoverage() and scales its weights by the coverage.
    virtual bool hasCoverage() const { return false; }
    /// Like evaluate(), and writes how much of each element (0…1, one per layout element) the
    /// frame really holds; elements covered less than 1 are not filled with a rest pose.
    virtual void evaluateWithCoverage(double t, std::span<float> out, std::span<float> coverage) const
    {
        evaluate(t, out);
        std::fill(coverage.begin(), coverage.end(), 1.0f);
    }
    /// Changes whenever an edit changes what evaluate() returns (including edits of nested
    /// blendables); caches compare it. Immutable blendables return 0.
    virtual std::uint64_t revision() const { return 0; }
    /// True when `other` is played somewhere inside this blendable (not counting itself), so
    /// schedules can refuse cycles, which would recurse forever.
    virtual bool plays(const BlendableObject& other) const
    {
        (void)other;
        return false;
    }
};

using BlendablePtr = std::shared_ptr<const BlendableObject>;

} // namespace thespis::core::anim
