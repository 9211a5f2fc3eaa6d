// core/ar (paper §7.2): the live AR loop's parts.
//
// Tracking/grid, Tracking/charuco: one 640 × 480 frame of synthetic footage (noise, motion blur,
//   a board moving at 0.35–0.6 m; frames rendered beforehand) through a TrackingSession: marker
//   detection, sub-pixel corners, the pose and the temporal filter. Frames per second reported.
// ArLoop/samples/shadow: the whole loop but the capture's decoding: a 640 × 480 frame of the same
//   footage tracked (grid), filtered, the built-in humanoid (23k triangles, one character)
//   drawn from the tracked pose on llvmpipe (EGL) with its shadow catcher, and laid over the
//   frame. samples 1: one draw per pixel; 4: 2 × 2 supersampled edges; shadow 0: no shadow catcher.
// CaptureToPose: a synthetic camera delivering 30 frames per second on the capture thread, the
//   consumer tracking the newest frame: the time from a frame's capture to its filtered pose.
#include <benchmark/benchmark.h>

#include "ar/board.h"
#include "ar/live_capture.h"
#include "ar/marker_tracker.h"
#include "ar/synthetic_source.h"
#include "ar/tracking_session.h"
#include "render/ar_compositor.h"

using namespace thespis::core;
using namespace thespis::core::ar;

namespace {

SyntheticScene scene(const char* board, std::int64_t frames)
{
    SyntheticScene s;
    s.board = *parseBoard(board);
    s.camera.width = 640;
    s.camera.height = 480;
    s.camera.matrix = {536.1, 0, 342.4, 0, 536.1, 235.6, 0, 0, 1}; // OpenCV's calibration sample
    s.frames = frames;
    s.noise = 3;
    return s;
}

const char* boardOf(std::int64_t which)
{
    return which == 0 ? "aruco-grid:DICT_4X4_50:4x3:0.04:0.01" : "charuco:DICT_4X4_1000:5x7:0.03:0.022";
}

void Tracking(benchmark::State& state)
{
    constexpr std::int64_t Frames = 90;
    const SyntheticScene s = scene(boardOf(state.range(0)), Frames);
    auto source = SyntheticSource::create(s).value();
    std::vector<VideoFrame> frames(Frames);
    for (VideoFrame& frame : frames)
        (void)source->read(frame);
    TrackingSession session(MarkerTracker::create(s.board, s.camera).value());
    std::size_t i = 0;
    std::int64_t tracked = 0;
    double time = 0;
    for (auto _ : state) {
        VideoFrame& frame = frames[i++ % frames.size()];
        frame.time = time; // the footage loops; its clock goes on
        time += 1.0 / s.fps;
        tracked += session.process(frame).tracked ? 1 : 0;
    }
    state.counters["fps"] = benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
    state.counters["tracked"] = double(tracked) / double(state.iterations());
}

void ArLoop(benchmark::State& state)
{
    constexpr std::int64_t Frames = 60;
    const SyntheticScene s = scene(boardOf(0), Frames);
    auto source = SyntheticSource::create(s).value();
    std::vector<VideoFrame> footage(Frames);
    for (VideoFrame& frame : footage)
        (void)source->read(frame);
    scenario::Scenario standing;
    scenario::Character hero;
    hero.name = "Hero";
    hero.skeleton = "hanim-25";
    standing.characters.push_back(hero);
    standing.ar.scale = 0.06;
    standing.ar.shadowCatcher = state.range(1) != 0;
    auto tracker = MarkerTracker::create(s.board, s.camera).value();
    const TargetGeometry geometry = tracker->geometry();
    TrackingSession session(std::move(tracker));
    render::ArCompositorSettings settings;
    settings.samples = int(state.range(0));
    auto compositor = render::ArCompositor::create(standing, scenario::Assets(), s.camera, geometry, settings);
    if (!compositor) {
        state.SkipWithError(compositor.error().message.c_str());
        return;
    }
    VideoFrame frame = footage[0];
    std::size_t i = 0;
    double time = 0;
    for (auto _ : state) {
        const VideoFrame& filmed = footage[i++ % footage.size()];
        std::copy(filmed.bgr.begin(), filmed.bgr.end(), frame.bgr.begin()); // the decoded frame
        frame.time = time;
        time += 1.0 / s.fps;
        const TrackedFrame tracked = session.process(frame);
        if (tracked.hasPose)
            (void)(*compositor)->compose(frame, tracked.pose);
    }
    state.counters["fps"] = benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
}

void CaptureToPose(benchmark::State& state)
{
    for (auto _ : state) {
        LiveCapture capture(SyntheticSource::create(scene(boardOf(0), 150)).value(), true);
        TrackingSession session(MarkerTracker::create(*parseBoard(boardOf(0)), scene(boardOf(0), 1).camera).value());
        VideoFrame frame;
        while (capture.waitNewest(frame, std::chrono::seconds(2)))
            session.process(frame);
        state.counters["latency_ms"] = session.statistics().meanLatency * 1000;
        state.counters["max_latency_ms"] = session.statistics().maxLatency * 1000;
        state.counters["dropped"] = double(capture.dropped());
    }
}

} // namespace

BENCHMARK(Tracking)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(ArLoop)->Args({1, 1})->Args({1, 0})->Args({4, 1})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(CaptureToPose)->Iterations(1)->Unit(benchmark::kMillisecond)->UseRealTime();
