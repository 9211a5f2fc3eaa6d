#include "util/job.h"

#include <thread>

namespace thespis::core {

void JobContext::beginStage(std::string name, std::uint64_t total)
{
    {
        std::lock_guard lock(m_mutex);
        m_stage = std::move(name);
        m_total = total;
        m_done = 0;
    }
    notify();
}

void JobContext::setDone(std::uint64_t done)
{
    m_done.store(done, std::memory_order_relaxed);
    notify();
}

JobProgress JobContext::progress() const
{
    std::lock_guard lock(m_mutex);
    return JobProgress{m_stage, m_done.load(std::memory_order_relaxed), m_total.load(std::memory_order_relaxed)};
}

void JobContext::notify()
{
    m_reports.fetch_add(1, std::memory_order_release);
    m_changed.notify_all();
}

void JobContext::waitForProgress(std::chrono::milliseconds timeout) const
{
    std::unique_lock lock(m_mutex);
    const std::uint64_t seen = m_reports.load(std::memory_order_acquire);
    m_changed.wait_for(lock, timeout, [&] { return m_reports.load(std::memory_order_acquire) != seen; });
}

Error cancelledError(const std::string& what)
{
    return makeError(ErrorCode::Cancelled, what + " was cancelled; nothing was written.");
}

Result<void> runJobWatched(Job& job, std::chrono::milliseconds interval, const JobWatcher& watch)
{
    if (auto valid = job.validate(); !valid)
        return valid;
    std::stop_source stop;
    JobContext context(stop.get_token());
    Result<void> result;
    std::atomic<bool> finished{false};
    std::jthread worker([&] {
        result = job.run(context);
        finished = true;
        context.setDone(context.progress().done); // wakes the watcher
    });
    bool stopped = false;
    while (!finished) {
        context.waitForProgress(interval);
        if (!finished && !stopped && watch && !watch(context.progress())) {
            stop.request_stop();
            stopped = true;
        }
    }
    worker.join();
    if (watch && !stopped && !watch(context.progress()))
        stopped = true;
    if (stopped && result) {
        job.discardOutput();
        return cancelledError(job.title());
    }
    return result;
}

} // namespace thespis::core
