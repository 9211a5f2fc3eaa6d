#include "runtime/player.h"

#include <algorithm>

namespace thespis::core::runtime {

void PoseMailbox::publish(const PoseSet& poses)
{
    {
        const std::lock_guard lock(m_mutex);
        copyPoses(poses, m_poses);
        ++m_sequence;
    }
    m_published.notify_all();
}

std::uint64_t PoseMailbox::takeNewer(PoseSet& out, std::uint64_t seen) const
{
    const std::lock_guard lock(m_mutex);
    if (m_sequence <= seen)
        return 0;
    copyPoses(m_poses, out);
    return m_sequence;
}

std::uint64_t PoseMailbox::waitNewer(std::uint64_t seen, std::chrono::milliseconds timeout) const
{
    std::unique_lock lock(m_mutex);
    m_published.wait_for(lock, timeout, [&] { return m_sequence > seen; });
    return m_sequence;
}

Player::Player(std::shared_ptr<Stage> stage, std::shared_ptr<Clock> clock, PlayerOptions options)
    : m_stage(std::move(stage)), m_clock(std::move(clock)), m_options(options)
{
}

Player::~Player() { stop(); }

void Player::start()
{
    if (!isRunning())
        m_thread = std::jthread([this](std::stop_token stop) { run(stop); });
}

void Player::stop()
{
    if (isRunning()) {
        m_thread.request_stop();
        m_thread.join();
        m_thread = {};
    }
}

void Player::run(std::stop_token stop)
{
    using Steady = std::chrono::steady_clock;
    const auto period = std::chrono::duration_cast<Steady::duration>(
        std::chrono::duration<double>(1.0 / std::clamp(m_options.rate, 1.0, 1000.0)));
    PoseSet poses = m_stage->makePoseSet();
    std::mutex sleeping;
    std::condition_variable_any woken;
    auto next = Steady::now();
    while (!stop.stop_requested()) {
        m_stage->evaluate(m_clock->now(), poses);
        m_mailbox.publish(poses);
        // Ticks keep their rhythm; a late one runs at once, and missed ones are not made up for.
        next = std::max(next + period, Steady::now());
        std::unique_lock lock(sleeping);
        woken.wait_until(lock, stop, next, [] { return false; });
    }
}

} // namespace thespis::core::runtime
