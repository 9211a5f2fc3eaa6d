// Speech on the face (core/speech/speech_plan.h, speak_job.h, core/edit/speech_edits.h): the
// demo's Creon says a line through the user's path — the speak job, Insert into the scenario,
// the runtime and the Stage — and the face is checked where a person would look: the lips shut
// on every p, b and m, each viseme's weight peaks on its phoneme, gestures span their words.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "edit/bml_edits.h"
#include "edit/speech_edits.h"
#include "runtime/sound.h"
#include "runtime/stage.h"
#include "scenario/scenario_io.h"
#include "scene/fap.h"
#include "speech/bml_plan.h"
#include "speech/speak_job.h"
#include "test_support.h"

namespace thespis::test {
namespace {

namespace speech = core::speech;
using core::scenario::Scenario;

Scenario demo()
{
    auto scenario = core::scenario::loadScenario(resources("demo.thespis"));
    EXPECT_TRUE(scenario) << core::describe(scenario.error());
    return scenario ? std::move(scenario).value() : Scenario{};
}

// Creon's gesticon gains a face gesture: his eyebrows raised (FAPs 31–36), held a second.
void addEyebrowGesture(Scenario& scenario)
{
    auto& creon = scenario.characters[0];
    core::scenario::ClipAsset clip;
    clip.name = "eyebrows up";
    clip.frameRate = 1;
    clip.scalars = {"fap31", "fap32", "fap33", "fap34", "fap35", "fap36"};
    clip.frames = {200, 200, 200, 200, 200, 200, 200, 200, 200, 200, 200, 200};
    creon.clips.push_back(clip);
    creon.gestures.push_back({.name = "raise_eyebrows", .clip = "eyebrows up", .fadeIn = core::secondsToTicks(0.1),
                              .fadeOut = core::secondsToTicks(0.1)});
}

speech::SpeakJob spoken(const std::string& text)
{
    speech::SpeakJob job;
    job.text = text;
    core::JobContext context;
    auto ran = job.run(context);
    EXPECT_TRUE(ran.ok()) << (ran.ok() ? "" : ran.error().message);
    return job;
}

core::scenario::SpeechLine lineOf(const speech::SpeakJob& job, double at)
{
    return core::edit::speechLine(job.text, job.voice, job.utterance.timing, "line.wav", core::secondsToTicks(at));
}

struct Played {
    Scenario scenario;
    std::shared_ptr<core::runtime::Stage> stage;
};

// Inserted as the studio's Insert does: gestures timed on the gesticon as built.
core::Result<core::edit::SpeechInsertion> insertedSpeech(const Scenario& scenario, const speech::SpeakJob& job, double at)
{
    auto runtime = core::scenario::buildRuntime(scenario, resources());
    if (!runtime)
        return runtime.error();
    return core::edit::insertSpeech(scenario, 0, lineOf(job, at), job.visemeCues, job.gestureBml, &*runtime);
}

Played insertedAndPlayed(Scenario scenario, const speech::SpeakJob& job, double at)
{
    auto inserted = insertedSpeech(scenario, job, at);
    EXPECT_TRUE(inserted.ok()) << (inserted.ok() ? "" : inserted.error().message);
    if (!inserted)
        return {};
    EXPECT_TRUE(inserted->edit.apply(scenario).ok());
    auto runtime = core::scenario::buildRuntime(scenario, resources());
    EXPECT_TRUE(runtime) << core::describe(runtime.error());
    return {scenario, std::make_shared<core::runtime::Stage>(std::move(runtime).value())};
}

std::vector<float> faceAt(core::runtime::Stage& stage, double seconds)
{
    core::runtime::PoseSet poses = stage.makePoseSet();
    stage.evaluate(core::secondsToTicks(seconds), poses);
    return poses.characters[0].face;
}

} // namespace

TEST(SpeechPlan, LipsShutOnEveryPBAndM)
{
    const double at = 1.0;
    const speech::SpeakJob job = spoken("Pop the bubble, Bob. Maybe mum may come by the mill.");
    Played played = insertedAndPlayed(demo(), job, at);
    ASSERT_TRUE(played.stage);
    int closures = 0;
    for (const speech::PhonemeTiming& p : job.utterance.timing.phonemes) {
        if (p.phoneme != "P" && p.phoneme != "B" && p.phoneme != "M")
            continue;
        const std::vector<float> face = faceAt(*played.stage, at + (p.start + p.end) / 2);
        const float closed = face[std::size_t(core::scene::visemeChannel(1))];
        for (int v = 2; v <= core::scene::kVisemeCount; ++v)
            EXPECT_GT(closed, face[std::size_t(core::scene::visemeChannel(v))])
                << p.phoneme << " at " << p.start << " s: viseme " << v << " dominates the closed lips";
        EXPECT_GT(closed, 0.6f) << p.phoneme << " at " << p.start << " s";
        ++closures;
    }
    EXPECT_GE(closures, 12);
    // Between sentences the mouth rests.
    const auto pause = std::find_if(job.utterance.timing.phonemes.begin(), job.utterance.timing.phonemes.end(),
                                    [](const auto& p) { return speech::isPause(p.phoneme) && p.end - p.start > 0.1 && p.start > 0; });
    ASSERT_NE(pause, job.utterance.timing.phonemes.end());
    const std::vector<float> rest = faceAt(*played.stage, at + (pause->start + pause->end) / 2);
    for (int v = 1; v <= core::scene::kVisemeCount; ++v)
        EXPECT_LT(rest[std::size_t(core::scene::visemeChannel(v))], 0.05f) << v;
}

TEST(SpeechPlan, EachVisemePeaksOnItsPhoneme)
{
    const double at = 0.5;
    const speech::SpeakJob job = spoken("Are you really sure about that?");
    Played played = insertedAndPlayed(demo(), job, at);
    const auto& layers = played.scenario.characters[0].layers;
    const auto layer = std::find_if(layers.begin(), layers.end(), [](const auto& l) { return l.name == "Speech"; });
    ASSERT_NE(layer, layers.end());
    ASSERT_EQ(layer->actions.size(), job.visemeCues.size());
    for (std::size_t i = 0; i < job.visemeCues.size(); ++i) {
        const speech::VisemeCue& cue = job.visemeCues[i];
        const auto& action = layer->actions[i];
        EXPECT_EQ(action.weight.kind(), core::anim::CurveKind::Dominance);
        // The action's weight over its stretched length, sampled every millisecond.
        const double start = core::ticksToSeconds(action.start), duration = action.modifiers.at(0).factor;
        double best = -1, peak = 0;
        for (double t = 0; t <= duration; t += 0.001)
            if (const double w = action.weight.evaluate(t, duration); w > best) {
                best = w;
                peak = start + t;
            }
        const speech::PhonemeTiming& p = job.utterance.timing.phonemes[std::size_t(cue.phonemeIndex)];
        EXPECT_NEAR(peak, at + (p.start + p.end) / 2, 0.020) << p.phoneme;
    }
}

TEST(SpeechPlan, AGestureSpansItsWordsAndMovesTheBrows)
{
    Scenario scenario = demo();
    addEyebrowGesture(scenario);
    const speech::SpeakJob job = spoken(
        R"(Are you <begin_gesture id="g1" anim="raise_eyebrows"/>really sure<end_gesture id="g1"/> about that?)");
    ASSERT_EQ(job.gestureCues.size(), 1u);
    const auto& words = job.utterance.timing.words;
    ASSERT_EQ(words.size(), 6u);
    EXPECT_EQ(job.gestureCues[0].start, words[2].start);
    EXPECT_EQ(job.gestureCues[0].end, words[3].end);

    Played played = insertedAndPlayed(scenario, job, 0);
    const int brow = core::scene::fapChannel(31);
    const double middle = (words[2].start + words[3].end) / 2;
    EXPECT_GT(faceAt(*played.stage, middle)[std::size_t(brow)], 190.0f) << "the brows are raised on 'really sure'";
    EXPECT_LT(std::abs(faceAt(*played.stage, words[5].end + 0.3)[std::size_t(brow)]), 1.0f) << "and down after";
}

TEST(SpeechPlan, UnknownGesturesAreNamedWithTheirPlace)
{
    const speech::SpeakJob job = spoken("Hello <begin_gesture id=\"g\" anim=\"juggle\"/>there<end_gesture id=\"g\"/>.");
    Scenario scenario = demo();
    auto refused = insertedSpeech(scenario, job, 0);
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.error().message, "line 1, column 7: gesture \"g\": the gesticon has no gesture \"juggle\" the "
                                       "character can play (it has: greet, agree, point).");
}

