// thespis-cli export and import: scenario packages (core/scenario/package*.h). `export` runs
// core's ExportPackageJob; `import` opens a package (every check of package.h) and writes its
// files into a folder. `validate` takes packages too (command_validate.cpp).

#include <cstdio>

#include "commands.h"
#include "exit_codes.h"
#include "job_progress.h"
#include "scenario/package.h"
#include "scenario/package_export_job.h"

namespace thespis::cli {

namespace {

std::string megabytes(std::uint64_t bytes)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.2f MB", double(bytes) / 1e6);
    return text;
}

} // namespace

CommandSpec exportSpec()
{
    CommandSpec spec;
    spec.name = "export";
    spec.summary = "Pack a scenario and every file it names into one package (.thespkg).";
    spec.positionals = {"SCENARIO"};
    spec.options = {
        {"out", "FILE.thespkg", "the package to write; replaced only when complete", true},
        {"list", "", "list what goes in, with sizes"},
        {"bake", "", "first bake the lighting of every character whose bake is missing or no longer fits (into the package only)"},
        {"rays", "N", "--bake: rays per vertex for a character that had no bake (default 1024; a stale bake keeps its own)"},
        {"quiet", "", "no progress and no summary"},
    };
    spec.description =
        "The package is a zip with manifest.json first (the writer, and the size and SHA-256 of every\n"
        "entry), the scenario, and its models, bakes, clips, idle motion databases, probe, posture\n"
        "bases and occluder models. Files inside the scenario's folder keep their names; others go\n"
        "to assets/; so do the sounds and dialogue files a script names in quotes (its text then names\n"
        "them as the package does). Open it with `import`, check it with `validate`.\n"
        "Example: thespis-cli export resources/demo.thespis --out demo.thespkg\n"
        "Exit status: 0 written, 2 bad command line, 3 a file the scenario names is missing or\n"
        "unreadable, 4 the package could not be written, 130 cancelled.";
    return spec;
}

int runExport(const CommandSpec& spec, const ParsedArguments& arguments)
{
    const std::filesystem::path path = arguments.positionals[0];
    const bool quiet = arguments.has("quiet");
    auto scenario = loadScenarioReporting(spec.name, path);
    if (!scenario)
        return ExitInvalidInput;
    core::scenario::ExportPackageJob job;
    job.scenario = std::move(*scenario);
    job.assets = core::scenario::Assets::besideFile(path);
    job.scenarioEntry = path.filename().string();
    job.output = *arguments.value("out");
    job.bakeLighting = arguments.has("bake");
    int exitCode = ExitOk;
    if (const auto rays = integerOption(spec, arguments, "rays", 1, 1 << 20, exitCode))
        job.bakeSettings.raysPerVertex = int(*rays);
    if (exitCode != ExitOk)
        return exitCode;
    if (arguments.has("rays") && !job.bakeLighting)
        return usageError(spec, "--rays goes with --bake");
    if (auto valid = job.validate(); !valid)
        return usageError(spec, valid.error().message);
    const JobBar bar = job.bakeLighting ? JobBar{core::scenario::ExportPackageJob::BakeStage, "vertices"}
                                        : JobBar{core::scenario::ExportPackageJob::WriteStage, "bytes"};
    const auto exported = runJobWithProgress(spec.name, job, bar, quiet, job.output.string() + " was not written");
    if (!exported)
        return reportJobFailure(spec.name, exported.error());
    if (arguments.has("list"))
        for (const core::scenario::PackageEntry& entry : job.manifest.entries)
            std::printf("  %10llu  %s\n", static_cast<unsigned long long>(entry.size), entry.name.c_str());
    if (!quiet)
        for (const std::string& baked : job.baked)
            std::printf("Baked the lighting of %s.\n", baked.c_str());
    if (!quiet)
        std::printf("Wrote %s: the scenario and %zu files, %s (%s before compression).\n", job.output.string().c_str(),
                    job.plan.files.size(), megabytes(job.packageBytes).c_str(), megabytes(job.contentBytes).c_str());
    return ExitOk;
}

CommandSpec importSpec()
{
    CommandSpec spec;
    spec.name = "import";
    spec.summary = "Check a package and write its scenario and files into a folder.";
    spec.positionals = {"PACKAGE"};
    spec.options = {
        {"to", "FOLDER", "where the files go (made if missing); a file already there must be the same", true},
        {"quiet", "", "no summary"},
    };
    spec.description =
        "Every check of `validate PACKAGE` comes first: names inside the package, no links, sizes\n"
        "and compression within limits, every SHA-256 as the manifest says. Nothing is written\n"
        "unless all pass. Scripts in the scenario are not run.\n"
        "Example: thespis-cli import demo.thespkg --to ~/scenarios/demo\n"
        "Exit status: 0 imported, 2 bad command line, 3 the package is refused (the message names\n"
        "the entry), 4 a file could not be written.";
    return spec;
}

int runImport(const CommandSpec& spec, const ParsedArguments& arguments)
{
    const std::filesystem::path path = arguments.positionals[0];
    auto package = core::scenario::Package::open(path);
    if (!package) {
        printError(spec.name, core::describe(package.error()));
        return ExitInvalidInput;
    }
    auto scenario = (*package)->extractTo(*arguments.value("to"));
    if (!scenario) {
        printError(spec.name, core::describe(scenario.error()));
        return scenario.error().code == core::ErrorCode::IoError ? ExitFailure : ExitInvalidInput;
    }
    if (!arguments.has("quiet"))
        std::printf("Imported the scenario and %zu files from %s; the scenario is %s.\n",
                    (*package)->manifest().entries.size() - 1,
                    path.string().c_str(), scenario->string().c_str());
    return ExitOk;
}

} // namespace thespis::cli
