#include "anim/modifiers.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "anim/hanim.h"

namespace thespis::core::anim {
namespace {

Result<void> checkSource(const BlendablePtr& source, const char* modifier)
{
    if (!source)
        return makeError(ErrorCode::InvalidArgument, std::string(modifier) + " needs something to modify.");
    return {};
}

} // namespace

Result<std::shared_ptr<TimeStretch>> TimeStretch::create(BlendablePtr source, double factor)
{
    if (auto ok = checkSource(source, "A time stretch"); !ok)
        return ok.error();
    if (!(factor > 0) || !std::isfinite(factor))
        return makeError(ErrorCode::InvalidArgument, "A time stretch factor must be a positive number, not "
                                                         + std::to_string(factor) + ".");
    return std::shared_ptr<TimeStretch>(new TimeStretch(std::move(source), factor));
}

TimeDomain TimeStretch::domain() const
{
    const TimeDomain d = m_source->domain();
    return {d.start, d.openEnded() ? d.end : d.start + d.duration() * m_factor};
}

void TimeStretch::evaluate(double t, std::span<float> out) const
{
    const double start = m_source->domain().start;
    m_source->evaluate(start + (t - start) / m_factor, out);
}

Result<std::shared_ptr<TimeWarp>> TimeWarp::create(BlendablePtr source, Curve warp, double duration)
{
    if (auto ok = checkSource(source, "A time warp"); !ok)
        return ok.error();
    if (auto ok = warp.validate(); !ok)
        return makeError(ErrorCode::InvalidArgument, "Time warp curve: " + ok.error().message);
    if (!(duration > 0) || !std::isfinite(duration))
        return makeError(ErrorCode::InvalidArgument, "A time warp needs a positive, finite duration.");
    return std::shared_ptr<TimeWarp>(new TimeWarp(std::move(source), std::move(warp), duration));
}

TimeDomain TimeWarp::domain() const
{
    const double start = m_source->domain().start;
    return {start, start + m_duration};
}

void TimeWarp::evaluate(double t, std::span<float> out) const
{
    const double start = m_source->domain().start;
    const double local = std::clamp(t - start, 0.0, m_duration);
    m_source->evaluate(start + m_warp.evaluate(local, m_duration), out);
}

Result<std::shared_ptr<Loop>> Loop::create(BlendablePtr source, int count, bool rootMotion)
{
    if (auto ok = checkSource(source, "A loop"); !ok)
        return ok.error();
    if (count < 0)
        return makeError(ErrorCode::InvalidArgument, "A loop count must be 0 (forever) or more.");
    if (source->domain().openEnded())
        return makeError(ErrorCode::InvalidArgument, "An open-ended animation cannot be looped.");
    std::shared_ptr<Loop> loop(new Loop(std::move(source), count));
    loop->m_root = rootElements(*loop->layout());
    if (rootMotion && loop->m_root.valid) {
        // One repetition moves the root from where the source starts to where it ends.
        const TimeDomain d = loop->m_source->domain();
        std::vector<float> first(loop->layout()->floatCount()), last(first.size());
        loop->m_source->evaluate(d.start, first);
        loop->m_source->evaluate(d.end, last);
        const RootElements& root = loop->m_root;
        const auto at = [&](const std::vector<float>& f) {
            return Vec3{f[root.translation], f[root.translation + 1], f[root.translation + 2]};
        };
        const auto facing = [&](const std::vector<float>& f) {
            return root.rotation >= 0 ? heading(rotationAt(std::span<const float>(f), root.rotation)) : 0.0;
        };
        loop->m_cycle = FloorMove::onto(at(first), facing(first), at(last), facing(last));
    }
    return loop;
}

TimeDomain Loop::domain() const
{
    const TimeDomain d = m_source->domain();
    if (m_count == 0)
        return {d.start, std::numeric_limits<double>::infinity()};
    return {d.start, d.start + d.duration() * m_count};
}

void Loop::evaluate(double t, std::span<float> out) const
{
    const TimeDomain d = m_source->domain();
    const double length = d.duration();
    const double local = t - d.start;
    if (!(local > 0) || !(length > 0)) {
        m_source->evaluate(d.start, out);
        return;
    }
    if (m_count > 0 && local >= length * m_count) {
        m_source->evaluate(d.end, out);
        if (m_cycle)
            m_cycle->repeated(m_count - 1).apply(m_root, out);
        return;
    }
    m_source->evaluate(d.start + std::fmod(local, length), out);
    if (m_cycle)
        if (const auto repetition = static_cast<long long>(std::floor(local / length)); repetition > 0)
            m_cycle->repeated(repetition).apply(m_root, out);
}

Result<std::shared_ptr<Mirror>> Mirror::create(BlendablePtr source, int axis)
{
    if (auto ok = checkSource(source, "A mirror"); !ok)
        return ok.error();
    if (axis < 0 || axis > 2)
        return makeError(ErrorCode::InvalidArgument, "A mirror axis must be 0 (x), 1 (y) or 2 (z).");
    return std::shared_ptr<Mirror>(new Mirror(std::move(source), axis));
}

Mirror::Mirror(BlendablePtr source, int axis) : Modifier(std::move(source)), m_axis(axis)
{
    const FrameLayout& layout = *m_source->layout();
    m_pairOf.resize(std::size_t(layout.elementCount()));
    for (int e = 0; e < layout.elementCount(); ++e) {
        const int pair = layout.find(hanim::mirrorName(layout.name(e)), layout.kind(e));
        m_pairOf[std::size_t(e)] = pair >= 0 ? pair : e;
    }
    m_scratch.resize(layout.floatCount());
}

void Mirror::evaluate(double t, std::span<float> out) const
{
    const FrameLayout& layout = *m_source->layout();
    m_source->evaluate(t, m_scratch);
    // Reflection across the plane normal to the axis: a rotation keeps its axis component and
    // negates the other two (and w stays); a translation negates its axis component.
    for (int e = 0; e < layout.elementCount(); ++e) {
        const std::size_t to = layout.floatOffset(e);
        const std::size_t from = layout.floatOffset(m_pairOf[std::size_t(e)]);
        switch (layout.kind(e)) {
        case ElementKind::Rotation:
            for (int c = 0; c < 3; ++c)
                out[to + std::size_t(c)] = c == m_axis ? m_scratch[from + std::size_t(c)] : -m_scratch[from + std::size_t(c)];
            out[to + 3] = m_scratch[from + 3];
            break;
        case ElementKind::Translation:
            for (int c = 0; c < 3; ++c)
                out[to + std::size_t(c)] = c == m_axis ? -m_scratch[from + std::size_t(c)] : m_scratch[from + std::size_t(c)];
            break;
        case ElementKind::Scalar:
            out[to] = m_scratch[from];
            break;
        }
    }
}

Result<std::shared_ptr<GlobalTransform>> GlobalTransform::create(BlendablePtr source, Quat rotation, Vec3 translation)
{
    if (auto ok = checkSource(source, "A global transform"); !ok)
        return ok.error();
    const FrameLayout& layout = *source->layout();
    if (layout.translationCount() == 0)
        return makeError(ErrorCode::InvalidArgument, "A global transform needs a layout with a root translation.");
    const int root = layout.find(layout.translationNames().front(), ElementKind::Rotation);
    if (dot(rotation, rotation) < 1e-12f || !std::isfinite(rotation.w) || !std::isfinite(translation.x)
        || !std::isfinite(translation.y) || !std::isfinite(translation.z))
        return makeError(ErrorCode::InvalidArgument, "A global transform needs a valid rotation and a finite translation.");
    return std::shared_ptr<GlobalTransform>(new GlobalTransform(std::move(source), normalize(rotation), translation, root));
}

GlobalTransform::GlobalTransform(BlendablePtr source, Quat rotation, Vec3 translation, int rootRotation)
    : Modifier(std::move(source)), m_rotation(rotation), m_translation(translation), m_rootRotation(rootRotation)
{
}

void GlobalTransform::evaluate(double t, std::span<float> out) const
{
    m_source->evaluate(t, out);
    const FrameLayout& layout = *m_source->layout();
    if (m_rootRotation >= 0) {
        Quat& q = rotationAt(out, m_rootRotation);
        q = m_rotation * q;
    }
    float* p = out.data() + layout.translationOffset();
    const Vec3 moved = rotate(m_rotation, Vec3{p[0], p[1], p[2]}) + m_translation;
    p[0] = moved.x;
    p[1] = moved.y;
    p[2] = moved.z;
}

TimeDomain TimeOffset::domain() const
{
    const TimeDomain d = m_source->domain();
    return {d.start + m_offset, d.end + m_offset};
}

void TimeOffset::evaluate(double t, std::span<float> out) const
{
    m_source->evaluate(t - m_offset, out);
}

Result<std::shared_ptr<Trim>> Trim::create(BlendablePtr source, double start, double end)
{
    if (auto ok = checkSource(source, "A trim"); !ok)
        return ok.error();
    const TimeDomain d = source->domain();
    if (!std::isfinite(start) || !std::isfinite(end) || !(start < end))
        return makeError(ErrorCode::InvalidArgument, "A trim needs finite times with start before end.");
    if (start < d.start || end > d.end)
        return makeError(ErrorCode::InvalidArgument, "A trim from " + std::to_string(start) + " to "
                                                         + std::to_string(end) + " s lies outside the animation ("
                                                         + std::to_string(d.start) + " to " + std::to_string(d.end) + " s).");
    return std::shared_ptr<Trim>(new Trim(std::move(source), start, end));
}

void Trim::evaluate(double t, std::span<float> out) const
{
    m_source->evaluate(std::clamp(t, m_start, m_end), out);
}

Result<std::pair<std::shared_ptr<Trim>, std::shared_ptr<Trim>>> split(BlendablePtr source, double at)
{
    if (auto ok = checkSource(source, "A split"); !ok)
        return ok.error();
    const TimeDomain d = source->domain();
    if (d.openEnded())
        return makeError(ErrorCode::InvalidArgument, "An open-ended animation cannot be split.");
    if (!(at > d.start && at < d.end))
        return makeError(ErrorCode::InvalidArgument, "A split point must lie strictly inside the animation.");
    auto before = Trim::create(source, d.start, at);
    auto after = Trim::create(source, at, d.end);
    if (!before)
        return before.error();
    if (!after)
        return after.error();
    return std::make_pair(std::move(before).value(), std::move(after).value());
}

} // namespace thespis::core::anim
