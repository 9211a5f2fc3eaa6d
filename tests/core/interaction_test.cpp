// The interaction service (runtime/interaction_service.h, paper §5.3) on the demo's stage: a
// script plays Antigone's idle motion, then hands her to a conversation with the bot the demo
// ships (resources/dialogue/antigone) — the motion goes on without a jump, and her answers are
// spoken with her lips, her nod on the tagged words and her eyes on the visitor. And the bot's
// own grammar (dialogue/bot_grammar.h): what espeak-ng says of its patterns in two voices is
// heard, and Rosie's every pattern is a sentence of hers.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "dialogue/bot_grammar.h"
#include "listening_source.h"
#include "runtime/clock.h"
#include "runtime/interaction_service.h"
#include "runtime/sound.h"
#include "scenario/open_scenario.h"
#include "scene/fap.h"
#include "speech/espeak_voice.h"
#include "speech/jsgf.h"
#include "speech/resample.h"
#include "test_support.h"
#include "util/text.h"

namespace thespis::test {
namespace {

namespace dialogue = core::dialogue;
namespace runtime = core::runtime;
namespace speech = core::speech;
using core::secondsToTicks;

constexpr double kFrame = 1.0 / 60;
constexpr double kDegree = std::numbers::pi / 180;

std::shared_ptr<const dialogue::Bot> antigoneBot()
{
    auto loaded = dialogue::loadBotFolder(resources("dialogue/antigone"));
    EXPECT_TRUE(loaded) << core::describe(loaded.error());
    if (!loaded)
        return nullptr;
    EXPECT_TRUE(loaded->problems.empty()) << dialogue::describe(loaded->problems.front());
    return loaded->bot;
}

class InteractionTest : public ::testing::Test {
protected:
    void SetUp() override
    {
        auto opened = core::scenario::openScenario(resources("demo.thespis"));
        ASSERT_TRUE(opened) << core::describe(opened.error());
        auto built = core::scenario::buildRuntime(opened->scenario, opened->assets);
        ASSERT_TRUE(built) << core::describe(built.error());
        stage = std::make_shared<runtime::Stage>(std::move(built).value());
        clock = std::make_shared<runtime::ManualClock>();
        sound = std::make_shared<runtime::SoundService>(opened->assets, clock);
        service = std::make_unique<runtime::InteractionService>(stage, sound);
        poses = stage->makePoseSet();
        antigone = stage->findCharacter("Antigone");
        ASSERT_GE(antigone, 0);
        auto skeleton = stage->skeleton("Antigone");
        ASSERT_TRUE(skeleton);
        joints = skeleton->jointCount();
        // The visitor: a camera in front of the two, at eye height.
        stage->setCameraPosition(core::anim::Vec3d{0.3, 1.6, 3});
        bot = antigoneBot();
        ASSERT_TRUE(bot);
    }

    // Plays on from the last frame to `until` a frame at a time; the fastest any of Antigone's
    // joints turns in each frame (degrees a second) goes to `speeds`, the face to `faces`.
    void playTo(double until)
    {
        const double from = times.empty() ? 0.0 : times.back() + kFrame;
        for (double t = from; t <= until + 1e-9; t += kFrame) {
            clock->setTime(secondsToTicks(t));
            stage->evaluate(secondsToTicks(t), poses);
            const std::vector<float>& body = poses.characters[std::size_t(antigone)].body;
            double fastest = 0;
            if (!last.empty())
                for (int j = 0; j < joints; ++j) {
                    const core::anim::Quat& a = core::anim::rotationAt(std::span<const float>(last), j);
                    const core::anim::Quat& b = core::anim::rotationAt(std::span<const float>(body), j);
                    fastest = std::max(fastest, double(core::anim::angleBetween(a, b)) / kDegree / kFrame);
                }
            last = body;
            times.push_back(t);
            speeds.push_back(fastest);
            faces.push_back(poses.characters[std::size_t(antigone)].face);
        }
    }
    double fastestBetween(double from, double to) const
    {
        double fastest = 0;
        for (std::size_t i = 1; i < times.size(); ++i)
            if (times[i] >= from && times[i] <= to)
                fastest = std::max(fastest, speeds[i]);
        return fastest;
    }

