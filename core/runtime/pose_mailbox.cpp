#include "runtime/pose_mailbox.h"

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

} // namespace thespis::core::runtime
