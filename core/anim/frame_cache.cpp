#include "anim/frame_cache.h"

#include <algorithm>
#include <bit>
#include <cmath>

namespace thespis::core::anim {
namespace {

std::uint64_t mix(std::uint64_t x) // splitmix64 finalizer
{
    x ^= x >> 30;
    x *= 0xbf58476d1ce4e5b9ULL;
    x ^= x >> 27;
    x *= 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
}

} // namespace

CachedBlendable::CachedBlendable(BlendablePtr source, int capacity)
    : m_source(std::move(source)), m_capacity(std::max(1, capacity)), m_floats(m_source->layout()->floatCount()),
      m_elements(std::size_t(m_source->layout()->elementCount()))
{
    // Direct-mapped: a time has one slot; a newer time in the same slot replaces the older one.
    // Bounded, O(1), and no bookkeeping that could allocate.
    const auto slots = std::size_t(m_capacity);
    m_plain.times.assign(slots, std::nan(""));
    m_plain.frames.resize(slots * m_floats);
    if (m_source->hasCoverage()) {
        m_covered.times.assign(slots, std::nan(""));
        m_covered.frames.resize(slots * m_floats);
        m_covered.coverage.resize(slots * m_elements);
    }
    m_revision = m_source->revision();
}

int CachedBlendable::slotOf(double t) const
{
    return int(mix(std::bit_cast<std::uint64_t>(t)) % std::uint64_t(m_capacity));
}

void CachedBlendable::dropIfEdited() const
{
    const std::uint64_t revision = m_source->revision();
    if (revision == m_revision)
        return;
    std::fill(m_plain.times.begin(), m_plain.times.end(), std::nan(""));
    std::fill(m_covered.times.begin(), m_covered.times.end(), std::nan(""));
    m_size = 0;
    m_revision = revision;
}

void CachedBlendable::lookUp(Table& table, double t, std::span<float> out, std::span<float> coverage) const
{
    dropIfEdited();
    const auto slot = std::size_t(slotOf(t));
    float* stored = table.frames.data() + slot * m_floats;
    float* storedCoverage = coverage.empty() ? nullptr : table.coverage.data() + slot * m_elements;
    if (table.times[slot] == t) { // NaN never compares equal: empty slots miss
        ++m_hits;
        std::copy_n(stored, m_floats, out.data());
        if (storedCoverage)
            std::copy_n(storedCoverage, m_elements, coverage.data());
        return;
    }
    ++m_misses;
    if (storedCoverage)
        m_source->evaluateWithCoverage(t, out, coverage);
    else
        m_source->evaluate(t, out);
    if (std::isnan(table.times[slot]))
        ++m_size;
    table.times[slot] = t;
    std::copy_n(out.data(), m_floats, stored);
    if (storedCoverage)
        std::copy_n(coverage.data(), m_elements, storedCoverage);
}

void CachedBlendable::evaluate(double t, std::span<float> out) const { lookUp(m_plain, t, out, {}); }

void CachedBlendable::evaluateWithCoverage(double t, std::span<float> out, std::span<float> coverage) const
{
    if (!m_source->hasCoverage()) {
        BlendableObject::evaluateWithCoverage(t, out, coverage);
        return;
    }
    lookUp(m_covered, t, out, coverage);
}

} // namespace thespis::core::anim
