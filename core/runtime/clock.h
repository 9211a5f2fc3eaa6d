#pragma once
// Clocks the runtime plays by (paper §3: the animation service runs in a thread of its own,
// controlled by scripts that wait for actions). Time is exact ticks (util/tick.h); seconds only
// at the edges. Three kinds:
//   ManualClock   — moves only when told; a wait jumps to the awaited time at once, so a script
//                   runs in batch (tests, the CLI). A hook sees each jump first, so a headless
//                   runner can render every frame in between before time moves on.
//   RealTimeClock — the wall clock since start(); a wait sleeps.
//   ExternalClock — set from outside (video frame timestamps, audio position, the studio's
//                   playhead); a wait blocks until the driver reaches the time.
// Every wait returns false, early, when its stop token is triggered or its patience runs out
// (so a caller can look at signals now and then, as Python's Ctrl-C needs).

#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <stop_token>

#include "util/tick.h"

namespace thespis::core::runtime {

class Clock {
public:
    virtual ~Clock() = default;
    virtual Tick now() const = 0;
    using Patience = std::chrono::nanoseconds;
    static constexpr Patience Forever = Patience::max();

    /// Blocks until now() ≥ t (true), or until `stop` is requested or `patience` has passed
    /// (false).
    virtual bool waitUntil(Tick t, std::stop_token stop, Patience patience = Forever) = 0;
};

class ManualClock final : public Clock {
public:
    /// Called before the clock jumps forward from `from` to `to`; returns false to stop.
    using JumpHook = std::function<bool(Tick from, Tick to)>;

    explicit ManualClock(Tick start = 0) : m_now(start) {}

    Tick now() const override;
    /// Jumps to t if it is later (the hook sees the jump first); true unless stopped.
    bool waitUntil(Tick t, std::stop_token stop, Patience patience = Forever) override;
    /// Sets the time, forwards or back (scrubbing); the hook is not called.
    void setTime(Tick t);
    /// Moves forward by `ticks` (≥ 0) through the hook; false when stopped.
    bool advance(Tick ticks, std::stop_token stop = {});
    void setJumpHook(JumpHook hook);

private:
    mutable std::mutex m_mutex;
    Tick m_now;
    JumpHook m_hook;
};

class RealTimeClock final : public Clock {
public:
    /// Starts at `start` now.
    explicit RealTimeClock(Tick start = 0);
    Tick now() const override;
    bool waitUntil(Tick t, std::stop_token stop, Patience patience = Forever) override;

private:
    std::chrono::steady_clock::time_point m_origin;
    Tick m_start;
};

class ExternalClock final : public Clock {
public:
    explicit ExternalClock(Tick start = 0) : m_now(start) {}
    Tick now() const override;
    bool waitUntil(Tick t, std::stop_token stop, Patience patience = Forever) override;
    /// The driver's new time (any direction); wakes the waits it reaches.
    void setTime(Tick t);

private:
    mutable std::mutex m_mutex;
    std::condition_variable_any m_changed;
    Tick m_now;
};

} // namespace thespis::core::runtime
