// Gaze on the Stage (motion/gaze.h, runtime/stage.h): measured on the poses the Stage gives, as a
// viewer would see them — where the eyes point after the head and body turned, how fast the head
// turned, how long the eyes' jumps take — against SmartBody's limits and Eyes Alive's formula.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <tuple>
#include <cmath>
#include <numbers>
#include <vector>

#include "anim/hanim.h"
#include "anim/keyframe_clip.h"
#include "motion/eye_ray.h"
#include "motion/gaze.h"
#include "motion/gaze_target.h"
#include "motion/saccades.h"
#include "runtime/stage.h"
#include "scene/fap.h"

namespace thespis::test {
namespace {

using core::anim::Quatd;
using core::anim::Vec3d;
namespace motion = core::motion;
namespace runtime = core::runtime;
namespace hanim = core::anim::hanim;

constexpr double kDegree = std::numbers::pi / 180;

double length(const Vec3d& v) { return std::sqrt(core::anim::dot(v, v)); }
double angleBetween(const Vec3d& a, const Vec3d& b)
{
    return std::acos(std::clamp(core::anim::dot(a, b) / (length(a) * length(b)), -1.0, 1.0)) / kDegree;
}

struct Look {
    Vec3d eyes;        // between the eyes
    Vec3d direction;   // where they look
    Quatd head, chest; // world orientations of skullbase and vt1
};

// Where the character in `pose` looks: the head's orientation turned by the eyeball FAPs.
Look lookOf(const runtime::CharacterPose& pose, const motion::GazeRig& rig)
{
    const auto& skeleton = hanim::skeleton(hanim::Level::Loa2);
    std::vector<Vec3d> positions(std::size_t(skeleton.jointCount()));
    std::vector<Quatd> orientations(positions.size());
    skeleton.worldTransforms(pose.body, positions, orientations);
    Look look;
    const auto head = std::size_t(skeleton.find("skullbase")), chest = std::size_t(skeleton.find("vt1"));
    look.head = orientations[head];
    look.chest = orientations[chest];
    const motion::EyeRay ray = motion::eyeRay(rig, skeleton, pose.body, pose.face);
    look.eyes = ray.origin;
    look.direction = ray.direction;
    return look;
}

// Heading (+ left) of the head relative to the chest, degrees.
double headTurn(const Look& look)
{
    const Vec3d forward = core::anim::rotate(core::anim::conjugate(look.chest) * look.head, Vec3d{0, 0, 1});
    return std::atan2(forward.x, forward.z) / kDegree;
}

// Heading (+ left) of the eyes in the head, degrees: their FAP 23.
double eyeYaw(const runtime::CharacterPose& pose)
{
    return pose.face[std::size_t(core::scene::fapChannel(23))] * 1e-5 / kDegree;
}

// Heading (+ left) and pitch (+ down) of a direction, degrees, as the gaze measures them.
std::pair<double, double> anglesOf(const Vec3d& d)
{
    return {std::atan2(d.x, d.z) / kDegree, std::atan2(-d.y, std::hypot(d.x, d.z)) / kDegree};
}

class GazeTest : public ::testing::Test {
protected:
    void SetUp() override
    {
        ASSERT_TRUE(stage.addCharacter("Ann", hanim::skeleton(hanim::Level::Loa2)));
        poses = stage.makePoseSet();
        auto made = motion::GazeRig::create(hanim::skeleton(hanim::Level::Loa2));
        ASSERT_TRUE(made);
        rig = *made;
    }
    // The target `headingDegrees` to the left and `pitchDegrees` down, `distance` from the eyes at rest.
    Vec3d around(double headingDegrees, double pitchDegrees, double distance = 2) const
    {
        const Vec3d eyes = restLook().eyes;
        const double h = headingDegrees * kDegree, p = pitchDegrees * kDegree;
        return eyes + Vec3d{std::cos(p) * std::sin(h), -std::sin(p), std::cos(p) * std::cos(h)} * distance;
    }
    Look restLook() const
    {
        runtime::CharacterPose rest;
        rest.body = hanim::skeleton(hanim::Level::Loa2).restFrame();
        rest.face = core::anim::neutralFrame(*core::anim::FrameLayout::mpeg4Face());
        return lookOf(rest, rig);
    }
    // Plays from `from` to `to` seconds in steps of `step`, calling `each` after every frame.
    template <class Each> void play(double from, double to, double step, Each each)
    {
        for (double t = from; t <= to + 1e-9; t += step) {
            stage.evaluate(core::secondsToTicks(t), poses);
            each(t, lookOf(poses.characters[0], rig));
        }
    }
    Look settleAt(const Vec3d& target, motion::GazeSettings settings)
    {
        settings.saccades = false;
        EXPECT_TRUE(stage.gaze("Ann", {runtime::GazeTarget::Kind::Point, target, {}, {}}, settings, 0));
        Look last;
        play(0, 3, 1.0 / 60, [&](double, const Look& look) { last = look; });
        return last;
    }

