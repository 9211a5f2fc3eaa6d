// thespis-cli build-idle: runs core's BuildIdleJob (the paper's §4.3 idle motion database from
// standing recordings) with a progress bar and reports the rests and transitions it found.

#include <cstdio>

#include "commands.h"
#include "exit_codes.h"
#include "job_progress.h"
#include "scenario/build_idle_job.h"

namespace thespis::cli {

CommandSpec buildIdleSpec()
{
    CommandSpec spec;
    spec.name = "build-idle";
    spec.summary = "Build an idle motion database (balance shifts, small variations) from standing recordings.";
    spec.positionals = {"CLIP"};
    spec.repeatsLast = true;
    spec.options = {
        {"out", "FILE.idle", "the database to write; an existing file is replaced atomically", true},
        {"skip", "SECONDS", "left out at each recording's start, e.g. a capture's T-pose and settling (default 0)"},
        {"bases", "FILE.pca", "measure postures in these bases (thespis-cli train-pca); default: trained on the recordings"},
        {"categories", "N", "rest-posture categories (default 3: weight on the left foot, both, the right foot)"},
        {"rate", "N", "frames per second the database keeps (default 30)"},
        {"quiet", "", "no progress and no summary"},
    };
    spec.description =
        "Each CLIP is a recording of someone standing (BVH, or a glTF file's first animation);\n"
        "FILE@FPS replaces its frame rate and FILE+SECONDS skips its start, over --skip. In each\n"
        "recording the rests are found by clustering its postures, ordered by where the weight is,\n"
        "and every stretch from one rest to the next becomes a transition of the database. The\n"
        "summary lists the rests and transitions per recording, and the transitions no recording\n"
        "had. A scenario's clip plays the database as idle motion ({\"idle\": {\"database\": F}}).\n"
        "Exit status: 0 written, 2 bad command line, 3 a recording that cannot be used,\n"
        "4 the file could not be written, 130 cancelled.";
    return spec;
}

int runBuildIdle(const CommandSpec& spec, const ParsedArguments& arguments)
{
    core::scenario::BuildIdleJob job;
    int exitCode = ExitOk;
    double skip = 0;
    if (const auto text = arguments.value("skip")) {
        const auto value = parseNumber(*text);
        if (!value)
            return usageError(spec, "--skip must be a number, not '" + *text + "'");
        skip = *value;
    }
    if (const auto text = arguments.value("rate")) {
        const auto value = parseNumber(*text);
        if (!value || !(*value > 0))
            return usageError(spec, "--rate must be a positive number, not '" + *text + "'");
        job.options.frameRate = float(*value);
    }
    const auto categories = integerOption(spec, arguments, "categories", 2, 16, exitCode);
    if (exitCode != ExitOk)
        return exitCode;
    job.options.categoryCount = int(categories.value_or(3));
    auto sources = postureSources(spec, arguments.positionals, skip, exitCode);
    if (!sources)
        return exitCode;
    job.sources = std::move(*sources);
    job.output = *arguments.value("out");
    job.basesFile = arguments.value("bases").value_or("");
    const bool quiet = arguments.has("quiet");
    if (auto valid = job.validate(); !valid)
        return usageError(spec, valid.error().message);

    const auto built = runJobWithProgress(spec.name, job, {core::scenario::BuildIdleJob::ReadingStage, "recordings"}, quiet,
                                          job.output.string() + " was not written");
    if (!built)
        return reportJobFailure(spec.name, built.error());
    if (quiet)
        return ExitOk;
    const core::motion::IdleDatabase& db = job.database;
    std::printf("Built %s: %zu transitions, %zu frames at %g fps, categories %s.\n", job.output.string().c_str(),
                db.segments.size(), db.postures.size() / std::size_t(db.postureSize()), double(db.frameRate),
                joinNames(db.categories).c_str());
    for (const auto& recording : job.report.recordings)
        std::printf("  %s: %d frames, %d rests, %d transitions\n", recording.name.c_str(), recording.frames,
                    recording.rests, recording.segments);
    for (std::size_t from = 0; from < db.categories.size(); ++from)
        for (std::size_t to = 0; to < db.categories.size(); ++to)
            if (from != to && job.report.counts[from][to] > 0)
                std::printf("  %s → %s: %d\n", db.categories[from].c_str(), db.categories[to].c_str(),
                            job.report.counts[from][to]);
    if (!job.report.missing.empty())
        std::printf("No recording shifts %s.\n", joinNames(job.report.missing).c_str());
    return ExitOk;
}

} // namespace thespis::cli
