#include "ar/track_job.h"

#include <cstdio>

#include "ar/frame_source.h"
#include "util/file_io.h"

namespace thespis::core::ar {

std::string TrackJob::title() const
{
    return "Tracking " + (video.empty() ? std::string("the pictures") : video.filename().string());
}

Result<void> TrackJob::validate() const
{
    if (video.empty() == pictures.empty())
        return makeError(ErrorCode::InvalidArgument, "Track either a video or pictures (one of the two)");
    if (!pictures.empty() && !(picturesFps > 0))
        return makeError(ErrorCode::InvalidArgument, "The pictures' frame rate must be positive");
    if (cameraFile.empty())
        return makeError(ErrorCode::InvalidArgument, "Tracking needs the camera's calibration file");
    if (target.board.has_value() == !target.picture.empty())
        return makeError(ErrorCode::InvalidArgument, "Track either a board or a picture (one of the two)");
    if (!target.picture.empty() && !(target.pictureWidth > 0))
        return makeError(ErrorCode::InvalidArgument, "The picture's printed width must be a positive number of metres");
    return {};
}

Result<void> TrackJob::run(JobContext& context)
{
    frames.clear();
    auto camera = readCameraFile(cameraFile);
    if (!camera)
        return camera.error();
    auto source = video.empty() ? openImageSequence(pictures, picturesFps) : openVideoFile(video);
    if (!source)
        return source.error();
    FrameSource& frameSource = **source;
    if (auto fits = checkCameraFits(*camera, cameraFile.filename().string(), frameSource); !fits)
        return fits.error();
    auto tracker = makeTracker(target, *camera);
    if (!tracker)
        return tracker.error();
    trackerDescription = (*tracker)->description();
    TrackingSession session(std::move(*tracker), {}, filter);
    context.beginStage(Stage, std::uint64_t(std::max<std::int64_t>(0, frameSource.frameCount())));
    VideoFrame frame;
    while (true) {
        if (context.stopRequested())
            return cancelledError(title());
        Result<bool> read = frameSource.read(frame);
        if (!read)
            return read.error();
        if (!*read)
            break;
        frames.push_back(session.process(frame));
        context.setDone(std::uint64_t(frames.size()));
    }
    statistics = session.statistics();
    if (frames.empty())
        return makeError(ErrorCode::InvalidArgument, frameSource.description() + " holds no frame");
    if (!output.empty())
        if (auto written = writeFileAtomically(output, formatPosesCsv(frames)); !written)
            return written.error();
    return {};
}

void TrackJob::discardOutput()
{
    if (!output.empty()) {
        std::error_code ignored;
        std::filesystem::remove(output, ignored);
    }
}

std::string formatPosesCsv(const std::vector<TrackedFrame>& frames)
{
    std::string csv = "frame,tracked,rx,ry,rz,tx,ty,tz,blur_px,blur_deg,ambiguity\n";
    char line[320];
    for (const TrackedFrame& f : frames) {
        if (f.tracked) {
            const TargetPose& p = f.pose;
            const TrackerEstimate& m = f.measured;
            std::snprintf(line, sizeof line, "%lld,1,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.3f,%.1f,%.3g\n",
                          static_cast<long long>(f.frame), p.rotation[0], p.rotation[1], p.rotation[2], p.translation[0],
                          p.translation[1], p.translation[2], m.blur.length, m.blur.angle * 180 / 3.14159265358979323846,
                          m.ambiguity);
        } else {
            std::snprintf(line, sizeof line, "%lld,0,,,,,,,,,\n", static_cast<long long>(f.frame));
        }
        csv += line;
    }
    return csv;
}

} // namespace thespis::core::ar
