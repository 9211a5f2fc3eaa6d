// The live AR loop on three threads (issue 16 §4, §6): synthetic footage of a board (known poses)
// captured, tracked and drawn over, the newest composed frame taken by a consumer, the recording
// written as a video that decodes, and the ways a session ends: the video ends, the user stops it,
// a camera file for another resolution is refused before anything starts. The characters are a
// stage's, drawn with the poses its owner publishes (the studio's Session).

#include <gtest/gtest.h>

#include <thread>

#include "ar/frame_source.h"
#include "ar/synthetic_source.h"
#include "anim/quat.h"
#include "motion/eye_ray.h"
#include "motion/gaze.h"
#include "render/ar_view.h"
#include "scene/fap.h"
#include "render/ar_session.h"
#include "runtime/stage.h"
#include "scenario/scenario_runtime.h"
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

// What the studio's Session hands a session: the stage it plays and the mailbox of its poses,
// filled here once, at 0 s.
std::shared_ptr<runtime::PoseMailbox> playedBy(ArSessionSettings& settings, const scenario::Scenario& s)
{
    auto built = scenario::buildRuntime(s, scenario::Assets());
    EXPECT_TRUE(built) << built.error().message;
    settings.stage = std::make_shared<runtime::Stage>(std::move(built).value());
    auto mailbox = std::make_shared<runtime::PoseMailbox>();
    runtime::PoseSet poses = settings.stage->makePoseSet();
    settings.stage->evaluate(0, poses);
    mailbox->publish(poses);
    settings.poses = mailbox;
    return mailbox;
}

