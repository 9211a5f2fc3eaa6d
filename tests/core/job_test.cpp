// The job model (util/job.h) and the jobs on it: a watched run reports its stages, stopping it
// returns Cancelled, and every job that writes leaves no file when cancelled — also when the
// cancel comes after the work ended. Real data: the demo scenario, RobotExpressive, a Poly Haven
// probe.

#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <set>
#include <thread>

#include "anim/bvh.h"
#include "lighting/probe_projection_job.h"
#include "lighting/transfer_bake_job.h"
#include "render/frame_sequence_job.h"
#include "runtime/motion_bake_job.h"
#include "scenario/scenario_io.h"
#include "scene/gltf_mesh.h"
#include "util/file_io.h"
#include "test_support.h"

namespace {

using namespace thespis::core;
namespace fs = std::filesystem;

fs::path freshFolder(const std::string& name)
{
    const fs::path folder = thespis::test::artifact("jobs") / name;
    fs::remove_all(folder);
    fs::create_directories(folder);
    return folder;
}

std::size_t filesIn(const fs::path& folder)
{
    std::size_t count = 0;
    for ([[maybe_unused]] const auto& entry : fs::directory_iterator(folder))
        ++count;
    return count;
}

// Counts to `total` in two stages, slowly enough to be watched; writes a file at the end.
struct CountingJob final : Job {
    fs::path file;
    int total = 20;
    std::string title() const override { return "The count"; }
    Result<void> validate() const override
    {
        if (total < 1)
            return makeError(ErrorCode::InvalidArgument, "total must be at least 1.");
        return {};
    }
    Result<void> run(JobContext& context) override
    {
        context.beginStage("Warming up", 1);
        context.setDone(1);
        context.beginStage("Counting", std::uint64_t(total));
        for (int i = 0; i < total; ++i) {
            if (context.stopRequested())
                return cancelledError(title());
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
            context.setDone(std::uint64_t(i + 1));
        }
        return writeFileAtomically(file, "counted");
    }
    void discardOutput() override { fs::remove(file); }
};

scenario::Scenario demo()
{
    return scenario::loadScenario(thespis::test::resources("demo.thespis")).value();
}

} // namespace

TEST(JobModel, WatchedRunReportsEveryStageAndEndsAtTheTotal)
{
    CountingJob job;
    job.file = freshFolder("counting") / "count.txt";
    std::set<std::string> stages;
    JobProgress last;
    const auto ran = runJobWatched(job, std::chrono::milliseconds(2), [&](const JobProgress& p) {
        stages.insert(p.stage);
        EXPECT_LE(p.done, p.total);
        last = p;
        return true;
    });
    ASSERT_TRUE(ran.ok()) << ran.error().message;
    EXPECT_TRUE(stages.count("Counting"));
    EXPECT_EQ(last.stage, "Counting");
    EXPECT_EQ(last.done, 20u);
    EXPECT_TRUE(fs::exists(job.file));
}

TEST(JobModel, InvalidJobDoesNotRun)
{
    CountingJob job;
    job.total = 0;
    job.file = freshFolder("invalid") / "count.txt";
    int calls = 0;
    const auto ran = runJobWatched(job, std::chrono::milliseconds(2), [&](const JobProgress&) { return ++calls, true; });
    ASSERT_FALSE(ran.ok());
    EXPECT_EQ(ran.error().code, ErrorCode::InvalidArgument);
    EXPECT_EQ(calls, 0);
    EXPECT_FALSE(fs::exists(job.file));
}

TEST(JobModel, StoppedJobIsCancelledAndLeavesNoFile)
{
    CountingJob job;
    job.file = freshFolder("stopped") / "count.txt";
    const auto ran = runJobWatched(job, std::chrono::milliseconds(2),
                                   [&](const JobProgress& p) { return !(p.stage == "Counting" && p.done >= 3); });
    ASSERT_FALSE(ran.ok());
    EXPECT_EQ(ran.error().code, ErrorCode::Cancelled);
    EXPECT_NE(ran.error().message.find("The count was cancelled"), std::string::npos) << ran.error().message;
    EXPECT_FALSE(fs::exists(job.file));
}

TEST(JobModel, ACancelAfterTheEndTakesTheFileBack)
{
    CountingJob job;
    job.total = 1;
    job.file = freshFolder("late") / "count.txt";
    // The watcher says stop only once the job has ended: its last call.
    const auto ran = runJobWatched(job, std::chrono::milliseconds(2), [&](const JobProgress& p) {
        return !(p.stage == "Counting" && p.done == 1 && fs::exists(job.file));
    });
    ASSERT_FALSE(ran.ok());
    EXPECT_EQ(ran.error().code, ErrorCode::Cancelled);
    EXPECT_FALSE(fs::exists(job.file));
}

