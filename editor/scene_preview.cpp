#include "editor/scene_preview.h"

#include <QColor>
#include <QVector3D>

#include "editor/document.h"
#include "editor/job_runner.h"
#include "editor/qt_conversions.h"
#include "editor/session.h"
#include "render/gl_context.h"
#include "render/picking.h"
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
    if (viewport)
        connect(viewport, &widgets::OsgViewport::clicked, this, &ScenePreview::onViewportClicked);
}

ScenePreview::~ScenePreview()
{
    m_lightJob.reset(); // cancels a projection before the scene goes
    // The viewport may outlive the scene: it must not draw nodes that are gone.
    if (m_viewport)
        m_viewport->setSceneData(nullptr);
}

void ScenePreview::setSession(Session* session)
{
    m_session = session;
    session->addView([this](Document*) { build(true); }, this);
    connect(session, &Session::edited, this, &ScenePreview::onEdited);
    connect(session, &Session::posesChanged, this, &ScenePreview::setPoses);
}

void ScenePreview::build(bool frameCamera)
{
    m_viewport->setSceneData(nullptr);
    m_lightJob.reset();
    m_lightProblem.clear();
    m_problem.clear();
    m_scene.reset();
    const Document* document = m_session ? m_session->document() : nullptr;
    if (!document)
        return;
    core::render::ScenarioSceneOptions options;
    options.stage = m_session->stage();
    options.projectProbe = false; // projectLight() does it off the GUI thread
    auto scene = core::render::ScenarioScene::create(document->scenario(), document->assets(), options);
    if (!scene) {
        m_problem = fromUtf8(scene.error().message);
        emit sceneFailed(m_problem);
        return;
    }
    m_scene = std::move(scene).value();
    m_sources = SceneSources::of(document->scenario(), document->assets());
    projectLight(*document);
    m_scene->scene().setShading(m_shading);
    m_scene->scene().setGroundVisible(m_groundVisible);
    const auto& background = m_scene->scene().backgroundColor();
    m_viewport->setClearColor(QColor::fromRgbF(background[0], background[1], background[2]));
    applyHighlights();
    m_viewport->setSceneData(m_scene->scene().root());
    if (m_session->poses().characters.size() == m_scene->poses().characters.size())
        m_scene->setPoses(m_session->poses()); // what plays now, until the next tick
    emit sceneBuilt();
    if (!frameCamera)
        return;
    const double aspect = m_viewport->height() > 0 ? double(m_viewport->width()) / m_viewport->height() : 16.0 / 9.0;
    const core::render::Bounds bounds = m_scene->boundsOver(m_session->timelineSamples());
    if (!bounds.empty()) {
        const core::render::CameraView view = core::render::frameBounds(
            bounds, kHomeAzimuthDegrees, kHomeElevationDegrees, aspect, m_viewport->fieldOfView());
        m_viewport->setHomeView(toQt(view.eye), toQt(view.centre), toQt(view.up));
    }
}

bool ScenePreview::closeUp(int character)
{
    if (!m_scene || !m_viewport || !m_session || !m_session->document())
        return false;
    const auto& characters = m_session->document()->scenario().characters;
    if (character < 0 || std::size_t(character) >= characters.size())
        return false;
    const auto head = m_scene->head(characters[std::size_t(character)].name);
    if (!head)
        return false;
    const double aspect = m_viewport->height() > 0 ? double(m_viewport->width()) / m_viewport->height() : 16.0 / 9.0;
    const core::render::CameraView view =
        core::render::ScenarioScene::closeUpView(*head, 15, 5, aspect, m_viewport->fieldOfView());
    m_viewport->lookAt(toQt(view.eye), toQt(view.centre), toQt(view.up));
    return true;
}

void ScenePreview::onEdited(bool stageReplaced)
{
    // Same bodies and stage: only the schedules changed, and the scene draws the stage as it is
    // (the session's next tick shows the edit).
    const Document* document = m_session->document();
    const SceneSources next = SceneSources::of(document->scenario(), document->assets());
    if (m_scene && !stageReplaced && next == m_sources && m_scene->followStage())
        return;
    // Other bodies (a bake, tags, a model): rebuilt where the user is looking; characters come
    // or go: framed anew, so that every one is in view.
    build(!(m_scene && next.sameCast(m_sources)));
}

