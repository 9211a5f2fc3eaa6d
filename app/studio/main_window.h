#pragma once
// MainWindow: the studio's window. Shows one scenario as the Session plays it: the characters'
// bodies lit with PRT in a 3D viewport (first tab) and their skeletons as stick figures (second
// tab), the transport bar, and docks for the timeline, the curve editor, the joint-mask editor,
// the clip library, the scenario outline and the messages. Every view of what plays is a
// Session view; the window assembles them. Bringing content in (import, characters, layers,
// light) is ContentActions'; file handling is in main_window_files.cpp. File and Edit menus
// (new / open / save / recent, undo / redo); the dock layout is kept in QSettings.

#include <QElapsedTimer>
#include <QMainWindow>

#include <memory>
#include <optional>
#include <vector>

#include "editor/document.h"
#include "editor/playback_clock.h"
#include "editor/scene_preview.h"
#include "editor/session.h"
#include "editor/skeleton_view.h"
#include "util/tick.h"

class QAction;
class QActionGroup;
class QDockWidget;
class QLabel;
class QMenu;
class QTabWidget;
class QTimer;
class QUndoGroup;
class QTreeView;

namespace thespis::editor {
class ArPreviewPanel;
class Autosaver;
class MessagesPanel;
class ScriptPanel;
class ClipLibraryPanel;
class ConversationPanel;
class CurvePanel;
class BakePanel;
class PostureChartPanel;
class FacePosePanel;
class SpeechPanel;
class StageAudio;
class GesticonPanel;
class SegmentPanel;
class JointMaskPanel;
class PropertiesPanel;
class ScenarioTreeModel;
class TimelinePanel;
}
namespace thespis::widgets {
class OsgViewport;
class PoseView;
class TransportBar;
}

namespace thespis::editor {
class ContentActions;
}

namespace thespis::studio {

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    /// Opens a .thespis file or a package (.thespkg). On failure shows the error over the window, keeps what was open,
    /// and returns false.
    bool openScenario(const QString& path);
    /// Shows a document built elsewhere (a scenario made in code, tests); null closes it.
    void setDocument(std::unique_ptr<editor::Document> document);

    editor::Document* document() const { return m_session->document(); }
    editor::Session* session() const { return m_session; }
    editor::PlaybackClock* clock() const { return m_clock; }
    widgets::PoseView* poseView() const { return m_poseView; }
    editor::SkeletonView* skeletonView() const { return m_skeletons; }
    widgets::OsgViewport* viewport() const { return m_viewport; }
    editor::ScenePreview* scenePreview() const { return m_preview; }
    QTabWidget* views() const { return m_views; }
    widgets::TransportBar* transportBar() const { return m_transport; }
    QTreeView* outlineView() const { return m_outline; }
    editor::ScenarioTreeModel* outlineModel() const { return m_model; }
    editor::TimelinePanel* timeline() const { return m_timeline; }
    editor::CurvePanel* curveEditor() const { return m_curves; }
    editor::JointMaskPanel* maskEditor() const { return m_masks; }
    editor::ClipLibraryPanel* clipLibrary() const { return m_library; }
    editor::PropertiesPanel* properties() const { return m_properties; }
    editor::GesticonPanel* gesticon() const { return m_gesticon; }
    editor::FacePosePanel* facePose() const { return m_facePose; }
    editor::SpeechPanel* speech() const { return m_speech; }
    editor::ConversationPanel* conversation() const { return m_conversation; }
    editor::StageAudio* audio() const { return m_audio; }
    editor::SegmentPanel* segments() const { return m_segments; }
    editor::BakePanel* bakePanel() const { return m_bake; }
    editor::PostureChartPanel* postureChart() const { return m_postureChart; }
    editor::ArPreviewPanel* arPreview() const { return m_arPreview; }
    editor::Autosaver* autosaver() const { return m_autosaver; }
    QAction* undoAction() const { return m_undoAction; }
    QAction* redoAction() const { return m_redoAction; }
    editor::ContentActions* contentActions() const { return m_content; }
    editor::MessagesPanel* messagesPanel() const { return m_messages; }

    /// The character the Character menu and imports act on: the one selected in the outline
    /// (or owning the selected layer or action), else the timeline's current action's, else the
    /// first; -1 without characters.
    int currentCharacter() const;
    /// The layer selected in the outline, else the timeline's current action's, else none.
    std::optional<core::edit::LayerPath> currentLayer() const;
    /// Selects a character in the outline (and shows its properties).
    void selectCharacter(int character);