    std::shared_ptr<runtime::Stage> stage;
    std::shared_ptr<runtime::ManualClock> clock;
    std::shared_ptr<runtime::SoundService> sound;
    std::unique_ptr<runtime::InteractionService> service;
    std::shared_ptr<const dialogue::Bot> bot;
    runtime::PoseSet poses;
    int antigone = -1, joints = 0;
    std::vector<float> last;
    std::vector<double> times, speeds;
    std::vector<std::vector<float>> faces;
};

TEST_F(InteractionTest, TheScriptHandsOverToConversationWithoutAJump)
{
    // The script: her idle motion from the start.
    ASSERT_TRUE(stage->activateAction("Antigone", runtime::Track::Body, "antigone_idle", 0));
    playTo(3);
    // Handed over at 3 s; the visitor asks at 3.5 s, and she answers with her nod.
    ASSERT_TRUE(service->converse("Antigone", bot));
    EXPECT_TRUE(service->conversing("Antigone"));
    playTo(3.5);
    auto exchange = service->hear("Antigone", "Why did you bury him?");
    ASSERT_TRUE(exchange) << core::describe(exchange.error());
    EXPECT_TRUE(exchange->warnings.empty()) << exchange->warnings.front();
    EXPECT_NE(exchange->answer.text.find("laws of the gods"), std::string::npos) << exchange->answer.text;
    ASSERT_FALSE(exchange->answer.matched.empty());
    EXPECT_NE(exchange->answer.matched.back().source.file.find("antigone.aiml"), std::string::npos);
    EXPECT_NEAR(exchange->start, 3.5, 1e-6);
    EXPECT_GT(exchange->end, exchange->start + 2) << "a sentence of a dozen words";
    playTo(exchange->end + 1);

    // No joint jumps at the hand-over or as the answer starts: nothing turns faster than a
    // head turning toward the visitor may (200°/s, motion/gaze.h) plus the idle motion's own.
    const double idle = fastestBetween(0.5, 3);
    EXPECT_GT(idle, 0.5) << "the idle motion plays";
    const double handOver = fastestBetween(3, exchange->end + 1);
    EXPECT_LT(handOver, 200 + 2 * idle) << "degrees a second; the idle motion's fastest was " << idle;
    // Still the idle motion under the conversation.
    EXPECT_GT(fastestBetween(exchange->end, exchange->end + 1), 0.5 * idle);

    // Her lips move while she answers, and not before.
    const auto mouth = [&](std::size_t i) {
        float open = 0;
        for (int v = 1; v <= 14; ++v)
            open = std::max(open, faces[i][std::size_t(core::scene::visemeChannel(v))]);
        return open;
    };
    float before = 0, during = 0;
    for (std::size_t i = 0; i < times.size(); ++i) {
        if (times[i] < exchange->start)
            before = std::max(before, mouth(i));
        else if (times[i] < exchange->end)
            during = std::max(during, mouth(i));
    }
    EXPECT_EQ(before, 0.f);
    EXPECT_GT(during, 0.5f);

    // Her eyes are on the visitor: the gaze settled toward the camera.
    auto gaze = stage->gazeState("Antigone");
    ASSERT_TRUE(gaze);
    ASSERT_TRUE(gaze->has_value()) << "she looks at the visitor while conversing";
    EXPECT_FALSE((*gaze)->shifting);

    // Given back to the script: she lets go of the visitor, the idle motion goes on.
    EXPECT_TRUE(service->handBack("Antigone"));
    EXPECT_FALSE(service->conversing("Antigone"));
    EXPECT_FALSE(service->hear("Antigone", "hello"));
    const double back = times.back();
    playTo(back + 3);
    EXPECT_FALSE(*stage->gazeState("Antigone"));
    EXPECT_LT(fastestBetween(back, back + 3), 200 + 2 * idle);
}

TEST_F(InteractionTest, WhatWasNotUnderstoodIsAnsweredByItsCategoryAndTheStateCarriesOver)
{
    ASSERT_TRUE(service->converse("Antigone", bot, {.speak = false}));
    speech::Recognition rejected;
    rejected.text = "who is creon";
    rejected.confidence = -3;
    auto exchange = service->hear("Antigone", rejected);
    ASSERT_TRUE(exchange);
    EXPECT_FALSE(exchange->understood);
    EXPECT_TRUE(exchange->heard.empty());
    ASSERT_FALSE(exchange->answer.matched.empty());
    EXPECT_EQ(exchange->answer.matched.back().pattern, dialogue::kNotUnderstood);
    EXPECT_EQ(exchange->start, exchange->end) << "not spoken";

    ASSERT_TRUE(service->hear("Antigone", "My name is Ada"));
    auto saved = service->saveState("Antigone");
    ASSERT_TRUE(saved);
    ASSERT_TRUE(service->handBack("Antigone"));
    ASSERT_TRUE(service->converse("Antigone", bot, {.speak = false}, *saved));
    auto named = service->hear("Antigone", "What is my name?");
    ASSERT_TRUE(named);
    EXPECT_EQ(named->answer.text, "You are Ada.");
    ASSERT_TRUE(service->transcript("Antigone"));
    EXPECT_EQ(service->transcript("Antigone")->size(), 1u) << "a new visit's transcript";

    EXPECT_FALSE(service->converse("Nobody", bot));
    EXPECT_FALSE(service->converse("Antigone", bot, {.speak = false}, "{\"format\": \"something else\"}"));
}

TEST(BotGrammar, WhatTheDemoBotCanAnswerIsHeardInTwoVoices)
{
    const auto bot = antigoneBot();
    ASSERT_TRUE(bot);
    const dialogue::GrammarSource source = dialogue::grammarSourceOf(*bot);
    auto recogniser = dialogue::listenFor(*bot);
    ASSERT_TRUE(recogniser) << core::describe(recogniser.error());
    int sentences = 0, exact = 0;
    for (const speech::VoiceSettings& voice : {speech::VoiceSettings{"en-us", 160}, speech::VoiceSettings{"gmw/en", 150}})
        for (const auto& pattern : source.patterns) {
            const std::string said = core::joined(literalForm(source, pattern, "creon"));
            auto utterance = speech::speak(said, voice);
            ASSERT_TRUE(utterance) << core::describe(utterance.error());
            auto heard = recogniser->recognise(
                speech::dithered16(speech::resampled(utterance->samples, utterance->rate, speech::kSphinxRate)));
            ASSERT_TRUE(heard) << core::describe(heard.error());
            ++sentences;
            exact += heard->text == said;
            if (heard->text != said)
                std::cout << voice.voice << ": \"" << said << "\" heard as \"" << heard->text << "\"\n";
        }
    std::cout << exact << " of " << sentences << " heard exactly\n";
    EXPECT_GE(sentences, 60);
    // Issue 34 asks for 90 %: 61 of 66 with the wildcards' words weighted 0.01 against the
    // patterns' own, 52 when they weigh as much (the loops of "hello *" hear words not said).
    EXPECT_GE(double(exact) / sentences, 0.9);
}

TEST(BotGrammar, EveryPatternOfRosieIsASentenceOfHerGrammar)
{
    auto loaded = dialogue::loadBotFolder(sharedData("dialogue/rosie"));
    ASSERT_TRUE(loaded) << core::describe(loaded.error());
    const dialogue::GrammarSource source = dialogue::grammarSourceOf(*loaded->bot);
    EXPECT_GT(source.patterns.size(), 10000u);
    auto grammar = dialogue::makeListeningGrammar(source);
    ASSERT_TRUE(grammar) << core::describe(grammar.error());
    auto parsed = speech::parseJsgf(grammar->jsgf);
    ASSERT_TRUE(parsed) << core::describe(parsed.error());
    auto set = speech::resolveJsgf(std::move(*parsed), {});
    ASSERT_TRUE(set) << core::describe(set.error());
    std::size_t accepted = 0, checked = 0;
    const speech::WordGraphWalker graph(grammar->graph);
    for (const auto& pattern : source.patterns) {
        const std::vector<std::string> words = literalForm(source, pattern, grammar->wildcardWords.front());
        if (words.empty())
            continue;
        ++checked;
        accepted += set->accepts(words) && graph.accepts(words);
    }
    EXPECT_EQ(accepted, checked);
    // What the recogniser listens with stays small: pocketsphinx's own compilation of the JSGF
    // makes some 17 million arcs of it.
    std::cout << "Rosie's word graph: " << grammar->graph.states << " states, " << grammar->graph.wordArcs() << " word arcs\n";
    EXPECT_LT(grammar->graph.wordArcs(), 400000u);
    EXPECT_EQ(checked + grammar->patternsSkipped, source.patterns.size());
}

TEST(BotGrammar, RosieListensWithHerWholeGrammar)
{
    // The whole of a real bot: pocketsphinx compiles her JSGF into some 17 million arcs in 14
    // minutes; her word graph opens in seconds. What she hears is a sentence of it, each word as
    // the grammar spells it (not as one of its pronunciations, "word(2)").
    auto loaded = dialogue::loadBotFolder(sharedData("dialogue/rosie"));
    ASSERT_TRUE(loaded) << core::describe(loaded.error());
    const dialogue::GrammarSource source = dialogue::grammarSourceOf(*loaded->bot);
    auto grammar = dialogue::makeListeningGrammar(source);
    ASSERT_TRUE(grammar) << core::describe(grammar.error());
    auto recogniser = dialogue::listenFor(*loaded->bot);
    ASSERT_TRUE(recogniser) << core::describe(recogniser.error());
    const speech::WordGraphWalker graph(grammar->graph);
    int heardSomething = 0;
    for (const char* said : {"tongue thruster", "what does a dog say", "open maps"}) {
        auto utterance = speech::speak(said, {"en-us", 160});
        ASSERT_TRUE(utterance) << core::describe(utterance.error());
        auto heard = recogniser->recognise(speech::dithered16(speech::resampled(utterance->samples, utterance->rate, speech::kSphinxRate)));
        ASSERT_TRUE(heard) << core::describe(heard.error());
        std::cout << "\"" << said << "\" heard as \"" << heard->text << "\", confidence " << heard->confidence << "\n";
        if (heard->text.empty())
            continue;
        ++heardSomething;
        std::vector<std::string> words;
        for (const speech::HeardWord& word : heard->words)
            words.push_back(word.word);
        EXPECT_TRUE(graph.accepts(words)) << heard->text;
    }
    EXPECT_GE(heardSomething, 2);
}

} // namespace
} // namespace thespis::test