TEST(SpeechPlan, InsertIsOneStepThatUndoes)
{
    Scenario scenario = demo();
    const Scenario before = scenario;
    const speech::SpeakJob job = spoken("Maybe.");
    auto inserted = insertedSpeech(scenario, job, 2);
    ASSERT_TRUE(inserted.ok()) << inserted.error().message;
    ASSERT_TRUE(inserted->edit.apply(scenario).ok());
    EXPECT_NE(scenario, before);
    EXPECT_TRUE(scenario.findMask("Speech"));
    EXPECT_TRUE(scenario.characters[0].findClip("viseme p_b_m"));
    ASSERT_EQ(scenario.characters[0].speech.size(), before.characters[0].speech.size() + 1);
    EXPECT_EQ(scenario.characters[0].speech.back().text, "Maybe.");
    EXPECT_EQ(scenario.characters[0].speech.back().words.size(), 1u);
    ASSERT_EQ(inserted->edit.changes().size(), 2u) << "the Speech mask and the character";
    // The scenario reads back as written.
    auto reread = core::scenario::parseScenario(core::scenario::serializeScenario(scenario));
    ASSERT_TRUE(reread.ok()) << reread.error().message;
    EXPECT_EQ(*reread, scenario);
    ASSERT_TRUE(inserted->edit.inverse().apply(scenario).ok());
    EXPECT_EQ(scenario, before);
}

