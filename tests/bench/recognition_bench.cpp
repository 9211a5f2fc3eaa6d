// Speech recognition benchmarks (paper §5.3: the recogniser listens for what the dialogue can
// answer), one thread, on a Rosie-sized source (listening_source.h: 12 000 patterns over 3 000
// CMUdict words, seeded):
//
// Recognition/generate: the source → its JSGF grammar and word graph (listening_grammar.h).
// Recognition/open: generate, then the recogniser ready to listen: pronunciations looked up,
//   pocketsphinx given the word graph, its phone loop made (grammar_recogniser.h).
// Recognition/decode: espeak-ng's speech of 24 patterns' literal forms decoded with that grammar;
//   counter rtf = decoding time / speech time. Goal rtf ≤ 0.2. Counter exact: share of the
//   sentences heard word for word.
// Recognition/openRosie, Recognition/decodeRosie: the same on the real Rosie (../shared/data).
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <filesystem>

#include "dialogue/bot.h"
#include "dialogue/bot_grammar.h"
#include "dialogue/listening_grammar.h"
#include "listening_source.h"
#include "speech/espeak_voice.h"
#include "speech/grammar_recogniser.h"
#include "speech/resample.h"
#include "util/text.h"

using namespace thespis::core;

namespace {

const dialogue::GrammarSource& largeSource()
{
    static const dialogue::GrammarSource source =
        thespis::test::largeGrammarSource(speech::SphinxModel::installed().dictionary.string(), 12000, 3000);
    return source;
}

void Generate(benchmark::State& state)
{
    std::size_t bytes = 0, states = 0, arcs = 0;
    for (auto _ : state) {
        auto grammar = dialogue::makeListeningGrammar(largeSource());
        if (!grammar) {
            state.SkipWithError(grammar.error().message.c_str());
            return;
        }
        bytes = grammar->jsgf.size();
        states = std::size_t(grammar->graph.states);
        arcs = grammar->graph.arcs.size();
    }
    state.counters["patterns"] = double(largeSource().patterns.size());
    state.counters["KiB"] = double(bytes) / 1024;
    state.counters["states"] = double(states);
    state.counters["arcs"] = double(arcs);
}
BENCHMARK(Generate)->Name("Recognition/generate")->Unit(benchmark::kMillisecond);

void Open(benchmark::State& state)
{
    for (auto _ : state) {
        auto grammar = dialogue::makeListeningGrammar(largeSource());
        auto recogniser = grammar ? speech::GrammarRecogniser::open(grammar->graph) : Result<speech::GrammarRecogniser>(grammar.error());
        if (!recogniser) {
            state.SkipWithError(recogniser.error().message.c_str());
            return;
        }
        benchmark::DoNotOptimize(recogniser);
    }
}
BENCHMARK(Open)->Name("Recognition/open")->Unit(benchmark::kSecond)->Iterations(2);

// Decodes espeak-ng's speech of every `step`th pattern of `source` (its wildcards said as the
// inner loop's first word) with the recogniser listening for it.
void measureDecoding(benchmark::State& state, const dialogue::GrammarSource& source, std::size_t step,
                     const dialogue::ListeningOptions& listening, const speech::RecogniserOptions& options)
{
    auto grammar = dialogue::makeListeningGrammar(source, listening);
    auto recogniser = grammar ? speech::GrammarRecogniser::open(grammar->graph, options) : Result<speech::GrammarRecogniser>(grammar.error());
    if (!recogniser) {
        state.SkipWithError(recogniser.error().message.c_str());
        return;
    }
    std::vector<std::string> expected;
    std::vector<std::vector<std::int16_t>> sounds;
    double seconds = 0;
    for (std::size_t p = 0; p < source.patterns.size(); p += step) {
        const auto words = thespis::test::literalForm(source, source.patterns[p], grammar->innerWildcardWords.front());
        const std::string text = joined(words);
        auto spoken = speech::speak(text, {"en-us", 160});
        if (!spoken) {
            state.SkipWithError(spoken.error().message.c_str());
            return;
        }
        sounds.push_back(speech::dithered16(speech::resampled(spoken->samples, spoken->rate, speech::kSphinxRate)));
        seconds += double(sounds.back().size()) / speech::kSphinxRate;
        expected.push_back(text);
    }
    double decoding = 0;
    int exact = 0, heard = 0;
    for (auto _ : state) {
        const auto began = std::chrono::steady_clock::now();
        for (std::size_t i = 0; i < sounds.size(); ++i) {
            auto result = recogniser->recognise(sounds[i]);
            exact += result && result->text == expected[i];
            ++heard;
        }
        decoding += std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
    }
    state.counters["rtf"] = decoding / (seconds * double(state.iterations()));
    state.counters["speech_s"] = seconds;
    state.counters["exact"] = double(exact) / std::max(1, heard);
    state.counters["states"] = grammar->graph.states;
}

// Args: the most HMMs a frame keeps, the beam's exponent (1e-N), the wildcard words' weight's
// (1e-N; 2 is ListeningOptions' default).
void Decode(benchmark::State& state)
{
    speech::RecogniserOptions options;
    options.maxActiveHmms = int(state.range(0));
    options.beam = std::pow(10.0, -double(state.range(1)));
    options.wordBeam = std::pow(10.0, -double(state.range(1)) * 0.6);
    measureDecoding(state, largeSource(), 500, {.wildcardWordWeight = float(std::pow(10.0, -double(state.range(2))))}, options);
}
BENCHMARK(Decode)->Name("Recognition/decode")->Unit(benchmark::kSecond)->Iterations(1)->Args({30000, 48, 2})->Args({1000, 48, 2});

// The real Rosie (../shared/data/dialogue/rosie): her bot loaded, her grammar made, the
// recogniser opened.
const dialogue::Bot* rosie()
{
    static const auto loaded = dialogue::loadBotFolder(std::filesystem::path(THESPIS_SHARED_DATA) / "dialogue" / "rosie");
    return loaded ? loaded->bot.get() : nullptr;
}

void OpenRosie(benchmark::State& state)
{
    if (!rosie()) {
        state.SkipWithError("Rosie does not load");
        return;
    }
    for (auto _ : state) {
        auto recogniser = dialogue::listenFor(*rosie());
        if (!recogniser) {
            state.SkipWithError(recogniser.error().message.c_str());
            return;
        }
        benchmark::DoNotOptimize(recogniser);
    }
}
BENCHMARK(OpenRosie)->Name("Recognition/openRosie")->Unit(benchmark::kSecond)->Iterations(1);

// Args: as Decode's, and the most words of the wildcard loop (0: ListeningOptions' default).
void DecodeRosie(benchmark::State& state)
{
    if (!rosie()) {
        state.SkipWithError("Rosie does not load");
        return;
    }
    speech::RecogniserOptions options;
    options.maxActiveHmms = int(state.range(0));
    options.beam = std::pow(10.0, -double(state.range(1)));
    options.wordBeam = std::pow(10.0, -double(state.range(1)) * 0.6);
    dialogue::ListeningOptions listening{.wildcardWordWeight = float(std::pow(10.0, -double(state.range(2))))};
    if (state.range(3) > 0) listening.maxWildcardWords = std::size_t(state.range(3));
    measureDecoding(state, dialogue::grammarSourceOf(*rosie()), 700, listening, options);
}
BENCHMARK(DecodeRosie)->Name("Recognition/decodeRosie")->Unit(benchmark::kSecond)->Iterations(1)->Args({30000, 48, 2, 0})->Args({1000, 48, 2, 0})->Args({1000, 48, 2, 500})->Args({300, 48, 2, 0});

} // namespace
