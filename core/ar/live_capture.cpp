#include "ar/live_capture.h"

namespace thespis::core::ar {

LiveCapture::LiveCapture(std::unique_ptr<FrameSource> source, bool realTime)
    : m_source(std::move(source)), m_description(m_source->description()), m_realTime(realTime),
      m_thread([this](std::stop_token stop) { run(stop); })
{
}

LiveCapture::~LiveCapture() { stop(); }

void LiveCapture::stop()
{
    m_thread.request_stop();
    if (m_thread.joinable())
        m_thread.join();
}

void LiveCapture::run(std::stop_token stop)
{
    VideoFrame back;
    const auto start = std::chrono::steady_clock::now();
    const bool pace = m_realTime && m_source->frameCount() >= 0; // a camera paces itself
    std::condition_variable_any sleeper;
    std::mutex sleepMutex;
    while (!stop.stop_requested()) {
        Result<bool> read = m_source->read(back);
        if (!read || !*read) {
            std::lock_guard lock(m_mutex);
            m_state = read ? CaptureState::Ended : CaptureState::Failed;
            m_message = read ? m_description + " ended after " + std::to_string(m_captured) + " frames"
                             : read.error().message;
            m_arrived.notify_all();
            return;
        }
        if (pace) {
            // Frame times are the source's own: wait until the frame is due, or a stop.
            const auto due = start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                         std::chrono::duration<double>(back.time));
            std::unique_lock lock(sleepMutex);
            sleeper.wait_until(lock, stop, due, [] { return false; });
            back.captured = std::chrono::steady_clock::now();
        }
        std::lock_guard lock(m_mutex);
        if (m_fresh)
            ++m_dropped;
        std::swap(back, m_newest);
        m_fresh = true;
        ++m_captured;
        m_arrived.notify_all();
    }
    std::lock_guard lock(m_mutex);
    m_state = CaptureState::Stopped;
    m_message = m_description + " stopped";
    m_arrived.notify_all();
}

bool LiveCapture::takeNewest(VideoFrame& frame)
{
    std::lock_guard lock(m_mutex);
    if (!m_fresh)
        return false;
    std::swap(frame, m_newest);
    m_fresh = false;
    return true;
}

bool LiveCapture::waitNewest(VideoFrame& frame, std::chrono::milliseconds timeout)
{
    std::unique_lock lock(m_mutex);
    m_arrived.wait_for(lock, timeout, [&] { return m_fresh || m_state != CaptureState::Running; });
    if (!m_fresh)
        return false;
    std::swap(frame, m_newest);
    m_fresh = false;
    return true;
}

CaptureState LiveCapture::state() const
{
    std::lock_guard lock(m_mutex);
    return m_state;
}

std::string LiveCapture::message() const
{
    std::lock_guard lock(m_mutex);
    return m_message;
}

std::int64_t LiveCapture::captured() const
{
    std::lock_guard lock(m_mutex);
    return m_captured;
}

std::int64_t LiveCapture::dropped() const
{
    std::lock_guard lock(m_mutex);
    return m_dropped;
}

} // namespace thespis::core::ar