TEST(SpeakJob, SentencesAreSpokenInTurnAndTheWavHoldsThemAll)
{
    speech::SpeakJob job;
    job.text = "First sentence.  Second one! And a third?";
    job.wavOutput = artifact("speak_job.wav");
    std::vector<double> ready;
    job.sentenceReady = [&](const speech::Utterance& soFar) { ready.push_back(soFar.duration()); };
    core::JobContext context;
    ASSERT_TRUE(job.run(context).ok());
    ASSERT_EQ(ready.size(), 3u);
    EXPECT_LT(ready[0], ready[1]);
    EXPECT_DOUBLE_EQ(ready[2], job.utterance.duration());
    EXPECT_EQ(job.utterance.timing.words.size(), 7u);
    EXPECT_EQ(job.utterance.timing.words[2].text, "Second");
    EXPECT_GT(job.utterance.timing.words[2].start, ready[0] - 1e-9);
    auto wav = core::runtime::loadSound(job.wavOutput);
    ASSERT_TRUE(wav.ok()) << wav.error().message;
    EXPECT_EQ((*wav)->rate, 22050);
    EXPECT_EQ((*wav)->samples.size(), job.utterance.samples.size());
    EXPECT_NEAR(job.utterance.timing.phonemes.back().end, (*wav)->duration(), 0.020);
}

TEST(SpeakJob, CancelLeavesNoFile)
{
    speech::SpeakJob job;
    job.text = "One. Two. Three.";
    job.wavOutput = artifact("speak_job_cancelled.wav");
    std::filesystem::remove(job.wavOutput);
    std::stop_source stop;
    job.sentenceReady = [&](const speech::Utterance&) { stop.request_stop(); };
    core::JobContext context(stop.get_token());
    auto ran = job.run(context);
    ASSERT_FALSE(ran.ok());
    EXPECT_EQ(ran.error().code, core::ErrorCode::Cancelled);
    EXPECT_FALSE(std::filesystem::exists(job.wavOutput));
}

