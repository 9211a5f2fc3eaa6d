// PlayJob, the path `thespis-cli play` takes: the demo scenario played over real footage — the
// ChArUco tutorial's photos written as a video — its characters standing on the tracked board, the
// result a video that decodes with the characters in it; the demo on its own; and a stop that
// leaves no file.

#include <gtest/gtest.h>

#include "ar/frame_source.h"
#include "ar/video_writer.h"
#include "render/play_job.h"
#include "scenario/scenario_io.h"
#include "test_support.h"

using namespace thespis::core;
using namespace thespis::core::ar;
using namespace thespis::core::render;
using thespis::test::artifact;
using thespis::test::resources;
using thespis::test::sharedData;

namespace {

std::filesystem::path folder()
{
    const std::filesystem::path path = artifact("play_job");
    std::filesystem::create_directories(path);
    return path;
}

// The four tutorial photos as a 2 fps Motion JPEG video: real footage of the board.
std::filesystem::path photoVideo()
{
    // One file per test: ctest runs the tests of this file side by side.
    const std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    const std::filesystem::path path = folder() / ("charuco_photos_" + test + ".avi");
    auto writer = VideoWriter::create(path, 640, 480, 2);
    EXPECT_TRUE(writer) << writer.error().message;
    for (int i = 0; i < 4; ++i) {
        auto photo = readPicture(sharedData("vision/aruco_real") / ("charuco_img_0" + std::to_string(i) + ".jpg"));
        EXPECT_TRUE(photo);
        EXPECT_TRUE((*writer)->write(*photo));
    }
    EXPECT_TRUE((*writer)->finish());
    return path;
}

std::vector<VideoFrame> framesOf(const std::filesystem::path& path)
{
    std::vector<VideoFrame> frames;
    auto video = openVideoFile(path);
    EXPECT_TRUE(video) << video.error().message;
    if (!video)
        return frames;
    VideoFrame frame;
    while (*(*video)->read(frame))
        frames.push_back(frame);
    return frames;
}

PlayJob demoOver(const std::filesystem::path& video)
{
    PlayJob job;
    job.scenario = scenario::loadScenario(resources("demo.thespis")).value();
    job.scenario.ar.scale = 0.08;
    job.assets = scenario::Assets(resources());
    job.video = video;
    job.cameraFile = sharedData("vision/aruco_real/tutorial_camera_charuco.yml");
    job.target.board = *parseBoard("charuco:DICT_6X6_250:5x7:0.04:0.02");
    job.compositor.samples = 1;
    return job;
}

} // namespace

TEST(PlayJob, TheDemoStandsOnTheRealBoardInTheVideo)
{
    const std::filesystem::path input = photoVideo();
    PlayJob job = demoOver(input);
    job.output = folder() / "demo_on_board.mp4";
    JobContext context;
    const auto played = job.run(context);
    ASSERT_TRUE(played) << describe(played.error());
    EXPECT_EQ(job.frames, 4);
    EXPECT_EQ(job.tracked, 4);
    const std::vector<VideoFrame> filmed = framesOf(input), out = framesOf(job.output);
    ASSERT_EQ(out.size(), 4u);
    ASSERT_EQ(filmed.size(), 4u);
    (void)writePicture(folder() / "demo_on_board_frame1.png", out[1]);
    // The characters stand near the board's middle: there the picture changed, in the corners not.
    const auto changed = [&](const VideoFrame& a, const VideoFrame& b, int x0, int y0, int x1, int y1) {
        int count = 0;
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x) {
                const std::size_t i = (std::size_t(y) * 640 + std::size_t(x)) * 3;
                count += std::abs(int(a.bgr[i]) - int(b.bgr[i])) + std::abs(int(a.bgr[i + 1]) - int(b.bgr[i + 1])) > 60;
            }
        return count;
    };
    for (std::size_t f = 0; f < 4; ++f) {
        EXPECT_GT(changed(filmed[f], out[f], 200, 60, 440, 300), 1500) << "frame " << f;
        EXPECT_LT(changed(filmed[f], out[f], 0, 400, 100, 480), 50) << "frame " << f;
    }
}

TEST(PlayJob, TheDemoPlaysOnItsOwn)
{
    PlayJob job;
    job.scenario = scenario::loadScenario(resources("demo.thespis")).value();
    job.assets = scenario::Assets(resources());
    job.picture.width = 160;
    job.picture.height = 90;
    job.picture.samples = 0;
    job.fps = 4;
    job.output = folder() / "demo.mp4";
    JobContext context;
    const auto played = job.run(context);
    ASSERT_TRUE(played) << describe(played.error());
    EXPECT_GT(job.frames, 4);
    EXPECT_EQ(std::int64_t(framesOf(job.output).size()), job.frames);
}

TEST(PlayJob, AStopLeavesNoFile)
{
    PlayJob job = demoOver(photoVideo());
    job.output = folder() / "stopped.mp4";
    std::stop_source stop;
    stop.request_stop();
    JobContext context(stop.get_token());
    const auto played = job.run(context);
    ASSERT_FALSE(played);
    EXPECT_EQ(played.error().code, ErrorCode::Cancelled);
    EXPECT_FALSE(std::filesystem::exists(job.output));
    EXPECT_FALSE(std::filesystem::exists(folder() / "stopped.partial.mp4"));
    job.output = folder() / "x.mov";
    EXPECT_FALSE(job.validate());
}
