#pragma once
// Baking a character's motion as a job (util/job.h): the character's poses as the Stage plays them
// (runtime/stage.h: the idle motion under the authored schedule, as the studio shows it), taken
// at a fixed frame rate over the scenario (or part of it) and written as a BVH clip on the character's
// skeleton, or as a glTF 2.0 animation (.glb) on the rig of its model (scene/gltf_motion_export.h)
// or, for the built-in humanoid, with the humanoid itself (scene/gltf_character_export.h) —
// the frames retargeted onto the body as the renderer poses it, the face layers as the weights
// of the model's own morph targets, as its face mapping table drives them (face_mapping.h). `thespis-cli bake-motion` and Python's
// thespis.scenario.bake_motion run it. Frames are baked into memory first and written atomically
// at the end, so a stopped or failed bake leaves no file.

#include <chrono>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "scenario/asset_resolver.h"
#include "scenario/scenario.h"
#include "scenario/scenario_runtime.h"
#include "util/job.h"

namespace thespis::core::runtime {

struct MotionBakeJob final : Job {
    static constexpr const char* LoadingStage = "Loading the scenario";
    static constexpr const char* FramesStage = "Evaluating frames";

    scenario::Scenario scenario;
    scenario::Assets assets{"."}; ///< where the scenario's files are
    std::string character;
    std::filesystem::path output; ///< a .bvh or .glb file
    /// .glb: only the model's nodes and the animation, without its meshes and images.
    bool animationOnly = false;
    double fps = 30;
    double start = 0;
    std::optional<double> end; ///< default: the scenario's duration
    /// Extra time per frame, so that tests can interrupt a bake and watch its progress.
    std::chrono::milliseconds frameDelay{0};

    long frameCount = 0;   ///< after run(): frames written
    double lastTime = 0;   ///< after run(): the last frame's time
    /// After run() of a .glb: the morph targets that got face weights ("mesh Head: Angry").
    std::vector<std::string> morphTargets;
    /// After run(): what the file leaves out, one sentence each.
    std::vector<std::string> warnings;

    std::string title() const override;
    /// fps > 0; start ≥ 0; end ≥ start; the output ends in .bvh or .glb and its folder exists;
    /// the scenario has the character. A .glb of a character with a glTF model is that model
    /// with the motion; of the built-in humanoid, the humanoid written as a glTF character.
    Result<void> validate() const override;
    Result<void> run(JobContext& context) override;
    void discardOutput() override;

private:
    Result<void> writeGltf(const scenario::CharacterRuntime& body, std::span<const float> frames,
                           std::span<const float> face, long count);
};

} // namespace thespis::core::runtime