TEST(SpeakJob, BadTagsAreRefusedBeforeSpeaking)
{
    speech::SpeakJob job;
    job.text = "Hello\n<begin_gesture id=\"g\"/>there";
    auto valid = job.validate();
    ASSERT_FALSE(valid.ok());
    EXPECT_NE(valid.error().message.find("line 2, column 1"), std::string::npos) << valid.error().message;
}

TEST(SpeakJob, SentenceRanges)
{
    const std::string text = "Mr. Smith said \"Hi!\" Then (he left.) 3.5 apples? Yes";
    std::vector<std::string> sentences;
    for (auto [b, e] : speech::sentenceRanges(text))
        sentences.push_back(text.substr(b, e - b));
    EXPECT_EQ(sentences, (std::vector<std::string>{"Mr.", "Smith said \"Hi!\"", "Then (he left.)", "3.5 apples?", "Yes"}));
}

TEST(SpeechPlan, WideSpreadsStayInsideTheUtterance)
{
    // Found by fuzz_viseme_set: a spread of 1.5 reached past the end of the audio.
    speech::VisemeSet set = speech::mpeg4Visemes();
    for (speech::Viseme& v : set.visemes)
        v.spread = 2.0;
    speech::SpeechTiming timing;
    timing.phonemes = {{"M", 0.0, 0.1, 0}, {"AA", 0.1, 0.3, 0}, {"M", 0.3, 0.4, 0}};
    timing.duration = 0.4;
    const auto cues = speech::visemeCues(timing, set);
    ASSERT_EQ(cues.size(), 3u);
    for (const speech::VisemeCue& cue : cues) {
        EXPECT_GE(cue.start, 0.0);
        EXPECT_LE(cue.start + cue.duration, timing.duration + 1e-12) << cue.phoneme;
        EXPECT_NEAR(cue.start + cue.duration / 2, cue.centre, 1e-12) << "the peak stays on " << cue.phoneme;
    }
    EXPECT_NEAR(cues[1].duration, 0.2 + 2 * 0.1, 1e-12); // the vowel reaches as far as both ends allow
}

} // namespace thespis::test

