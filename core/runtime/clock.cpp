#include "runtime/clock.h"

#include <algorithm>
#include <thread>

namespace thespis::core::runtime {

Tick ManualClock::now() const
{
    const std::lock_guard lock(m_mutex);
    return m_now;
}

bool ManualClock::waitUntil(Tick t, std::stop_token stop, Patience)
{
    std::unique_lock lock(m_mutex);
    if (t <= m_now)
        return !stop.stop_requested();
    const Tick from = m_now;
    const JumpHook hook = m_hook;
    lock.unlock(); // the hook may read the clock (a renderer evaluating the frames in between)
    if (stop.stop_requested() || (hook && !hook(from, t)))
        return false;
    lock.lock();
    m_now = std::max(m_now, t);
    return true;
}

void ManualClock::setTime(Tick t)
{
    const std::lock_guard lock(m_mutex);
    m_now = t;
}

bool ManualClock::advance(Tick ticks, std::stop_token stop)
{
    return waitUntil(now() + std::max<Tick>(ticks, 0), std::move(stop), Forever);
}

void ManualClock::setJumpHook(JumpHook hook)
{
    const std::lock_guard lock(m_mutex);
    m_hook = std::move(hook);
}

RealTimeClock::RealTimeClock(Tick start) : m_origin(std::chrono::steady_clock::now()), m_start(start) {}

namespace {
using Flicks = std::chrono::duration<Tick, std::ratio<1, TicksPerSecond>>;
}

Tick RealTimeClock::now() const
{
    return m_start + std::chrono::duration_cast<Flicks>(std::chrono::steady_clock::now() - m_origin).count();
}

bool RealTimeClock::waitUntil(Tick t, std::stop_token stop, Patience patience)
{
    // Sleep in short steps so that a stop is seen within 10 ms.
    const auto giveUp = patience == Forever ? std::chrono::steady_clock::time_point::max()
                                            : std::chrono::steady_clock::now() + patience;
    while (!stop.stop_requested() && std::chrono::steady_clock::now() < giveUp) {
        const Tick left = t - now();
        if (left <= 0)
            return true;
        const Flicks step(std::min<Tick>(left, TicksPerSecond / 100));
        std::this_thread::sleep_for(std::chrono::ceil<std::chrono::nanoseconds>(step));
    }
    return false;
}

Tick ExternalClock::now() const
{
    const std::lock_guard lock(m_mutex);
    return m_now;
}

bool ExternalClock::waitUntil(Tick t, std::stop_token stop, Patience patience)
{
    std::unique_lock lock(m_mutex);
    if (patience == Forever)
        return m_changed.wait(lock, stop, [&] { return m_now >= t; });
    return m_changed.wait_for(lock, stop, patience, [&] { return m_now >= t; });
}

void ExternalClock::setTime(Tick t)
{
    {
        const std::lock_guard lock(m_mutex);
        m_now = t;
    }
    m_changed.notify_all();
}

} // namespace thespis::core::runtime
