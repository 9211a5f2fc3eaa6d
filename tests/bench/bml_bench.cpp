// BML → Stage actions (runtime/bml_performance.h): a block with a 20-word speech and four
// gestures on its words (two beats, a wave, an agreeing nod whose stroke the words pin), a head
// nod, a faceLexeme over the speech and a gaze, realised for the demo's Creon — timing resolved, the speech's visemes built, every
// action put on the Stage. The speech is synthesised once beforehand: synthesis is excluded.
// Goal (issue 33): ≤ 5 ms.
#include <benchmark/benchmark.h>

#include "runtime/bml_performance.h"
#include "scenario/scenario_io.h"
#include "speech/espeak_voice.h"

using namespace thespis::core;

namespace {

constexpr const char* kBlock = R"(<bml id="bml1">
  <speech id="s1"><text>Hear me now, <sync id="t1"/>Antigone, daughter of Oedipus: you knew my edict, and still
  you <sync id="t2"/>buried him, <sync id="t3"/>against the law of the city.</text></speech>
  <gesture id="g1" lexeme="BEAT" stroke="s1:t1"/>
  <gesture id="g2" lexeme="WAVE" start="s1:start" end="s1:t1"/>
  <gesture id="g3" lexeme="BEAT" stroke="s1:t2"/>
  <gesture id="g4" name="agree" ready="s1:t3" stroke="s1:t3" relax="s1:end"/>
  <head id="h1" lexeme="NOD" start="s1:t3"/>
  <faceLexeme id="f1" lexeme="LOWER_BROWS" start="s1:start" end="s1:end"/>
  <gaze id="z1" target="Antigone" influence="HEAD" start="s1:start"/>
</bml>)";

void BmlToStage(benchmark::State& state)
{
    const std::filesystem::path demo = std::filesystem::path(THESPIS_RESOURCES) / "demo.thespis";
    auto scenario = scenario::loadScenario(demo);
    auto built = scenario ? scenario::buildRuntime(*scenario, demo.parent_path()) : Result<scenario::ScenarioRuntime>(scenario.error());
    auto block = speech::parseBml(kBlock);
    if (!built || !block) {
        state.SkipWithError("the demo or the block does not read");
        return;
    }
    runtime::BmlOptions options;
    auto spoken = std::make_shared<std::map<std::string, speech::Utterance>>();
    auto said = speech::speak(block->behaviors[0].text, options.voice);
    if (!said) {
        state.SkipWithError("espeak-ng cannot speak");
        return;
    }
    (*spoken)["s1"] = std::move(said).value();
    options.spoken = spoken;
    auto stage = std::make_shared<runtime::Stage>(std::move(built).value());
    runtime::BmlRealizer realizer(stage, nullptr);
    const std::string creon = scenario->characters[0].name;
    Tick at = 0;
    for (auto _ : state) {
        auto performed = realizer.perform(creon, *block, options, at);
        if (!performed) {
            state.SkipWithError(performed.error().message.c_str());
            return;
        }
        benchmark::DoNotOptimize(performed->end);
        at += secondsToTicks(10);
        state.PauseTiming();
        stage->resetLive();
        state.ResumeTiming();
    }
}
BENCHMARK(BmlToStage)->Name("Bml/toStage")->Unit(benchmark::kMillisecond);

} // namespace
