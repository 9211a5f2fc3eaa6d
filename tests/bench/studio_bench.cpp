// Studio benchmarks (issue 5 §10), on the Qt offscreen platform with the studio's own panels.
//
// TimelineRepaint/1000: one full repaint of the timeline view (1200 × 400, every clip in view
//   after Frame All) showing 1000 actions on 8 tracks, rendered into an image. Goal < 8 ms.
//   TimelineRepaint/0 is the same view without actions (ruler, headers, lanes);
//   TimelineRepaintZoomed/1000 the 1000 actions at a working zoom (80 px/s, about 13 s in view).
// OpenScenario/1000: what the studio does to open a 1000-action scenario before it first draws:
//   read and validate the file and build every schedule (Document::open), fill the outline and
//   the timeline, and build the 3D scene (bodies, retargeting, the camera's bounds over the
//   whole timeline). Counters split the time. Goal < 300 ms.
// ScrubToFrame: a playhead move to a new time until the viewport's frame is ready — the clock
//   seeks, the timeline and the 3D scene follow (schedules evaluated, bodies skinned, light
//   rotated), and the 1280 × 720 frame is drawn offscreen through EGL and read back, as the
//   studio's viewport draws it (Mesa llvmpipe here). Goal < 33 ms.
// DragStep/1000: one step of a timeline drag on the 1000-action scenario — an action moved by a
//   frame, merged into the drag's undo command — from the edit to the views showing it:
//   Document::edit (apply, rebuild what the edit touched, undo stack), the Session giving its
//   stage the new runtime and ticking, the scene posed from the published poses. Goal < 5 ms.
// StudioTick: one tick of playback on the demo with the 3D view's scene, the stick figures, the
//   posture chart and the AR mailbox following the Session.
#include <benchmark/benchmark.h>

#include <QApplication>
#include <QElapsedTimer>
#include <QImage>
#include <QTemporaryDir>
#include <QUndoStack>

#include <algorithm>
#include <filesystem>
#include <memory>

#include "edit/document_edits.h"
#include "editor/document.h"
#include "editor/playback_clock.h"
#include "editor/posture_chart_panel.h"
#include "editor/scenario_tree_model.h"
#include "editor/session.h"
#include "editor/skeleton_view.h"
#include "editor/timeline_panel.h"
#include "render/offscreen_renderer.h"
#include "render/scenario_scene.h"
#include "scenario/scenario_io.h"
#include "widgets/pose_view.h"
#include "widgets/timeline_view.h"

using namespace thespis;

