#pragma once
// MainWindow: the studio's window. Shows one scenario posed at the playback clock's time: the
// characters' bodies lit with PRT in a 3D viewport (first tab) and their skeletons as stick
// figures (second tab), the characters / layers / actions outline (a dock), the transport bar,
// and the file and preview rate in the status bar. Owns the open Document, the clock, the 3D
// preview and one PoseSampler per character.

#include <QElapsedTimer>
#include <QMainWindow>

#include <memory>
#include <vector>

#include "editor/document.h"
#include "editor/playback_clock.h"
#include "editor/pose_sampler.h"
#include "editor/scene_preview.h"

class QAction;
class QActionGroup;
class QDockWidget;
class QLabel;
class QTabWidget;
class QTimer;
class QTreeView;

namespace thespis::editor {
class ScenarioTreeModel;
}
namespace thespis::widgets {
class OsgViewport;
class PoseView;
class TransportBar;
}

namespace thespis::studio {

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    /// Opens a .thespis file. On failure shows the error over the window, keeps what was open,
    /// and returns false.
    bool openScenario(const QString& path);
    /// Shows a document built elsewhere (a scenario made in code, tests); null closes it.
    void setDocument(std::unique_ptr<editor::Document> document);

    editor::Document* document() const { return m_document.get(); }
    editor::PlaybackClock* clock() const { return m_clock; }
    widgets::PoseView* poseView() const { return m_poseView; }
    widgets::OsgViewport* viewport() const { return m_viewport; }
    editor::ScenePreview* scenePreview() const { return m_preview; }
    QTabWidget* views() const { return m_views; }
    widgets::TransportBar* transportBar() const { return m_transport; }
    QTreeView* outlineView() const { return m_outline; }
    editor::ScenarioTreeModel* outlineModel() const { return m_model; }

private:
    void createActions();
    void createMenus();
    void createOutlineDock();
    void createStatusBar();
    void createShadingActions();
    void onOpen();
    void onReload();
    void onAbout();
    void onTimeChanged(double seconds);
    void onPlayingChanged(bool playing);
    void updateFps();
    void updateTitle();

    // The samplers point into the document's runtime: declared after it, destroyed before it.
    std::unique_ptr<editor::Document> m_document;
    std::vector<editor::PoseSampler> m_samplers;

    editor::PlaybackClock* m_clock = nullptr;
    editor::ScenarioTreeModel* m_model = nullptr;
    editor::ScenePreview* m_preview = nullptr;
    QTabWidget* m_views = nullptr;
    widgets::OsgViewport* m_viewport = nullptr;
    widgets::PoseView* m_poseView = nullptr;
    widgets::TransportBar* m_transport = nullptr;
    QTreeView* m_outline = nullptr;
    QDockWidget* m_outlineDock = nullptr;
    QLabel* m_fileLabel = nullptr;
    QLabel* m_fpsLabel = nullptr;

    QAction* m_openAction = nullptr;
    QAction* m_reloadAction = nullptr;
    QAction* m_quitAction = nullptr;
    QAction* m_playPauseAction = nullptr;
    QAction* m_toStartAction = nullptr;
    QAction* m_loopAction = nullptr;
    QActionGroup* m_projectionGroup = nullptr;
    QActionGroup* m_shadingGroup = nullptr;
    QAction* m_groundAction = nullptr;
    QAction* m_homeViewAction = nullptr;
    QAction* m_aboutAction = nullptr;
    QAction* m_aboutQtAction = nullptr;

    // Preview rate: pose updates counted over about half a second.
    QTimer* m_fpsTimer = nullptr;
    QElapsedTimer m_fpsClock;
    int m_framesSinceFps = 0;
};

} // namespace thespis::studio
