#pragma once
// Baking a character's body motion as a job (util/job.h): the body schedule evaluated at a fixed
// frame rate over the scenario (or part of it) and written as a BVH clip on the character's
// skeleton. `thespis-cli bake-motion` and Python's thespis.scenario.bake_motion run it. Frames are
// baked into memory first and written atomically at the end, so a stopped or failed bake leaves
// no file.

#include <chrono>
#include <filesystem>
#include <optional>
#include <string>

#include "scenario/asset_resolver.h"
#include "scenario/scenario.h"
#include "util/job.h"

namespace thespis::core::scenario {

struct MotionBakeJob final : Job {
    static constexpr const char* LoadingStage = "Loading the scenario";
    static constexpr const char* FramesStage = "Evaluating frames";

    Scenario scenario;
    Assets assets{"."}; ///< where the scenario's files are
    std::string character;
    std::filesystem::path output; ///< a .bvh file
    double fps = 30;
    double start = 0;
    std::optional<double> end; ///< default: the scenario's duration
    /// Extra time per frame, so that tests can interrupt a bake and watch its progress.
    std::chrono::milliseconds frameDelay{0};

    long frameCount = 0;   ///< after run(): frames written
    double lastTime = 0;   ///< after run(): the last frame's time

    std::string title() const override;
    /// fps > 0; start ≥ 0; end ≥ start; the output ends in .bvh and its folder exists; the
    /// scenario has the character.
    Result<void> validate() const override;
    Result<void> run(JobContext& context) override;
    void discardOutput() override;
};

} // namespace thespis::core::scenario
