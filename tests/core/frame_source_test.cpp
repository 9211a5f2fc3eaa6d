// core/ar's frame sources (issue 16 §1) on real files: the video in ../shared/data/vision/video,
// the calibration photos as an image sequence, the synthetic scene; the live capture thread
// (newest frame wins, nothing queues behind a slow consumer, a clear state when a source ends or
// fails); and the bad inputs a user meets: no camera, a missing or broken video, a missing picture.

#include <gtest/gtest.h>

#include <fstream>
#include <thread>

#include "ar/board.h"
#include "ar/frame_source.h"
#include "ar/live_capture.h"
#include "ar/synthetic_source.h"
#include "test_support.h"

using namespace thespis::core;
using namespace thespis::core::ar;
using thespis::test::sharedData;

TEST(FrameSources, TheSharedVideoDecodesWithIncreasingTimestamps)
{
    auto video = openVideoFile(sharedData("vision/video/cockatoo.mp4"));
    ASSERT_TRUE(video) << video.error().message;
    EXPECT_GT((*video)->fps(), 0);
    VideoFrame frame;
    std::int64_t frames = 0;
    double lastTime = -1;
    while (true) {
        const Result<bool> read = (*video)->read(frame);
        ASSERT_TRUE(read) << read.error().message;
        if (!*read)
            break;
        EXPECT_EQ(frame.index, frames);
        EXPECT_GT(frame.time, lastTime);
        lastTime = frame.time;
        ASSERT_EQ(frame.bgr.size(), std::size_t(frame.width) * std::size_t(frame.height) * 3);
        ++frames;
    }
    EXPECT_EQ(frame.width, (*video)->width());
    EXPECT_EQ(frame.height, (*video)->height());
    EXPECT_GT(frames, 10);
    // The last frame's time agrees with the frame rate the container states.
    EXPECT_NEAR(lastTime, double(frames - 1) / (*video)->fps(), 2.0 / (*video)->fps());
}

TEST(FrameSources, PicturesPlayAsASequenceAtTheirFrameRate)
{
    std::vector<std::filesystem::path> pictures;
    for (const char* name : {"left01.jpg", "left02.jpg", "left03.jpg"})
        pictures.push_back(sharedData("vision/calibration") / name);
    auto sequence = openImageSequence(pictures, 10);
    ASSERT_TRUE(sequence) << sequence.error().message;
    EXPECT_EQ((*sequence)->frameCount(), 3);
    VideoFrame frame;
    for (int i = 0; i < 3; ++i) {
        ASSERT_TRUE(*(*sequence)->read(frame));
        EXPECT_EQ(frame.width, 640);
        EXPECT_DOUBLE_EQ(frame.time, i * 0.1);
    }
    EXPECT_FALSE(*(*sequence)->read(frame));
}

TEST(FrameSources, BadInputSaysWhatAndWhere)
{
    const auto missing = openVideoFile("/nowhere/clip.mp4");
    ASSERT_FALSE(missing);
    EXPECT_NE(missing.error().message.find("/nowhere/clip.mp4"), std::string::npos);

    const std::filesystem::path broken = thespis::test::artifact("broken.mp4");
    std::ofstream(broken) << "this is not a video, only text pretending to be one";
    const auto notVideo = openVideoFile(broken);
    if (notVideo) { // FFmpeg may open the container and fail on the first frame
        VideoFrame frame;
        const Result<bool> read = (*notVideo)->read(frame);
        ASSERT_FALSE(read);
        EXPECT_NE(read.error().message.find("broken.mp4"), std::string::npos) << read.error().message;
    } else {
        EXPECT_NE(notVideo.error().message.find("broken.mp4"), std::string::npos);
    }

    const auto noPicture = openImageSequence({sharedData("vision/calibration/left01.jpg"), "/nowhere/left99.jpg"}, 30);
    ASSERT_FALSE(noPicture);
    EXPECT_NE(noPicture.error().message.find("left99.jpg"), std::string::npos);
    EXPECT_FALSE(openImageSequence({}, 30));
    EXPECT_FALSE(readPicture("/nowhere/x.png"));
}

