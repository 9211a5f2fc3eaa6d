#pragma once
// A scenario made drawable: its runtime (schedules), each character's body (scenario_character.h)
// in a RenderScene, the schedule's frames retargeted onto each body's skeleton, and the light
// from the scenario's probe (or the scene's default light). It plays through a runtime::Stage,
// so live actions and scripts show: setTime evaluates the stage and poses every character, or
// setPoses poses them from a PoseSet evaluated elsewhere (a Player). The CLI's `render` and
// `run`, the studio's viewport and the picture tests all draw through it, so they show the same
// thing.

#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "anim/retarget.h"
#include "lighting/probe_projection_job.h"
#include "lighting/transfer_bake.h"
#include "render/render_scene.h"
#include "runtime/stage.h"
#include "scenario/asset_resolver.h"
#include "scenario/scenario.h"
#include "scenario/scenario_runtime.h"
#include "util/error.h"

namespace thespis::core::render {

struct ScenarioSceneOptions {
    int skinningThreads = 0; ///< as scene::SkinningWorkers
    scene::SkinningMethod skinning = scene::SkinningMethod::Linear;
    /// Baked transfer by character name (for its body mesh). A character without one here uses
    /// the bake file its scenario entry names (Character::bake, an asset name) when that
    /// can be read and fits its body; otherwise, or without a file, it gets DU (and a warning
    /// says why a named file was left out).
    std::map<std::string, std::shared_ptr<const lighting::TransferBake>> bakes;
    /// SH order the scenario's probe is projected to (the transfer's order is at most 6).
    int lightOrder = 6;
    /// Draw the probe behind the characters (when the scenario has one).
    bool probeBackground = false;
    /// Play this stage (of the scenario's runtime: the studio's session stage) instead of one
    /// built for the scene.
    std::shared_ptr<runtime::Stage> stage;
    /// Project the scenario's probe while making the scene. When false the scene starts with
    /// the default light and the caller projects the probe (probeProjectionFor, e.g. off the
    /// GUI thread) and hands the result to setProbeLight().
    bool projectProbe = true;
};

/// The job that projects the scenario's light probe for its scene, or nothing when it has no
/// probe. Errors: an unknown layout (naming lighting.layout).
Result<std::optional<lighting::ProbeProjectionJob>> probeProjectionFor(const scenario::Scenario& scenario,
                                                                        const scenario::Assets& assets,
                                                                        int lightOrder);

class ScenarioScene {
public:
    static Result<std::unique_ptr<ScenarioScene>> create(const scenario::Scenario& scenario,
                                                         const scenario::Assets& assets,
                                                         const ScenarioSceneOptions& options = {});
    ScenarioScene(const ScenarioScene&) = delete;
    ScenarioScene& operator=(const ScenarioScene&) = delete;

    RenderScene& scene() { return *m_scene; }
    const RenderScene& scene() const { return *m_scene; }
    const scenario::ScenarioRuntime& runtime() const { return m_stage->runtime(); }
    /// The stage the scene plays: scripts and the live runtime activate actions on it.
    runtime::Stage& stage() { return *m_stage; }
    const std::shared_ptr<runtime::Stage>& sharedStage() const { return m_stage; }
    double duration() const { return runtime().duration; }
    /// Things worth telling the user (unmapped joints, characters whose skeleton shares few
    /// joints with their body, bake files left out); one sentence each.
    const std::vector<std::string>& warnings() const { return m_warnings; }

    /// Plays a new runtime of the same scenario (after an edit) on the same stage, so live
    /// actions play on: the characters and their skeletons must be the same; otherwise an
    /// error says so and the scene must be rebuilt.
    Result<void> setRuntime(scenario::ScenarioRuntime runtime);


    /// Lights the scene with the scenario's probe as projected (turned and scaled as the
    /// scenario's lighting says; drawn behind the characters with probeBackground).
    void setProbeLight(const lighting::LightProbe& probe, const lighting::ShRgb& light);

    /// Evaluates the stage at `seconds` and poses every character (no allocation).
    void setTime(double seconds);
    /// Poses every character from poses the stage gave (its character order).
    void setPoses(const runtime::PoseSet& poses);
    /// The poses setTime() evaluated last (the stage's character order).
    const runtime::PoseSet& poses() const { return m_poses; }
    double time() const { return m_time; }
    /// The bounds of every character over the whole timeline (sampled at 10 Hz), for a camera
    /// that keeps everyone in view while the scenario plays. Leaves the scene at time().
    Bounds boundsOverTimeline();

private:
    ScenarioScene() = default;

    struct Performer {
        std::string name;
        const scenario::CharacterRuntime* runtime = nullptr;
        CharacterNode* node = nullptr;
        anim::FrameRetarget retarget;
        anim::FrameLayoutPtr bodyLayout;
        anim::FrameLayoutPtr skeletonLayout; ///< of the character's skeleton when the scene was made
        std::vector<float> bodyFrame;
    };
    void attachPerformers();
    Result<void> fitsPerformers(const scenario::ScenarioRuntime& next) const;

    std::shared_ptr<runtime::Stage> m_stage;
    runtime::PoseSet m_poses;
    std::vector<int> m_performerPose; // per performer, its character's index in the stage
    std::unique_ptr<RenderScene> m_scene;
    std::vector<Performer> m_performers;
    std::vector<std::string> m_warnings;
    scenario::LightingSpec m_lighting;
    bool m_probeBackground = false;
    double m_time = 0;
};

} // namespace thespis::core::render
