#include "render/play_job.h"

#include <cmath>
#include <limits>
#include <stop_token>

#include "ar/frame_source.h"
#include "ar/video_writer.h"

namespace thespis::core::render {

// Where the frames come from, whatever the mode: writeUntil writes every frame that starts before
// `until` (seconds) — the frames a script's wait jumps over — and writeRest the ones after the
// script, up to the end of the video.
class PlayFrameWriter {
public:
    virtual ~PlayFrameWriter() = default;
    virtual Result<void> writeUntil(double until) = 0;
    virtual Result<void> writeRest(double scriptEnd) = 0;
    virtual Result<void> finish() = 0;
    virtual double seconds() const = 0; ///< the length of what was written
};

namespace {

// On its own: frame i shows time i / fps, up to the scenario's end or the script's.
class OwnFrames final : public PlayFrameWriter {
public:
    OwnFrames(ScenarioPicture& shot, ar::VideoWriter& writer, double fps, JobContext& context, std::int64_t& written)
        : m_shot(shot), m_writer(writer), m_fps(fps), m_context(context), m_written(written)
    {
        m_frame.resize(shot.settings().width, shot.settings().height);
    }

    Result<void> writeUntil(double until) override
    {
        for (; double(m_next) / m_fps < until; ++m_next)
            if (auto wrote = write(double(m_next) / m_fps); !wrote)
                return wrote;
        return {};
    }
    Result<void> writeRest(double scriptEnd) override
    {
        const double end = std::max(ticksToSeconds(m_shot.scene().duration()), scriptEnd);
        const auto count = std::int64_t(std::floor(end * m_fps)) + 1;
        if (std::uint64_t(count) > m_context.progress().total) { // a script that outlasts the scenario
            m_context.beginStage(PlayJob::FramesStage, std::uint64_t(count));
            m_context.setDone(std::uint64_t(m_written));
        }
        for (; m_next < count; ++m_next)
            if (auto wrote = write(double(m_next) / m_fps); !wrote)
                return wrote;
        return {};
    }
    Result<void> finish() override { return m_writer.finish(); }
    double seconds() const override { return double(m_next) / m_fps; }

private:
    Result<void> write(double time)
    {
        if (m_context.stopRequested())
            return makeError(ErrorCode::Cancelled, "stopped");
        m_shot.playAt(secondsToTicks(time));
        auto drawn = m_shot.draw();
        if (!drawn)
            return drawn.error();
        const RgbaImage& image = **drawn;
        for (std::size_t p = 0, n = std::size_t(image.width) * std::size_t(image.height); p < n; ++p) {
            m_frame.bgr[3 * p] = image.rgba[4 * p + 2];
            m_frame.bgr[3 * p + 1] = image.rgba[4 * p + 1];
            m_frame.bgr[3 * p + 2] = image.rgba[4 * p];
        }
        if (auto written = m_writer.write(m_frame); !written)
            return written;
        m_context.setDone(std::uint64_t(++m_written));
        return {};
    }

    ScenarioPicture& m_shot;
    ar::VideoWriter& m_writer;
    double m_fps;
    JobContext& m_context;
    std::int64_t& m_written;
    std::int64_t m_next = 0;
    ar::VideoFrame m_frame;
};

// Over a video: each frame is tracked and composed at its own time. Without a script the
// scenario loops over the video; with one it follows the script's clock.
class VideoFrames final : public PlayFrameWriter {
public:
    VideoFrames(ar::FrameSource& input, ar::TrackingSession& tracking, ArCompositor& ar, ar::VideoWriter& writer,
                const std::filesystem::path& video, bool loop, JobContext& context, std::int64_t& written,
                std::int64_t& tracked)
        : m_input(input), m_video(video), m_tracking(tracking), m_ar(ar), m_writer(writer), m_loop(loop), m_context(context),
          m_written(written), m_tracked(tracked)
    {
    }

