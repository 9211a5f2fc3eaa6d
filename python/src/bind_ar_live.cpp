// thespis.ar, continued (bind_ar.cpp binds boards, frames, trackers and the jobs): where frames
// come from (video files, pictures, cameras, the synthetic scene with known poses), the live
// capture thread where the newest frame wins, video files written atomically, and the live light
// probe of a mirror ball.
//
// A Python FrameSource owns its core source behind a mutex. LiveCapture reads it on its own thread
// through a forwarding source, so the Python object stays valid (SyntheticSource.truth() still
// answers) and reading it from Python meanwhile only takes frames away from the capture. Waits
// and reads release the GIL; waits wake every 100 ms to notice Ctrl-C.

#include <algorithm>
#include <chrono>
#include <mutex>
#include <optional>

#include "ar/frame_source.h"
#include "ar/live_capture.h"
#include "ar/live_probe.h"
#include "ar/synthetic_source.h"
#include "ar/video_writer.h"
#include "bind_ar.h"
#include "bind_common.h"
#include "errors.h"

namespace thespis::python {

using namespace pybind11::literals;
namespace ar = core::ar;


namespace {

struct SourceHandle {
    explicit SourceHandle(std::unique_ptr<ar::FrameSource> s) : source(std::move(s)), description(source->description()) {}
    virtual ~SourceHandle() = default;

    /// Runs `work(source)` with the GIL released and the source's mutex held.
    template <class Work>
    auto locked(Work&& work)
    {
        py::gil_scoped_release release;
        std::lock_guard lock(mutex);
        return work(*source);
    }

    std::unique_ptr<ar::FrameSource> source;
    std::string description;
    std::mutex mutex;
};

struct SyntheticHandle final : SourceHandle {
    explicit SyntheticHandle(std::unique_ptr<ar::SyntheticSource> s)
        : SourceHandle(std::unique_ptr<ar::FrameSource>(s.release())), synthetic(static_cast<ar::SyntheticSource*>(source.get()))
    {
    }
    ar::SyntheticSource* synthetic; // owned by `source`
};

// What LiveCapture's thread reads: the Python source, under its mutex (no GIL needed).
class SharedSource final : public ar::FrameSource {
    std::shared_ptr<SourceHandle> m_handle;

    template <class Work>
    auto with(Work&& work) const
    {
        std::lock_guard lock(m_handle->mutex);
        return work(*m_handle->source);
    }

public:
    explicit SharedSource(std::shared_ptr<SourceHandle> handle) : m_handle(std::move(handle)) {}
    std::string description() const override { return m_handle->description; }
    core::Result<bool> read(ar::VideoFrame& frame) override { return with([&](ar::FrameSource& s) { return s.read(frame); }); }
    double fps() const override { return with([](ar::FrameSource& s) { return s.fps(); }); }
    int width() const override { return with([](ar::FrameSource& s) { return s.width(); }); }
    int height() const override { return with([](ar::FrameSource& s) { return s.height(); }); }
    std::int64_t frameCount() const override { return with([](ar::FrameSource& s) { return s.frameCount(); }); }
};

std::shared_ptr<SourceHandle> sourceHandle(std::unique_ptr<ar::FrameSource> source)
{
    return std::make_shared<SourceHandle>(std::move(source));
}

std::optional<ar::VideoFrame> readFrame(SourceHandle& h)
{
    ar::VideoFrame frame;
    auto read = h.locked([&](ar::FrameSource& s) { return s.read(frame); });
    if (!unwrap(std::move(read)))
        return std::nullopt;
    return frame;
}

struct CaptureHandle {
    std::shared_ptr<SourceHandle> source;
    std::unique_ptr<ar::LiveCapture> capture;
};

const char* stateName(ar::CaptureState state)
{
    switch (state) {
    case ar::CaptureState::Running: return "running";
    case ar::CaptureState::Ended: return "ended";
    case ar::CaptureState::Failed: return "failed";
    case ar::CaptureState::Stopped: return "stopped";
    }
    return "";
}

// The newest frame, waiting up to `timeout` seconds (None: until one comes or the capture stops),
// in slices of 100 ms so that Ctrl-C is noticed.
std::optional<ar::VideoFrame> waitFrame(CaptureHandle& h, std::optional<double> timeout)
{
    using Clock = std::chrono::steady_clock;
    const auto deadline = timeout ? Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                                       std::chrono::duration<double>(std::max(0.0, *timeout)))
                                  : Clock::time_point::max();
    ar::VideoFrame frame;
    while (true) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
        const auto slice = std::clamp(left, std::chrono::milliseconds(0), std::chrono::milliseconds(100));
        bool got = false;
        {
            py::gil_scoped_release release;
            got = slice.count() > 0 ? h.capture->waitNewest(frame, slice) : h.capture->takeNewest(frame);
        }
        if (got)
            return frame;
        if (h.capture->state() != ar::CaptureState::Running || Clock::now() >= deadline)
            return std::nullopt;
        if (PyErr_CheckSignals() != 0)
            throw py::error_already_set();
    }
}