void ScenePreview::setPoses(const core::runtime::PoseSet& poses)
{
    if (!m_scene)
        return;
    m_scene->setPoses(poses);
    if (m_viewIsTheCamera && m_session && m_session->stage()) {
        const QVector3D eye = m_viewport->eye();
        m_session->stage()->setCameraPosition(core::anim::Vec3d{eye.x(), eye.y(), eye.z()});
    }
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
    if (!m_lightProblem.isEmpty())
        list << m_lightProblem;
    return list;
}

bool ScenePreview::isLightLoading() const
{
    return m_lightJob && m_lightJob->isRunning();
}

void ScenePreview::projectLight(const Document& document)
{
    auto projection = core::render::probeProjectionFor(document.scenario(), document.assets(),
                                                       core::render::ScenarioSceneOptions{}.lightOrder);
    if (!projection) {
        m_lightProblem = fromUtf8(projection.error().message);
        return;
    }
    if (!*projection)
        return; // no probe: the default light
    m_lightJob = std::make_unique<JobRunner>();
    connect(m_lightJob.get(), &JobRunner::finished, this, &ScenePreview::onLightProjected);
    if (auto started = m_lightJob->start(std::make_unique<core::lighting::ProbeProjectionJob>(std::move(**projection)));
        !started)
        onLightProjected(started);
}

void ScenePreview::onLightProjected(const core::Result<void>& result)
{
    if (!result) {
        if (result.error().code == core::ErrorCode::Cancelled)
            return;
        m_lightProblem = tr("The light probe could not be used (the default light shows instead): %1")
                             .arg(fromUtf8(result.error().message));
        emit lightLoaded(false);
        return;
    }
    auto* job = m_lightJob->jobAs<core::lighting::ProbeProjectionJob>();
    if (m_scene && job && job->probe) {
        m_scene->setProbeLight(*job->probe, job->light);
        if (m_viewport)
            m_viewport->update();
    }
    emit lightLoaded(true);
}

// ---- Segment selection ----------------------------------------------------------------------

std::optional<ScenePreview::SegmentHit> ScenePreview::pickSegment(const QVector3D& origin,
                                                                  const QVector3D& direction) const
{
    if (!m_scene)
        return std::nullopt;
    const core::render::PickRay ray{{origin.x(), origin.y(), origin.z()}, {direction.x(), direction.y(), direction.z()}};
    const auto hit = core::render::pick(m_scene->scene(), ray);
    if (!hit)
        return std::nullopt;
    return SegmentHit{int(hit->character), int(hit->segment), hit->distance};
}

void ScenePreview::setHighlightedSegments(int character, const std::vector<int>& segments)
{
    m_highlightCharacter = segments.empty() ? -1 : character;
    m_highlightSegments = m_highlightCharacter < 0 ? std::vector<int>() : segments;
    applyHighlights();
    if (m_viewport)
        m_viewport->update();
}

void ScenePreview::applyHighlights()
{
    if (!m_scene)
        return;
    core::render::RenderScene& scene = m_scene->scene();
    for (std::size_t c = 0; c < scene.characterCount(); ++c) {
        core::render::CharacterNode& node = scene.character(c);
        for (std::size_t s = 0; s < node.segmentCount(); ++s)
            if (node.segmentHighlighted(s))
                node.setSegmentHighlighted(s, false);
    }
    if (m_highlightCharacter < 0 || std::size_t(m_highlightCharacter) >= scene.characterCount())
        return;
    core::render::CharacterNode& node = scene.character(std::size_t(m_highlightCharacter));
    for (int s : m_highlightSegments)
        if (s >= 0 && std::size_t(s) < node.segmentCount())
            node.setSegmentHighlighted(std::size_t(s), true);
}

void ScenePreview::onViewportClicked(const QVector3D& origin, const QVector3D& direction,
                                     Qt::KeyboardModifiers modifiers)
{
    if (const auto hit = pickSegment(origin, direction))
        emit segmentClicked(hit->character, hit->segment, modifiers);
    else
        emit emptySpaceClicked(modifiers);
}

} // namespace thespis::editor
