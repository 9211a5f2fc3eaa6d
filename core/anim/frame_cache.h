#pragma once
// A bounded cache of rendered frames in front of a blendable (paper §4.2: "a cache is
// maintained of previously rendered frames"). Frames are keyed by their exact time in a
// direct-mapped table of `capacity` slots; the whole cache is dropped when the source's
// revision changes, i.e. after any edit that affects it. Storage is allocated once; a lookup
// or insert allocates nothing. Like the schedule, one thread at a time.

#include <cstdint>
#include <vector>

#include "anim/blendable.h"

namespace thespis::core::anim {

class CachedBlendable final : public BlendableObject {
public:
    CachedBlendable(BlendablePtr source, int capacity = 256);

    const FrameLayoutPtr& layout() const override { return m_source->layout(); }
    TimeDomain domain() const override { return m_source->domain(); }
    void evaluate(double t, std::span<float> out) const override;
    std::uint64_t revision() const override { return m_source->revision(); }
    bool plays(const BlendableObject& other) const override
    {
        return m_source.get() == &other || m_source->plays(other);
    }

    int capacity() const { return m_capacity; }
    std::uint64_t hits() const { return m_hits; }
    std::uint64_t misses() const { return m_misses; }
    int size() const { return m_size; }

private:
    int slotOf(double t) const;

    BlendablePtr m_source;
    int m_capacity;
    std::size_t m_floats;
    mutable std::vector<double> m_times; // per slot; NaN when empty
    mutable std::vector<float> m_frames; // per slot
    mutable int m_size = 0;
    mutable std::uint64_t m_revision = 0, m_hits = 0, m_misses = 0;
};

} // namespace thespis::core::anim
