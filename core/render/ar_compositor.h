#pragma once
// The virtual humans over live video (paper §7.2): the scenario's scene drawn as a layer from
// where the real camera saw the tracked target (ar_view.h), then laid over the video frame.
// What the layer holds besides the characters:
// - phantom occluders (the scenario's ArSpec): real objects as boxes, planes or glTF models
//   drawn into depth only, first, so that the video shows through them and hides what of the
//   characters is behind them;
// - a shadow catcher instead of the ground disc: the real ground darkened where the characters
//   hide the sky from it (ambient occlusion of sphere proxies of each posed character, worked out
//   into a small texture over their footprint each frame), so they stand on it.
// The layer is drawn with a transparent background; compositing is frame = video·(1 − α) + layer.
// Draw on the thread that created the compositor (its GL context's).

#include <memory>

#include "ar/camera_file.h"
#include "ar/pose.h"
#include "ar/tracker.h"
#include "ar/video_frame.h"
#include "render/offscreen_renderer.h"
#include "render/scenario_scene.h"
#include "scenario/asset_resolver.h"
#include "scenario/scenario.h"

namespace thespis::core::render {

struct ArCompositorSettings {
    /// Supersampling of the layer (OffscreenRenderer): 4 draws 2 × 2 per pixel, smoother edges at
    /// about a third of the frame rate on llvmpipe; live previews draw once per pixel.
    int samples = 1;
    Shading shading = Shading::Prt;
    scene::SkinningMethod skinning = scene::SkinningMethod::Linear;
    float shadowStrength = 0.6f; ///< how dark a fully covered patch of ground gets
    /// Draw this stage (the studio's, posed through scene().setPoses()) instead of playing one
    /// of the compositor's own (posed through scene().playAt()).
    std::shared_ptr<runtime::Stage> stage;
};

class ArCompositor {
public:
    /// A scene of the scenario for the video of `camera` (its size) with the world placed on
    /// `target` as the scenario's ArSpec says. Errors: the scenario's (ScenarioScene), no GL
    /// context, a phantom model that cannot be read (naming it).
    static Result<std::unique_ptr<ArCompositor>> create(const scenario::Scenario& scenario,
                                                        const scenario::Assets& assets,
                                                        const ar::CameraIntrinsics& camera,
                                                        const ar::TargetGeometry& target,
                                                        const ArCompositorSettings& settings = {});
    ~ArCompositor();

    ScenarioScene& scene() { return *m_scene; }
    const ar::CameraIntrinsics& camera() const { return m_camera; }
    const scenario::ArSpec& placement() const { return m_placement; }
    /// Where the real camera is in the scenario's world when the target is at `pose`.
    anim::Vec3d cameraPosition(const ar::TargetPose& pose) const;
    /// A new placement (the user moved, turned or scaled the world, or edited the occluders).
    Result<void> setPlacement(const scenario::ArSpec& placement);

    /// Lights the characters with light captured in the camera's frame (a mirror ball seen by
    /// it, ar::LiveProbe), turned into the world by the target's pose.
    void setCameraLight(const lighting::ShRgb& light, const ar::TargetPose& pose);

    /// Draws the scene as it is posed now, as the camera saw the target at `pose`, and lays it
    /// over `frame` (in place).
    Result<void> compose(ar::VideoFrame& frame, const ar::TargetPose& pose);
    /// The last layer drawn (premultiplied: black and transparent where nothing was drawn).
    const RgbaImage& layer() const { return m_layer; }
    /// The spheres the characters' shadow was worked out from, last frame.
    int shadowSpheres() const { return m_sphereCount; }

private:
    ArCompositor() = default;
    Result<void> buildOccluders();
    void updateShadow();

    ar::CameraIntrinsics m_camera;
    ar::TargetGeometry m_target;
    scenario::ArSpec m_placement;
    scenario::Assets m_assets;
    ArCompositorSettings m_settings;
    std::unique_ptr<ScenarioScene> m_scene;
    std::unique_ptr<OffscreenRenderer> m_renderer;
    osg::ref_ptr<osg::Group> m_occluders;
    osg::ref_ptr<osg::Node> m_shadowCatcher;
    osg::ref_ptr<osg::Image> m_shadowImage;  // the shadow over the characters' footprint
    osg::ref_ptr<osg::Uniform> m_shadowArea;
    int m_sphereCount = 0;
    struct Cell;
    std::vector<Cell> m_cells; // the shadow spheres' hash grid, reused per frame
    RgbaImage m_layer;
};

} // namespace thespis::core::render
