#include "render/ar_session.h"

#include <condition_variable>
#include <deque>

#include "ar/video_writer.h"

namespace thespis::core::render {

namespace {
// How long a stage waits for the one before it before checking whether it should stop.
constexpr auto Poll = std::chrono::milliseconds(50);
} // namespace

struct ArSession::Shared {
    ArSessionSettings settings;
    scenario::Scenario scenario;
    scenario::Assets assets;
    std::unique_ptr<ar::LiveCapture> capture;
    std::unique_ptr<ar::TrackingSession> tracking; // the tracking thread's
    ar::TargetGeometry geometry;
    double sourceFps = 30;

    mutable std::mutex mutex;
    std::condition_variable tracked;
    // Tracking → drawing: the newest tracked frame.
    ar::VideoFrame trackedFrame;
    ar::TrackedFrame trackedResult;
    bool trackedFresh = false, trackingDone = false;
    // Drawing → consumers.
    ArSnapshot snapshot;
    bool snapshotFresh = false;
    ArSessionState state = ArSessionState::Running;
    std::string message;
    std::optional<scenario::ArSpec> placement;
    std::unique_ptr<ar::VideoWriter> writer;

    void finish(ArSessionState how, std::string why)
    {
        std::lock_guard lock(mutex);
        if (state == ArSessionState::Running) {
            state = how;
            message = std::move(why);
        }
    }
};

ArSession::ArSession(std::unique_ptr<Shared> shared) : m_shared(std::move(shared)) {}

ArSession::~ArSession() { stop(); }

Result<std::unique_ptr<ArSession>> ArSession::start(std::unique_ptr<ar::FrameSource> source,
                                                    const scenario::Scenario& scenario,
                                                    const scenario::Assets& assets, const ArSessionSettings& settings)
{
    const ar::CameraIntrinsics& camera = settings.camera;
    if (auto fits = ar::checkCameraFits(camera, "The camera file", *source); !fits)
        return fits.error();
    if (!scenario.characters.empty()) {
        if (!settings.stage || !settings.poses)
            return makeError(ErrorCode::InvalidArgument,
                             "The AR session draws a stage as its owner plays it: give it the stage and its poses.");
        if (settings.stage->characterCount() != int(scenario.characters.size()))
            return makeError(ErrorCode::InvalidArgument, "The stage does not play this scenario's characters.");
    }
    auto tracker = ar::makeTracker(settings.target, camera);
    if (!tracker)
        return tracker.error();
    auto shared = std::make_unique<Shared>();
    shared->settings = settings;
    shared->settings.compositor.stage = settings.stage;
    shared->scenario = scenario;
    shared->assets = assets;
    shared->geometry = (*tracker)->geometry();
    shared->tracking = std::make_unique<ar::TrackingSession>(std::move(*tracker), ar::PoseFilterSettings{}, settings.filter);
    if (source->fps() > 0)
        shared->sourceFps = source->fps();
    shared->capture = std::make_unique<ar::LiveCapture>(std::move(source), settings.realTime);
    std::unique_ptr<ArSession> session(new ArSession(std::move(shared)));
    session->m_tracking = std::jthread([s = session.get()](std::stop_token stop) { s->track(stop); });
    session->m_drawing = std::jthread([s = session.get()](std::stop_token stop) { s->draw(stop); });
    return session;
}

void ArSession::track(std::stop_token stop)
{
    Shared& s = *m_shared;
    ar::VideoFrame frame;
    while (!stop.stop_requested()) {
        if (!s.capture->waitNewest(frame, Poll)) {
            if (s.capture->state() != ar::CaptureState::Running)
                break;
            continue;
        }
        ar::TrackedFrame result = s.tracking->process(frame);
        std::lock_guard lock(s.mutex);
        std::swap(s.trackedFrame, frame);
        s.trackedResult = result;
        s.trackedFresh = true;
        s.tracked.notify_all();
    }
    std::lock_guard lock(s.mutex);
    s.trackingDone = true;
    s.tracked.notify_all();
}

void ArSession::draw(std::stop_token stop)
{
    Shared& s = *m_shared;
    auto compositor = ArCompositor::create(s.scenario, s.assets, s.settings.camera, s.geometry, s.settings.compositor);
    if (!compositor) {
        s.finish(ArSessionState::Failed, describe(compositor.error()));
        s.capture->stop();
        return;
    }
    ArCompositor& ar = **compositor;
    std::optional<ar::LiveProbe> probe;
    if (s.settings.probe) {
        auto made = ar::LiveProbe::create(*s.settings.probe);
        if (!made) {
            s.finish(ArSessionState::Failed, describe(made.error()));
            s.capture->stop();
            return;
        }
        probe.emplace(std::move(made).value());
    }
    runtime::PoseSet poses = ar.scene().poses();
    std::uint64_t posesSeen = 0;
    ar::VideoFrame frame;
    ar::TrackedFrame tracking;
    std::deque<std::chrono::steady_clock::time_point> composed; // the last second's, for the fps
    while (!stop.stop_requested()) {
        std::optional<scenario::ArSpec> placement;
        {
            std::unique_lock lock(s.mutex);
            s.tracked.wait_for(lock, Poll, [&] { return s.trackedFresh || s.trackingDone; });
            if (!s.trackedFresh) {
                if (s.trackingDone)
                    break;
                continue;
            }
            std::swap(frame, s.trackedFrame);
            tracking = s.trackedResult;
            s.trackedFresh = false;
            placement.swap(s.placement);
        }
        if (placement)
            if (auto placed = ar.setPlacement(*placement); !placed) {
                s.finish(ArSessionState::Failed, describe(placed.error()));
                break;
            }
        bool lit = false, probeChanged = false;
        if (probe) {
            probeChanged = probe->update(frame);
            if (probe->hasLight() && tracking.hasPose) {
                ar.setCameraLight(probe->light(), tracking.pose);
                lit = true;
            }
        }
        if (s.settings.poses)
            if (const std::uint64_t newest = s.settings.poses->takeNewer(poses, posesSeen)) {
                posesSeen = newest;
                ar.scene().setPoses(poses);
            }
        if (tracking.hasPose) {
            if (auto drawn = ar.compose(frame, tracking.pose); !drawn) {
                s.finish(ArSessionState::Failed, describe(drawn.error()));
                break;
            }
            // A character told to look at the camera looks at the visitor's real one.
            s.settings.stage->setCameraPosition(ar.cameraPosition(tracking.pose));
        }
        const auto now = std::chrono::steady_clock::now();
        composed.push_back(now);
        while (now - composed.front() > std::chrono::seconds(1))
            composed.pop_front();
        std::lock_guard lock(s.mutex);
        if (s.writer)
            if (auto written = s.writer->write(frame); !written)
                s.writer.reset(); // a frame of another size: the recording stops, the preview goes on
        s.snapshot.tracking = tracking;
        s.snapshot.videoTime = secondsToTicks(frame.time);
        runtime::copyPoses(ar.scene().poses(), s.snapshot.poses);
        s.snapshot.fps = double(composed.size());
        s.snapshot.latency = std::chrono::duration<double>(now - frame.captured).count();
        s.snapshot.dropped = s.capture->dropped();
        s.snapshot.lit = lit;
        if (probeChanged) {
            s.snapshot.probePicture = probe->picture();
            ++s.snapshot.probeVersion;
        }
        if (probe)
            s.snapshot.probeStatus = probe->ball().found ? std::string("mirror ball found") : probe->ball().reason;
        std::swap(s.snapshot.frame, frame);
        s.snapshotFresh = true;
    }
    // Why it ended: the source's reason, unless the session was stopped or failed already.
    const ar::CaptureState capture = s.capture->state();
    if (capture == ar::CaptureState::Failed)
        s.finish(ArSessionState::Failed, s.capture->message());
    else if (capture == ar::CaptureState::Ended)
        s.finish(ArSessionState::Ended, s.capture->message());
    else
        s.finish(ArSessionState::Stopped, "Stopped");
    std::lock_guard lock(s.mutex);
    if (s.writer)
        (void)s.writer->finish();
    s.writer.reset();
}

bool ArSession::takeSnapshot(ArSnapshot& snapshot)
{
    std::lock_guard lock(m_shared->mutex);
    if (!m_shared->snapshotFresh)
        return false;
    std::swap(snapshot.frame, m_shared->snapshot.frame);
    snapshot.tracking = m_shared->snapshot.tracking;
    snapshot.videoTime = m_shared->snapshot.videoTime;
    runtime::copyPoses(m_shared->snapshot.poses, snapshot.poses);
    snapshot.fps = m_shared->snapshot.fps;
    snapshot.latency = m_shared->snapshot.latency;
    snapshot.dropped = m_shared->snapshot.dropped;
    snapshot.lit = m_shared->snapshot.lit;
    if (snapshot.probeVersion != m_shared->snapshot.probeVersion) {
        snapshot.probePicture = m_shared->snapshot.probePicture;
        snapshot.probeVersion = m_shared->snapshot.probeVersion;
    }
    snapshot.probeStatus = m_shared->snapshot.probeStatus;
    m_shared->snapshotFresh = false;
    return true;
}

void ArSession::stop()
{
    m_shared->capture->stop();
    m_tracking.request_stop();
    m_drawing.request_stop();
    if (m_tracking.joinable())
        m_tracking.join();
    if (m_drawing.joinable())
        m_drawing.join();
}

ArSessionState ArSession::state() const
{
    std::lock_guard lock(m_shared->mutex);
    return m_shared->state;
}

std::string ArSession::message() const
{
    std::lock_guard lock(m_shared->mutex);
    return m_shared->message;
}

void ArSession::setPlacement(const scenario::ArSpec& placement)
{
    std::lock_guard lock(m_shared->mutex);
    m_shared->placement = placement;
}

Result<void> ArSession::startRecording(const std::filesystem::path& path)
{
    auto writer = ar::VideoWriter::create(path, m_shared->settings.camera.width, m_shared->settings.camera.height,
                                          m_shared->sourceFps);
    if (!writer)
        return writer.error();
    std::lock_guard lock(m_shared->mutex);
    if (m_shared->writer)
        (void)m_shared->writer->finish();
    m_shared->writer = std::move(writer).value();
    return {};
}

Result<void> ArSession::stopRecording()
{
    std::lock_guard lock(m_shared->mutex);
    if (!m_shared->writer)
        return {};
    auto finished = m_shared->writer->finish();
    m_shared->writer.reset();
    return finished;
}

bool ArSession::recording() const
{
    std::lock_guard lock(m_shared->mutex);
    return m_shared->writer != nullptr;
}

} // namespace thespis::core::render
