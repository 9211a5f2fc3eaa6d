// The live runtime (core/runtime): Stage semantics, the animation service's waits, the clocks
// and the pose mailbox that hands a tick's poses to another thread, on the demo scenario and on
// real CMU captures.

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <thread>

#include "anim/bvh.h"
#include "runtime/animation_service.h"
#include "runtime/pose_mailbox.h"
#include "runtime/stage.h"
#include "scenario/scenario_io.h"
#include "anim_test_support.h"
#include "test_support.h"

namespace thespis::test {
namespace {

using core::Tick;
using core::secondsToTicks;
using namespace core::runtime;

/// The middle of Creon's first blink in the demo (frame 15 of his looping blink clip).
constexpr double kMidBlink = 0.5;

std::shared_ptr<Stage> demoStage()
{
    auto scenario = core::scenario::loadScenario(resources("demo.thespis"));
    EXPECT_TRUE(scenario) << core::describe(scenario.error());
    auto runtime = core::scenario::buildRuntime(*scenario, resources());
    EXPECT_TRUE(runtime) << core::describe(runtime.error());
    return std::make_shared<Stage>(std::move(runtime).value());
}

/// Largest angle (radians) between the rotations of two frames of `layout`.
double maxAngle(const FrameLayout& layout, std::span<const float> a, std::span<const float> b)
{
    double worst = 0;
    for (int r = 0; r < layout.rotationCount(); ++r) {
        const std::size_t o = std::size_t(r) * 4;
        worst = std::max(worst, angle(Quat{a[o], a[o + 1], a[o + 2], a[o + 3]}, Quat{b[o], b[o + 1], b[o + 2], b[o + 3]}));
    }
    return worst;
}

std::vector<float> authoredBody(const Stage& stage, int character, double seconds)
{
    const auto& runtime = stage.runtime().characters[std::size_t(character)];
    std::vector<float> frame = runtime.skeleton.restFrame();
    runtime.body->evaluate(seconds, frame);
    return frame;
}

TEST(Stage, WithNothingLiveItPlaysTheAuthoredSchedulesExactly)
{
    auto stage = demoStage();
    PoseSet poses = stage->makePoseSet();
    ASSERT_EQ(poses.characters.size(), 2u);
    for (const double t : {0.0, 0.7, 1.9, 3.3, 6.0}) {
        stage->evaluate(secondsToTicks(t), poses);
        for (int c = 0; c < 2; ++c)
            EXPECT_EQ(poses.characters[std::size_t(c)].body, authoredBody(*stage, c, t)) << "t = " << t;
    }
    // The face track is played too: Creon's lids are half shut at 0.5 s, in his first blink.
    const auto& face = stage->runtime().characters[0].face;
    std::vector<float> expected = neutralFrame(*FrameLayout::mpeg4Face());
    face->evaluate(kMidBlink, expected);
    stage->evaluate(secondsToTicks(kMidBlink), poses);
    EXPECT_EQ(poses.characters[0].face, expected);
    EXPECT_NE(poses.characters[0].face, neutralFrame(*FrameLayout::mpeg4Face())) << "Creon blinks at 0.5 s";
}

TEST(Stage, ALiveActionFadesInOverWhatPlaysWithoutAJump)
{
    auto stage = demoStage();
    const auto& creon = stage->runtime().characters[0];
    const FrameLayout& layout = *creon.skeleton.frameLayout();
    PoseSet poses = stage->makePoseSet();
    const Tick at = secondsToTicks(2.5);
    ASSERT_TRUE(stage->activateAction("Creon", Track::Body, "nod", at)); // a clip: constant weight
    // At the moment it starts, the pose is what was playing; a frame later it has barely moved.
    stage->evaluate(at, poses);
    EXPECT_LT(maxAngle(layout, poses.characters[0].body, authoredBody(*stage, 0, 2.5)), 1e-4);
    // A frame later it has moved by the fade's first step (cubic over 0.25 s: 1.3 %) of the
    // way to the clip, not more.
    stage->evaluate(at + core::ticksPerFrame(60), poses);
    const std::vector<float> before = authoredBody(*stage, 0, 2.5 + 1.0 / 60);
    std::vector<float> nod = creon.skeleton.restFrame();
    creon.clips.at("nod")->evaluate(1.0 / 60, nod);
    EXPECT_LT(maxAngle(layout, poses.characters[0].body, before), 0.015 * maxAngle(layout, nod, before));
    // Once faded in (0.25 s), the live clip has taken over entirely.
    creon.clips.at("nod")->evaluate(0.5, nod);
    stage->evaluate(at + secondsToTicks(0.5), poses);
    EXPECT_LT(maxAngle(layout, poses.characters[0].body, nod), 1e-4);
    EXPECT_GT(maxAngle(layout, authoredBody(*stage, 0, 3.0), nod), 0.05) << "the test needs a visible difference";
    // Antigone is untouched.
    EXPECT_EQ(poses.characters[1].body, authoredBody(*stage, 1, 3.0));
}

TEST(Stage, CutOffInTheMiddleOfAFadeInEndsAfterItsFade)
{
    auto stage = demoStage();
    ActivateOptions slow;
    slow.weight = Curve::cubicFade(1.0, 0.0);
    ASSERT_TRUE(stage->activateAction("Creon", Track::Body, "nod", secondsToTicks(1.0), slow));
    ASSERT_TRUE(*stage->cutOffAction("Creon", Track::Body, "nod", secondsToTicks(1.5), 0.5));
    EXPECT_DOUBLE_EQ(*stage->actionEnd("Creon", Track::Body, "nod"), 2.0);
    EXPECT_TRUE(*stage->isPlaying("Creon", Track::Body, "nod", secondsToTicks(1.9)));
    EXPECT_FALSE(*stage->isPlaying("Creon", Track::Body, "nod", secondsToTicks(2.0)));
    EXPECT_DOUBLE_EQ(*stage->timeUntilFinished("Creon", Track::Body, "nod", secondsToTicks(1.75)), 0.25);
    PoseSet poses = stage->makePoseSet();
    stage->evaluate(secondsToTicks(2.0), poses);
    EXPECT_EQ(poses.characters[0].body, authoredBody(*stage, 0, 2.0)); // gone: exactly the authored pose
    // Nothing left to cut.
    EXPECT_FALSE(*stage->cutOffAction("Creon", Track::Body, "nod", secondsToTicks(2.5), 0.5));
}

TEST(Stage, RemoveEndsALiveActionAtOnce)
{
    auto stage = demoStage();
    ASSERT_TRUE(stage->activateAction("Creon", Track::Body, "nod", 0, {.fadeIn = 0}));
    EXPECT_TRUE(*stage->removeAction("Creon", Track::Body, "nod"));
    EXPECT_FALSE(*stage->removeAction("Creon", Track::Body, "nod"));
    PoseSet poses = stage->makePoseSet();
    stage->evaluate(secondsToTicks(0.4), poses);
    EXPECT_EQ(poses.characters[0].body, authoredBody(*stage, 0, 0.4));
}

TEST(Stage, ALiveGestureWithAMaskMovesOnlyItsJoints)
{
    // creon_wave is an Override action on the right arm: live, it plays over the idle.
    auto stage = demoStage();
    const auto& creon = stage->runtime().characters[0];
    const FrameLayout& layout = *creon.skeleton.frameLayout();
    const double start = 6.0; // after the authored wave
    ASSERT_TRUE(stage->activateAction("Creon", Track::Body, "creon_wave", secondsToTicks(start)));
    PoseSet poses = stage->makePoseSet();
    stage->evaluate(secondsToTicks(start + 1.0), poses);
    const std::vector<float> idle = authoredBody(*stage, 0, start + 1.0);
    const int elbow = layout.find("r_elbow", ElementKind::Rotation), knee = layout.find("l_knee", ElementKind::Rotation);
    ASSERT_GE(elbow, 0);
    ASSERT_GE(knee, 0);
    const auto rotation = [](std::span<const float> f, int r) {
        return Quat{f[std::size_t(r) * 4], f[std::size_t(r) * 4 + 1], f[std::size_t(r) * 4 + 2], f[std::size_t(r) * 4 + 3]};
    };
    EXPECT_GT(angle(rotation(poses.characters[0].body, elbow), rotation(idle, elbow)), 0.1);
    EXPECT_LT(angle(rotation(poses.characters[0].body, knee), rotation(idle, knee)), 1e-5);
}

TEST(Stage, CuttingOffAnAuthoredActionIsUndoneByAReset)
{
    auto stage = demoStage();
    const std::vector<float> uncut = authoredBody(*stage, 1, 3.0);
    ASSERT_TRUE(*stage->cutOffAction("Antigone", Track::Body, "antigone_idle", secondsToTicks(1.0), 1.0));
    PoseSet poses = stage->makePoseSet();
    stage->evaluate(secondsToTicks(3.0), poses);
    EXPECT_NE(poses.characters[1].body, uncut);
    EXPECT_FALSE(*stage->isPlaying("Antigone", Track::Body, "antigone_idle", secondsToTicks(2.5)));
    stage->resetLive();
    EXPECT_TRUE(*stage->isPlaying("Antigone", Track::Body, "antigone_idle", secondsToTicks(2.5)));
    stage->evaluate(secondsToTicks(3.0), poses);
    EXPECT_EQ(poses.characters[1].body, uncut);
}

TEST(Stage, AnEditedScenarioPlaysOnWithItsLiveActions)
{
    auto stage = demoStage();
    ASSERT_TRUE(stage->activateAction("Antigone", Track::Body, "nod", secondsToTicks(1.0)));
    // The scenario edited: Creon's idle starts a second later.
    auto scenario = core::scenario::loadScenario(resources("demo.thespis"));
    ASSERT_TRUE(scenario);
    scenario->characters[0].layers[0].actions[0].start += core::TicksPerSecond;
    auto edited = core::scenario::buildRuntime(*scenario, resources());
    ASSERT_TRUE(edited);
    ASSERT_TRUE(stage->setRuntime(std::move(edited).value()));
    EXPECT_TRUE(*stage->isPlaying("Antigone", Track::Body, "nod", secondsToTicks(1.5)));
    PoseSet poses = stage->makePoseSet();
    stage->evaluate(secondsToTicks(0.5), poses);
    EXPECT_EQ(poses.characters[0].body, authoredBody(*stage, 0, 0.5)); // the new schedule plays
    // Another cast cannot be swapped in.
    auto other = core::scenario::buildRuntime(core::scenario::Scenario{}, resources());
    ASSERT_TRUE(other);
    EXPECT_FALSE(stage->setRuntime(std::move(other).value()));
}

TEST(Stage, TheFrameCacheGivesTheSamePosesAndPaysWhenScrubbingBack)
{
    auto cached = demoStage(), plain = demoStage();
    cached->setFrameCache(240);
    PoseSet a = cached->makePoseSet(), b = plain->makePoseSet();
    const auto compareAt = [&](double t) {
        cached->evaluate(secondsToTicks(t), a);
        plain->evaluate(secondsToTicks(t), b);
        for (std::size_t c = 0; c < a.characters.size(); ++c) {
            ASSERT_EQ(a.characters[c].body, b.characters[c].body) << "character " << c << " at " << t << " s";
            ASSERT_EQ(a.characters[c].face, b.characters[c].face) << "character " << c << " at " << t << " s";
        }
    };
    // A scrub: forward over 2 s at 30 fps, then back over the same frames.
    for (int f = 0; f <= 60; ++f)
        compareAt(f / 30.0);
    const std::uint64_t forward = cached->frameCacheHits();
    for (int f = 60; f >= 0; --f)
        compareAt(f / 30.0);
    EXPECT_GE(cached->frameCacheHits() - forward, 2u * 61u - 4u); // body and face, nearly every frame
    // A live action and a cut-off authored one play over the cached frames as over the others.
    for (auto* stage : {cached.get(), plain.get()}) {
        ASSERT_TRUE(stage->activateAction("Antigone", Track::Body, "nod", secondsToTicks(0.5)));
        ASSERT_TRUE(*stage->cutOffAction("Creon", Track::Body, "creon_idle", secondsToTicks(1.0), 0.5));
    }
    for (int f = 60; f >= 0; --f)
        compareAt(f / 30.0);
    // After an edit the new schedules play, cached or not.
    auto scenario = core::scenario::loadScenario(resources("demo.thespis"));
    ASSERT_TRUE(scenario);
    scenario->characters[0].layers[0].actions[0].start += core::TicksPerSecond / 3;
    for (auto* stage : {cached.get(), plain.get()}) {
        auto edited = core::scenario::buildRuntime(*scenario, resources());
        ASSERT_TRUE(edited);
        ASSERT_TRUE(stage->setRuntime(std::move(edited).value()));
    }
    for (int f = 0; f <= 60; ++f)
        compareAt(f / 30.0);
}

TEST(Stage, UnknownNamesAreNamedWithTheKnownOnes)
{
    auto stage = demoStage();
    auto noCharacter = stage->activateAction("Ismene", Track::Body, "nod", 0);
    ASSERT_FALSE(noCharacter);
    EXPECT_EQ(noCharacter.error().code, core::ErrorCode::NotFound);
    EXPECT_NE(noCharacter.error().message.find("Ismene"), std::string::npos);
    EXPECT_NE(noCharacter.error().message.find("Creon, Antigone"), std::string::npos);
    auto noAction = stage->activateAction("Creon", Track::Body, "dance", 0);
    ASSERT_FALSE(noAction);
    EXPECT_NE(noAction.error().message.find("dance"), std::string::npos);
    EXPECT_NE(noAction.error().message.find("creon_idle"), std::string::npos);
    EXPECT_NE(noAction.error().message.find("nod"), std::string::npos);
    auto neverPlayed = stage->actionEnd("Creon", Track::Body, "nod");
    ASSERT_FALSE(neverPlayed);
}

TEST(Stage, AFaceTrackTurnedOffStaysNeutral)
{
    auto stage = demoStage();
    PoseSet poses = stage->makePoseSet();
    stage->evaluate(secondsToTicks(kMidBlink), poses);
    ASSERT_NE(poses.characters[0].face, neutralFrame(*FrameLayout::mpeg4Face())) << "Creon blinks at 0.5 s";
    stage->setTrackEnabled(Track::Face, false);
    stage->evaluate(secondsToTicks(kMidBlink), poses);
    EXPECT_EQ(poses.characters[0].face, neutralFrame(*FrameLayout::mpeg4Face()));
}

/// A blendable that counts its evaluations.
class CountingClip final : public BlendableObject {
public:
    explicit CountingClip(std::shared_ptr<const KeyframeClip> clip) : m_clip(std::move(clip)) {}
    const FrameLayoutPtr& layout() const override { return m_clip->layout(); }
    TimeDomain domain() const override { return m_clip->domain(); }
    void evaluate(double t, std::span<float> out) const override
    {
        ++count;
        m_clip->evaluate(t, out);
    }
    mutable std::atomic<int> count{0};

private:
    std::shared_ptr<const KeyframeClip> m_clip;
};

TEST(Stage, EverySourceIsEvaluatedOncePerTick)
{
    auto walk = core::anim::bvh::load(sharedData("mocap/cmu/02_01.bvh"));
    ASSERT_TRUE(walk) << core::describe(walk.error());
    core::scenario::ScenarioRuntime runtime;
    core::scenario::CharacterRuntime performer;
    performer.name = "Walker";
    performer.skeleton = walk->skeleton;
    performer.body = std::make_shared<BlendingSchedule>(walk->skeleton);
    performer.face = std::make_shared<BlendingSchedule>(FrameLayout::mpeg4Face());
    auto authored = std::make_shared<CountingClip>(walk->clip);
    BlendingAction action;
    action.source = authored;
    action.renderOutsideDomain = true;
    ASSERT_TRUE(performer.body->addAction(action));
    runtime.characters.push_back(std::move(performer));
    Stage stage(std::move(runtime));
    auto live = std::make_shared<CountingClip>(walk->clip);
    ASSERT_TRUE(stage.defineAction("Walker", Track::Body, "walk", {live, {}, true}));
    ASSERT_TRUE(stage.activateAction("Walker", Track::Body, "walk", secondsToTicks(0.5)));
    PoseSet poses = stage.makePoseSet();
    for (int f = 0; f < 120; ++f)
        stage.evaluate(f * core::ticksPerFrame(60), poses);
    EXPECT_EQ(authored->count, 120);
    EXPECT_EQ(live->count, 120 - 30); // from 0.5 s on
    EXPECT_EQ(stage.ticks(), 120u);
}

TEST(AnimationService, WaitsUntilSecondsBeforeTheEndOnAManualClock)
{
    auto stage = demoStage();
    auto clock = std::make_shared<ManualClock>();
    std::vector<std::pair<Tick, Tick>> jumps;
    clock->setJumpHook([&](Tick from, Tick to) {
        jumps.emplace_back(from, to);
        return true;
    });
    AnimationService anim(stage, clock);
    ASSERT_TRUE(clock->advance(secondsToTicks(1.0)));
    ASSERT_TRUE(anim.activateAction("Creon", Track::Body, "creon_wave"));
    const double waveLength = stage->runtime().characters[0].clips.at("wave")->domain().duration();
    auto reached = anim.waitUntilActionFinished("Creon", Track::Body, "creon_wave", -1.0);
    ASSERT_TRUE(reached) << core::describe(reached.error());
    EXPECT_EQ(*reached, secondsToTicks(1.0 + waveLength - 1.0));
    EXPECT_EQ(clock->now(), *reached);
    ASSERT_EQ(jumps.size(), 2u);
    EXPECT_EQ(jumps[1], std::make_pair(secondsToTicks(1.0), *reached));
    EXPECT_TRUE(*anim.isPlaying("Creon", Track::Body, "creon_wave"));
    // A looping idle never ends: waiting for it is refused with a reason.
    ASSERT_TRUE(anim.activateAction("Creon", Track::Body, "creon_idle"));
    auto never = anim.waitUntilActionFinished("Creon", Track::Body, "creon_idle", 0.0);
    ASSERT_FALSE(never);
    EXPECT_NE(never.error().message.find("never ends"), std::string::npos);
}

TEST(AnimationService, StopEndsAWaitInProgress)
{
    auto stage = demoStage();
    auto clock = std::make_shared<ExternalClock>();
    AnimationService anim(stage, clock);
    std::jthread stopper([&] {
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
        anim.requestStop();
    });
    auto waited = anim.wait(3600.0);
    ASSERT_FALSE(waited);
    EXPECT_EQ(waited.error().code, core::ErrorCode::Cancelled);
}

TEST(Clock, ExternalClockWakesWaitsItReaches)
{
    ExternalClock clock;
    std::atomic<bool> woke = false;
    std::jthread waiter([&] { woke = clock.waitUntil(secondsToTicks(2.0), {}); });
    clock.setTime(secondsToTicks(1.0));
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    EXPECT_FALSE(woke);
    clock.setTime(secondsToTicks(2.0));
    waiter.join();
    EXPECT_TRUE(woke);
    EXPECT_FALSE(clock.waitUntil(secondsToTicks(3.0), {}, std::chrono::milliseconds(5)));
}

TEST(Clock, RealTimeClockMovesOnAndWaits)
{
    RealTimeClock clock(secondsToTicks(10.0));
    const Tick start = clock.now();
    EXPECT_GE(start, secondsToTicks(10.0));
    EXPECT_TRUE(clock.waitUntil(start + secondsToTicks(0.02), {}));
    EXPECT_GE(clock.now(), start + secondsToTicks(0.02));
    std::stop_source stop;
    stop.request_stop();
    EXPECT_FALSE(clock.waitUntil(start + secondsToTicks(100.0), stop.get_token()));
}

// What a script can play live: body clips, face clips (on the face track), the scenario's
// actions and the gesticon's gestures, each as the runtime built it. Creon's "greet" is the
// wave over his right arm through the dependent-joint filter; an unknown name lists them all.
TEST(Stage, ScriptsPlayGesticonGesturesAndFaceClips)
{
    auto stage = demoStage();
    const auto body = stage->actionNames("Creon", Track::Body);
    ASSERT_TRUE(body);
    EXPECT_NE(std::find(body->begin(), body->end(), "greet"), body->end());
    const auto face = stage->actionNames("Creon", Track::Face);
    ASSERT_TRUE(face);
    EXPECT_NE(std::find(face->begin(), face->end(), "blink"), face->end()) << "a clip of FAP values plays on the face";
    EXPECT_EQ(std::find(body->begin(), body->end(), "blink"), body->end()) << "and not on the body";

    const Tick start = secondsToTicks(0.2), during = secondsToTicks(1.4);
    PoseSet authored = stage->makePoseSet(), played = stage->makePoseSet();
    stage->evaluate(during, authored);
    ASSERT_TRUE(stage->activateAction("Creon", Track::Body, "greet", start));
    stage->evaluate(during, played);
    const auto& creon = stage->runtime().characters[0];
    const auto& layout = *creon.skeleton.frameLayout();
    const auto rotation = [&](const PoseSet& poses, const char* joint) {
        return core::anim::rotationAt(std::span<const float>(poses.characters[0].body),
                                      layout.find(joint, core::anim::ElementKind::Rotation));
    };
    const auto angle = [](core::anim::Quat a, core::anim::Quat b) {
        return 2.0 * std::acos(std::min(1.0, std::abs(double(core::anim::dot(a, b)))));
    };
    EXPECT_GT(angle(rotation(played, "r_shoulder"), rotation(authored, "r_shoulder")), 0.2) << "the arm waves";
    EXPECT_GT(angle(rotation(played, "l_shoulder"), rotation(authored, "l_shoulder")), 1e-3)
        << "the filter moves the upper body outside the gesture's mask";
    EXPECT_LT(angle(rotation(played, "l_hip"), rotation(authored, "l_hip")), 1e-6) << "the legs go on as authored";
    // The gesture ends after its clip, faded out.
    const double end = *stage->actionEnd("Creon", Track::Body, "greet");
    EXPECT_NEAR(end, 0.2 + creon.clips.at("wave")->domain().duration(), 1e-9);

    // A face clip plays on the face track: a blink started at 1 s half shuts the lids at 1.5 s,
    // where the authored blinks leave the face neutral.
    stage->evaluate(secondsToTicks(1.5), authored);
    ASSERT_EQ(authored.characters[0].face, neutralFrame(*FrameLayout::mpeg4Face()));
    ASSERT_TRUE(stage->activateAction("Creon", Track::Face, "blink", secondsToTicks(1.0), {.fadeIn = 0}));
    stage->evaluate(secondsToTicks(1.5), played);
    EXPECT_NE(played.characters[0].face, neutralFrame(*FrameLayout::mpeg4Face()));
    const auto unknown = stage->activateAction("Creon", Track::Body, "bow", start);
    ASSERT_FALSE(unknown);
    EXPECT_NE(unknown.error().message.find("greet"), std::string::npos) << unknown.error().message;
}

// The studio's Session evaluates on the GUI thread and the AR preview draws on its own: what
// the drawing thread takes from the mailbox is exactly the tick's poses, placement included.
TEST(PoseMailbox, ADrawingThreadGetsExactlyThePosesOfEachTick)
{
    auto stage = demoStage();
    PoseMailbox mailbox;
    std::atomic<std::uint64_t> acknowledged = 0;
    std::vector<PoseSet> received;
    std::jthread reader([&](std::stop_token stop) {
        PoseSet poses;
        std::uint64_t seen = 0;
        while (!stop.stop_requested()) {
            seen = mailbox.waitNewer(seen, std::chrono::milliseconds(20));
            if (mailbox.takeNewer(poses, acknowledged) == 0)
                continue;
            received.push_back(poses);
            acknowledged = seen;
        }
    });
    PoseSet poses = stage->makePoseSet();
    std::vector<PoseSet> sent;
    for (int step = 0; step <= 20; ++step) {
        const Tick t = secondsToTicks(0.3 * step);
        if (step == 5) {
            ASSERT_TRUE(stage->activateAction("Antigone", Track::Body, "nod", t));
        }
        stage->evaluate(t, poses);
        mailbox.publish(poses);
        sent.push_back(poses);
        while (acknowledged < std::uint64_t(step + 1)) // one at a time, so that every tick is seen
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    reader.request_stop();
    reader.join();
    ASSERT_EQ(received.size(), sent.size());
    for (std::size_t i = 0; i < sent.size(); ++i) {
        EXPECT_EQ(received[i].time, sent[i].time);
        for (std::size_t c = 0; c < sent[i].characters.size(); ++c) {
            EXPECT_EQ(received[i].characters[c].body, sent[i].characters[c].body) << "tick " << i;
            EXPECT_EQ(received[i].characters[c].face, sent[i].characters[c].face) << "tick " << i;
            EXPECT_EQ(received[i].characters[c].placement, sent[i].characters[c].placement) << "tick " << i;
        }
    }
    // Where each character stands travels with its pose (Antigone stands away from the origin).
    const auto& antigone = stage->runtime().characters[1];
    EXPECT_EQ(received.back().characters[1].placement, antigone.placement);
    EXPECT_NE(antigone.placement.translation, (core::anim::Vec3{}));
}

} // namespace
} // namespace thespis::test
