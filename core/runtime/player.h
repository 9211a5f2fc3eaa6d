#pragma once
// Player (paper §3: the animation service's integrated player, in a thread of its own). It
// evaluates a Stage at its clock's time at a fixed rate and publishes every PoseSet to a
// latest-value mailbox: readers (the renderer) take the newest and never wait for the player,
// and the player never waits for them. At the same clock times it gives exactly the poses a
// manual Stage::evaluate() gives.

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <thread>

#include "runtime/clock.h"
#include "runtime/pose_set.h"
#include "runtime/stage.h"

namespace thespis::core::runtime {

class PoseMailbox {
public:
    /// Copies `poses` in as the newest (no allocation once sized).
    void publish(const PoseSet& poses);
    /// Copies the newest pose set into `out` and returns its number (1, 2, …), or 0 with `out`
    /// untouched when nothing newer than `seen` was published.
    std::uint64_t takeNewer(PoseSet& out, std::uint64_t seen = 0) const;
    /// Waits up to `timeout` for a pose set newer than `seen`; returns the newest number.
    std::uint64_t waitNewer(std::uint64_t seen, std::chrono::milliseconds timeout) const;

private:
    mutable std::mutex m_mutex;
    mutable std::condition_variable m_published;
    PoseSet m_poses;
    std::uint64_t m_sequence = 0;
};

struct PlayerOptions {
    double rate = 60; ///< evaluations per second
};

class Player {
public:
    Player(std::shared_ptr<Stage> stage, std::shared_ptr<Clock> clock, PlayerOptions options = {});
    ~Player(); ///< stops the thread
    Player(const Player&) = delete;
    Player& operator=(const Player&) = delete;

    void start();
    void stop();
    bool isRunning() const { return m_thread.joinable(); }
    const PoseMailbox& mailbox() const { return m_mailbox; }

private:
    void run(std::stop_token stop);

    std::shared_ptr<Stage> m_stage;
    std::shared_ptr<Clock> m_clock;
    PlayerOptions m_options;
    PoseMailbox m_mailbox;
    std::jthread m_thread;
};

} // namespace thespis::core::runtime