TEST(FrameSources, NoCameraIsAClearAnswer)
{
    // These machines have no camera: opening one names the device and what the machine has.
    const std::vector<CameraDevice> cameras = listCameras();
    const auto camera = openCamera({.index = 63});
    ASSERT_FALSE(camera);
    EXPECT_EQ(camera.error().code, ErrorCode::NotFound);
    EXPECT_NE(camera.error().message.find("No camera found at /dev/video63"), std::string::npos);
    if (cameras.empty()) {
        EXPECT_NE(camera.error().message.find("this machine has none"), std::string::npos);
    }
}

namespace {
SyntheticScene smallScene(std::int64_t frames)
{
    SyntheticScene scene;
    scene.board = *parseBoard("aruco-grid:DICT_4X4_50:4x3:0.04:0.01");
    scene.camera.width = 320;
    scene.camera.height = 240;
    scene.camera.matrix = {300, 0, 160, 0, 300, 120, 0, 0, 1};
    scene.frames = frames;
    return scene;
}
} // namespace

TEST(LiveCapture, TheNewestFrameWinsAndASlowConsumerDropsFrames)
{
    LiveCapture capture(SyntheticSource::create(smallScene(60)).value(), false);
    VideoFrame frame;
    std::int64_t last = -1, taken = 0;
    while (capture.waitNewest(frame, std::chrono::seconds(5))) {
        EXPECT_GT(frame.index, last) << "frames come in order, never twice";
        last = frame.index;
        ++taken;
        // Slower than the source, whatever the machine's load: wait until two newer frames have
        // been captured (or the source ended), so the first of them is overwritten. A capture that
        // blocked its source instead would never get there: the wait gives up after 2 s.
        const auto giveUp = std::chrono::steady_clock::now() + std::chrono::seconds(2);
        while (capture.state() == CaptureState::Running && capture.captured() < frame.index + 3 &&
               std::chrono::steady_clock::now() < giveUp)
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    EXPECT_EQ(capture.state(), CaptureState::Ended);
    EXPECT_NE(capture.message().find("ended after 60 frames"), std::string::npos) << capture.message();
    EXPECT_EQ(capture.captured(), 60);
    EXPECT_EQ(taken + capture.dropped(), 60) << "every frame either taken or counted as dropped";
    EXPECT_GT(capture.dropped(), 0);
    EXPECT_EQ(last, 59) << "the last frame is never lost";
}

namespace {
// A camera that stops answering after a few frames, as one unplugged while running does.
class UnpluggedCamera final : public FrameSource {
public:
    std::string description() const override { return "camera /dev/video9"; }
    Result<bool> read(VideoFrame& frame) override
    {
        if (m_next == 5)
            return makeError(ErrorCode::IoError, "camera /dev/video9 stopped sending frames after frame 5 (unplugged?)");
        frame.resize(64, 48);
        frame.index = m_next++;
        frame.time = double(frame.index) / 30;
        frame.captured = std::chrono::steady_clock::now();
        return true;
    }
    double fps() const override { return 30; }
    int width() const override { return 64; }
    int height() const override { return 48; }
    std::int64_t frameCount() const override { return -1; }

private:
    std::int64_t m_next = 0;
};
} // namespace

TEST(LiveCapture, ACameraUnpluggedWhileRunningStopsWithItsReason)
{
    LiveCapture capture(std::make_unique<UnpluggedCamera>(), true);
    VideoFrame frame;
    std::int64_t last = -1;
    while (capture.waitNewest(frame, std::chrono::seconds(5)))
        last = frame.index;
    EXPECT_EQ(capture.state(), CaptureState::Failed);
    EXPECT_NE(capture.message().find("stopped sending frames after frame 5"), std::string::npos) << capture.message();
    EXPECT_EQ(last, 4) << "the frames before it are still delivered";
}

TEST(LiveCapture, RealTimePlaybackIsPacedAndStopsOnRequest)
{
    SyntheticScene scene = smallScene(1000);
    scene.fps = 50;
    LiveCapture capture(SyntheticSource::create(scene).value(), true);
    VideoFrame frame;
    ASSERT_TRUE(capture.waitNewest(frame, std::chrono::seconds(5)));
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    capture.stop();
    EXPECT_EQ(capture.state(), CaptureState::Stopped);
    // Paced at 50 fps, a fraction of a second delivers a fraction of the 1000 frames.
    EXPECT_LT(capture.captured(), 500);
}
