#include "render/play_job.h"

#include <cmath>

#include "ar/frame_source.h"
#include "ar/video_writer.h"

namespace thespis::core::render {

std::string PlayJob::title() const { return "Playing " + (scenario.name.empty() ? std::string("the scenario") : scenario.name); }

Result<void> PlayJob::validate() const
{
    if (output.empty())
        return makeError(ErrorCode::InvalidArgument, "Playing needs a video file to write (.mp4 or .avi)");
    const std::string extension = output.extension().string();
    if (extension != ".mp4" && extension != ".avi")
        return makeError(ErrorCode::InvalidArgument, output.string() + ": videos are written as .mp4 or .avi");
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
    return video.empty() ? onItsOwn(context) : overVideo(context);
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
    const double duration = ar.scene().duration();
    context.beginStage(FramesStage, std::uint64_t(std::max<std::int64_t>(0, input.frameCount())));
    ar::VideoFrame frame;
    while (true) {
        if (context.stopRequested())
            return cancelledError(title()); // the writer takes its unfinished file back
        Result<bool> read = input.read(frame);
        if (!read)
            return read.error();
        if (!*read)
            break;
        const ar::TrackedFrame seen = tracking.process(frame);
        tracked += seen.tracked ? 1 : 0;
        ar.scene().setTime(duration > 0 ? std::fmod(frame.time, duration) : frame.time);
        if (seen.hasPose)
            if (auto drawn = ar.compose(frame, seen.pose); !drawn)
                return drawn.error();
        if (auto written = (*writer)->write(frame); !written)
            return written.error();
        context.setDone(std::uint64_t(++frames));
    }
    if (frames == 0)
        return makeError(ErrorCode::InvalidArgument, video.string() + " holds no frame");
    return (*writer)->finish();
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
    const auto count = std::int64_t(std::floor(shot.scene().duration() * fps)) + 1;
    context.beginStage(FramesStage, std::uint64_t(count));
    ar::VideoFrame frame;
    frame.resize(picture.width, picture.height);
    for (std::int64_t i = 0; i < count; ++i) {
        if (context.stopRequested())
            return cancelledError(title());
        shot.scene().setTime(double(i) / fps);
        auto drawn = shot.draw();
        if (!drawn)
            return drawn.error();
        const RgbaImage& image = **drawn;
        for (std::size_t p = 0, n = std::size_t(image.width) * std::size_t(image.height); p < n; ++p) {
            frame.bgr[3 * p] = image.rgba[4 * p + 2];
            frame.bgr[3 * p + 1] = image.rgba[4 * p + 1];
            frame.bgr[3 * p + 2] = image.rgba[4 * p];
        }
        if (auto written = (*writer)->write(frame); !written)
            return written.error();
        context.setDone(std::uint64_t(++frames));
    }
    return (*writer)->finish();
}

} // namespace thespis::core::render
