#pragma once
// PoseMailbox: the newest PoseSet, handed from the thread that evaluates the Stage (the studio's
// Session, once per tick) to threads that draw it (the AR preview's renderer). A latest-value
// box: readers take the newest and never wait for the writer, the writer never waits for them,
// and copies allocate nothing once both sides are sized.

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>

#include "runtime/pose_set.h"

namespace thespis::core::runtime {

class PoseMailbox {
public:
    /// Copies `poses` in as the newest.
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

} // namespace thespis::core::runtime