namespace {

QApplication& application()
{
    static int argc = 1;
    static char name[] = "thespis-bench";
    static char* argv[] = {name, nullptr};
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    static QApplication app(argc, argv);
    return app;
}

core::Result<core::scenario::Scenario> demoScenario()
{
    return core::scenario::loadScenario(THESPIS_RESOURCES "/demo.thespis");
}

// The demo with `actionCount` actions spread over 8 body tracks (4 layers per character), each
// a copy of one of the character's actions other than endless loops, one every 0.4 s on its
// track: after Frame All every clip is in view, wide enough for its name, fades and curve. The
// copies of the idle motion are open-ended: their bars reach the view's right edge.
core::Result<core::scenario::Scenario> scenarioWithActions(int actionCount)
{
    auto scenario = demoScenario();
    if (!scenario)
        return scenario.error();
    constexpr int kLayersPerCharacter = 4;
    const int tracks = int(scenario->characters.size()) * kLayersPerCharacter;
    int track = 0;
    for (std::size_t c = 0; c < scenario->characters.size(); ++c) {
        core::scenario::Character& character = scenario->characters[c];
        core::scenario::Layer base = character.layers.front();
        std::erase_if(base.actions, [](const core::scenario::ActionSpec& action) {
            return std::any_of(action.modifiers.begin(), action.modifiers.end(), [](const core::scenario::ModifierSpec& m) {
                return m.kind == core::scenario::ModifierKind::Loop && m.count == 0;
            });
        });
        if (base.actions.empty())
            return core::Error{core::ErrorCode::InvalidArgument, character.name + " has no finite action to copy"};
        character.layers.clear();
        for (int l = 0; l < kLayersPerCharacter; ++l) {
            core::scenario::Layer layer = base;
            layer.name = "track " + std::to_string(l + 1);
            layer.actions.clear();
            const int count = actionCount / tracks + (track < actionCount % tracks ? 1 : 0);
            ++track;
            for (int a = 0; a < count; ++a) {
                core::scenario::ActionSpec action = base.actions[std::size_t(a) % base.actions.size()];
                action.name = "action " + std::to_string(a + 1);
                action.start = core::secondsToTicks(0.4 * a);
                layer.actions.push_back(std::move(action));
            }
            if (l > 0)
                layer.mode = core::anim::BlendMode::Override;
            character.layers.push_back(std::move(layer));
        }
    }
    return scenario;
}

// A document of scenarioWithActions(state.range(0)); null (the benchmark skipped) when it fails.
std::unique_ptr<editor::Document> documentWithActions(benchmark::State& state)
{
    application();
    auto scenario = scenarioWithActions(int(state.range(0)));
    if (!scenario) {
        state.SkipWithError(scenario.error().message.c_str());
        return nullptr;
    }
    auto document = editor::Document::fromScenario(std::move(*scenario), QStringLiteral(THESPIS_RESOURCES));
    if (!document) {
        state.SkipWithError(document.error().message.c_str());
        return nullptr;
    }
    return std::move(document).value();
}

void repaintTimeline(benchmark::State& state, double pixelsPerSecond)
{
    auto document = documentWithActions(state);
    if (!document)
        return;
    editor::TimelinePanel panel;
    panel.resize(1200, 400);
    panel.setDocument(document.get());
    widgets::TimelineView* view = panel.view();
    panel.show(); // offscreen: lays the view out at its size
    QApplication::processEvents();
    view->frameAll();
    if (pixelsPerSecond > 0)
        view->setPixelsPerSecond(pixelsPerSecond);
    QImage image(view->viewport()->size(), QImage::Format_ARGB32_Premultiplied);
    for (auto _ : state) {
        view->viewport()->render(&image);
        benchmark::DoNotOptimize(image.constBits());
    }
    state.counters["clips"] = view->clipCount();
    state.counters["tracks"] = double(view->tracks().size());
}
void TimelineRepaint(benchmark::State& state)
{
    repaintTimeline(state, 0);
}
BENCHMARK(TimelineRepaint)->Arg(0)->Arg(1000)->Unit(benchmark::kMillisecond);

void TimelineRepaintZoomed(benchmark::State& state)
{
    repaintTimeline(state, 80);
}
BENCHMARK(TimelineRepaintZoomed)->Arg(1000)->Unit(benchmark::kMillisecond);

void OpenScenario(benchmark::State& state)
{
    application();
    auto scenario = scenarioWithActions(int(state.range(0)));
    if (!scenario) {
        state.SkipWithError(scenario.error().message.c_str());
        return;
    }
    // The scenario's folder holds what the demo refers to (its idle database and posture bases).
    QTemporaryDir dir;
    std::error_code copied;
    std::filesystem::copy(THESPIS_RESOURCES "/motion", dir.filePath(QStringLiteral("motion")).toStdString(),
                          std::filesystem::copy_options::recursive, copied);
    if (copied) {
        state.SkipWithError(("cannot copy the demo's motion folder: " + copied.message()).c_str());
        return;
    }
    const QString path = dir.filePath(QStringLiteral("bench.thespis"));
    if (auto written = core::scenario::saveScenario(path.toStdString(), *scenario); !written) {
        state.SkipWithError(written.error().message.c_str());
        return;
    }
    editor::ScenarioTreeModel outline;
    editor::TimelinePanel timeline;
    timeline.resize(1200, 400);
    double documentMs = 0, panelsMs = 0, sceneMs = 0;
    for (auto _ : state) {
        QElapsedTimer clock;
        clock.start();
        auto document = editor::Document::open(path);
        if (!document) {
            state.SkipWithError(document.error().message.c_str());
            return;
        }
        documentMs += double(clock.nsecsElapsed()) * 1e-6;
        clock.restart();
        outline.setDocument(document->get());
        timeline.setDocument(document->get());
        panelsMs += double(clock.nsecsElapsed()) * 1e-6;
        clock.restart();
        auto scene = core::render::ScenarioScene::create((*document)->scenario(), dir.path().toStdString());
        if (!scene) {
            state.SkipWithError(scene.error().message.c_str());
            return;
        }
        benchmark::DoNotOptimize((*scene)->boundsOverTimeline());
        sceneMs += double(clock.nsecsElapsed()) * 1e-6;
        state.PauseTiming(); // closing is not opening
        outline.setDocument(nullptr);
        timeline.setDocument(nullptr);
        scene->reset();
        document->reset();
        state.ResumeTiming();
    }
    const double n = double(state.iterations());
    state.counters["document_ms"] = documentMs / n;
    state.counters["panels_ms"] = panelsMs / n;
    state.counters["scene_ms"] = sceneMs / n;
}
BENCHMARK(OpenScenario)->Arg(1000)->Unit(benchmark::kMillisecond);

// The studio's views of one Session, without the window: the 3D view's scene (drawing the
// session's stage), the stick figures, the posture chart and the AR preview's mailbox (which
// the session fills at every tick).
struct StudioViews {
    editor::PlaybackClock clock;
    editor::Session session{&clock};
    std::unique_ptr<core::render::ScenarioScene> scene;
    widgets::PoseView poseView;
    std::unique_ptr<editor::SkeletonView> skeletons;
    editor::PostureChartPanel chart;

