// The visitor stops speaking → the character's first sound and viseme (paper §5.3; issue 34's
// goal ≤ 300 ms): the demo's Antigone converses with her bot (resources/dialogue/antigone) on the
// demo's Stage, a new visit each time (so that her answer's speech is synthesised, not found
// again). The visitor's "who is creon" (espeak-ng, 16 kHz) is fed to the recogniser in 100 ms
// blocks as it is spoken (not timed); timed from the last block: the recogniser's finish (the
// grammar and its phone loop), the answer from the bot, its speech synthesised and put on the
// Stage with its visemes and gestures (InteractionService::hear), and the Stage evaluated at the
// answer's start — the first frame that shows it, whose sound starts with it.
#include <benchmark/benchmark.h>

#include "dialogue/bot.h"
#include "dialogue/bot_grammar.h"
#include "runtime/clock.h"
#include "runtime/interaction_service.h"
#include "scenario/scenario_io.h"
#include "speech/espeak_voice.h"
#include "speech/resample.h"

using namespace thespis::core;

namespace {

void AnswerLatency(benchmark::State& state)
{
    const std::filesystem::path resources(THESPIS_RESOURCES);
    auto scenario = scenario::loadScenario(resources / "demo.thespis");
    auto built = scenario ? scenario::buildRuntime(*scenario, resources) : Result<scenario::ScenarioRuntime>(scenario.error());
    auto bot = dialogue::loadBot(std::vector<std::filesystem::path>{resources / "dialogue/antigone/antigone.aiml"});
    // espeak-ng's voice scores lower against the free phone loop than people do (about −2 here,
    // the real recordings of the tests −0.05 to −0.5): the bench lets it through to the answer.
    speech::RecogniserOptions recognising;
    recognising.rejectBelow = -3;
    auto recogniser = bot ? dialogue::listenFor(*bot->bot, {}, recognising) : Result<speech::GrammarRecogniser>(bot.error());
    auto question = speech::speak("who is creon", {"en-us", 160});
    if (!built || !recogniser || !question) {
        state.SkipWithError("the demo, its bot or espeak-ng is missing");
        return;
    }
    const std::vector<std::int16_t> heard =
        speech::dithered16(speech::resampled(question->samples, question->rate, speech::kSphinxRate));
    auto stage = std::make_shared<runtime::Stage>(std::move(built).value());
    auto clock = std::make_shared<runtime::ManualClock>();
    runtime::PoseSet poses = stage->makePoseSet();
    constexpr std::size_t kBlock = speech::kSphinxRate / 10;
    double t = 1;
    int understood = 0;
    for (auto _ : state) {
        state.PauseTiming();
        clock->setTime(secondsToTicks(t));
        // A new visit each time: the sound service keeps what it synthesised, and the answer's
        // speech is to be made, as the first time it is said.
        auto sound = std::make_shared<runtime::SoundService>(resources, clock);
        runtime::InteractionService service(stage, sound);
        if (auto ok = service.converse("Antigone", bot->bot); !ok) {
            state.SkipWithError(ok.error().message.c_str());
            return;
        }
        bool fed = bool(recogniser->start());
        for (std::size_t at = 0; fed && at < heard.size(); at += kBlock)
            fed = bool(recogniser->feed(std::span(heard).subspan(at, std::min(kBlock, heard.size() - at))));
        state.ResumeTiming();
        auto recognised = recogniser->finish();
        auto exchange = fed && recognised ? service.hear("Antigone", *recognised) : Result<runtime::Exchange>(recognised.error());
        if (!exchange) {
            state.SkipWithError(exchange.error().message.c_str());
            return;
        }
        stage->evaluate(secondsToTicks(exchange->start), poses);
        benchmark::DoNotOptimize(poses.characters.data());
        understood += exchange->understood && exchange->heard == "who is creon";
        t = exchange->end + 1;
    }
    state.counters["understood"] = double(understood) / double(std::max<benchmark::IterationCount>(1, state.iterations()));
}
BENCHMARK(AnswerLatency)->Name("Interaction/answerLatency")->Unit(benchmark::kMillisecond)->Iterations(10);

} // namespace
