#pragma once
// A scenario made drawable: its runtime (schedules), each character's body (scenario_character.h)
// in a RenderScene, the schedule's frames retargeted onto each body's skeleton, and the light
// from the scenario's probe (or the scene's default light). setTime poses every character for a
// time on the timeline; the CLI's `render`, the studio's viewport and the picture tests all
// draw through it, so they show the same thing.

#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "anim/retarget.h"
#include "lighting/transfer_bake.h"
#include "render/render_scene.h"
#include "scenario/scenario.h"
#include "scenario/scenario_runtime.h"
#include "util/error.h"

namespace thespis::core::render {

struct ScenarioSceneOptions {
    int skinningThreads = 0; ///< as scene::SkinningWorkers
    scene::SkinningMethod skinning = scene::SkinningMethod::Linear;
    /// Baked transfer by character name (for its body mesh). A character without one here uses
    /// the bake file its scenario entry names (Character::bake, relative to baseDir) when that
    /// can be read and fits its body; otherwise, or without a file, it gets DU (and a warning
    /// says why a named file was left out).
    std::map<std::string, std::shared_ptr<const lighting::TransferBake>> bakes;
    /// SH order the scenario's probe is projected to (the transfer's order is at most 6).
    int lightOrder = 6;
    /// Draw the probe behind the characters (when the scenario has one).
    bool probeBackground = false;
};

class ScenarioScene {
public:
    static Result<std::unique_ptr<ScenarioScene>> create(const scenario::Scenario& scenario,
                                                         const std::filesystem::path& baseDir,
                                                         const ScenarioSceneOptions& options = {});
    ScenarioScene(const ScenarioScene&) = delete;
    ScenarioScene& operator=(const ScenarioScene&) = delete;

    RenderScene& scene() { return *m_scene; }
    const RenderScene& scene() const { return *m_scene; }
    const scenario::ScenarioRuntime& runtime() const { return m_runtime; }
    double duration() const { return m_runtime.duration; }
    /// Things worth telling the user (unmapped joints, characters whose skeleton shares few
    /// joints with their body, bake files left out); one sentence each.
    const std::vector<std::string>& warnings() const { return m_warnings; }

    /// Plays a new runtime of the same scenario (after an edit): the characters and their
    /// skeletons must be the same; otherwise an error says so and the scene must be rebuilt.
    Result<void> setRuntime(scenario::ScenarioRuntime runtime);

    /// Poses every character at `seconds` on the timeline (no allocation).
    void setTime(double seconds);
    double time() const { return m_time; }
    /// The bounds of every character over the whole timeline (sampled at 10 Hz), for a camera
    /// that keeps everyone in view while the scenario plays. Leaves the scene at time().
    Bounds boundsOverTimeline();

private:
    ScenarioScene() = default;

    struct Performer {
        const scenario::CharacterRuntime* runtime = nullptr;
        CharacterNode* node = nullptr;
        anim::FrameRetarget retarget;
        anim::FrameLayoutPtr bodyLayout;
        std::vector<float> scheduleFrame, bodyFrame;
    };
    scenario::ScenarioRuntime m_runtime;
    std::unique_ptr<RenderScene> m_scene;
    std::vector<Performer> m_performers;
    std::vector<std::string> m_warnings;
    double m_time = 0;
};

} // namespace thespis::core::render
