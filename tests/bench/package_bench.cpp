// Scenario packages (issue 17): the built-in demo (its scenario, idle motion database and posture
// bases, 0.31 MB) exported to a package, and the package opened with every check (the zip's
// directory, the manifest, each entry's SHA-256) and played: its runtime built from the zip.
//
// PackageExport: ExportPackageJob, written to the system's temporary folder.
// PackageOpen: openPackage (Package::open + the scenario).
// PackageOpenAndBuild: the same, then buildRuntime from the package — what `play PACKAGE` pays
//   before its first frame.
#include <benchmark/benchmark.h>

#include <filesystem>

#include "scenario/package_export_job.h"
#include "scenario/package_resolver.h"
#include "scenario/scenario_io.h"
#include "scenario/scenario_runtime.h"

using namespace thespis::core;
using namespace thespis::core::scenario;

namespace {

const std::filesystem::path kDemo = THESPIS_RESOURCES "/demo.thespis";

std::filesystem::path demoPackage()
{
    static const std::filesystem::path file = [] {
        const auto path = std::filesystem::temp_directory_path() / "thespis-bench-demo.thespkg";
        ExportPackageJob job;
        job.scenario = loadScenario(kDemo).value();
        job.assets = Assets::besideFile(kDemo);
        job.scenarioEntry = "demo.thespis";
        job.output = path;
        JobContext context;
        if (!job.run(context))
            std::abort();
        return path;
    }();
    return file;
}

void PackageExport(benchmark::State& state)
{
    ExportPackageJob job;
    job.scenario = loadScenario(kDemo).value();
    job.assets = Assets::besideFile(kDemo);
    job.scenarioEntry = "demo.thespis";
    job.output = std::filesystem::temp_directory_path() / "thespis-bench-export.thespkg";
    for (auto _ : state) {
        JobContext context;
        if (!job.run(context))
            state.SkipWithError("the export failed");
    }
    state.counters["MB"] = double(job.packageBytes) / 1e6;
    state.counters["contentMB"] = double(job.contentBytes) / 1e6;
}
BENCHMARK(PackageExport)->Unit(benchmark::kMillisecond);

void PackageOpen(benchmark::State& state)
{
    const auto file = demoPackage();
    for (auto _ : state) {
        auto opened = openPackage(file);
        if (!opened)
            state.SkipWithError("the package was refused");
        benchmark::DoNotOptimize(opened);
    }
}
BENCHMARK(PackageOpen)->Unit(benchmark::kMillisecond);

void PackageOpenAndBuild(benchmark::State& state)
{
    const auto file = demoPackage();
    for (auto _ : state) {
        auto opened = openPackage(file);
        auto runtime = buildRuntime(opened->scenario, opened->assets);
        if (!runtime)
            state.SkipWithError("the runtime did not build");
        benchmark::DoNotOptimize(runtime);
    }
}
BENCHMARK(PackageOpenAndBuild)->Unit(benchmark::kMillisecond);

} // namespace
