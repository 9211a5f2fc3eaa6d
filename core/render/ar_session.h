#pragma once
// The live AR loop (paper §7.2), as the studio's AR preview runs it: frames captured on one
// thread (ar::LiveCapture, the newest wins), tracked on a second (ar::TrackingSession), and the
// scenario drawn over them on a third (ArCompositor, which owns its GL context there), lit by a
// mirror ball in view when asked (ar::LiveProbe). Each stage takes the newest result of the one
// before and drops what it could not take in time, so a slow stage never makes a queue. The
// scenario is the studio's Stage as its Session plays it: each frame is drawn with the newest
// poses the Session published (PoseMailbox), so scripts, live actions, the playhead and edits
// show over the video at once. Which clock the Session follows — its transport, or the video's
// time, which the snapshots carry — is the preview's choice; the session never evaluates.
//
// Consumers (the studio's preview, tests) take the newest composed frame with its overlay facts
// (fps, latency, tracking state, why it stopped). A source that ends or fails, a scenario that
// cannot be drawn: the session stops in a state that says why; nothing throws or hangs.

#include <atomic>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "ar/frame_source.h"
#include "ar/live_capture.h"
#include "ar/live_probe.h"
#include "ar/tracking_session.h"
#include "ar/tracking_target.h"
#include "lighting/probe_preview.h"
#include "render/ar_compositor.h"
#include "runtime/pose_mailbox.h"

namespace thespis::core::render {

struct ArSessionSettings {
    ar::CameraIntrinsics camera;
    ar::TrackingTarget target;
    bool filter = true;                           ///< the temporal filter on the poses
    ArCompositorSettings compositor;
    std::optional<ar::LiveProbeSettings> probe;   ///< a mirror ball in view lights the characters
    bool realTime = true;                         ///< files paced at their frame rate (cameras always are)
    /// The stage drawn (of the scenario's runtime) and the mailbox its poses come through; both
    /// are needed to draw characters (without them only the video and the tracking run).
    std::shared_ptr<runtime::Stage> stage;
    std::shared_ptr<const runtime::PoseMailbox> poses;
};

/// What the preview shows: the newest composed frame and the facts of the overlay.
struct ArSnapshot {
    ar::VideoFrame frame;          ///< the video with the scenario drawn over it (as it is when not tracked)
    ar::TrackedFrame tracking;     ///< the frame's tracking: state, poses, event
    Tick videoTime = 0;            ///< the frame's time in its video (what a video clock follows)
    runtime::PoseSet poses;        ///< the characters' poses drawn over it (time: the stage's tick)
    double fps = 0;                ///< frames composed per second, over the last second
    double latency = 0;            ///< seconds from the frame's capture to its composition
    std::int64_t dropped = 0;      ///< frames the capture dropped because tracking was busy
    bool lit = false;              ///< the characters are lit by the live probe
    /// The mirror ball as the camera sees it (RGBA, transparent outside the ball) when a live
    /// probe runs, and why it is not found when it is not.
    lighting::PreviewImage probePicture;
    std::string probeStatus;
    std::uint64_t probeVersion = 0; ///< grows when the picture changes (it is copied only then)
};

enum class ArSessionState { Running, Ended, Failed, Stopped };

class ArSession {
public:
    /// Starts the three threads. Errors before anything runs: a tracker that cannot be made
    /// (the target), a camera calibrated for another size than the source's frames, a stage that
    /// does not play the scenario's characters.
    static Result<std::unique_ptr<ArSession>> start(std::unique_ptr<ar::FrameSource> source,
                                                    const scenario::Scenario& scenario,
                                                    const scenario::Assets& assets, const ArSessionSettings& settings);
    /// Stops and joins every thread.
    ~ArSession();

    /// Swaps the newest composed frame into `snapshot` when one was made since the last call.
    bool takeSnapshot(ArSnapshot& snapshot);
    void stop();
    ArSessionState state() const;
    /// Why it ended, failed or stopped ("cockatoo.mp4 ended after 250 frames", a source's or the
    /// renderer's error); empty while running.
    std::string message() const;
    /// Applied by the render thread before its next frame (the user moved the world).
    void setPlacement(const scenario::ArSpec& placement);
    /// Records the composed frames to a video (.mp4 / .avi) until stopRecording(), which
    /// finishes the file. Errors: the file cannot be written.
    Result<void> startRecording(const std::filesystem::path& path);
    Result<void> stopRecording();
    bool recording() const;

private:
    struct Shared;
    explicit ArSession(std::unique_ptr<Shared> shared);
    void track(std::stop_token stop);
    void draw(std::stop_token stop);

    std::unique_ptr<Shared> m_shared;
    std::jthread m_tracking, m_drawing;
};

} // namespace thespis::core::render