namespace thespis::test {
namespace {

double warpAt(const speech::GestureFit& fit, double local)
{
    return core::anim::Curve::keyframed(fit.warp).value().evaluate(local, fit.duration);
}

} // namespace

TEST(GestureFit, EspeakStressesContentWordsNotArticles)
{
    const speech::SpeakJob job = spoken("The old man sat on a bench.");
    const auto stressed = [&](const std::string& text) {
        for (const speech::WordTiming& w : job.utterance.timing.words)
            if (w.text == text)
                return w.stressed;
        ADD_FAILURE() << "espeak-ng said no word \"" << text << "\"";
        return false;
    };
    EXPECT_FALSE(stressed("The"));
    EXPECT_TRUE(stressed("old"));
    EXPECT_TRUE(stressed("man"));
    EXPECT_TRUE(stressed("sat"));
    EXPECT_TRUE(stressed("bench"));
}

// Tagged text's gestures planned as BML's are (speech/tagged_bml.h, bml_plan.h), on a gesticon of
// one entry named `name`.
speech::BmlPlanned plannedTag(const speech::SpeakJob& job, const std::string& name, const speech::BmlGestureEntry& entry)
{
    const speech::BmlGesticon gesticon{{name}, [&](const std::string& n) {
        return n == name ? std::optional(entry) : std::nullopt;
    }};
    auto plan = speech::planBml(job.gestureBml.block, job.gestureBml.speech, gesticon, speech::BmlLexicon::defaults());
    EXPECT_TRUE(plan) << plan.error().message;
    return plan && plan->behaviors.size() == 2 ? plan->behaviors[1] : speech::BmlPlanned{};
}

TEST(GestureFit, AMarkedStrokeFallsOnTheFirstStressedWordOfItsWords)
{
    const speech::SpeakJob job =
        spoken("Look at <begin_gesture id=\"g1\" anim=\"point\"/>the old bench<end_gesture id=\"g1\"/> there.");
    const auto& words = job.utterance.timing.words;
    ASSERT_EQ(words[2].text, "the");
    ASSERT_EQ(words[4].text, "bench");
    ASSERT_FALSE(words[2].stressed);
    ASSERT_TRUE(words[3].stressed);

    // A 1.2 s pointing gesture with its stroke 0.8 s in: the stroke lands on "old"; both sides scaled.
    const speech::BmlPlanned planned = plannedTag(job, "point", {1.2, 0.3, 0.3, {.hold = false, .stroke = 0.8}});
    const speech::GestureFit& fit = planned.fit;
    EXPECT_NEAR(fit.start, words[2].start - 0.3, 1e-9) << "its fade-in ends as its first word starts";
    EXPECT_NEAR(fit.start + fit.duration, words[4].end + 0.3, 1e-9) << "its fade-out starts as its last word ends";
    ASSERT_FALSE(fit.warp.empty());
    EXPECT_NEAR(warpAt(fit, words[3].start - fit.start), 0.8, 1e-6) << "\"old\", not \"the\"";
    EXPECT_NEAR(warpAt(fit, 0), 0.0, 1e-9);
    EXPECT_NEAR(warpAt(fit, fit.duration), 1.2, 1e-6);
    for (double t = 0.01; t <= fit.duration; t += 0.01)
        EXPECT_GE(warpAt(fit, t), warpAt(fit, t - 0.01) - 1e-9) << "time never runs back, at " << t;
    // Without a mark the gesture is only stretched.
    const speech::BmlPlanned stretched = plannedTag(job, "point", {1.2, 0.3, 0.3, {}});
    EXPECT_TRUE(stretched.fit.warp.empty());
    EXPECT_NEAR(stretched.fit.stretch, stretched.fit.duration / 1.2, 1e-9);
}

// One planner for tags and BML (issue 33): a tagged gesture and the same gesture written as BML —
// ready as its first word starts, stroke on its stressed word, relax as its last word ends — become
// the same action on the timeline, stroke and fades included.
TEST(GestureFit, TaggedTextAndTheSameBmlInsertTheSameGesture)
{
    Scenario scenario = demo();
    auto& gestures = scenario.characters[0].gestures;
    const auto greet = std::find_if(gestures.begin(), gestures.end(), [](const auto& g) { return g.name == "greet"; });
    ASSERT_NE(greet, gestures.end());
    greet->stroke = 0.5; // so that where the stroke goes counts too
    auto runtime = core::scenario::buildRuntime(scenario, resources());
    ASSERT_TRUE(runtime) << core::describe(runtime.error());
    const speech::SpeakJob tagged =
        spoken("Look at <begin_gesture id=\"g1\" anim=\"greet\"/>the old bench<end_gesture id=\"g1\"/> there.");
    // The same words as BML, said alike (the tagged text's utterance, so that only planning differs).
    const auto bml = speech::parseBml(
        R"(<bml id="b"><speech id="s1"><text>Look at <sync id="a"/>the <sync id="old"/>old bench<sync id="z"/> there.</text>)"
        R"(</speech><gesture id="g1" name="greet" ready="s1:a" stroke="s1:old" relax="s1:z"/></bml>)");
    ASSERT_TRUE(bml) << bml.error().message;
    ASSERT_EQ(bml->behaviors[0].text, tagged.tagged.text);
    const std::map<std::string, speech::Utterance> said{{"s1", tagged.utterance}};

    const auto gestureAction = [](const Scenario& before, const core::edit::Edit& edit) {
        Scenario after = before;
        EXPECT_TRUE(edit.apply(after).ok());
        const auto& layers = after.characters[0].layers;
        const auto layer = std::find_if(layers.begin(), layers.end(), [](const auto& l) { return l.name == "Gestures"; });
        EXPECT_NE(layer, layers.end());
        return layer == layers.end() || layer->actions.empty() ? core::scenario::ActionSpec{} : layer->actions.back();
    };
    auto fromTags = core::edit::insertSpeech(scenario, 0, lineOf(tagged, 1.0), tagged.visemeCues, tagged.gestureBml, &*runtime);
    ASSERT_TRUE(fromTags) << fromTags.error().message;
    const core::edit::BmlInsertOptions options;
    auto fromBml = core::edit::insertBml(scenario, *runtime, 0, *bml, said, options, core::secondsToTicks(1.0));
    ASSERT_TRUE(fromBml) << fromBml.error().message;
    const core::scenario::ActionSpec a = gestureAction(scenario, fromTags->edit), b = gestureAction(scenario, fromBml->edit);
    EXPECT_EQ(a.name, "g1 greet");
    EXPECT_EQ(a, b);
    ASSERT_FALSE(a.modifiers.empty());
    EXPECT_EQ(a.modifiers.front().kind, core::scenario::ModifierKind::TimeWarp) << "its stroke kept on \"old\"";
}

TEST(GestureFit, AHoldingGesturePlaysAtItsOwnSpeedAndHoldsItsStroke)
{
    // Three seconds of words (1 … 4 s) for a one-second gesture with 0.2 s fades, stroke on its first word.
    const speech::GestureSpan span{0.8, 4.2, 1.0};
    const speech::GestureFit fit = speech::fitGesture(span, 1.0, {.hold = true, .stroke = 0.4});
    EXPECT_NEAR(fit.start, 0.8, 1e-9);
    EXPECT_NEAR(fit.duration, 3.4, 1e-9);
    // Into the stroke at its own speed (it was at 0.4 s on its first word), held, then out at its own speed.
    EXPECT_NEAR(warpAt(fit, span.stroke - fit.start), 0.4, 1e-6);
    EXPECT_NEAR(warpAt(fit, 2.0), 0.4, 1e-6);
    EXPECT_NEAR(warpAt(fit, fit.duration - 0.6), 0.4, 1e-6);
    EXPECT_NEAR(warpAt(fit, fit.duration), 1.0, 1e-6);
    EXPECT_NEAR(warpAt(fit, fit.duration - 0.3) , 0.7, 0.08) << "the way out at about its own speed";
    // Stretched instead, the same gesture plays three times slower.
    EXPECT_NEAR(speech::fitGesture(span, 1.0).stretch, 3.4, 1e-9);
}

TEST(GestureFit, AnInsertedHoldingGestureHoldsOnTheTimeline)
{
    Scenario scenario = demo();
    auto& creon = scenario.characters[0];
    auto greet = std::find_if(creon.gestures.begin(), creon.gestures.end(), [](const auto& g) { return g.name == "greet"; });
    ASSERT_NE(greet, creon.gestures.end());
    greet->hold = true;
    greet->stroke = 0.5;
    const speech::SpeakJob job = spoken(
        "<begin_gesture id=\"g1\" anim=\"greet\"/>Welcome, all of you, to the old palace of Thebes.<end_gesture id=\"g1\"/>");
    auto inserted = insertedSpeech(scenario, job, 1.0);
    ASSERT_TRUE(inserted) << inserted.error().message;
    Scenario after = scenario;
    ASSERT_TRUE(inserted->edit.apply(after));
    const auto& layers = after.characters[0].layers;
    const auto gestures = std::find_if(layers.begin(), layers.end(), [](const auto& l) { return l.name == "Gestures"; });
    ASSERT_NE(gestures, layers.end());
    const core::scenario::ActionSpec& action = gestures->actions.back();
    ASSERT_FALSE(action.modifiers.empty());
    EXPECT_EQ(action.modifiers.front().kind, core::scenario::ModifierKind::TimeWarp);
    auto built = core::scenario::buildRuntime(after, resources());
    ASSERT_TRUE(built) << core::describe(built.error());
}

} // namespace thespis::test

