// Speech recognition benchmarks (paper §5.3: the recogniser listens for what the dialogue can
// answer), one thread, on a Rosie-sized source (listening_source.h: 12 000 patterns over 3 000
// CMUdict words, seeded):
//
// Recognition/generate: the source → its JSGF grammar (listening_grammar.h).
// Recognition/open: generate, then the recogniser ready to listen: pronunciations looked up,
//   pocketsphinx's grammar compiled, its phone loop made (grammar_recogniser.h).
// Recognition/decode: espeak-ng's speech of 8 patterns' literal forms decoded with that grammar;
//   counter rtf = decoding time / speech time. Goal rtf ≤ 0.2. Counter exact: share of the
//   sentences heard word for word.
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>

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
    std::size_t bytes = 0;
    for (auto _ : state) {
        auto grammar = dialogue::makeListeningGrammar(largeSource());
        if (!grammar) {
            state.SkipWithError(grammar.error().message.c_str());
            return;
        }
        bytes = grammar->jsgf.size();
    }
    state.counters["patterns"] = double(largeSource().patterns.size());
    state.counters["KiB"] = double(bytes) / 1024;
}
BENCHMARK(Generate)->Name("Recognition/generate")->Unit(benchmark::kMillisecond);

void Open(benchmark::State& state)
{
    for (auto _ : state) {
        auto grammar = dialogue::makeListeningGrammar(largeSource());
        auto recogniser = grammar ? speech::GrammarRecogniser::open(grammar->jsgf) : Result<speech::GrammarRecogniser>(grammar.error());
        if (!recogniser) {
            state.SkipWithError(recogniser.error().message.c_str());
            return;
        }
        benchmark::DoNotOptimize(recogniser);
    }
}
BENCHMARK(Open)->Name("Recognition/open")->Unit(benchmark::kSecond)->Iterations(2);

void Decode(benchmark::State& state)
{
    speech::RecogniserOptions options;
    options.maxActiveHmms = int(state.range(0));
    options.beam = std::pow(10.0, -double(state.range(1)));
    options.wordBeam = std::pow(10.0, -double(state.range(1)) * 0.6);
    auto grammar = dialogue::makeListeningGrammar(largeSource());
    auto recogniser = grammar ? speech::GrammarRecogniser::open(grammar->jsgf, options) : Result<speech::GrammarRecogniser>(grammar.error());
    if (!recogniser) {
        state.SkipWithError(recogniser.error().message.c_str());
        return;
    }
    // Sentences of the grammar: every 1500th pattern, its wildcards said as the loop's first word.
    std::vector<std::string> expected;
    std::vector<std::vector<std::int16_t>> sounds;
    double seconds = 0;
    for (std::size_t p = 0; p < largeSource().patterns.size(); p += 1500) {
        const auto words = thespis::test::literalForm(largeSource(), largeSource().patterns[p], grammar->innerWildcardWords.front());
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
}
BENCHMARK(Decode)->Name("Recognition/decode")->Unit(benchmark::kSecond)->Iterations(1)->Args({30000, 48})->Args({3000, 48})->Args({3000, 30})->Args({1000, 30});

} // namespace
