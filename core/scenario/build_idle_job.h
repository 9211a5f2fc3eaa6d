#pragma once
// Building an idle motion database as a job (util/job.h): standing recordings read onto the
// posture skeleton (posture_clip.h), built into a database (idle_builder.h) and written
// atomically as a .idle file (idle_database.h). `thespis-cli build-idle` and
// scripts/make_motion_data.sh run it.

#include <filesystem>
#include <string>
#include <vector>

#include "motion/idle_builder.h"
#include "scenario/posture_clip.h"
#include "scenario/asset_resolver.h"
#include "scenario/scenario.h"
#include "util/job.h"

namespace thespis::core::scenario {

struct BuildIdleJob final : Job {
    static constexpr const char* ReadingStage = "Reading recordings";
    static constexpr const char* BuildingStage = "Finding rests and transitions";

    std::vector<PostureSource> sources;
    Assets assets{"."};
    std::filesystem::path output;      ///< a .idle file
    std::filesystem::path basesFile;   ///< a .pca file to measure in; empty: trained on the recordings
    motion::IdleBuildOptions options;

    motion::IdleDatabase database;  ///< after run()
    motion::IdleBuildReport report; ///< after run()

    std::string title() const override;
    /// At least one recording; skips ≥ 0; the output ends in .idle.
    Result<void> validate() const override;
    Result<void> run(JobContext& context) override;
    void discardOutput() override;
};

} // namespace thespis::core::scenario
