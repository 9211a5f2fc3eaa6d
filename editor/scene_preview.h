#pragma once
// ScenePreview: the 3D view of the open document. Builds the scenario's render scene (bodies,
// light, ground — core::render::ScenarioScene) for a Document, hands its root node to an
// OsgViewport, frames the camera on the characters over the whole timeline, and poses every
// character whenever the playback time changes.

#include <QObject>
#include <QPointer>
#include <QString>
#include <QStringList>

#include <memory>

#include "render/scenario_scene.h"
#include "render/shading.h"
#include "util/error.h"

namespace thespis::widgets {
class OsgViewport;
}

namespace thespis::editor {

class Document;

class ScenePreview : public QObject {
    Q_OBJECT
public:
    explicit ScenePreview(widgets::OsgViewport* viewport, QObject* parent = nullptr);
    ~ScenePreview() override;

    /// Builds the scene of `document` (null clears the view). On failure the view is left empty
    /// and the error says which character or file could not be loaded.
    core::Result<void> setDocument(const Document* document);
    /// After an edit of `document`: plays its new schedules (rebuilding the scene only when the
    /// characters themselves changed) and redraws at the current time.
    core::Result<void> updateDocument(const Document* document);
    /// Poses every character at `seconds` and redraws.
    void setTime(double seconds);
    void setShading(core::render::Shading shading);
    core::render::Shading shading() const { return m_shading; }
    void setGroundVisible(bool visible);
    bool groundVisible() const { return m_groundVisible; }

    /// Problems that did not stop loading (unmapped joints of a model, …).
    QStringList warnings() const;
    /// The scene shown, or null.
    core::render::ScenarioScene* scene() const { return m_scene.get(); }

private:
    QPointer<widgets::OsgViewport> m_viewport; // may go first when a window closes
    std::unique_ptr<core::render::ScenarioScene> m_scene;
    core::render::Shading m_shading = core::render::Shading::Prt;
    bool m_groundVisible = true;
};

} // namespace thespis::editor
