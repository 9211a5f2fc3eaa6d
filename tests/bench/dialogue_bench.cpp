// The AIML dialogue manager (core/dialogue) on Rosie, the largest real bot in the shared data:
// loading the whole bot folder (≈12 400 categories, 42 sets, 32 maps, 5 substitution lists), and
// answering varied real inputs one at a time (normalisation, graphmaster match, srai chains,
// template evaluation). Goals (issue: dialogue): load ≤ 0.5 s; one input's median ≤ 20 µs.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <filesystem>

#include "dialogue/bot.h"
#include "dialogue/conversation.h"

namespace dialogue = thespis::core::dialogue;

namespace {

const std::filesystem::path kRosie = std::filesystem::path(THESPIS_SHARED_DATA) / "dialogue" / "rosie";

// Inputs whose answers were read in Rosie's AIML: greetings through reductions, sets and maps,
// predicates, wildcards at either end, and inputs nothing but the catch-all answers.
constexpr const char* kInputs[] = {
    "Hello!", "How are you?", "My name is Ada.", "What is my name?", "What is the capital of France?",
    "Do you like cats?", "I am 30 years old", "How old am I?", "What time is it?", "Who are you?",
    "Tell me a joke", "knock knock", "What is 2 plus 2?", "My dog is called Rex", "I like pizza",
    "Can you help me with my homework please", "Why is the sky blue?", "bye", "xyzzy plugh", "I really love you",
};

void loadRosie(benchmark::State& state)
{
    for (auto _ : state) {
        auto loaded = dialogue::loadBotFolder(kRosie);
        if (!loaded) {
            state.SkipWithError("Rosie does not load");
            return;
        }
        benchmark::DoNotOptimize(loaded->bot->categories().size());
    }
}

void matchRosie(benchmark::State& state)
{
    auto loaded = dialogue::loadBotFolder(kRosie);
    if (!loaded) {
        state.SkipWithError("Rosie does not load");
        return;
    }
    dialogue::Conversation conversation(loaded->bot);
    std::vector<double> microseconds;
    std::size_t next = 0;
    for (auto _ : state) {
        const auto start = std::chrono::steady_clock::now();
        dialogue::Answer answer = conversation.respond(kInputs[next]);
        microseconds.push_back(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count());
        benchmark::DoNotOptimize(answer.text.data());
        next = (next + 1) % std::size(kInputs);
    }
    std::nth_element(microseconds.begin(), microseconds.begin() + std::ptrdiff_t(microseconds.size() / 2), microseconds.end());
    state.counters["median_us"] = microseconds[microseconds.size() / 2];
    state.counters["categories"] = double(loaded->bot->categories().size());
}

} // namespace

BENCHMARK(loadRosie)->Name("Dialogue/loadRosie")->Unit(benchmark::kMillisecond);
BENCHMARK(matchRosie)->Name("Dialogue/matchRosie")->Unit(benchmark::kMicrosecond);