TEST(TransferBakeJob, WritesWhatItBakedAndACancelledOneLeavesNoFile)
{
    auto mesh = scene::loadGltfMesh(thespis::test::sharedData("characters/RobotExpressive/RobotExpressive.glb"));
    ASSERT_TRUE(mesh.ok()) << mesh.error().message;
    const fs::path folder = freshFolder("transfer");

    lighting::TransferBakeJob small;
    small.mesh = *mesh;
    small.settings.order = 2;
    small.settings.raysPerVertex = 8;
    small.output = folder / "robot.prt";
    std::uint64_t lastDone = 0;
    const auto baked = runJobWatched(small, std::chrono::milliseconds(20), [&](const JobProgress& p) {
        lastDone = p.done;
        return true;
    });
    ASSERT_TRUE(baked.ok()) << baked.error().message;
    EXPECT_EQ(lastDone, mesh->vertexCount());
    auto file = lighting::readBakeFile(small.output);
    ASSERT_TRUE(file.ok()) << file.error().message;
    EXPECT_EQ(file->transfer, small.bake->transfer);
    EXPECT_TRUE(lighting::checkBakeMatchesMesh(*file, *mesh).ok());

    lighting::TransferBakeJob large = small;
    large.settings.order = 5;
    large.settings.raysPerVertex = 4096;
    large.settings.threads = 1;
    large.output = folder / "cancelled.prt";
    const auto cancelled = runJobWatched(large, std::chrono::milliseconds(20),
                                         [&](const JobProgress& p) { return p.done == 0; });
    ASSERT_FALSE(cancelled.ok());
    EXPECT_EQ(cancelled.error().code, ErrorCode::Cancelled);
    EXPECT_FALSE(fs::exists(large.output));
    EXPECT_EQ(filesIn(folder), 1u); // robot.prt only: no temporary file either
}

TEST(MotionBakeJob, BakesTheDemoAndACancelledOneLeavesNoFile)
{
    const fs::path folder = freshFolder("motion");
    runtime::MotionBakeJob job;
    job.scenario = demo();
    job.assets = thespis::test::resources();
    job.character = job.scenario.characters.front().name;
    job.output = folder / "demo.bvh";
    job.fps = 10;
    job.end = 2.0;
    const auto baked = runJobWatched(job, std::chrono::milliseconds(20), [](const JobProgress&) { return true; });
    ASSERT_TRUE(baked.ok()) << baked.error().message;
    EXPECT_EQ(job.frameCount, 21);
    auto clip = anim::bvh::load(job.output);
    ASSERT_TRUE(clip.ok()) << clip.error().message;
    EXPECT_EQ(clip->clip->frameCount(), 21);

    runtime::MotionBakeJob slow = job;
    slow.output = folder / "cancelled.bvh";
    slow.frameDelay = std::chrono::milliseconds(20);
    const auto cancelled = runJobWatched(slow, std::chrono::milliseconds(5), [](const JobProgress& p) {
        return !(p.stage == runtime::MotionBakeJob::FramesStage && p.done >= 2);
    });
    ASSERT_FALSE(cancelled.ok());
    EXPECT_EQ(cancelled.error().code, ErrorCode::Cancelled);
    EXPECT_FALSE(fs::exists(slow.output));

    runtime::MotionBakeJob nobody = job;
    nobody.character = "Nobody";
    const auto refused = nobody.validate();
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.error().code, ErrorCode::NotFound);
    EXPECT_NE(refused.error().message.find(job.character), std::string::npos) << refused.error().message;
}

TEST(ProbeProjectionJob, ProjectsARealProbeAsTheOneShotDoes)
{
    lighting::ProbeProjectionJob job;
    job.path = thespis::test::sharedData("probes/polyhaven_1k/venice_sunset_1k.hdr");
    job.order = 3;
    JobContext context;
    ASSERT_TRUE(job.validate().ok());
    ASSERT_TRUE(job.run(context).ok());
    ASSERT_TRUE(job.probe.has_value());
    EXPECT_EQ(job.probe->image().width, 1024);
    const auto oneShot = lighting::projectProbeFile(job.path, lighting::ProbeLayout::LatLong, 3);
    ASSERT_TRUE(oneShot.ok());
    for (int c = 0; c < 3; ++c)
        for (int i = 0; i < 9; ++i)
            EXPECT_EQ(job.light[c][std::size_t(i)], (*oneShot)[c][std::size_t(i)]);
    EXPECT_GT(job.light[0][0], 0.0); // a bright sky
    EXPECT_EQ(context.progress().stage, "Projecting onto spherical harmonics");

    std::stop_source stop;
    stop.request_stop();
    JobContext stopped(stop.get_token());
    const auto cancelled = job.run(stopped);
    ASSERT_FALSE(cancelled.ok());
    EXPECT_EQ(cancelled.error().code, ErrorCode::Cancelled);
}

TEST(FrameSequenceJob, RendersTheDemoAndACancelledOneTakesItsFramesBack)
{
    const fs::path folder = freshFolder("frames");
    render::FrameSequenceJob job;
    job.scenario = demo();
    job.assets = thespis::test::resources();
    job.picture.width = 96;
    job.picture.height = 64;
    job.picture.samples = 0;
    job.first = 3;
    job.last = 5;
    job.folder = folder / "sequence";
    const auto rendered = runJobWatched(job, std::chrono::milliseconds(20), [](const JobProgress&) { return true; });
    ASSERT_TRUE(rendered.ok()) << rendered.error().message;
    EXPECT_EQ(filesIn(job.folder), 3u);
    EXPECT_TRUE(fs::exists(job.folder / "frame_00003.png"));
    EXPECT_TRUE(fs::exists(job.folder / "frame_00005.png"));

    render::FrameSequenceJob cancelled = job;
    cancelled.folder = folder / "cancelled";
    cancelled.last = 400;
    const auto stopped = runJobWatched(cancelled, std::chrono::milliseconds(5), [](const JobProgress& p) {
        return !(p.stage == render::FrameSequenceJob::FramesStage && p.done >= 2);
    });
    ASSERT_FALSE(stopped.ok());
    EXPECT_EQ(stopped.error().code, ErrorCode::Cancelled);
    EXPECT_EQ(filesIn(cancelled.folder), 0u);
}
