// thespis-cli train-pca: runs core's TrainPcaJob (the paper's §4.1 posture PCA of motion capture
// clips) with a progress bar and prints how much of the postures' variance the leading PCs hold.

#include <cstdio>

#include "commands.h"
#include "exit_codes.h"
#include "job_progress.h"
#include "scenario/train_pca_job.h"

namespace thespis::cli {

CommandSpec trainPcaSpec()
{
    CommandSpec spec;
    spec.name = "train-pca";
    spec.summary = "Train the posture PCA (whole body and upper body) on motion capture clips.";
    spec.positionals = {"CLIP"};
    spec.repeatsLast = true;
    spec.options = {
        {"out", "FILE.pca", "the bases file to write; an existing file is replaced atomically", true},
        {"rate", "N", "postures taken per second of each clip (default 30)"},
        {"skip", "SECONDS", "left out at each clip's start, e.g. a capture's T-pose and settling (default 0)"},
        {"quiet", "", "no progress and no summary"},
    };
    spec.description =
        "Each CLIP is a BVH file or a glTF file (its first animation), retargeted onto the H-Anim\n"
        "25-joint skeleton; FILE@FPS replaces the file's frame rate (77_02.bvh@60) and FILE+SECONDS\n"
        "skips its start (111_28.bvh+6), over --skip. Postures are\n"
        "exponential maps of the 25 joints and the root's place over the feet (78 numbers); the\n"
        "upper body is the 15 joints above the pelvis (45). The summary gives the share of the\n"
        "variance that 5, 10 and 20 PCs explain.\n"
        "Exit status: 0 written, 2 bad command line, 3 a clip that cannot be used,\n"
        "4 the file could not be written, 130 cancelled.";
    return spec;
}

int runTrainPca(const CommandSpec& spec, const ParsedArguments& arguments)
{
    core::scenario::TrainPcaJob job;
    double skip = 0;
    for (auto [name, target] : {std::pair{"rate", &job.sampleRate}, std::pair{"skip", &skip}})
        if (const auto text = arguments.value(name)) {
            const auto value = parseNumber(*text);
            if (!value)
                return usageError(spec, std::string("--") + name + " must be a number, not '" + *text + "'");
            *target = *value;
        }
    int exitCode = ExitOk;
    auto sources = postureSources(spec, arguments.positionals, skip, exitCode);
    if (!sources)
        return exitCode;
    job.sources = std::move(*sources);
    job.output = *arguments.value("out");
    const bool quiet = arguments.has("quiet");
    if (auto valid = job.validate(); !valid)
        return usageError(spec, valid.error().message);

    const auto trained = runJobWithProgress(spec.name, job, {core::scenario::TrainPcaJob::ReadingStage, "clips"}, quiet,
                                            job.output.string() + " was not written");
    if (!trained)
        return reportJobFailure(spec.name, trained.error());
    if (!quiet) {
        std::printf("Trained on %ld postures of %zu clips; wrote %s.\n", job.frameCount, job.sources.size(),
                    job.output.string().c_str());
        for (const auto* basis : {&job.bases.whole, &job.bases.upper})
            std::printf("%s (%d dimensions): 5 PCs explain %.1f %%, 10 PCs %.1f %%, 20 PCs %.1f %% of the variance.\n",
                        basis == &job.bases.whole ? "Whole body" : "Upper body", basis->dimension(),
                        100 * basis->explainedVariance(5), 100 * basis->explainedVariance(10),
                        100 * basis->explainedVariance(20));
    }
    return ExitOk;
}

} // namespace thespis::cli