    runtime::Stage stage;
    runtime::PoseSet poses;
    motion::GazeRig rig;
};

TEST_F(GazeTest, TheEyesSettleOnATargetInsideTheLimits)
{
    for (const auto& [h, p] : {std::pair{20.0, 10.0}, {-35.0, -20.0}, {60.0, 0.0}, {0.0, 30.0}}) {
        SCOPED_TRACE(std::to_string(h) + "° left, " + std::to_string(p) + "° down");
        const Vec3d target = around(h, p);
        const Look look = settleAt(target, {});
        EXPECT_LT(angleBetween(look.direction, target - look.eyes), 1.0);
        stage.resetLive();
    }
}

TEST_F(GazeTest, EachPartStaysInsideItsLimitsForATargetBehind)
{
    // 150° to the left: beyond eyes (40°) and neck (90°) together; chest (15°) and back (30°) make up the rest.
    const Vec3d target = around(150, 0);
    motion::GazeSettings settings;
    settings.influence = motion::GazeInfluence::Waist;
    const Look look = settleAt(target, settings);
    const auto state = stage.gazeState("Ann");
    ASSERT_TRUE(state && *state);
    const auto& s = **state;
    EXPECT_NEAR(s.heading[2], 90, 1e-6) << "the neck turns as far as it goes";
    EXPECT_LE(std::abs(s.heading[1]), 15 + 1e-6);
    EXPECT_LE(std::abs(s.heading[0]), 30 + 1e-6);
    EXPECT_LE(std::abs(s.eyeHeading), 40 + 1e-6);
    EXPECT_LT(headTurn(look), 90.5) << "the head on the chest, as the viewer sees it";
    EXPECT_LT(angleBetween(look.direction, target - look.eyes), 1.0);

    // With the head alone (BML influence HEAD) the eyes stop at their limit, 20° short.
    stage.resetLive();
    settings.influence = motion::GazeInfluence::Head;
    const Look headOnly = settleAt(target, settings);
    EXPECT_NEAR(headTurn(headOnly), 90, 0.5);
    EXPECT_NEAR(angleBetween(headOnly.direction, target - headOnly.eyes), 20, 1.5);
}

// A near target far up or down (an AR camera held over the character, a hand at the chest):
// turning the neck and back moves the eyes too, so they see it at another angle than the shift
// was shared out with. The eyes keep part of their range for that and still reach it (with all of
// it planned, these were 5.0°, 4.5° and 3.2° off).
TEST_F(GazeTest, TheEyesReachANearTargetFarUpOrDownAfterTheBodyTurns)
{
    motion::GazeSettings settings;
    settings.influence = motion::GazeInfluence::Waist;
    for (const auto& [h, p, distance] : {std::tuple{60.0, 70.0, 1.0}, {0.0, 70.0, 0.5}, {30.0, -100.0, 1.0}}) {
        SCOPED_TRACE(std::to_string(h) + "° left, " + std::to_string(p) + "° down, " + std::to_string(distance) + " m");
        const Vec3d target = around(h, p, distance);
        const Look look = settleAt(target, settings);
        EXPECT_LT(angleBetween(look.direction, target - look.eyes), 1.0);
        stage.resetLive();
    }
}

TEST_F(GazeTest, TheEyesLeadTheHeadFollowsWithinItsSpeedAndStopsWithoutOvershoot)
{
    motion::GazeSettings settings;
    settings.saccades = false;
    settings.influence = motion::GazeInfluence::Head;
    ASSERT_TRUE(stage.gaze("Ann", {runtime::GazeTarget::Kind::Point, around(70, 0), {}, {}}, settings, 0));
    const double step = 1.0 / 240;
    double previous = 0, peak = 0, highest = 0, eyesMoved = -1, headMoved = -1;
    play(0, 2, step, [&](double t, const Look& look) {
        const double turn = headTurn(look);
        peak = std::max(peak, std::abs(turn - previous) / step);
        highest = std::max(highest, turn);
        const double eyeYaw = poses.characters[0].face[std::size_t(core::scene::fapChannel(23))] * 1e-5 / kDegree;
        if (eyesMoved < 0 && eyeYaw > 1)
            eyesMoved = t;
        if (headMoved < 0 && turn > 1)
            headMoved = t;
        previous = turn;
    });
    const double settled = previous;
    EXPECT_GT(settled, 30);
    EXPECT_LE(peak, settings.neck.maxSpeed * 1.02) << "degrees a second";
    EXPECT_GT(peak, settings.neck.maxSpeed * 0.5) << "a 35° turn nears the top speed";
    EXPECT_LE(highest, settled + 0.1) << "no overshoot";
    ASSERT_GE(eyesMoved, 0);
    ASSERT_GE(headMoved, 0);
    EXPECT_GE(headMoved - eyesMoved, settings.neck.latency) << "the eyes lead";
}

// Every body part keeps to its own top speed and stops on its goal: for a target behind, the
// chest (60°/s) and back (45°/s) turn too, each after its latency, none overshooting.
TEST_F(GazeTest, ChestAndBackTurnWithinTheirSpeedsAndStopWithoutOvershoot)
{
    motion::GazeSettings settings;
    settings.saccades = false;
    settings.influence = motion::GazeInfluence::Waist;
    ASSERT_TRUE(stage.gaze("Ann", {runtime::GazeTarget::Kind::Point, around(150, 0), {}, {}}, settings, 0));
    const double step = 1.0 / 240;
    std::array<double, motion::kGazeBodyParts> previous{}, peak{}, highest{}, started{-1, -1, -1};
    play(0, 4, step, [&](double t, const Look&) {
        const motion::GazeState state = **stage.gazeState("Ann");
        for (std::size_t p = 0; p < motion::kGazeBodyParts; ++p) {
            peak[p] = std::max(peak[p], std::abs(state.heading[p] - previous[p]) / step);
            highest[p] = std::max(highest[p], state.heading[p]);
            if (started[p] < 0 && state.heading[p] > 0.5)
                started[p] = t;
            previous[p] = state.heading[p];
        }
    });
    const auto back = std::size_t(motion::GazePart::Back), chest = std::size_t(motion::GazePart::Chest);
    for (const auto& [p, limits] : {std::pair{back, settings.back}, {chest, settings.chest}}) {
        SCOPED_TRACE(p == back ? "back" : "chest");
        EXPECT_GT(previous[p], 0.5 * limits.heading) << "it takes part";
        EXPECT_LE(peak[p], limits.maxSpeed * 1.02) << "degrees a second";
        EXPECT_GT(peak[p], limits.maxSpeed * 0.3) << "it speeds up toward its top speed";
        EXPECT_LE(highest[p], previous[p] + 0.1) << "no overshoot";
        EXPECT_GE(started[p], limits.latency - step) << "it waits for its latency";
    }
}

// Smooth onset (Pejsa et al.): a shift starts from rest, not with a jump in speed. The eyes'
// jump is minimum-jerk, so it leaves with no speed; the head, after its latency, speeds up no
// faster than its acceleration (1200°/s²), so its first frames turn at a small share of its top
// speed. A head that set off at its top speed, or eyes that jumped at a constant speed, fail here.
TEST_F(GazeTest, AShiftStartsSmoothlyTheEyesAndTheHeadSpeedUpFromRest)
{
    constexpr double kStep = 1.0 / 240;      // seconds a frame
    constexpr int kFirstFrames = 2;          // frames after each part starts that must be slow
    constexpr double kSlowHeadShare = 0.1;   // of the neck's top speed (they are 2.5 % and 5 %)
    constexpr double kSlowEyeShare = 0.1;    // of the jump's peak speed (they are 0.7 % and 4.4 %)
    motion::GazeSettings settings;
    settings.saccades = false;
    settings.influence = motion::GazeInfluence::Head;
    ASSERT_TRUE(stage.gaze("Ann", {runtime::GazeTarget::Kind::Point, around(70, 0), {}, {}}, settings, 0));
    std::vector<double> head, eyes; // degrees, one a frame
    play(0, 1, kStep, [&](double, const Look& look) {
        head.push_back(headTurn(look));
        eyes.push_back(eyeYaw(poses.characters[0]));
    });
    const auto speeds = [&](const std::vector<double>& angles) {
        std::vector<double> v(angles.size(), 0);
        for (std::size_t i = 1; i < angles.size(); ++i)
            v[i] = (angles[i] - angles[i - 1]) / kStep;
        return v;
    };
    const std::vector<double> headSpeed = speeds(head), eyeSpeed = speeds(eyes);

    // The head: slow on its first frames, and never speeding up faster than its acceleration.
    const auto headStart = std::find_if(headSpeed.begin(), headSpeed.end(), [](double v) { return v > 1e-3; });
    ASSERT_NE(headStart, headSpeed.end()) << "the head turns";
    ASSERT_LT(headStart + kFirstFrames, headSpeed.end());
    for (int i = 0; i < kFirstFrames; ++i)
        EXPECT_LE(headStart[i], kSlowHeadShare * settings.neck.maxSpeed) << "degrees a second, frame " << i;
    double speedingUp = 0;
    for (std::size_t i = 1; i < headSpeed.size(); ++i)
        speedingUp = std::max(speedingUp, (headSpeed[i] - headSpeed[i - 1]) / kStep);
    EXPECT_LE(speedingUp, settings.neck.acceleration * 1.05) << "degrees a second²";
    EXPECT_GT(*std::max_element(headSpeed.begin(), headSpeed.end()), 0.9 * settings.neck.maxSpeed) << "it gets going";

    // The eyes: their jump starts at the shift and speeds up smoothly to its peak.
    ASSERT_NEAR(eyes[0], 0, 1e-6) << "the jump starts from rest";
    const double eyePeak = *std::max_element(eyeSpeed.begin(), eyeSpeed.end());
    EXPECT_GT(eyePeak, 100) << "degrees a second: a saccade, not a drift";
    for (int i = 1; i <= kFirstFrames; ++i)
        EXPECT_LE(eyeSpeed[std::size_t(i)], kSlowEyeShare * eyePeak) << "degrees a second, frame " << i;
}

// Pejsa et al.'s eye range that shrinks while the head moves (after Guitton and Volle): for a
// target behind, beyond the eyes' and head's reach, the eyes press against their limit; at the
// head's top speed that limit is 75 % of their range (30° of 40°), and once the head has stopped
// it is their whole range again.
TEST_F(GazeTest, TheEyesRangeShrinksWhileTheHeadTurnsFast)
{
    constexpr double kStep = 1.0 / 240;        // seconds a frame
    constexpr double kShrunk = 0.75;           // of the eyes' range left at the head's top speed
    constexpr double kFast = 0.98;             // of the head's top speed that counts as at it
    constexpr double kTolerance = 0.5;         // degrees
    motion::GazeSettings settings;
    settings.saccades = false;
    settings.influence = motion::GazeInfluence::Head;
    ASSERT_TRUE(stage.gaze("Ann", {runtime::GazeTarget::Kind::Point, around(150, 0), {}, {}}, settings, 0));
    double previous = 0, fastLeast = 1e9, fastMost = -1e9, last = 0;
    int fastFrames = 0;
    play(0, 2, kStep, [&](double, const Look& look) {
        const double turn = headTurn(look), speed = (turn - previous) / kStep;
        previous = turn;
        last = eyeYaw(poses.characters[0]);
        if (speed >= kFast * settings.neck.maxSpeed) {
            ++fastFrames;
            fastLeast = std::min(fastLeast, last);
            fastMost = std::max(fastMost, last);
        }
    });
    ASSERT_GT(fastFrames, 10) << "the head turns at its top speed for a while";
    EXPECT_NEAR(fastMost, kShrunk * settings.eyes.heading, kTolerance) << "degrees in the head, the head at its top speed";
    EXPECT_NEAR(fastLeast, kShrunk * settings.eyes.heading, kTolerance) << "pressed against the shrunk limit all along";
    EXPECT_NEAR(last, settings.eyes.heading, kTolerance) << "degrees in the head, the head stopped";
}

// BML's offsetAngle and offsetDirection: the eyes settle that many degrees off the target, toward
// that side of the character (RIGHT is her right, UP up), and on the target with no offset.
TEST_F(GazeTest, AnOffsetSettlesTheGazeThatFarOffTheTargetInItsDirection)
{
    constexpr double kOffset = 20;    // degrees
    constexpr double kTolerance = 1;  // degrees
    struct Case {
        double heading, pitch;        // of the target: degrees left, down
        const char* direction;
        double headingOff, pitchOff;  // where the gaze should be from the target, per degree of offset
    };
    for (const Case& c : {Case{30, 0, "RIGHT", -1, 0}, Case{-20, 0, "LEFT", 1, 0}, Case{0, 10, "UP", 0, -1}, Case{0, -5, "DOWN", 0, 1}}) {
        for (const double angle : {kOffset, 0.0}) {
            SCOPED_TRACE(std::to_string(angle) + "° " + c.direction + " of a target " + std::to_string(c.heading) + "° left, " +
                         std::to_string(c.pitch) + "° down");
            stage.resetLive();
            motion::GazeSettings settings;
            ASSERT_TRUE(motion::setGazeOffset(settings, angle, c.direction));
            const Vec3d target = around(c.heading, c.pitch);
            const Look look = settleAt(target, settings);
            const auto [heading, pitch] = anglesOf(look.direction);
            const auto [targetHeading, targetPitch] = anglesOf(target - look.eyes);
            EXPECT_NEAR(heading - targetHeading, c.headingOff * angle, kTolerance) << "degrees left of the target";
            EXPECT_NEAR(pitch - targetPitch, c.pitchOff * angle, kTolerance) << "degrees below the target";
            EXPECT_NEAR(angleBetween(look.direction, target - look.eyes), angle, kTolerance) << "degrees off the target";
        }
    }
}

TEST_F(GazeTest, EyeJumpsLastEyesAlivesTwentyFiveMillisecondsPlusTwoPointFourADegree)
{
    motion::GazeSettings settings;
    settings.saccades = false;
    settings.influence = motion::GazeInfluence::Eyes;
    settings.blinkAbove = 90;
    for (const double amplitude : {5.0, 12.0, 30.0}) {
        SCOPED_TRACE(amplitude);
        stage.resetLive();
        ASSERT_TRUE(stage.gaze("Ann", {runtime::GazeTarget::Kind::Point, around(0, 0, 50), {}, {}}, settings, 0));
        play(0, 0.5, 0.001, [](double, const Look&) {});
        ASSERT_TRUE(stage.gaze("Ann", {runtime::GazeTarget::Kind::Point, around(amplitude, 0, 50), {}, {}}, settings,
                               core::secondsToTicks(0.6)));
        double start = -1, end = -1, previous = 0;
        play(0.501, 1.5, 0.001, [&](double t, const Look&) {
            const double yaw = poses.characters[0].face[std::size_t(core::scene::fapChannel(23))] * 1e-5 / kDegree;
            if (start < 0 && std::abs(yaw - previous) > 1e-9 && t > 0.55)
                start = t - 0.001;
            if (start >= 0 && end < 0 && std::abs(yaw - previous) < 1e-9)
                end = t - 0.001;
            previous = yaw;
        });
        ASSERT_GE(start, 0);
        ASSERT_GE(end, 0);
        EXPECT_NEAR(end - start, 0.025 + 0.0024 * amplitude, 0.003);
    }
}

TEST_F(GazeTest, ALargeShiftOfTheEyesComesWithABlink)
{
    motion::GazeSettings settings;
    settings.saccades = false;
    settings.influence = motion::GazeInfluence::Eyes;
    const auto lid = [&] { return poses.characters[0].face[std::size_t(core::scene::fapChannel(19))]; };
    float closed = 0;
    ASSERT_TRUE(stage.gaze("Ann", {runtime::GazeTarget::Kind::Point, around(10, 0), {}, {}}, settings, 0));
    play(0, 0.5, 0.01, [&](double, const Look&) { closed = std::max(closed, lid()); });
    EXPECT_EQ(closed, 0.0f) << "10° needs no blink";
    ASSERT_TRUE(stage.gaze("Ann", {runtime::GazeTarget::Kind::Point, around(-30, 0), {}, {}}, settings,
                           core::secondsToTicks(0.5)));
    play(0.51, 1.0, 0.01, [&](double, const Look&) { closed = std::max(closed, lid()); });
    EXPECT_GT(closed, 800.0f) << "40° shuts the lids on the way";
}

TEST_F(GazeTest, FixatingTheEyesMakeEyesAlivesSaccadesAndListenersLookAwayLess)
{
    const auto mutualShare = [&](bool talking) {
        stage.resetLive();
        motion::GazeSettings settings;
        settings.influence = motion::GazeInfluence::Eyes;
        settings.talking = talking;
        settings.seed = 7;
        const Vec3d target = around(0, 0, 3);
        EXPECT_TRUE(stage.gaze("Ann", {runtime::GazeTarget::Kind::Point, target, {}, {}}, settings, 0));
        int onTarget = 0, frames = 0;
        play(0, 120, 1.0 / 30, [&](double t, const Look& look) {
            if (t < 1)
                return;
            ++frames;
            onTarget += angleBetween(look.direction, target - look.eyes) < 0.5;
        });
        return double(onTarget) / frames;
    };
    const double talking = mutualShare(true), listening = mutualShare(false);
    // Eyes Alive's fits: mutual gaze 94 of 122 frames talking (77 %), 238 of 251 listening (95 %).
    EXPECT_NEAR(talking, 0.77, 0.12);
    EXPECT_NEAR(listening, 0.93, 0.06);
    EXPECT_GT(listening, talking + 0.1);
}

TEST(Saccades, AmplitudesFollowEyesAlivesDistribution)
{
    motion::SaccadeGenerator generator(3);
    generator.restart(0, true);
    double sum = 0, h = 0, v = 0;
    int away = 0;
    for (double t = 0; away < 2000; t += 0.01) {
        const int before = generator.count();
        generator.offset(t, h, v);
        if (generator.count() != before && generator.current().toHeading != 0) {
            ++away;
            sum += generator.current().amplitude();
            EXPECT_NEAR(generator.current().duration, 0.025 + 0.0024 * generator.current().amplitude(), 1e-12);
        }
    }
    // A = −6.9 ln(P/15.7), P uniform on (0, 15], clipped at 15°: mean ≈ 6.9 + 6.9 ln(15.7/15) − the clip's share.
    EXPECT_NEAR(sum / away, 6.4, 0.5);
}

TEST_F(GazeTest, ACharacterLooksAnotherInTheEyesAsHeWalksPast)
{
    const auto& skeleton = hanim::skeleton(hanim::Level::Loa2);
    ASSERT_TRUE(stage.addCharacter("Ben", skeleton));
    poses = stage.makePoseSet();
    // Ben faces Ann from 1.5 m ahead and walks from 0.4 m on her left to 0.6 m on her right in 4 s.
    std::vector<float> frames = skeleton.restFrame();
    core::anim::rotationAt(std::span<float>(frames), 0) = {0, 1, 0, 0};
    frames.insert(frames.end(), frames.begin(), frames.end());
    const std::size_t root = skeleton.frameLayout()->floatOffset(skeleton.translationElement(0));
    frames[root] = 0.4f;
    frames[root + 2] = 1.5f;
    frames[skeleton.frameLayout()->floatCount() + root] = -0.6f;
    frames[skeleton.frameLayout()->floatCount() + root + 2] = 1.5f;
    auto walk = core::anim::KeyframeClip::create(skeleton.frameLayout(), 0.25, frames, "walk past");
    ASSERT_TRUE(walk);
    runtime::ActionTemplate action;
    action.source = *walk;
    ASSERT_TRUE(stage.playAction("Ben", runtime::Track::Body, "walk past", action, 0, {.fadeIn = 0}));

    motion::GazeSettings settings;
    settings.saccades = false;
    ASSERT_TRUE(stage.gaze("Ann", {runtime::GazeTarget::Kind::Joint, {}, "Ben", {}}, settings, 0));
    EXPECT_FALSE(stage.gaze("Ann", {runtime::GazeTarget::Kind::Joint, {}, "Nobody", {}}, settings, 0));
    EXPECT_FALSE(stage.gaze("Ann", {runtime::GazeTarget::Kind::Joint, {}, "Ben", "tail"}, settings, 0));
    double worst = 0;
    play(0, 3.9, 1.0 / 60, [&](double t, const Look& ann) {
        const Look ben = lookOf(poses.characters[1], rig);
        if (t > 1)
            worst = std::max(worst, angleBetween(ann.direction, ben.eyes - ann.eyes));
    });
    EXPECT_LT(worst, 1.0) << "degrees from Ben's eyes";
}

TEST_F(GazeTest, LettingGoGivesThePoseBack)
{
    const Look rest = restLook();
    motion::GazeSettings settings;
    ASSERT_TRUE(stage.gaze("Ann", {runtime::GazeTarget::Kind::Point, around(50, 10), {}, {}}, settings, 0));
    play(0, 2, 1.0 / 60, [](double, const Look&) {});
    ASSERT_TRUE(*stage.stopGaze("Ann", core::secondsToTicks(2)));
    Look last;
    play(2, 5, 1.0 / 60, [&](double, const Look& look) { last = look; });
    EXPECT_FALSE(*stage.gazeState("Ann")) << "the gaze is off once back";
    EXPECT_LT(angleBetween(last.direction, rest.direction), 1e-3);
    EXPECT_EQ(poses.characters[0].body, hanim::skeleton(hanim::Level::Loa2).restFrame());
}

} // namespace
} // namespace thespis::test