struct WriterHandle {
    std::unique_ptr<ar::VideoWriter> writer;
    std::filesystem::path path;
    bool finished = false;
    std::mutex mutex;

    ar::VideoWriter& open()
    {
        if (!writer || finished)
            throw py::value_error("The video " + path.filename().string() + " is " + (finished ? "finished" : "discarded") +
                                  "; write to a new VideoWriter.");
        return *writer;
    }
};

struct ProbeHandle {
    explicit ProbeHandle(ar::LiveProbe p) : probe(std::move(p)) {}
    ar::LiveProbe probe;
    std::mutex mutex;
};

void bindSources(py::module_& a)
{
    py::class_<SourceHandle, std::shared_ptr<SourceHandle>>(
        a, "FrameSource", "Frames from a video, pictures, a camera or a synthetic scene; iterate for VideoFrames.")
        .def_readonly("description", &SourceHandle::description)
        .def_property_readonly("fps", [](SourceHandle& h) { return h.locked([](ar::FrameSource& s) { return s.fps(); }); },
                               "Frames per second (0 when unknown).")
        .def_property_readonly("width", [](SourceHandle& h) { return h.locked([](ar::FrameSource& s) { return s.width(); }); })
        .def_property_readonly("height", [](SourceHandle& h) { return h.locked([](ar::FrameSource& s) { return s.height(); }); })
        .def_property_readonly("frame_count",
                               [](SourceHandle& h) { return h.locked([](ar::FrameSource& s) { return s.frameCount(); }); },
                               "Frames in a file or sequence; −1 for a camera.")
        .def("read", &readFrame, "The next VideoFrame, or None at the end. Releases the GIL.")
        .def("__iter__", [](py::object self) { return self; })
        .def("__next__",
             [](SourceHandle& h) {
                 auto frame = readFrame(h);
                 if (!frame)
                     throw py::stop_iteration();
                 return std::move(*frame);
             })
        .def("__repr__", [](const SourceHandle& h) { return "<thespis.ar.FrameSource " + h.description + ">"; });

    a.def("open_video", [](const std::filesystem::path& path) { return sourceHandle(unwrap(ar::openVideoFile(path))); },
          "path"_a, "A video file (whatever FFmpeg decodes); frame times are its timestamps.");
    a.def(
        "open_pictures",
        [](std::vector<std::filesystem::path> paths, double fps) {
            return sourceHandle(unwrap(ar::openImageSequence(std::move(paths), fps)));
        },
        "paths"_a, "fps"_a = 30.0, "Pictures read in order, frame i at i / fps seconds.");

    py::class_<ar::CameraDevice>(a, "CameraDevice")
        .def_readonly("index", &ar::CameraDevice::index)
        .def_readonly("path", &ar::CameraDevice::path)
        .def_readonly("name", &ar::CameraDevice::name)
        .def("__repr__", [](const ar::CameraDevice& c) { return "<thespis.ar.CameraDevice " + c.path + " " + c.name + ">"; });
    a.def("list_cameras", &ar::listCameras, "The video capture devices of this machine (often none).");
    a.def(
        "open_camera",
        [](int index, int width, int height, double fps) {
            const ar::CameraRequest request{index, width, height, fps};
            return sourceHandle(unwrap(withoutGil([&] { return ar::openCamera(request); })));
        },
        "index"_a = 0, "width"_a = 640, "height"_a = 480, "fps"_a = 30.0,
        "Opens /dev/video<index> asking for that size and rate (the camera may choose another). No such camera "
        "raises KeyError naming the device and the cameras there are.");

    py::class_<SyntheticHandle, SourceHandle, std::shared_ptr<SyntheticHandle>>(
        a, "SyntheticSource",
        "A camera looking at a hand-held board with known poses: sensor noise, motion blur, a hand over the board "
        "in frames hand_over = (first, last) and the board hidden in frames hidden = (first, last).")
        .def(py::init([](const py::object& board, const py::object& camera, std::int64_t frames, double fps,
                         double nearest, double farthest, double noise, double exposure,
                         std::optional<std::pair<std::int64_t, std::int64_t>> handOver,
                         std::optional<std::pair<std::int64_t, std::int64_t>> hidden, unsigned seed) {
                 ar::SyntheticScene scene;
                 scene.board = boardArgument(board);
                 scene.camera = cameraArgument(camera);
                 scene.frames = frames;
                 scene.fps = fps;
                 scene.nearest = nearest;
                 scene.farthest = farthest;
                 scene.noise = noise;
                 scene.exposure = exposure;
                 scene.handOver = handOver.value_or(std::pair<std::int64_t, std::int64_t>{-1, -1});
                 scene.hidden = hidden.value_or(std::pair<std::int64_t, std::int64_t>{-1, -1});
                 scene.seed = seed;
                 return std::make_shared<SyntheticHandle>(unwrap(withoutGil([&] { return ar::SyntheticSource::create(scene); })));
             }),
             "board"_a, "camera"_a, py::kw_only(), "frames"_a = 300, "fps"_a = 30.0, "nearest"_a = 0.35,
             "farthest"_a = 0.6, "noise"_a = 2.0, "exposure"_a = 0.5, "hand_over"_a = py::none(), "hidden"_a = py::none(),
             "seed"_a = 1,
             "board: Board or text; camera: CameraIntrinsics or a camera file (its distortion is not rendered); "
             "nearest / farthest: metres to the board; noise: grey levels; exposure: share of a frame's time.")
        .def("truth", [](const SyntheticHandle& h, std::int64_t frame) { return h.synthetic->truth(frame); }, "frame"_a,
             "The board's true Pose at a frame.")
        .def("visible", [](const SyntheticHandle& h, std::int64_t frame) { return h.synthetic->visible(frame); }, "frame"_a,
             "Whether the board can be seen at a frame (not hidden).")
        .def_property_readonly("board", [](const SyntheticHandle& h) { return h.synthetic->scene().board; })
        .def_property_readonly("camera", [](const SyntheticHandle& h) { return h.synthetic->scene().camera; });
}

