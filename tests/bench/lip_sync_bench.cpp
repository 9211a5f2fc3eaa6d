// Lip sync benchmark (issue 32 goal, one thread):
//
// LipSync/librivox: a 10 s recording with its transcript (LibriVox utterances of
//   ../shared/data/speech/pocketsphinx/librivox, one after another) → word and phoneme timing:
//   speech::lipSync, the model's loading and the dictionary's reading included. Goal ≤ 1 s (a
//   real-time factor of 0.1).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "runtime/sound.h"
#include "speech/lip_sync.h"
#include "util/file_io.h"

using namespace thespis::core;

namespace {

void LipSync(benchmark::State& state)
{
    const std::filesystem::path folder = std::filesystem::path(THESPIS_SHARED_DATA) / "speech/pocketsphinx/librivox";
    std::vector<std::filesystem::path> wavs;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(folder, ec))
        if (entry.path().extension() == ".wav")
            wavs.push_back(entry.path());
    std::sort(wavs.begin(), wavs.end());
    std::vector<float> samples;
    std::string transcript;
    int rate = 0;
    for (const auto& wav : wavs) {
        auto clip = runtime::loadSound(wav);
        auto text = readTextFile(std::filesystem::path(wav).replace_extension(".txt"));
        if (!clip || !text) {
            state.SkipWithError(("cannot read " + wav.string()).c_str());
            return;
        }
        rate = (*clip)->rate;
        samples.insert(samples.end(), (*clip)->samples.begin(), (*clip)->samples.end());
        transcript += *text + " ";
        if (double(samples.size()) >= 10.0 * rate)
            break;
    }
    if (rate == 0 || double(samples.size()) < 10.0 * rate) {
        state.SkipWithError(("less than 10 s of recordings in " + folder.string()).c_str());
        return;
    }
    const double seconds = double(samples.size()) / rate;
    for (auto _ : state) {
        JobContext context;
        auto synced = speech::lipSync(samples, rate, transcript, context);
        if (!synced) {
            state.SkipWithError(describe(synced.error()).c_str());
            return;
        }
        benchmark::DoNotOptimize(synced->timing.phonemes.data());
    }
    state.counters["audio_s"] = seconds;
    state.counters["real_time_factor"] =
        benchmark::Counter(seconds * double(state.iterations()), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

} // namespace

BENCHMARK(LipSync)->Name("LipSync/librivox")->Unit(benchmark::kMillisecond)->UseRealTime();