ArSessionSettings settingsFor(const SyntheticScene& scene)
{
    ArSessionSettings settings;
    settings.camera = scene.camera;
    settings.target.board = scene.board;
    settings.realTime = false;
    settings.compositor.samples = 1;
    playedBy(settings, standingOnTheBoard());
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

// The session draws what its owner publishes, when it is published: a raised arm given while the
// video plays is what the next frames are drawn with, placement and all; the session evaluates
// nothing of its own.
TEST(ArSession, FramesAreDrawnWithThePosesTheOwnerPublishes)
{
    const SyntheticScene scene = boardScene(60);
    ArSessionSettings settings = settingsFor(scene);
    const auto mailbox = playedBy(settings, standingOnTheBoard());
    settings.realTime = true; // paced, so that the poses below arrive while frames are drawn
    auto session = ArSession::start(SyntheticSource::create(scene).value(), standingOnTheBoard(), scenario::Assets(),
                                    settings);
    ASSERT_TRUE(session) << session.error().message;
    runtime::PoseSet raised = settings.stage->makePoseSet();
    settings.stage->evaluate(secondsToTicks(0.5), raised);
    const auto& layout = *settings.stage->runtime().characters[0].skeleton.frameLayout();
    const int shoulder = layout.find("r_shoulder", anim::ElementKind::Rotation);
    ASSERT_GE(shoulder, 0);
    anim::rotationAt(std::span<float>(raised.characters[0].body), shoulder) =
        anim::Quat::fromAxisAngle({0, 0, 1}, 1.5f);
    const std::uint64_t ticksBefore = settings.stage->ticks();

    ArSnapshot snapshot;
    bool sawRest = false, sawRaised = false;
    bool published = false;
    while (true) {
        const bool running = (*session)->state() == ArSessionState::Running;
        if ((*session)->takeSnapshot(snapshot)) {
            ASSERT_EQ(snapshot.poses.characters.size(), 1u);
            if (snapshot.poses.time == 0)
                sawRest = true;
            if (snapshot.poses.time == raised.time) {
                sawRaised = true;
                EXPECT_EQ(snapshot.poses.characters[0].body, raised.characters[0].body);
            }
            if (!published && snapshot.tracking.frame >= 10) {
                mailbox->publish(raised);
                published = true;
            }
            EXPECT_EQ(snapshot.videoTime, secondsToTicks(double(snapshot.tracking.frame) / 30.0));
            continue;
        }
        if (!running)
            break;
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    EXPECT_EQ((*session)->state(), ArSessionState::Ended) << (*session)->message();
    EXPECT_TRUE(sawRest) << "the frames before the new poses show the ones published first";
    EXPECT_TRUE(sawRaised) << "the frames after show the raised arm";
    EXPECT_EQ(settings.stage->ticks(), ticksBefore) << "the session evaluated nothing itself";
}

TEST(ArSession, CharactersWithoutTheirStageAreRefused)
{
    const SyntheticScene scene = boardScene(5);
    ArSessionSettings settings = settingsFor(scene);
    settings.poses.reset();
    auto session = ArSession::start(SyntheticSource::create(scene).value(), standingOnTheBoard(), scenario::Assets(), settings);
    ASSERT_FALSE(session);
    EXPECT_NE(session.error().message.find("stage"), std::string::npos) << session.error().message;
}

// Gaze in AR (issue 33): a character told to look at the camera looks at the real, tracked one —
// the synthetic footage's camera moves round and over the board, and whenever the gaze has
// settled his eyes point at where its known pose puts it, within 3°.
TEST(ArSession, TheCharacterLooksAtTheTrackedCamera)
{
    const SyntheticScene scene = boardScene(120);
    ArSessionSettings settings = settingsFor(scene);
    const auto mailbox = playedBy(settings, standingOnTheBoard());
    motion::GazeSettings look;
    look.saccades = false;
    // The footage's camera looks down on the board from nearly overhead (up to 84° above the
    // character's eyes): beyond eyes and neck (80°), so the back bends too.
    look.influence = motion::GazeInfluence::Waist;
    ASSERT_TRUE(settings.stage->gaze("Hero", {runtime::GazeTarget::Kind::Camera, {}, {}, {}}, look, 0));
    const auto truth = SyntheticSource::create(scene);
    ASSERT_TRUE(truth);
    auto session = ArSession::start(SyntheticSource::create(scene).value(), standingOnTheBoard(), scenario::Assets(),
                                    settings);
    ASSERT_TRUE(session) << session.error().message;
    const anim::Skeleton& skeleton = settings.stage->runtime().characters[0].skeleton;
    const auto rig = motion::GazeRig::create(skeleton);
    ASSERT_TRUE(rig);
    auto tracker = makeTracker(settings.target, scene.camera);
    ASSERT_TRUE(tracker);
    const TargetGeometry target = (*tracker)->geometry();
    const scenario::ArSpec placement = standingOnTheBoard().ar;

    ArSnapshot snapshot;
    runtime::PoseSet poses = settings.stage->makePoseSet();
    double worst = 0, worstCamera = 0;
    int checked = 0;
    std::int64_t last = -1;
    while (true) {
        const bool running = (*session)->state() == ArSessionState::Running;
        if ((*session)->takeSnapshot(snapshot)) {
            const std::int64_t frame = snapshot.tracking.frame;
            if (frame <= last)
                continue;
            // The owner plays the stage at the video's time, every frame as a player does, and
            // publishes the poses. The session hands over the camera of each frame it draws: a
            // frame during which it moved (a slow machine, a sanitizer build) is not measured.
            const std::optional<anim::Vec3d> given = settings.stage->cameraPosition();
            for (std::int64_t f = last + 1; f <= frame; ++f)
                settings.stage->evaluate(secondsToTicks(double(f) / scene.fps), poses);
            last = frame;
            mailbox->publish(poses);
            const std::optional<anim::Vec3d> camera = settings.stage->cameraPosition();
            if (!camera || camera != given || frame < 40)
                continue;
            const anim::Vec3d real = arCameraView(scene.camera, (*truth)->truth(frame), target, placement).eye;
            worstCamera = std::max(worstCamera, std::sqrt(anim::dot(*camera - real, *camera - real)));
            const motion::EyeRay eyes = motion::eyeRay(*rig, skeleton, poses.characters[0].body, poses.characters[0].face);
            // Settled: passing overhead the camera makes the head swing round, the eyes' range
            // shrunk while it does (as people's is), and the gaze catch up after.
            if ((**settings.stage->gazeState("Hero")).shifting)
                continue;
            worst = std::max(worst, motion::degreesOff(eyes, *camera));
            ++checked;
            continue;
        }
        if (!running)
            break;
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    EXPECT_GE(checked, 10);
    // With the eyes planned to their full range, frames settled with the camera almost overhead
    // measured 3.1°: turning the back moved the eyes, which then needed more than their range.
    EXPECT_LT(worst, 3.0) << "degrees between his eyes' direction and the camera";
    EXPECT_LT(worstCamera, 0.5) << "the tracked camera, in world metres (the board's scale makes 1 m 6 cm)";
}
