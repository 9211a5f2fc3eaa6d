#pragma once
// Modifiers (paper §4.2): blendables that wrap a blendable and change its time or its frames.
// Any chain of modifiers is again a blendable.

#include <cstdint>
#include <optional>
#include <vector>

#include "anim/blendable.h"
#include "anim/curve.h"
#include "anim/root_motion.h"
#include "util/error.h"

namespace thespis::core::anim {

/// Base: forwards the layout and revision of the wrapped source.
class Modifier : public BlendableObject {
public:
    explicit Modifier(BlendablePtr source) : m_source(std::move(source)) {}
    const BlendablePtr& source() const { return m_source; }
    const FrameLayoutPtr& layout() const override { return m_source->layout(); }
    std::uint64_t revision() const override { return m_source->revision(); }
    bool plays(const BlendableObject& other) const override
    {
        return m_source.get() == &other || m_source->plays(other);
    }

protected:
    BlendablePtr m_source;
};

/// Plays the source `factor` times slower (factor 2 = twice as long). factor > 0.
class TimeStretch final : public Modifier {
public:
    static Result<std::shared_ptr<TimeStretch>> create(BlendablePtr source, double factor);
    double factor() const { return m_factor; }
    TimeDomain domain() const override;
    void evaluate(double t, std::span<float> out) const override;

private:
    TimeStretch(BlendablePtr source, double factor) : Modifier(std::move(source)), m_factor(factor) {}
    double m_factor;
};

/// Remaps time through a curve: the frame at local time u is the source's at
/// source start + warp(u), for u in [0, duration].
class TimeWarp final : public Modifier {
public:
    static Result<std::shared_ptr<TimeWarp>> create(BlendablePtr source, Curve warp, double duration);
    const Curve& warp() const { return m_warp; }
    TimeDomain domain() const override;
    void evaluate(double t, std::span<float> out) const override;

private:
    TimeWarp(BlendablePtr source, Curve warp, double duration)
        : Modifier(std::move(source)), m_warp(std::move(warp)), m_duration(duration) {}
    Curve m_warp;
    double m_duration;
};

/// Repeats the source `count` times, or forever when count = 0 (open-ended). With root motion,
/// each repetition starts where the previous one ended (the root's position on the floor and its
/// heading), as a walk goes on, instead of jumping back to where the source starts.
class Loop final : public Modifier {
public:
    static Result<std::shared_ptr<Loop>> create(BlendablePtr source, int count, bool rootMotion = false);
    int count() const { return m_count; }
    bool rootMotion() const { return m_cycle.has_value(); }
    TimeDomain domain() const override;
    void evaluate(double t, std::span<float> out) const override;

private:
    Loop(BlendablePtr source, int count) : Modifier(std::move(source)), m_count(count) {}
    int m_count;
    RootElements m_root;
    std::optional<FloorMove> m_cycle; ///< from one repetition's start onto the next's
};

/// Left/right flip: swaps the elements of paired joints (H-Anim l_/r_ names and common
/// Left/Right spellings) and reflects rotations and translations across the plane normal to
/// `axis` (0 = x, the H-Anim sagittal plane). Applied twice it gives the source back.
class Mirror final : public Modifier {
public:
    static Result<std::shared_ptr<Mirror>> create(BlendablePtr source, int axis = 0);
    int axis() const { return m_axis; }
    TimeDomain domain() const override { return m_source->domain(); }
    void evaluate(double t, std::span<float> out) const override;

private:
    Mirror(BlendablePtr source, int axis);
    int m_axis;
    std::vector<int> m_pairOf; // element → element it takes its value from
    mutable std::vector<float> m_scratch;
};

/// Moves the whole animation: the root rotation becomes R·q and the root translation R·t + T.
/// The root is the rotation element named like the layout's first translation element.
class GlobalTransform final : public Modifier {
public:
    static Result<std::shared_ptr<GlobalTransform>> create(BlendablePtr source, Quat rotation, Vec3 translation);
    Quat rotation() const { return m_rotation; }
    Vec3 translation() const { return m_translation; }
    TimeDomain domain() const override { return m_source->domain(); }
    void evaluate(double t, std::span<float> out) const override;

private:
    GlobalTransform(BlendablePtr source, Quat rotation, Vec3 translation, int rootRotation);
    Quat m_rotation;
    Vec3 m_translation;
    int m_rootRotation;
};

/// Shifts the source in time: the frame at t is the source's at t − offset.
class TimeOffset final : public Modifier {
public:
    TimeOffset(BlendablePtr source, double offset) : Modifier(std::move(source)), m_offset(offset) {}
    double offset() const { return m_offset; }
    TimeDomain domain() const override;
    void evaluate(double t, std::span<float> out) const override;

private:
    double m_offset;
};

/// Keeps the part of the source between `start` and `end` (source times), in the source's time.
/// Two trims at the same point split a clip.
class Trim final : public Modifier {
public:
    static Result<std::shared_ptr<Trim>> create(BlendablePtr source, double start, double end);
    TimeDomain domain() const override { return {m_start, m_end}; }
    void evaluate(double t, std::span<float> out) const override;

private:
    Trim(BlendablePtr source, double start, double end) : Modifier(std::move(source)), m_start(start), m_end(end) {}
    double m_start, m_end;
};

/// Splits a blendable with a fixed domain at time `at` into the part before and the part after.
Result<std::pair<std::shared_ptr<Trim>, std::shared_ptr<Trim>>> split(BlendablePtr source, double at);

} // namespace thespis::core::anim
