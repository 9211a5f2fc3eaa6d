// Light probe projection, comparable to google/spherical-harmonics' ProjectEnvironment
// (1024×512, l = 4: about 57 ms on this kind of machine).
//
// ProbeProjection/<width>/<l>: one projection of a real lat-long probe (Poly Haven
// venice_sunset, box-downsampled to width × width/2) onto bands 0 … l (order l + 1), with the
// projector (its per-row tables) built once outside the timed loop, as for a live probe.
// Threads: one per hardware thread (ProbeProjector's default); the work is split among threads,
// so iterations and Mpixels/s go by wall-clock time (the CPU column is the main thread's only).
#include <benchmark/benchmark.h>

#include <cstdlib>

#include "lighting/probe.h"

using namespace thespis::core::lighting;

namespace {

HdrImage probeOfWidth(int width)
{
    auto loaded = readHdrImage(std::filesystem::path(THESPIS_SHARED_DATA) / "probes/polyhaven_1k/venice_sunset_1k.hdr");
    if (!loaded.ok())
        std::abort();
    const HdrImage& full = *loaded;
    const int factor = full.width / width;
    HdrImage image{width, width / 2, std::vector<float>(size_t(width) * size_t(width / 2) * 3, 0.0f)};
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            for (int j = 0; j < factor; ++j)
                for (int i = 0; i < factor; ++i)
                    for (int c = 0; c < 3; ++c)
                        image.rgb[3 * (size_t(y) * size_t(width) + size_t(x)) + size_t(c)]
                            += full.pixel(x * factor + i, y * factor + j)[c] / float(factor * factor);
    return image;
}

void ProbeProjection(benchmark::State& state)
{
    const int width = int(state.range(0));
    const int order = int(state.range(1)) + 1;
    const HdrImage image = probeOfWidth(width);
    auto projector = ProbeProjector::create(ProbeLayout::LatLong, width, width / 2, order);
    if (!projector.ok())
        std::abort();
    for (auto _ : state) {
        auto coefficients = projector->project(image);
        benchmark::DoNotOptimize(coefficients);
    }
    state.counters["Mpixels/s"] = benchmark::Counter(double(width) * (width / 2) * double(state.iterations()) / 1e6,
                                                     benchmark::Counter::kIsRate);
}

} // namespace

BENCHMARK(ProbeProjection)
    ->Args({512, 2})
    ->Args({512, 4})
    ->Args({1024, 2})
    ->Args({1024, 4})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
