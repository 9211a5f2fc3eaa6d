// Speech benchmarks (issue 32 goals, one thread):
//
// Speech/faceSchedule: a 20-word sentence with 2 tagged gestures, its timing already spoken →
//   viseme and gesture cues and the Insert edit into the demo scenario (speech_plan.h,
//   edit/speech_edits.h). Synthesis excluded. Goal ≤ 5 ms.
// Speech/firstSound: a 20-word answer of two sentences → the first sentence's audio and visemes
//   ready (the SpeakJob hands each sentence on as it is synthesised). Goal ≤ 60 ms.
// Speech/live: the 20-word sentence's visemes and gestures started live on the demo's Stage
//   (runtime::performSpeech, what Preview and voiceService do once the audio is ready) and the
//   stage evaluated once: added to firstSound, the time to the first viseme on the face.
#include <benchmark/benchmark.h>

#include <stop_token>

#include "edit/speech_edits.h"
#include "runtime/speech_performance.h"
#include "runtime/stage.h"
#include "scenario/scenario_io.h"
#include "speech/speak_job.h"

using namespace thespis::core;

namespace {

constexpr const char* kTwentyWords =
    "Creon, <begin_gesture id=\"g1\" anim=\"agree\"/>you know very well<end_gesture id=\"g1\"/> that my brother still "
    "lies unburied outside the city walls, <begin_gesture id=\"g2\" anim=\"greet\"/>and I will bury him<end_gesture "
    "id=\"g2\"/> tonight.";

void FaceSchedule(benchmark::State& state)
{
    auto scenario = scenario::loadScenario(THESPIS_RESOURCES "/demo.thespis");
    speech::SpeakJob job;
    job.text = kTwentyWords;
    JobContext context;
    if (!scenario || !job.run(context).ok()) {
        state.SkipWithError("cannot load the demo or speak");
        return;
    }
    auto built = scenario::buildRuntime(*scenario, THESPIS_RESOURCES);
    if (!built) {
        state.SkipWithError("cannot build the demo");
        return;
    }
    for (auto _ : state) {
        const auto visemes = speech::visemeCues(job.utterance.timing);
        const auto gestures = speech::taggedBml(job.tagged, job.utterance.timing);
        auto inserted = edit::insertSpeech(*scenario, 0,
                                           edit::speechLine(job.text, job.voice, job.utterance.timing, "line.wav", 0),
                                           visemes, gestures, &*built);
        benchmark::DoNotOptimize(inserted);
    }
    state.counters["words"] = double(job.utterance.timing.words.size());
    state.counters["visemes"] = double(job.visemeCues.size());
}
BENCHMARK(FaceSchedule)->Name("Speech/faceSchedule")->Unit(benchmark::kMillisecond);

void FirstSound(benchmark::State& state)
{
    for (auto _ : state) {
        speech::SpeakJob job;
        job.text = "Creon, you know that my brother lies unburied outside the walls. I will bury him tonight, whatever "
                   "you say, dear.";
        std::stop_source stop;
        std::size_t visemes = 0;
        // Stop after the first sentence: what a player waits for before the first sound.
        job.sentenceReady = [&](const speech::Utterance& first) {
            visemes = speech::visemeCues(first.timing).size();
            stop.request_stop();
        };
        JobContext context(stop.get_token());
        (void)job.run(context);
        benchmark::DoNotOptimize(visemes);
    }
}
BENCHMARK(FirstSound)->Name("Speech/firstSound")->Unit(benchmark::kMillisecond);

void Live(benchmark::State& state)
{
    auto scenario = scenario::loadScenario(THESPIS_RESOURCES "/demo.thespis");
    speech::SpeakJob job;
    job.text = kTwentyWords;
    JobContext context;
    if (!scenario) {
        state.SkipWithError("cannot load the demo");
        return;
    }
    auto built = scenario::buildRuntime(*scenario, THESPIS_RESOURCES);
    if (!built || !job.run(context).ok()) {
        state.SkipWithError("cannot build the demo or speak");
        return;
    }
    runtime::Stage stage(std::move(built).value());
    runtime::PoseSet poses = stage.makePoseSet();
    for (auto _ : state) {
        auto performed = runtime::performSpeech(stage, "Creon", "line", job.visemeCues, job.gestureBml, 0);
        stage.evaluate(secondsToTicks(0.1), poses);
        benchmark::DoNotOptimize(performed);
        state.PauseTiming();
        stage.resetLive();
        state.ResumeTiming();
    }
}
BENCHMARK(Live)->Name("Speech/live")->Unit(benchmark::kMillisecond);

} // namespace
