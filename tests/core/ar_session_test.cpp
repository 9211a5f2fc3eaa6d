// The live AR loop on three threads (issue 16 §4, §6): synthetic footage of a board (known poses)
// captured, tracked and drawn over, the newest composed frame taken by a consumer, the recording
// written as a video that decodes, and the ways a session ends: the video ends, the user stops it,
// a camera file for another resolution is refused before anything starts.

#include <gtest/gtest.h>

#include <thread>

#include "ar/frame_source.h"
#include "ar/synthetic_source.h"
#include "render/ar_session.h"
#include "test_support.h"

using namespace thespis::core;
using namespace thespis::core::ar;
using namespace thespis::core::render;
using thespis::test::artifact;

namespace {

SyntheticScene boardScene(std::int64_t frames)
{
    SyntheticScene scene;
    scene.board = *parseBoard("aruco-grid:DICT_4X4_50:4x3:0.04:0.01");
    scene.camera.width = 640;
    scene.camera.height = 480;
    scene.camera.matrix = {600, 0, 320, 0, 600, 240, 0, 0, 1};
    scene.frames = frames;
    return scene;
}

scenario::Scenario standingOnTheBoard()
{
    scenario::Scenario s;
    scenario::Character hero;
    hero.name = "Hero";
    hero.skeleton = "hanim-25";
    s.characters.push_back(hero);
    s.ar.scale = 0.06;
    return s;
}

ArSessionSettings settingsFor(const SyntheticScene& scene)
{
    ArSessionSettings settings;
    settings.camera = scene.camera;
    settings.target.board = scene.board;
    settings.realTime = false;
    settings.compositor.samples = 1;
    return settings;
}

} // namespace

TEST(ArSession, FootageIsTrackedDrawnOverRecordedAndEnds)
{
    const SyntheticScene scene = boardScene(45);
    auto session = ArSession::start(SyntheticSource::create(scene).value(), standingOnTheBoard(), scenario::Assets(),
                                    settingsFor(scene));
    ASSERT_TRUE(session) << session.error().message;
    const std::filesystem::path recording = artifact("ar_session.mp4");
    ASSERT_TRUE((*session)->startRecording(recording));
    ArSnapshot snapshot;
    std::int64_t taken = 0, tracked = 0, last = -1;
    while (true) {
        // The state is read first: a frame published before the session ended is still taken.
        const bool running = (*session)->state() == ArSessionState::Running;
        if (!(*session)->takeSnapshot(snapshot)) {
            if (!running)
                break;
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
            continue;
        }
        EXPECT_GT(snapshot.tracking.frame, last) << "frames come in order";
        last = snapshot.tracking.frame;
        ++taken;
        tracked += snapshot.tracking.tracked ? 1 : 0;
        EXPECT_EQ(snapshot.frame.width, 640);
    }
    if ((*session)->state() == ArSessionState::Failed && (*session)->message().find("OpenGL") != std::string::npos &&
        !std::getenv("THESPIS_REQUIRE_GL"))
        GTEST_SKIP() << (*session)->message();
    EXPECT_EQ((*session)->state(), ArSessionState::Ended) << (*session)->message();
    EXPECT_NE((*session)->message().find("ended after 45 frames"), std::string::npos) << (*session)->message();
    EXPECT_GT(taken, 0);
    EXPECT_EQ(tracked, taken) << "every composed frame was tracked";
    EXPECT_EQ(last, 44) << "the last frame is drawn";
    EXPECT_FALSE((*session)->recording()) << "the recording is finished when the video ends";
    auto video = openVideoFile(recording);
    ASSERT_TRUE(video) << video.error().message;
    VideoFrame frame;
    std::int64_t frames = 0;
    while (*(*video)->read(frame))
        ++frames;
    EXPECT_GT(frames, 0);
    EXPECT_LE(frames, 45);
}

TEST(ArSession, AMirrorBallLightsTheCharacters)
{
    const SyntheticScene scene = boardScene(20);
    ArSessionSettings settings = settingsFor(scene);
    LiveProbeSettings probe;
    probe.location = BallLocation::Given;
    probe.givenCircle = {560, 80, 60}; // the top right of the frame, where the user marked it
    probe.updateEvery = 1;
    settings.probe = probe;
    auto session = ArSession::start(SyntheticSource::create(scene).value(), standingOnTheBoard(), scenario::Assets(),
                                    settings);
    ASSERT_TRUE(session) << session.error().message;
    ArSnapshot snapshot;
    bool lit = false;
    while (true) {
        const bool running = (*session)->state() == ArSessionState::Running;
        if ((*session)->takeSnapshot(snapshot)) {
            lit = lit || snapshot.lit;
            continue;
        }
        if (!running)
            break;
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    if ((*session)->state() == ArSessionState::Failed && !std::getenv("THESPIS_REQUIRE_GL"))
        GTEST_SKIP() << (*session)->message();
    EXPECT_EQ((*session)->state(), ArSessionState::Ended) << (*session)->message();
    EXPECT_TRUE(lit) << "the characters were lit by the ball";
    EXPECT_GT(snapshot.probePicture.width, 0) << "the captured probe is there to show";
    EXPECT_GT(snapshot.probeVersion, 0u);
}

TEST(ArSession, StoppingIsClean)
{
    const SyntheticScene scene = boardScene(100000);
    auto session = ArSession::start(SyntheticSource::create(scene).value(), standingOnTheBoard(), scenario::Assets(),
                                    settingsFor(scene));
    ASSERT_TRUE(session) << session.error().message;
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    (*session)->stop();
    EXPECT_NE((*session)->state(), ArSessionState::Running);
}

TEST(ArSession, ACameraFileForAnotherSizeIsRefusedBeforeStarting)
{
    const SyntheticScene scene = boardScene(10);
    ArSessionSettings settings = settingsFor(scene);
    settings.camera.width = 1280;
    settings.camera.height = 720;
    auto session = ArSession::start(SyntheticSource::create(scene).value(), standingOnTheBoard(), scenario::Assets(), settings);
    ASSERT_FALSE(session);
    EXPECT_NE(session.error().message.find("is for 1280 × 720 pictures but synthetic"), std::string::npos)
        << session.error().message;
    settings = settingsFor(scene);
    settings.target.board.reset();
    EXPECT_FALSE(ArSession::start(SyntheticSource::create(scene).value(), standingOnTheBoard(), scenario::Assets(), settings));
}
