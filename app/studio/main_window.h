#pragma once
// MainWindow: the studio's first window. Shows one scenario: every character as a stick figure
// posed at the playback clock's time (centre), the characters / layers / actions outline (a
// dock), the transport bar, and the file and preview rate in the status bar. Owns the open
// Document, the clock, and one PoseSampler per character.

#include <QElapsedTimer>
#include <QMainWindow>

#include <memory>
#include <vector>

#include "editor/document.h"
#include "editor/playback_clock.h"
#include "editor/pose_sampler.h"

class QAction;
class QActionGroup;
class QDockWidget;
class QLabel;
class QTimer;
class QTreeView;

namespace thespis::editor {
class ScenarioTreeModel;
}
namespace thespis::widgets {
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
    widgets::TransportBar* transportBar() const { return m_transport; }
    QTreeView* outlineView() const { return m_outline; }
    editor::ScenarioTreeModel* outlineModel() const { return m_model; }

private:
    void createActions();
    void createMenus();
    void createOutlineDock();
    void createStatusBar();
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
    QAction* m_aboutAction = nullptr;
    QAction* m_aboutQtAction = nullptr;

    // Preview rate: pose updates counted over about half a second.
    QTimer* m_fpsTimer = nullptr;
    QElapsedTimer m_fpsClock;
    int m_framesSinceFps = 0;
};

} // namespace thespis::studio
