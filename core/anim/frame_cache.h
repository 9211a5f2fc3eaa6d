#pragma once
// A bounded cache of rendered frames in front of a blendable (paper §4.2: "a cache is
// maintained of previously rendered frames"). Frames are keyed by their exact time in a
// direct-mapped table of `capacity` slots; the whole cache is dropped when the source's
// revision changes, i.e. after any edit that affects it. A source with coverage (a nested
// schedule) is cached with its coverage too, so a cached schedule blends exactly like the
// uncached one. Storage is allocated once; a lookup or insert allocates nothing. Like the
// schedule, one thread at a time.

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
    bool hasCoverage() const override { return m_source->hasCoverage(); }
    void evaluateWithCoverage(double t, std::span<float> out, std::span<float> coverage) const override;
    std::uint64_t revision() const override { return m_source->revision(); }
    bool plays(const BlendableObject& other) const override
    {
        return m_source.get() == &other || m_source->plays(other);
    }

    const BlendablePtr& source() const { return m_source; }
    int capacity() const { return m_capacity; }
    std::uint64_t hits() const { return m_hits; }
    std::uint64_t misses() const { return m_misses; }
    int size() const { return m_size; }

private:
    /// A direct-mapped table of frames (and, for coverage lookups, their coverage).
    struct Table {
        std::vector<double> times;   // per slot; NaN when empty
        std::vector<float> frames;   // per slot
        std::vector<float> coverage; // per slot, when the table holds coverage
    };
    int slotOf(double t) const;
    void dropIfEdited() const;
    /// Copies the cached frame (and coverage) at t into the outputs, or evaluates and stores it.
    void lookUp(Table& table, double t, std::span<float> out, std::span<float> coverage) const;

    BlendablePtr m_source;
    int m_capacity;
    std::size_t m_floats, m_elements;
    // evaluate() fills undriven elements with the rest pose and evaluateWithCoverage() does
    // not, so their frames differ: one table each.
    mutable Table m_plain, m_covered;
    mutable int m_size = 0;
    mutable std::uint64_t m_revision = 0, m_hits = 0, m_misses = 0;
};

} // namespace thespis::core::anim