void bindCapture(py::module_& a)
{
    py::class_<CaptureHandle>(a, "LiveCapture",
                              "A source read on its own thread for live previews: the newest frame wins, frames not "
                              "taken in time are dropped (and counted). Iterate for frames until it stops; a context "
                              "manager stops it on exit.")
        .def(py::init([](std::shared_ptr<SourceHandle> source, bool realTime) {
                 auto handle = std::make_unique<CaptureHandle>();
                 handle->source = source;
                 handle->capture = std::make_unique<ar::LiveCapture>(std::make_unique<SharedSource>(std::move(source)), realTime);
                 return handle;
             }),
             "source"_a, "real_time"_a = true,
             "Starts reading at once. real_time: files and sequences are paced at their frame rate (cameras pace "
             "themselves); False: as fast as they decode.")
        .def("newest", &waitFrame, "timeout"_a = py::none(),
             "The newest frame that arrived since the last call, waiting up to `timeout` seconds (None: until one "
             "arrives or the capture stops; 0: no wait). None when none came. Releases the GIL.")
        .def("__iter__", [](py::object self) { return self; })
        .def("__next__",
             [](CaptureHandle& h) {
                 auto frame = waitFrame(h, std::nullopt);
                 if (!frame)
                     throw py::stop_iteration();
                 return std::move(*frame);
             })
        .def("stop",
             [](CaptureHandle& h) {
                 py::gil_scoped_release release;
                 h.capture->stop();
             },
             "Stops the thread and waits for it.")
        .def("__enter__", [](py::object self) { return self; })
        .def("__exit__",
             [](CaptureHandle& h, const py::object&, const py::object&, const py::object&) {
                 py::gil_scoped_release release;
                 h.capture->stop();
                 return false;
             })
        .def_property_readonly("state", [](const CaptureHandle& h) { return std::string(stateName(h.capture->state())); },
                               "'running', 'ended', 'failed' or 'stopped'.")
        .def_property_readonly("message", [](const CaptureHandle& h) { return h.capture->message(); },
                               "Why it ended or failed.")
        .def_property_readonly("captured", [](const CaptureHandle& h) { return h.capture->captured(); })
        .def_property_readonly("dropped", [](const CaptureHandle& h) { return h.capture->dropped(); })
        .def_property_readonly("description", [](const CaptureHandle& h) { return h.capture->description(); })
        .def_readonly("source", &CaptureHandle::source);
}