    Result<void> writeUntil(double until) override
    {
        while (true) {
            if (!m_pending) {
                Result<bool> read = m_input.read(m_frame);
                if (!read)
                    return read.error();
                if (!*read)
                    return {};
                m_pending = true;
            }
            if (m_frame.time >= until)
                return {};
            if (auto wrote = write(); !wrote)
                return wrote;
        }
    }
    Result<void> writeRest(double) override { return writeUntil(std::numeric_limits<double>::infinity()); }
    Result<void> finish() override
    {
        if (m_written == 0)
            return makeError(ErrorCode::InvalidArgument, m_video.string() + " holds no frame");
        return m_writer.finish();
    }
    double seconds() const override
    {
        const double fps = m_input.fps() > 0 ? m_input.fps() : 30;
        return m_written > 0 ? m_lastTime + 1 / fps : 0;
    }

private:
    Result<void> write()
    {
        m_pending = false;
        if (m_context.stopRequested())
            return makeError(ErrorCode::Cancelled, "stopped");
        const ar::TrackedFrame seen = m_tracking.process(m_frame);
        m_tracked += seen.tracked ? 1 : 0;
        const Tick duration = m_ar.scene().duration();
        const Tick videoTime = secondsToTicks(m_frame.time);
        if (seen.hasPose) // a character told to look at the camera looks at the one that filmed
            m_ar.scene().stage().setCameraPosition(m_ar.cameraPosition(seen.pose));
        m_ar.scene().playAt(m_loop && duration > 0 ? videoTime % duration : videoTime);
        if (seen.hasPose)
            if (auto drawn = m_ar.compose(m_frame, seen.pose); !drawn)
                return drawn;
        if (auto written = m_writer.write(m_frame); !written)
            return written;
        m_lastTime = m_frame.time;
        m_context.setDone(std::uint64_t(++m_written));
        return {};
    }

