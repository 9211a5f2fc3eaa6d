#pragma once
// A scenario made drawable: each character's body (scenario_character.h) in a RenderScene, the
// stage's frames retargeted onto each body's skeleton and placed where the character stands, and
// the light from the scenario's probe (or the scene's default light). It draws a runtime::Stage,
// so live actions and scripts show. Two ways to use it:
//   - it plays a stage of its own (the CLI's `render` and `run`, pictures): playAt(t) evaluates
//     the stage and poses every character;
//   - it draws a stage someone else plays (ScenarioSceneOptions::stage: the studio's Session,
//     which evaluates once per tick for every view): setPoses() poses it from the PoseSet the
//     owner published, which holds everything needed, so this may run on another thread (the AR
//     preview's renderer). It never evaluates that stage itself.
// The CLI, the studio's viewport, the AR preview and the picture tests all draw through it, so
// they show the same thing.

#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <span>
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
    /// Draw this stage (of the scenario's runtime: the studio's session stage), posed by
    /// setPoses(), instead of playing one built for the scene.
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
    /// The stage's runtime (on the thread that changes it: its owner's).
    const scenario::ScenarioRuntime& runtime() const { return m_stage->runtime(); }
    /// The stage the scene draws: scripts and the live runtime activate actions on it.
    runtime::Stage& stage() { return *m_stage; }
    const std::shared_ptr<runtime::Stage>& sharedStage() const { return m_stage; }
    Tick duration() const { return runtime().duration; }
    /// Things worth telling the user (unmapped joints, characters whose skeleton shares few
    /// joints with their body, bake files left out); one sentence each.
    const std::vector<std::string>& warnings() const { return m_warnings; }

    /// After the stage's owner gave it a new runtime (an edit): the scene follows it, drawing
    /// the same bodies (nothing is evaluated; the next poses show the edit). Errors when the
    /// characters or their skeletons changed: the scene must be rebuilt.
    Result<void> followStage();

    /// Lights the scene with the scenario's probe as projected (turned and scaled as the
    /// scenario's lighting says; drawn behind the characters with probeBackground).
    void setProbeLight(const lighting::LightProbe& probe, const lighting::ShRgb& light);

    /// Evaluates the stage at `t` and poses every character (no allocation). For a scene that
    /// plays its own stage.
    void playAt(Tick t);
    /// Poses every character from poses the stage gave (its character order; no allocation).
    void setPoses(const runtime::PoseSet& poses);
    /// The poses shown (the stage's character order).
    const runtime::PoseSet& poses() const { return m_poses; }
    Tick time() const { return m_poses.time; }
    /// The bounds of every character over `samples` (runtime::sampleTimeline), for a camera that
    /// keeps everyone in view while the scenario plays. Leaves the scene posed as it was.
    Bounds boundsOver(std::span<const runtime::PoseSet> samples);
    /// boundsOver the stage's authored timeline sampled at 10 Hz.
    Bounds boundsOverTimeline();

    /// A character's head as posed now: the bounds of the segments that follow its skull joint
    /// (skullbase: skull, hair, eyes, lids, teeth …) and where its face looks (unit, world).
    struct Head {
        Bounds bounds;
        anim::Vec3d facing;
    };
    /// Errors: no character of that name (the names there are listed), or one without a head.
    Result<Head> head(std::string_view character) const;
    /// A close-up of a head: `azimuthDegrees` and `elevationDegrees` count from where the face
    /// looks, the camera kept from going more than 20° below the horizon (a bowed head is seen
    /// from the front, not from under the shoulders).
    static CameraView closeUpView(const Head& head, double azimuthDegrees, double elevationDegrees, double aspect,
                                  double fovYDegrees = 25);

private:
    ScenarioScene() = default;

    // Holds nothing of the stage's runtime (which its owner replaces at an edit, maybe while
    // this scene draws on another thread): names, layouts and retargets are its own.
    struct Performer {
        std::string name;
        CharacterNode* node = nullptr;
        anim::FrameRetarget retarget;
        anim::FrameLayoutPtr bodyLayout;
        anim::FrameLayoutPtr skeletonLayout; ///< of the character's skeleton when the scene was made
        std::vector<float> bodyFrame;
        std::size_t pose = 0; ///< its character's index in the stage's pose sets
    };
    void pose(Performer& performer, const runtime::CharacterPose& pose);

    std::shared_ptr<runtime::Stage> m_stage;
    runtime::PoseSet m_poses;
    std::unique_ptr<RenderScene> m_scene;
    std::vector<Performer> m_performers;
    std::vector<std::string> m_warnings;
    scenario::LightingSpec m_lighting;
    bool m_probeBackground = false;
};

} // namespace thespis::core::render
