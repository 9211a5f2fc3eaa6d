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
    : m_source(std::move(source)), m_capacity(std::max(1, capacity)), m_floats(m_source->layout()->floatCount())
{
    // Direct-mapped: a time has one slot; a newer time in the same slot replaces the older one.
    // Bounded, O(1), and no bookkeeping that could allocate.
    m_times.assign(std::size_t(m_capacity), std::nan(""));
    m_frames.resize(std::size_t(m_capacity) * m_floats);
    m_revision = m_source->revision();
}

int CachedBlendable::slotOf(double t) const
{
    return int(mix(std::bit_cast<std::uint64_t>(t)) % std::uint64_t(m_capacity));
}

void CachedBlendable::evaluate(double t, std::span<float> out) const
{
    const std::uint64_t revision = m_source->revision();
    if (revision != m_revision) {
        std::fill(m_times.begin(), m_times.end(), std::nan(""));
        m_size = 0;
        m_revision = revision;
    }
    const auto slot = std::size_t(slotOf(t));
    float* stored = m_frames.data() + slot * m_floats;
    if (m_times[slot] == t) { // NaN never compares equal: empty slots miss
        ++m_hits;
        std::copy_n(stored, m_floats, out.data());
        return;
    }
    ++m_misses;
    m_source->evaluate(t, out);
    if (std::isnan(m_times[slot]))
        ++m_size;
    m_times[slot] = t;
    std::copy_n(out.data(), m_floats, stored);
}

} // namespace thespis::core::anim