    ar::FrameSource& m_input;
    const std::filesystem::path& m_video;
    ar::TrackingSession& m_tracking;
    ArCompositor& m_ar;
    ar::VideoWriter& m_writer;
    bool m_loop;
    JobContext& m_context;
    std::int64_t& m_written;
    std::int64_t& m_tracked;
    ar::VideoFrame m_frame;
    bool m_pending = false;
    double m_lastTime = 0;
};

} // namespace

std::string PlayJob::title() const { return "Playing " + (scenario.name.empty() ? std::string("the scenario") : scenario.name); }

Result<void> PlayJob::validate() const
{
    if (output.empty())
        return makeError(ErrorCode::InvalidArgument, "Playing needs a video file to write (.mp4 or .avi)");
    const std::string extension = output.extension().string();
    if (extension != ".mp4" && extension != ".avi")
        return makeError(ErrorCode::InvalidArgument, output.string() + ": videos are written as .mp4 or .avi");
    if (!audio.empty() && audio.extension() != ".wav")
        return makeError(ErrorCode::InvalidArgument, audio.string() + ": the sound is written as a .wav file");
    if (script && (!script->run || !script->stop))
        return makeError(ErrorCode::InvalidArgument, "A script playing along needs a way to run it and to stop it");
    if (video.empty()) {
        if (!(fps > 0) || picture.width < 16 || picture.height < 16)
            return makeError(ErrorCode::InvalidArgument, "A played video needs a frame rate and a size of 16 pixels or more");
        return {};
    }
    if (cameraFile.empty())
        return makeError(ErrorCode::InvalidArgument, "Playing over a video needs the camera's calibration file");
    if (target.board.has_value() == !target.picture.empty())
        return makeError(ErrorCode::InvalidArgument, "Playing over a video needs a board or a picture to track (one of the two)");
    return {};
}

Result<void> PlayJob::run(JobContext& context)
{
    if (auto valid = validate(); !valid)
        return valid;
    frames = tracked = 0;
    seconds = 0;
    sounds = 0;
    auto played = video.empty() ? onItsOwn(context) : overVideo(context);
    if (!played && (played.error().code == ErrorCode::Cancelled || context.stopRequested()))
        return cancelledError(title()); // the writer takes its unfinished file back
    return played;
}

void PlayJob::discardOutput()
{
    std::error_code ignored;
    std::filesystem::remove(output, ignored);
    if (!audio.empty())
        std::filesystem::remove(audio, ignored);
}

Result<void> PlayJob::overVideo(JobContext& context)
{
    context.beginStage(PreparingStage);
    auto camera = ar::readCameraFile(cameraFile);
    if (!camera)
        return camera.error();
    auto source = ar::openVideoFile(video);
    if (!source)
        return source.error();
    ar::FrameSource& input = **source;
    if (auto fits = ar::checkCameraFits(*camera, cameraFile.filename().string(), input); !fits)
        return fits.error();
    auto tracker = ar::makeTracker(target, *camera);
    if (!tracker)
        return tracker.error();
    const ar::TargetGeometry geometry = (*tracker)->geometry();
    ar::TrackingSession tracking(std::move(*tracker));
    auto made = ArCompositor::create(scenario, assets, *camera, geometry, compositor);
    if (!made)
        return made.error();
    ArCompositor& ar = **made;
    warnings = ar.scene().warnings();
    auto writer = ar::VideoWriter::create(output, camera->width, camera->height, input.fps() > 0 ? input.fps() : 30);
    if (!writer)
        return writer.error();
    context.beginStage(FramesStage, std::uint64_t(std::max<std::int64_t>(0, input.frameCount())));
    VideoFrames frameWriter(input, tracking, ar, **writer, video, !script, context, frames, tracked);
    return play(context, frameWriter, ar.scene().sharedStage());
}

Result<void> PlayJob::onItsOwn(JobContext& context)
{
    context.beginStage(PreparingStage);
    auto made = ScenarioPicture::create(scenario, assets, picture);
    if (!made)
        return made.error();
    ScenarioPicture& shot = **made;
    warnings = shot.scene().warnings();
    auto writer = ar::VideoWriter::create(output, picture.width, picture.height, fps);
    if (!writer)
        return writer.error();
    context.beginStage(FramesStage, std::uint64_t(std::floor(ticksToSeconds(shot.scene().duration()) * fps)) + 1);
    OwnFrames frameWriter(shot, **writer, fps, context, frames);
    return play(context, frameWriter, shot.scene().sharedStage());
}

// The frames, with the script (if any) driving the clock, then the sound.
Result<void> PlayJob::play(JobContext& context, PlayFrameWriter& frameWriter, const std::shared_ptr<runtime::Stage>& stage)
{
    Tick scriptEnd = 0;
    std::shared_ptr<runtime::SoundService> sound;
    if (script) {
        auto played = runtime::playScript(
            *script, stage, assets, [&](Tick until) { return frameWriter.writeUntil(ticksToSeconds(until)); },
            context.stopToken());
        if (!played)
            return played.error();
        scriptEnd = played->clock->now();
        sound = played->sound;
        sounds = sound->activationCount();
    }
    if (auto rest = frameWriter.writeRest(ticksToSeconds(scriptEnd)); !rest)
        return rest;
    if (auto finished = frameWriter.finish(); !finished)
        return finished;
    seconds = frameWriter.seconds();
    if (!audio.empty()) {
        if (!sound)
            sound = std::make_shared<runtime::SoundService>(assets, std::make_shared<runtime::ManualClock>());
        // The characters' speech lines play where they are on the timeline, under the script's sounds.
        for (std::string& problem : sound->playSpeech(scenario))
            warnings.push_back(std::move(problem));
        sounds = sound->activationCount();
        if (auto written = sound->writeWav(audio, 0, secondsToTicks(seconds)); !written) {
            discardOutput();
            return written;
        }
    }
    return {};
}

} // namespace thespis::core::render