    /// Saves to the document's file, asking for one when it has none; false when not saved.
    bool save();
    bool saveAs(const QString& path);
    /// Offers the work an earlier, crashed session autosaved (a question over the window);
    /// returns true when a document was recovered.
    bool offerRecovery();
    /// Adds `path` to the top of File ▸ Open Recent.
    void addRecentFile(const QString& path);
    /// Starts a scenario never saved: empty, or with one character on the built-in humanoid
    /// standing in an idle (File ▸ New's two starting points).
    void newScenario(bool withCharacter);

protected:
    void closeEvent(QCloseEvent* event) override;

private:
    void createActions();
    void createMenus();
    void createToolBar();
    void createOutlineDock();
    void createEditorDocks();
    void onNew();
    bool onSaveAs();
    void onExportPackage();
    void onExportMotion();
    void updateRecentMenu();
    bool maybeSave();
    void onDocumentEdited();
    void refreshMessages();
    void createMessagesDock();
    void createScriptDock();
    /// True when the open scenario's file may run its scripts (asks the user once per file).
    bool confirmScriptTrust();
    void createStatusBar();
    void createShadingActions();
    void onOpen();
    void onReload();
    void onAbout();
    void onTimeChanged(core::Tick time);
    void onPlayingChanged(bool playing);
    void updateFps();
    void updateTitle();
    void setFrameRate(double framesPerSecond);
    void setShading(core::render::Shading shading);

    editor::Session* m_session = nullptr; // child: the document, its stage and the views that show it
    editor::SkeletonView* m_skeletons = nullptr;

    editor::PlaybackClock* m_clock = nullptr;
    editor::ScenarioTreeModel* m_model = nullptr;
    editor::ScenePreview* m_preview = nullptr;
    QTabWidget* m_views = nullptr;
    widgets::OsgViewport* m_viewport = nullptr;
    widgets::PoseView* m_poseView = nullptr;
    widgets::TransportBar* m_transport = nullptr;
    QTreeView* m_outline = nullptr;
    QDockWidget* m_outlineDock = nullptr;
    editor::TimelinePanel* m_timeline = nullptr;
    editor::CurvePanel* m_curves = nullptr;
    editor::JointMaskPanel* m_masks = nullptr;
    editor::ClipLibraryPanel* m_library = nullptr;
    editor::PropertiesPanel* m_properties = nullptr;
    editor::GesticonPanel* m_gesticon = nullptr;
    editor::FacePosePanel* m_facePose = nullptr;
    editor::SpeechPanel* m_speech = nullptr;
    editor::ConversationPanel* m_conversation = nullptr;
    editor::StageAudio* m_audio = nullptr; // child: what the studio plays aloud
    editor::SegmentPanel* m_segments = nullptr;
    editor::BakePanel* m_bake = nullptr;
    editor::PostureChartPanel* m_postureChart = nullptr;
    editor::ArPreviewPanel* m_arPreview = nullptr;
    editor::Autosaver* m_autosaver = nullptr;
    editor::MessagesPanel* m_messages = nullptr;
    QDockWidget* m_messagesDock = nullptr;
    editor::ScriptPanel* m_script = nullptr; // null when built without Python
    QDockWidget* m_scriptDock = nullptr;
    editor::ContentActions* m_content = nullptr;
    QList<QDockWidget*> m_editorDocks;
    QMenu* m_recentMenu = nullptr;
    QUndoGroup* m_undoGroup = nullptr; // the open document's undo stack, behind Edit ▸ Undo / Redo
    QLabel* m_fileLabel = nullptr;
    QLabel* m_fpsLabel = nullptr;

    QAction* m_newAction = nullptr;
    QAction* m_openAction = nullptr;
    QAction* m_saveAction = nullptr;
    QAction* m_saveAsAction = nullptr;
    QAction* m_exportPackageAction = nullptr;
    QAction* m_exportMotionAction = nullptr;
    QAction* m_undoAction = nullptr;
    QAction* m_redoAction = nullptr;
    QAction* m_reloadAction = nullptr;
    QAction* m_quitAction = nullptr;
    QAction* m_playPauseAction = nullptr;
    QAction* m_toStartAction = nullptr;
    QAction* m_toEndAction = nullptr;
    QAction* m_stepBackAction = nullptr;
    QAction* m_stepForwardAction = nullptr;
    QAction* m_loopAction = nullptr;
    QActionGroup* m_projectionGroup = nullptr;
    QActionGroup* m_shadingGroup = nullptr;
    QAction* m_groundAction = nullptr;
    QAction* m_homeViewAction = nullptr;
    QAction* m_preferencesAction = nullptr;
    QAction* m_aboutAction = nullptr;
    QAction* m_aboutQtAction = nullptr;

    // Preview rate: pose updates counted over about half a second.
    QTimer* m_fpsTimer = nullptr;
    QElapsedTimer m_fpsClock;
    int m_framesSinceFps = 0;
};

} // namespace thespis::studio