namespace thespis::test {

// Real motion capture as a tagged gesture: CMU 141_16 ("wave hello", 2.5 s at 120 fps) is Creon's
// gesture "hello" on his right arm. Tagged over five words, it is fitted to them — fading in before
// the first and out after the last, its recording stretched to fill that — and his right wrist
// waves while they are said. (A gesture whose clip was a file was once inserted unfitted.)
TEST(GestureFit, AMotionCaptureGestureIsFittedToItsWords)
{
    Scenario scenario = demo();
    auto& creon = scenario.characters[0];
    core::scenario::ClipAsset wave;
    wave.name = "cmu wave hello";
    wave.file = sharedData("mocap/cmu/141_16.bvh").string();
    creon.clips.push_back(wave);
    const double fade = 0.3;
    creon.gestures.push_back({.name = "hello", .clip = wave.name, .mask = "rightArm",
                              .fadeIn = core::secondsToTicks(fade), .fadeOut = core::secondsToTicks(fade)});
    const speech::SpeakJob job = spoken(
        "Well then, <begin_gesture id=\"w\" anim=\"hello\"/>good morning to you all<end_gesture id=\"w\"/>, friends.");
    ASSERT_EQ(job.gestureCues.size(), 1u);
    const speech::GestureCue& words = job.gestureCues[0];
    const double at = 1.0, frame = 1.0 / 60;

    Played played = insertedAndPlayed(scenario, job, at);
    ASSERT_TRUE(played.stage);
    const std::string name = creon.name;
    const auto end = played.stage->actionEnd(name, core::runtime::Track::Body, "w hello");
    ASSERT_TRUE(end) << end.error().message;
    EXPECT_NEAR(*end, at + words.end + fade, frame) << "it fades out after its last word";
    const auto& layers = played.scenario.characters[0].layers;
    const auto gestures = std::find_if(layers.begin(), layers.end(), [](const auto& l) { return l.name == "Gestures"; });
    ASSERT_NE(gestures, layers.end());
    ASSERT_EQ(gestures->actions.size(), 1u);
    EXPECT_NEAR(core::ticksToSeconds(gestures->actions[0].start), at + words.start - fade, frame)
        << "it fades in before its first word";
    EXPECT_FALSE(*played.stage->isPlaying(name, core::runtime::Track::Body, "w hello",
                                          core::secondsToTicks(at + words.start - fade - frame)));

    // The right wrist waves while the words are said; the left one is left alone.
    auto alone = core::scenario::buildRuntime(scenario, resources());
    ASSERT_TRUE(alone) << core::describe(alone.error());
    core::runtime::Stage still(std::move(alone).value());
    const auto& skeleton = played.stage->runtime().characters[0].skeleton;
    const auto wrist = [&](core::runtime::Stage& stage, double t, const char* joint) {
        core::runtime::PoseSet poses = stage.makePoseSet();
        stage.evaluate(core::secondsToTicks(t), poses);
        return skeleton.worldPositions(poses.characters[0].body)[std::size_t(skeleton.find(joint))];
    };
    ASSERT_GE(skeleton.find("r_radiocarpal"), 0);
    ASSERT_GE(skeleton.find("l_radiocarpal"), 0);
    double right = 0, left = 0;
    for (double t = at + words.start; t <= at + words.end; t += 0.1) {
        const auto moved = [&](const char* joint) {
            const auto a = wrist(*played.stage, t, joint), b = wrist(still, t, joint);
            return std::sqrt(core::anim::dot(a - b, a - b));
        };
        right = std::max(right, moved("r_radiocarpal"));
        left = std::max(left, moved("l_radiocarpal"));
    }
    EXPECT_GT(right, 0.10) << "metres: the right hand waves";
    EXPECT_LT(left, 0.02) << "metres: the left hand stays";
}

} // namespace thespis::test
