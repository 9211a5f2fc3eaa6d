#pragma once
// Training the posture PCA as a job (util/job.h): clips read onto the posture skeleton
// (posture_clip.h), their postures sampled at a fixed rate, the whole-body and upper-body bases
// trained and written atomically as a .pca file (posture_bases.h). `thespis-cli train-pca` runs it.

#include <filesystem>
#include <string>
#include <vector>

#include "motion/posture_bases.h"
#include "scenario/posture_clip.h"
#include "scenario/asset_resolver.h"
#include "scenario/scenario.h"
#include "util/job.h"

namespace thespis::core::scenario {

struct TrainPcaJob final : Job {
    static constexpr const char* ReadingStage = "Reading clips";
    static constexpr const char* AnalysingStage = "Analysing postures";

    std::vector<PostureSource> sources;
    Assets assets{"."};
    std::filesystem::path output; ///< a .pca file
    double sampleRate = 30;       ///< postures per second of each clip

    motion::PostureBases bases; ///< after run()
    long frameCount = 0;

    std::string title() const override;
    /// At least one clip; sampleRate > 0; skips ≥ 0; the output ends in .pca.
    Result<void> validate() const override;
    Result<void> run(JobContext& context) override;
    void discardOutput() override;
};

} // namespace thespis::core::scenario
