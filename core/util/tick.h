#pragma once
// Exact document time. The engine evaluates in double seconds; documents store integer ticks so
// that timeline edits and snapping are exact and survive save/load bit for bit.

#include <cmath>
#include <cstdint>

namespace thespis::core {

using Tick = std::int64_t;

/// 705,600,000 ticks per second ("flicks"): every common frame rate (24, 25, 30, 48, 50, 60, 90,
/// 100, 120) and audio rate (8k … 48k, 44.1k) is a whole number of ticks.
inline constexpr Tick TicksPerSecond = 705'600'000;

constexpr double ticksToSeconds(Tick ticks) { return double(ticks) / double(TicksPerSecond); }
inline Tick secondsToTicks(double seconds) { return Tick(std::llround(seconds * double(TicksPerSecond))); }
/// Ticks of one frame at a whole-number frame rate.
constexpr Tick ticksPerFrame(int framesPerSecond) { return TicksPerSecond / framesPerSecond; }

} // namespace thespis::core
