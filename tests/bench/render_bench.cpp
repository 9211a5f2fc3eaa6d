// Rendering benchmarks (issue 4 §4), on the built-in humanoid.
//
// RenderOffscreen/1280x720/<shading>: one frame of the demo humanoid (about 20k triangles) on the
//   ground, drawn offscreen through EGL (Mesa llvmpipe here) and read back into an RGBA8 picture:
//   what `thespis-cli render` pays per frame. Reports fps (wall clock: llvmpipe draws on its own
//   threads), and the CPU time of all the process's threads per frame (cpu_ms/frame: what the
//   frame costs whatever else runs on the machine). Goal ≥ 30 fps.
// FrameCPU/2x15k: the CPU side of a frame for two characters of about 15k triangles each: a
//   two-clip blending schedule evaluated into a frame, skinning (LBS, one thread), the light
//   rotated into every segment's frame (order 3 DU transfer) and the posed vertices copied into
//   the OSG arrays — everything but drawing. Goal ≤ 2 ms. Also reports heap allocations per frame.
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include <sys/resource.h>

#include "allocation_counter.h"
#include "anim/blending_schedule.h"
#include "anim/keyframe_clip.h"
#include "render/offscreen_renderer.h"
#include "render/render_scene.h"
#include "scene/default_humanoid.h"

using namespace thespis::core;

namespace {

/// User + system time of every thread of the process, in seconds.
double processCpuSeconds()
{
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) + 1e-6 * double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

std::shared_ptr<const scene::Character> humanoid(double detail)
{
    auto made = scene::makeDefaultHumanoid({.detail = detail});
    if (!made)
        return nullptr;
    return std::make_shared<const scene::Character>(std::move(*made));
}

// A 2 s clip on the character's skeleton: every joint wanders by small random steps, as mocap does.
std::shared_ptr<anim::KeyframeClip> wanderingClip(const anim::Skeleton& skeleton, std::mt19937& rng)
{
    std::normal_distribution<float> gaussian;
    const anim::FrameLayout& layout = *skeleton.frameLayout();
    const std::vector<float> rest = skeleton.restFrame();
    const int keys = 61;
    std::vector<float> data;
    std::vector<anim::Quat> current(std::size_t(layout.rotationCount()));
    for (int k = 0; k < keys; ++k) {
        std::vector<float> frame = rest;
        for (int r = 0; r < layout.rotationCount(); ++r) {
            const anim::Quat step =
                anim::normalize(anim::Quat{0.02f * gaussian(rng), 0.02f * gaussian(rng), 0.02f * gaussian(rng), 1.0f});
            current[std::size_t(r)] = anim::normalize(current[std::size_t(r)] * step);
            anim::rotationAt(std::span<float>(frame), r) = current[std::size_t(r)];
        }
        data.insert(data.end(), frame.begin(), frame.end());
    }
    return std::move(anim::KeyframeClip::create(skeleton.frameLayout(), 30.0, std::move(data))).value();
}

void RenderOffscreen(benchmark::State& state, render::Shading shading)
{
    auto renderer = render::OffscreenRenderer::create(1280, 720);
    if (!renderer) {
        state.SkipWithError(describe(renderer.error()).c_str());
        return;
    }
    const auto character = humanoid(1.0);
    if (!character) {
        state.SkipWithError("the default humanoid could not be made");
        return;
    }
    render::RenderScene scene(1);
    scene.setGroundVisible(true);
    scene.setShading(shading);
    if (!scene.addCharacter(character).ok()) {
        state.SkipWithError("the character could not be added to the scene");
        return;
    }
    const render::CameraView view = render::frameBounds(scene.characterBounds(), 25, 10, 1280.0 / 720.0);
    render::RgbaImage image;
    if (auto first = (*renderer)->render(scene, view, image); !first) { // compiles the shaders
        state.SkipWithError(describe(first.error()).c_str());
        return;
    }
    const double cpuBefore = processCpuSeconds();
    for (auto _ : state) {
        (void)(*renderer)->render(scene, view, image);
        benchmark::DoNotOptimize(image.rgba.data());
    }
    state.counters["fps"] = benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
    state.counters["cpu_ms/frame"] = 1000 * (processCpuSeconds() - cpuBefore) / double(state.iterations());
    state.counters["triangles"] = double(character->mesh.triangleCount());
    state.SetLabel((*renderer)->glDescription());
}

void FrameCPU(benchmark::State& state)
{
    // The triangle count goes with detail²: scale it to about 15k triangles.
    const auto full = humanoid(1.0);
    const auto character = full ? humanoid(std::sqrt(15000.0 / double(full->mesh.triangleCount()))) : nullptr;
    if (!character) {
        state.SkipWithError("the default humanoid could not be made");
        return;
    }
    render::RenderScene scene(1);
    std::mt19937 rng(3);
    struct Actor {
        render::CharacterNode* node = nullptr;
        std::unique_ptr<anim::BlendingSchedule> schedule;
        std::vector<float> frame;
    };
    std::vector<Actor> actors(2);
    for (Actor& actor : actors) {
        actor.node = std::move(scene.addCharacter(character)).value();
        actor.schedule = std::make_unique<anim::BlendingSchedule>(character->skeleton);
        for (int k = 0; k < 2; ++k) {
            anim::BlendingAction action;
            action.name = "clip" + std::to_string(k);
            action.source = wanderingClip(character->skeleton, rng);
            action.params.weight = anim::Curve::cubicFade(0.5, 0.5);
            action.renderOutsideDomain = true;
            (void)actor.schedule->addAction(std::move(action));
        }
        actor.frame.resize(character->skeleton.frameLayout()->floatCount());
    }
    double t = 0.6;
    const long before = thespis::test::allocationCount();
    for (auto _ : state) {
        for (Actor& actor : actors) {
            actor.schedule->evaluate(t, actor.frame);
            actor.node->setPose(actor.frame);
        }
        benchmark::DoNotOptimize(actors.front().node->posedPositions().data());
        t += 1.0 / 60.0;
        if (t > 1.4)
            t -= 0.8;
    }
    state.counters["allocs/frame"] =
        double(thespis::test::allocationCount() - before) / double(std::max<benchmark::IterationCount>(state.iterations(), 1));
    state.counters["triangles/character"] = double(character->mesh.triangleCount());
    state.counters["segments/character"] = double(character->mesh.segments.size());
}

} // namespace

BENCHMARK_CAPTURE(RenderOffscreen, 1280x720/prt, render::Shading::Prt)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(RenderOffscreen, 1280x720/phong, render::Shading::Phong)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(RenderOffscreen, 1280x720/unlit, render::Shading::Unlit)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(FrameCPU)->Name("FrameCPU/2x15k")->Unit(benchmark::kMicrosecond);