void bindWriter(py::module_& a)
{
    py::class_<WriterHandle>(a, "VideoWriter",
                             "Frames written as .mp4 (H.264, else MPEG-4) or .avi (Motion JPEG), beside the final name "
                             "and renamed by finish(). As a context manager it finishes on exit, or discards the file "
                             "when an exception left the block.")
        .def(py::init([](const std::filesystem::path& path, int width, int height, double fps) {
                 auto handle = std::make_unique<WriterHandle>();
                 handle->writer = unwrap(ar::VideoWriter::create(path, width, height, fps));
                 handle->path = path;
                 return handle;
             }),
             "path"_a, "width"_a, "height"_a, "fps"_a = 30.0)
        .def(
            "write",
            [](WriterHandle& h, const py::object& frame) {
                ar::VideoFrame storage;
                const ar::VideoFrame& f = frameArgument(frame, storage);
                ar::VideoWriter& writer = h.open();
                auto written = [&] {
                    py::gil_scoped_release release;
                    std::lock_guard lock(h.mutex);
                    return writer.write(f);
                }();
                unwrap(std::move(written));
            },
            "frame"_a, "Appends a VideoFrame or a BGR array of the video's size. Releases the GIL.")
        .def(
            "finish",
            [](WriterHandle& h) {
                ar::VideoWriter& writer = h.open();
                auto finished = [&] {
                    py::gil_scoped_release release;
                    std::lock_guard lock(h.mutex);
                    return writer.finish();
                }();
                unwrap(std::move(finished));
                h.finished = true;
            },
            "Closes the file and gives it its name.")
        .def_readonly("path", &WriterHandle::path)
        .def_property_readonly("frames", [](const WriterHandle& h) { return h.writer ? h.writer->frames() : 0; })
        .def("__enter__", [](py::object self) { return self; })
        .def("__exit__", [](WriterHandle& h, const py::object& type, const py::object&, const py::object&) {
            if (h.finished || !h.writer)
                return false;
            if (type.is_none()) {
                auto finished = h.writer->finish();
                unwrap(std::move(finished));
                h.finished = true;
            } else {
                h.writer.reset(); // removes the unfinished file
            }
            return false;
        });
}

py::array_t<double> lightArray(const core::lighting::ShRgb& light)
{
    const auto count = py::ssize_t(light.order) * light.order;
    py::array_t<double> out({py::ssize_t(3), count});
    for (int c = 0; c < 3 && count > 0; ++c)
        std::copy_n(light[c].data(), count, out.mutable_data(c, 0));
    return out;
}

