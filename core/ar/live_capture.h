#pragma once
// A frame source read on its own thread, for live previews: the newest frame wins. The capture
// thread never waits for the consumer and nothing queues up behind a slow one: a frame not taken
// before the next arrives is dropped (and counted). Frames are swapped, not copied, so their
// buffers go round between the two threads without allocation.
//
// When the source fails (a camera unplugged, a video that stops decoding) or ends, the capture
// stops in a state that says why; the consumer shows it and may start a new capture.

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "ar/frame_source.h"

namespace thespis::core::ar {

enum class CaptureState { Running, Ended, Failed, Stopped };

class LiveCapture {
public:
    /// Starts reading at once. `realTime`: a file or a sequence is paced at its frame rate, as a
    /// camera would deliver it (cameras pace themselves); otherwise frames come as fast as they
    /// decode.
    explicit LiveCapture(std::unique_ptr<FrameSource> source, bool realTime = true);
    /// Stops the thread and waits for it.
    ~LiveCapture();
    LiveCapture(const LiveCapture&) = delete;
    LiveCapture& operator=(const LiveCapture&) = delete;

    /// Swaps the newest frame into `frame` (its old buffer goes back for reuse) when one arrived
    /// since the last call; false when none did.
    bool takeNewest(VideoFrame& frame);
    /// The same, waiting up to `timeout` for a frame; false on timeout or when the capture stopped.
    bool waitNewest(VideoFrame& frame, std::chrono::milliseconds timeout);

    void stop();
    CaptureState state() const;
    /// Why it ended or failed ("cockatoo.mp4 ended after 250 frames", the source's error).
    std::string message() const;
    std::int64_t captured() const;
    std::int64_t dropped() const;
    const std::string& description() const { return m_description; }

private:
    void run(std::stop_token stop);

    std::unique_ptr<FrameSource> m_source;
    std::string m_description;
    bool m_realTime;
    mutable std::mutex m_mutex;
    std::condition_variable m_arrived;
    VideoFrame m_newest;       // guarded; the frame waiting to be taken
    bool m_fresh = false;      // guarded
    CaptureState m_state = CaptureState::Running; // guarded
    std::string m_message;     // guarded
    std::int64_t m_captured = 0, m_dropped = 0; // guarded
    std::jthread m_thread;     // last: started after everything it uses
};

} // namespace thespis::core::ar
