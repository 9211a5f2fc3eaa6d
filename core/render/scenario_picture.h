#pragma once
// The headless picture pipeline every front end shares: a scenario's scene (ScenarioScene), an
// offscreen renderer (EGL) and the camera that frames every character over the whole timeline
// (so a sequence does not jump). `thespis-cli render` and `run`, Python's thespis.render and the
// frame-sequence job draw through it. The renderer's GL context belongs to the thread that made
// the picture: draw on that thread.

#include <filesystem>
#include <map>
#include <memory>
#include <string>

#include "render/camera.h"
#include "render/offscreen_renderer.h"
#include "render/scenario_scene.h"
#include "render/shading.h"

namespace thespis::core::render {

struct PictureSettings {
    int width = 1280, height = 720;
    int samples = 4; ///< multisampling, 0 for none
    Shading shading = Shading::Prt;
    scene::SkinningMethod skinning = scene::SkinningMethod::Linear;
    bool ground = true;
    bool probeBackground = false;
    double azimuth = 20;   ///< degrees around the vertical: 0 in front
    double elevation = 8;  ///< degrees above the horizon
    /// A close-up of this character's head, following it frame by frame (azimuth and elevation
    /// then count from where its face looks); "" frames every character over the whole timeline.
    std::string closeUp;
    /// Baked transfer by character name (ScenarioSceneOptions::bakes).
    std::map<std::string, std::shared_ptr<const lighting::TransferBake>> bakes;
};

class ScenarioPicture {
public:
    static Result<std::unique_ptr<ScenarioPicture>> create(const scenario::Scenario& scenario,
                                                           const scenario::Assets& assets,
                                                           const PictureSettings& settings);

    ScenarioScene& scene() { return *m_scene; }
    const PictureSettings& settings() const { return m_settings; }
    const std::string& glDescription() const { return m_renderer->glDescription(); }

    /// Poses the scene at `t`, with this picture's camera as the one "camera" gaze targets look at
    /// (the last frame's, for a close-up that follows the head).
    void playAt(Tick t);
    /// Draws the scene as it is posed now (a close-up framed on the head as it is now).
    Result<const RgbaImage*> draw();
    /// Draws the scene as it is posed now into a PNG (written atomically).
    Result<void> writePng(const std::filesystem::path& file);

private:
    ScenarioPicture() = default;

    PictureSettings m_settings;
    std::unique_ptr<ScenarioScene> m_scene;
    std::unique_ptr<OffscreenRenderer> m_renderer;
    CameraView m_view;
    RgbaImage m_image;
};

/// "frame_00042.png".
std::string frameFileName(long frame);

} // namespace thespis::core::render