void bindProbe(py::module_& a)
{
    py::class_<ar::BallSighting>(a, "BallSighting", "Where the mirror ball was seen in the last processed frame.")
        .def_readonly("found", &ar::BallSighting::found)
        .def_property_readonly("circle",
                               [](const ar::BallSighting& b) -> py::object {
                                   if (!b.found)
                                       return py::none();
                                   return py::make_tuple(b.circle.centerX, b.circle.centerY, b.circle.radius);
                               },
                               "(centre x, centre y, radius) in pixels (the top-left pixel's centre is (0.5, 0.5)).")
        .def_readonly("reason", &ar::BallSighting::reason, "Why it was not found.");

    const ar::LiveProbeSettings d;
    py::class_<ProbeHandle>(a, "LiveProbe",
                            "The AR scene's light from a chrome ball in the frames (found, or at `circle`), "
                            "unwrapped every update_every-th frame, projected onto SH and smoothed over time.")
        .def(py::init([](std::optional<std::array<double, 3>> circle, double minRadius, double maxRadius, int searchSize,
                         int order, int probeSize, int updateEvery, double smoothing, double exposure, bool autoExposure,
                         double targetLuminance, double exposureSmoothing, double clippedGain) {
                 ar::LiveProbeSettings s;
                 if (circle) {
                     s.location = ar::BallLocation::Given;
                     s.givenCircle = {(*circle)[0], (*circle)[1], (*circle)[2]};
                 }
                 s.minRadius = minRadius;
                 s.maxRadius = maxRadius;
                 s.searchSize = searchSize;
                 s.order = order;
                 s.probeSize = probeSize;
                 s.updateEvery = updateEvery;
                 s.smoothingSeconds = smoothing;
                 s.exposureMode = autoExposure ? ar::ProbeExposure::Automatic : ar::ProbeExposure::Fixed;
                 s.exposure = exposure;
                 s.targetLuminance = targetLuminance;
                 s.exposureSmoothingSeconds = exposureSmoothing;
                 s.clippedGain = clippedGain;
                 return std::make_unique<ProbeHandle>(unwrap(ar::LiveProbe::create(s)));
             }),
             py::kw_only(), "circle"_a = py::none(), "min_radius"_a = d.minRadius, "max_radius"_a = d.maxRadius,
             "search_size"_a = d.searchSize, "order"_a = d.order, "probe_size"_a = d.probeSize,
             "update_every"_a = d.updateEvery, "smoothing_seconds"_a = d.smoothingSeconds, "exposure"_a = d.exposure,
             "auto_exposure"_a = false, "target_luminance"_a = d.targetLuminance,
             "exposure_smoothing_seconds"_a = d.exposureSmoothingSeconds, "clipped_gain"_a = d.clippedGain,
             "circle: (x, y, radius) pixels where the ball is, or None to find it (radii min_radius … max_radius, "
             "0: 4 % and 50 % of the frame's short side). auto_exposure brings the ball's mean to target_luminance; "
             "otherwise radiance = exposure × the sRGB-decoded value. Errors name the first wrong setting.")
        .def_static(
            "from_file",
            [](const std::filesystem::path& path, core::lighting::ProbeLayout layout, int order) {
                return std::make_unique<ProbeHandle>(unwrap(withoutGil([&] { return ar::LiveProbe::fromFile(path, layout, order); })));
            },
            "path"_a, "layout"_a, "order"_a = 6, "A fixed probe read from an HDR / EXR file (update() leaves it).")
        .def(
            "update",
            [](ProbeHandle& h, const py::object& frame) {
                ar::VideoFrame storage;
                const ar::VideoFrame& f = frameArgument(frame, storage);
                py::gil_scoped_release release;
                std::lock_guard lock(h.mutex);
                return h.probe.update(f);
            },
            "frame"_a, "Takes the next frame (VideoFrame or BGR array); returns whether the light changed. Releases the GIL.")
        .def("reset", [](ProbeHandle& h) { std::lock_guard lock(h.mutex); h.probe.reset(); })
        .def_property_readonly("light", [](ProbeHandle& h) { std::lock_guard lock(h.mutex); return lightArray(h.probe.light()); },
                               "RGB SH light (3, order²) float64 in the probe's frame; (3, 0) before any light.")
        .def_property_readonly("has_light", [](ProbeHandle& h) { std::lock_guard lock(h.mutex); return h.probe.hasLight(); })
        .def_property_readonly("from_ball", [](ProbeHandle& h) { std::lock_guard lock(h.mutex); return h.probe.fromBall(); })
        .def_property_readonly("ball", [](ProbeHandle& h) { std::lock_guard lock(h.mutex); return h.probe.ball(); })
        .def_property_readonly("exposure", [](ProbeHandle& h) { std::lock_guard lock(h.mutex); return h.probe.exposure(); })
        .def_property_readonly("clipped_fraction",
                               [](ProbeHandle& h) { std::lock_guard lock(h.mutex); return h.probe.clippedFraction(); })
        .def_property_readonly(
            "picture",
            [](ProbeHandle& h) {
                std::lock_guard lock(h.mutex);
                const auto& p = h.probe.picture();
                return toArray<std::uint8_t>(p.rgba, {p.height, p.width, 4});
            },
            "The unwrapped ball as seen (sRGB RGBA, transparent outside the disc), (h, w, 4) uint8; empty before a ball.")
        .def_property_readonly(
            "probe_image",
            [](ProbeHandle& h) {
                std::lock_guard lock(h.mutex);
                const auto& image = h.probe.probeImage();
                return toArray<float>(image.rgb, {image.height, image.width, 3});
            },
            "The probe as linear radiance (h, w, 3) float32, in probe_layout.")
        .def_property_readonly("probe_layout", [](ProbeHandle& h) { std::lock_guard lock(h.mutex); return h.probe.probeLayout(); })
        .def("probe", [](ProbeHandle& h) { std::lock_guard lock(h.mutex); return unwrap(h.probe.probe()); },
             "The probe as a thespis.lighting.LightProbe.");
}

} // namespace

void bindArLive(py::module_& a)
{
    bindSources(a);
    bindCapture(a);
    bindWriter(a);
    bindProbe(a);
}

} // namespace thespis::python