    // Opens `document` (the demo when null); false with the benchmark skipped when it or its
    // scene cannot be made.
    bool open(benchmark::State& state, std::unique_ptr<editor::Document> document, bool withFigures)
    {
        if (!document) {
            auto demo = editor::Document::open(QStringLiteral(THESPIS_RESOURCES "/demo.thespis"));
            if (!demo) {
                state.SkipWithError(demo.error().message.c_str());
                return false;
            }
            document = std::move(demo).value();
        }
        session.setDocument(std::move(document));
        core::render::ScenarioSceneOptions options;
        options.stage = session.stage();
        auto made = core::render::ScenarioScene::create(session.document()->scenario(), session.document()->assets(), options);
        if (!made) {
            state.SkipWithError(made.error().message.c_str());
            return false;
        }
        scene = std::move(made).value();
        QObject::connect(&session, &editor::Session::posesChanged, &session,
                         [this](const core::runtime::PoseSet& poses) { scene->setPoses(poses); });
        QObject::connect(&session, &editor::Session::edited, &session, [this] { (void)scene->followStage(); });
        if (withFigures) {
            skeletons = std::make_unique<editor::SkeletonView>(&poseView, &session);
            chart.setDefaultBases(QStringLiteral(THESPIS_RESOURCES "/motion/cmu_postures.pca"));
            chart.setSession(&session);
            session.addPanel(&chart);
        }
        return true;
    }
    std::uint64_t skinnings() const
    {
        std::uint64_t total = 0;
        for (std::size_t c = 0; c < scene->scene().characterCount(); ++c)
            total += scene->scene().character(c).poseCount();
        return total;
    }
};

// StudioTick: one tick of the studio's playback on the demo — the clock moves a frame, the
// Session evaluates its stage once and publishes the poses, and every view follows: the 3D
// view's bodies skinned, the stick figures, the posture chart, the AR mailbox. Counters: stage
// evaluations and skinnings per character per tick (goal: 1 and 1).
void StudioTick(benchmark::State& state)
{
    application();
    StudioViews views;
    if (!views.open(state, nullptr, true))
        return;
    const core::Tick step = core::ticksPerFrame(60), duration = views.clock.duration();
    const std::uint64_t evaluations = views.session.stage()->ticks(), skinnings = views.skinnings();
    core::Tick t = 0;
    for (auto _ : state) {
        t += step;
        if (t > duration)
            t -= duration;
        views.clock.seek(t);
        benchmark::DoNotOptimize(views.chart.components().data());
    }
    const double ticks = double(state.iterations()), characters = double(views.scene->scene().characterCount());
    state.counters["evaluations_per_tick"] = double(views.session.stage()->ticks() - evaluations) / ticks;
    state.counters["skinnings_per_character_tick"] = double(views.skinnings() - skinnings) / ticks / characters;
}
BENCHMARK(StudioTick)->Unit(benchmark::kMicrosecond);

void ScrubToFrame(benchmark::State& state)
{
    application();
    StudioViews views;
    if (!views.open(state, nullptr, false))
        return;
    auto renderer = core::render::OffscreenRenderer::create(1280, 720);
    if (!renderer) {
        state.SkipWithError(renderer.error().message.c_str());
        return;
    }
    core::render::ScenarioScene& shown = *views.scene;
    shown.scene().setGroundVisible(true);
    const core::render::CameraView view =
        core::render::frameBounds(shown.boundsOver(views.session.timelineSamples()), 20.0, 10.0, 1280.0 / 720.0, 30.0);
    editor::TimelinePanel timeline;
    timeline.resize(1200, 400);
    timeline.setDocument(views.session.document());
    QObject::connect(&views.clock, &editor::PlaybackClock::timeChanged, &timeline, &editor::TimelinePanel::setTime);
    core::render::RgbaImage frame;
    core::Tick t = 0;
    for (auto _ : state) {
        t += core::secondsToTicks(0.37); // a scrub jumps: no two frames alike
        if (t > views.clock.duration())
            t -= views.clock.duration();
        views.clock.seek(t);
        if (auto drawn = (*renderer)->render(shown.scene(), view, frame); !drawn) {
            state.SkipWithError(drawn.error().message.c_str());
            return;
        }
        benchmark::DoNotOptimize(frame);
    }
}
BENCHMARK(ScrubToFrame)->Unit(benchmark::kMillisecond)->UseRealTime();

void DragStep(benchmark::State& state)
{
    auto document = documentWithActions(state);
    if (!document)
        return;
    StudioViews views;
    if (!views.open(state, std::move(document), false))
        return;
    editor::Document& edited = *views.session.document();
    views.clock.seek(3 * core::TicksPerSecond);
    // An action in the middle of the first character's first track, dragged back and forth.
    const int middle = int(edited.scenario().characters[0].layers[0].actions.size()) / 2;
    const core::edit::ActionPath dragged{0, 0, middle};
    const core::Tick frame = core::ticksPerFrame(30);
    long step = 0;
    for (auto _ : state) {
        const core::Tick delta = (step++ % 2 == 0) ? frame : -frame;
        auto moved = core::edit::moveActions(edited.scenario(), std::span(&dragged, 1), delta);
        if (auto done = edited.edit(std::move(moved), QStringLiteral("Move Action"), editor::Merge{1, false}); !done) {
            state.SkipWithError(done.error().message.c_str());
            return;
        }
        benchmark::DoNotOptimize(views.scene->poses());
    }
    state.counters["actions"] = double(state.range(0));
    state.counters["undo_steps"] = edited.undoStack()->count();
}
BENCHMARK(DragStep)->Arg(1000)->Unit(benchmark::kMillisecond);

} // namespace
