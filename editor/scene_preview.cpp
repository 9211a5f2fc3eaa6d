#include "editor/scene_preview.h"

#include <QColor>
#include <QVector3D>

#include "editor/document.h"
#include "editor/qt_conversions.h"
#include "render/gl_context.h"
#include "widgets/osg_viewport.h"

namespace thespis::editor {

namespace {
// The viewport's default view: a little to the characters' left and above their eyes.
constexpr double kHomeAzimuthDegrees = 20.0;
constexpr double kHomeElevationDegrees = 8.0;

QVector3D toQt(const core::anim::Vec3d& v)
{
    return QVector3D(float(v.x), float(v.y), float(v.z));
}
} // namespace

ScenePreview::ScenePreview(widgets::OsgViewport* viewport, QObject* parent) : QObject(parent), m_viewport(viewport)
{
    core::render::quietOsgNotifications();
}

ScenePreview::~ScenePreview()
{
    // The viewport may outlive the scene: it must not draw nodes that are gone.
    if (m_viewport)
        m_viewport->setSceneData(nullptr);
}

core::Result<void> ScenePreview::setDocument(const Document* document)
{
    m_viewport->setSceneData(nullptr);
    m_scene.reset();
    if (!document)
        return {};
    auto scene = core::render::ScenarioScene::create(document->scenario(), toFsPath(document->baseDir()));
    if (!scene)
        return scene.error();
    m_scene = std::move(scene).value();
    m_scene->scene().setShading(m_shading);
    m_scene->scene().setGroundVisible(m_groundVisible);
    const auto& background = m_scene->scene().backgroundColor();
    m_viewport->setClearColor(QColor::fromRgbF(background[0], background[1], background[2]));
    m_viewport->setSceneData(m_scene->scene().root());
    const double aspect = m_viewport->height() > 0 ? double(m_viewport->width()) / m_viewport->height() : 16.0 / 9.0;
    const core::render::Bounds bounds = m_scene->boundsOverTimeline();
    if (!bounds.empty()) {
        const core::render::CameraView view = core::render::frameBounds(
            bounds, kHomeAzimuthDegrees, kHomeElevationDegrees, aspect, m_viewport->fieldOfView());
        m_viewport->setHomeView(toQt(view.eye), toQt(view.centre), toQt(view.up));
    }
    return {};
}

core::Result<void> ScenePreview::updateDocument(const Document* document)
{
    if (m_scene && document && m_scene->setRuntime(document->runtime())) {
        m_viewport->update();
        return {};
    }
    const double time = m_scene ? m_scene->time() : 0.0;
    auto rebuilt = setDocument(document);
    if (rebuilt)
        setTime(time);
    return rebuilt;
}

void ScenePreview::setTime(double seconds)
{
    if (!m_scene)
        return;
    m_scene->setTime(seconds);
    m_viewport->update();
}

void ScenePreview::setShading(core::render::Shading shading)
{
    m_shading = shading;
    if (m_scene)
        m_scene->scene().setShading(shading);
    m_viewport->update();
}

void ScenePreview::setGroundVisible(bool visible)
{
    m_groundVisible = visible;
    if (m_scene)
        m_scene->scene().setGroundVisible(visible);
    m_viewport->update();
}

QStringList ScenePreview::warnings() const
{
    QStringList list;
    if (m_scene)
        for (const std::string& warning : m_scene->warnings())
            list << QString::fromStdString(warning);
    return list;
}

} // namespace thespis::editor
