#pragma once
// ScenePreview: the 3D view of the Session's document, one of its views. Builds the scenario's
// render scene (bodies, light, ground — core::render::ScenarioScene) drawing the Session's
// Stage, hands its root node to an OsgViewport, frames the camera on the characters over the
// whole timeline (the Session's timeline samples), and poses every character from the poses the
// Session publishes each tick; it never evaluates anything. After an edit it follows the stage,
// rebuilding only when bodies, tags, bakes, the light or the cast changed. It also answers which
// segment a click in the viewport hits and tints selected segments.

#include <QObject>
#include <QPointer>
#include <QString>
#include <QStringList>
#include <QVector3D>

#include <memory>
#include <optional>
#include <vector>

#include "editor/scene_sources.h"
#include "render/scenario_scene.h"
#include "render/shading.h"
#include "util/error.h"

namespace thespis::widgets {
class OsgViewport;
}

namespace thespis::editor {

class JobRunner;

class Document;
class Session;

class ScenePreview : public QObject {
    Q_OBJECT
public:
    /// A segment under the mouse: indices into the document's characters and into that
    /// character's body segments (as loadCharacterBody orders them).
    struct SegmentHit {
        int character = -1;
        int segment = -1;
        double distance = 0; ///< from the ray's origin, metres
    };

    explicit ScenePreview(widgets::OsgViewport* viewport, QObject* parent = nullptr);
    ~ScenePreview() override;

    /// Shows `session`'s documents from now on (registers as its view). When a scene cannot be
    /// built the view is left empty and problem() says which character or file could not be
    /// loaded.
    void setSession(Session* session);
    /// Why the view is empty although a document is open; empty when the scene is shown.
    QString problem() const { return m_problem; }
    void setShading(core::render::Shading shading);
    core::render::Shading shading() const { return m_shading; }
    void setGroundVisible(bool visible);
    /// Whether the view's camera is the one the stage's "camera" gaze targets look at (true until
    /// the AR preview runs: then the tracked real camera is).
    void setViewIsTheCamera(bool view) { m_viewIsTheCamera = view; }
    bool groundVisible() const { return m_groundVisible; }

    /// Turns the camera to a close-up of the character's face as it is posed now (its home view
    /// stays); false when no scene is shown or the character has no head.
    bool closeUp(int character);

    /// The first segment the world-space ray meets on the posed bodies shown; nullopt when it
    /// meets none or no scene is shown.
    std::optional<SegmentHit> pickSegment(const QVector3D& origin, const QVector3D& direction) const;
    /// Tints these segments of `character` as selected and clears every other highlight (-1 or
    /// an empty list: none). Kept across scene rebuilds; indices the scene does not have are
    /// ignored.
    void setHighlightedSegments(int character, const std::vector<int>& segments);
    int highlightedCharacter() const { return m_highlightCharacter; }
    const std::vector<int>& highlightedSegments() const { return m_highlightSegments; }

    /// Problems that did not stop loading (unmapped joints of a model, a probe that cannot be
    /// read, …).
    QStringList warnings() const;
    /// The scenario's light probe is being read and projected (off the GUI thread); until then
    /// the scene shows the default light.
    bool isLightLoading() const;
    /// The scene shown, or null.
    core::render::ScenarioScene* scene() const { return m_scene.get(); }

signals:
    /// The viewport was clicked (not dragged) on a segment; `modifiers` as held at the click.
    void segmentClicked(int character, int segment, Qt::KeyboardModifiers modifiers);
    /// The viewport was clicked where no character is.
    void emptySpaceClicked(Qt::KeyboardModifiers modifiers);
    /// The probe's light reached the scene, or could not (see warnings()).
    void lightLoaded(bool ok);
    /// A scene could not be built (problem()), after opening or editing a document.
    void sceneFailed(const QString& problem);
    /// A scene was built (a document opened, or an edit of bodies, tags, bakes, light or cast).
    void sceneBuilt();

private:
    // Builds the scene of the session's document; frameCamera: also aim the home view.
    void build(bool frameCamera);
    void onEdited(bool stageReplaced);
    void setPoses(const core::runtime::PoseSet& poses);
    void onViewportClicked(const QVector3D& origin, const QVector3D& direction, Qt::KeyboardModifiers modifiers);
    // Starts projecting the document's probe for the scene just built (a job off the GUI thread).
    void projectLight(const Document& document);
    void onLightProjected(const core::Result<void>& result);
    void applyHighlights();

    bool m_viewIsTheCamera = true;
    QPointer<widgets::OsgViewport> m_viewport; // may go first when a window closes
    Session* m_session = nullptr;
    QString m_problem;
    std::unique_ptr<core::render::ScenarioScene> m_scene;
    SceneSources m_sources; // what the scene was built from (build()); compared by onEdited()
    std::unique_ptr<JobRunner> m_lightJob;   // the probe's projection; replaced (so cancelled) by a rebuild
    QString m_lightProblem;
    core::render::Shading m_shading = core::render::Shading::Prt;
    bool m_groundVisible = true;
    int m_highlightCharacter = -1;
    std::vector<int> m_highlightSegments;
};

} // namespace thespis::editor
