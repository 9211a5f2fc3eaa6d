#include "render/scenario_picture.h"

#include <cstdio>

namespace thespis::core::render {

Result<std::unique_ptr<ScenarioPicture>> ScenarioPicture::create(const scenario::Scenario& scenario,
                                                                 const scenario::Assets& assets,
                                                                 const PictureSettings& settings)
{
    ScenarioSceneOptions options;
    options.skinning = settings.skinning;
    options.probeBackground = settings.probeBackground;
    options.bakes = settings.bakes;
    auto scene = ScenarioScene::create(scenario, assets, options);
    if (!scene)
        return scene.error();
    auto renderer = OffscreenRenderer::create(settings.width, settings.height, settings.samples);
    if (!renderer)
        return renderer.error();
    std::unique_ptr<ScenarioPicture> self(new ScenarioPicture);
    self->m_settings = settings;
    self->m_scene = std::move(scene).value();
    self->m_renderer = std::move(renderer).value();
    self->m_scene->scene().setShading(settings.shading);
    self->m_scene->scene().setGroundVisible(settings.ground);
    if (!settings.closeUp.empty()) {
        if (auto head = self->m_scene->head(settings.closeUp); !head)
            return head.error();
    } else {
        self->m_view = frameBounds(self->m_scene->boundsOverTimeline(), settings.azimuth, settings.elevation,
                                   double(settings.width) / settings.height);
    }
    return self;
}

void ScenarioPicture::playAt(Tick t)
{
    m_scene->stage().setCameraPosition(m_view.eye);
    m_scene->playAt(t);
}

Result<const RgbaImage*> ScenarioPicture::draw()
{
    if (!m_settings.closeUp.empty()) {
        auto head = m_scene->head(m_settings.closeUp);
        if (!head)
            return head.error();
        m_view = ScenarioScene::closeUpView(*head, m_settings.azimuth, m_settings.elevation,
                                            double(m_settings.width) / m_settings.height);
    }
    if (auto drawn = m_renderer->render(m_scene->scene(), m_view, m_image); !drawn)
        return drawn.error();
    return &m_image;
}

Result<void> ScenarioPicture::writePng(const std::filesystem::path& file)
{
    if (auto drawn = draw(); !drawn)
        return drawn.error();
    return render::writePng(file, m_image);
}

std::string frameFileName(long frame)
{
    char name[32];
    std::snprintf(name, sizeof name, "frame_%05ld.png", frame);
    return name;
}

} // namespace thespis::core::render
