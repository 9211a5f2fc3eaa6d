#include "main_window.h"

#include "editor/stage_audio.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QDir>
#include <QDockWidget>
#include <QFrame>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QSettings>
#include <QUndoGroup>
#include <QUndoStack>
#include <QStatusBar>
#include <QStyle>
#include <QTabWidget>
#include <QTimer>
#include <QToolBar>
#include <QTreeView>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

#include "editor/ar_preview_panel.h"
#include "editor/autosave.h"
#include "editor/bake_panel.h"
#include "editor/clip_library_panel.h"
#include "editor/curve_panel.h"
#include "editor/face_pose_panel.h"
#include "editor/gesticon_panel.h"
#include "editor/joint_mask_panel.h"
#include "editor/messages_panel.h"
#ifdef THESPIS_WITH_PYTHON
#include "editor/script_panel.h"
#endif
#include "editor/posture_chart_panel.h"
#include "editor/properties_panel.h"
#include "editor/content_actions.h"
#include "preferences_dialog.h"
#include "editor/scenario_tree_model.h"
#include "editor/segment_panel.h"
#include "editor/timeline_panel.h"
#include "widgets/osg_viewport.h"
#include "widgets/pose_view.h"
#include "widgets/transport_bar.h"

namespace thespis::studio {

namespace {
const QString kWindowStateKey = QStringLiteral("mainWindow/state");
const QString kWindowGeometryKey = QStringLiteral("mainWindow/geometry");
const QString kFrameRateKey = QStringLiteral("playback/frameRate");
} // namespace

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent)
{
    setObjectName(QStringLiteral("mainWindow"));
    m_clock = new editor::PlaybackClock(this);
    m_session = new editor::Session(m_clock, this);
    m_audio = new editor::StageAudio(m_session, this);
    m_model = new editor::ScenarioTreeModel(this);

    auto* central = new QWidget(this);
    auto* layout = new QVBoxLayout(central);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    m_views = new QTabWidget(central);
    m_views->setObjectName(QStringLiteral("views"));
    m_views->setDocumentMode(true);
    QWidget* scene = nullptr;
    if (widgets::OsgViewport::isSupported()) {
        m_viewport = new widgets::OsgViewport(m_views);
        m_viewport->setObjectName(QStringLiteral("viewport"));
        m_viewport->setToolTip(tr("Drag to orbit, right-drag or wheel to zoom, middle-drag to pan, double-click for the home view"));
        m_preview = new editor::ScenePreview(m_viewport, this);
        m_preview->setSession(m_session);
        connect(m_preview, &editor::ScenePreview::sceneFailed, this, [this](const QString& problem) {
            statusBar()->showMessage(tr("The 3D view is empty: %1").arg(problem));
        });
        connect(m_viewport, &widgets::OsgViewport::glError, this,
                [this](const QString& message) { statusBar()->showMessage(message); });
        scene = m_viewport;
    } else {
        auto* unavailable = new QLabel(tr("No 3D view: this display offers no OpenGL.\n"
                                          "The Skeletons tab shows the animation; thespis-cli render draws the scene headless."),
                                       m_views);
        unavailable->setObjectName(QStringLiteral("viewportUnavailable"));
        unavailable->setAlignment(Qt::AlignCenter);
        unavailable->setWordWrap(true);
        scene = unavailable;
    }
    m_poseView = new widgets::PoseView(m_views);
    m_poseView->setObjectName(QStringLiteral("poseView"));
    // A click in either view gives it the keyboard, so that the arrows then step frames.
    if (m_viewport)
        m_viewport->setFocusPolicy(Qt::StrongFocus);
    m_poseView->setFocusPolicy(Qt::StrongFocus);
    m_views->addTab(scene, tr("Scene"));
    m_views->addTab(m_poseView, tr("Skeletons"));
    m_skeletons = new editor::SkeletonView(m_poseView, m_session, this);
    auto* line = new QFrame(central);
    line->setFrameShape(QFrame::HLine);
    line->setFrameShadow(QFrame::Sunken);
    m_transport = new widgets::TransportBar(central);
    m_transport->setObjectName(QStringLiteral("transportBar"));
    layout->addWidget(m_views, 1);
    layout->addWidget(line);
    layout->addWidget(m_transport);
    setCentralWidget(central);

    // The transport asks; the clock decides; everything shown follows the clock.
    connect(m_transport, &widgets::TransportBar::playRequested, m_clock, &editor::PlaybackClock::play);
    connect(m_transport, &widgets::TransportBar::pauseRequested, m_clock, &editor::PlaybackClock::pause);
    connect(m_transport, &widgets::TransportBar::seekRequested, m_clock,
            [this](double seconds) { m_clock->seek(core::secondsToTicks(seconds)); });
    connect(m_transport, &widgets::TransportBar::loopRequested, m_clock, &editor::PlaybackClock::setLooping);
    connect(m_clock, &editor::PlaybackClock::timeChanged, this, &MainWindow::onTimeChanged);
    connect(m_clock, &editor::PlaybackClock::playingChanged, this, &MainWindow::onPlayingChanged);
    connect(m_clock, &editor::PlaybackClock::loopingChanged, this, [this](bool looping) {
        m_transport->setLooping(looping);
        m_loopAction->setChecked(looping);
    });
    connect(m_clock, &editor::PlaybackClock::durationChanged, m_transport,
            [this](core::Tick duration) { m_transport->setDuration(core::ticksToSeconds(duration)); });
    connect(m_transport, &widgets::TransportBar::stepRequested, m_clock, &editor::PlaybackClock::step);
    connect(m_transport, &widgets::TransportBar::frameRateRequested, this, &MainWindow::setFrameRate);

    m_autosaver = new editor::Autosaver(this);
    m_autosaver->setInterval(PreferencesDialog::storedAutosaveMinutes() * 60 * 1000);
    connect(m_autosaver, &editor::Autosaver::failed, this, [this](const QString& message) { statusBar()->showMessage(message, 10000); });

    createActions();
    createShadingActions();
    m_content = new editor::ContentActions(m_session, this,
                                           {[this] { return currentCharacter(); }, [this] { return currentLayer(); },
                                            [this](int character) { selectCharacter(character); }});
    connect(m_content, &editor::ContentActions::message, this, [this](const QString& m) { statusBar()->showMessage(m, 8000); });
    createOutlineDock();
    createEditorDocks();
    createMessagesDock();
    createScriptDock();
    createMenus();
    createToolBar();
    createStatusBar();
    // Handed to the session once: each follows every document opened or closed from now on.
    m_session->addPanel(m_model);
    m_session->addPanel(m_timeline);
    m_session->addPanel(m_curves);
    m_session->addPanel(m_masks);
    m_session->addPanel(m_library);
    m_session->addPanel(m_properties);
    m_session->addPanel(m_gesticon);
    m_session->addPanel(m_facePose);
    m_session->addPanel(m_segments);
    m_session->addPanel(m_bake);
    m_session->addPanel(m_postureChart);
    m_session->addPanel(m_arPreview);
    connect(m_arPreview, &editor::ArPreviewPanel::runningChanged, this,
            [this](bool running) {
                if (m_preview)
                    m_preview->setViewIsTheCamera(!running);
            });
    m_session->addPanel(m_autosaver);
    // After the views: when the window refreshes its lists, the views have followed the edit.
    connect(m_session, &editor::Session::edited, this, &MainWindow::onDocumentEdited);

    m_fpsTimer = new QTimer(this);
    m_fpsTimer->setInterval(500);
    connect(m_fpsTimer, &QTimer::timeout, this, &MainWindow::updateFps);

    // Most of the screen, and enough for the outline's columns beside a usable preview.
    const QRect screen = this->screen() ? this->screen()->availableGeometry() : QRect(0, 0, 1600, 1000);
    resize(std::min(1500, screen.width() * 9 / 10), std::min(900, screen.height() * 9 / 10));
    resizeDocks({m_outlineDock}, {std::min(420, width() / 3)}, Qt::Horizontal);
    resizeDocks({m_editorDocks.front()}, {std::min(300, height() / 3)}, Qt::Vertical);
    const QSettings settings;
    setFrameRate(settings.value(kFrameRateKey, 30.0).toDouble());
    restoreGeometry(settings.value(kWindowGeometryKey).toByteArray());
    restoreState(settings.value(kWindowStateKey).toByteArray());
    setDocument(nullptr);
}

MainWindow::~MainWindow()
{
    // The model and the panels read the document: detach them before it goes.
    m_session->setDocument(nullptr);
}

void MainWindow::createActions()
{
    m_newAction = new QAction(tr("&New"), this);
    m_newAction->setObjectName(QStringLiteral("newScenario"));
    m_newAction->setShortcut(QKeySequence::New);
    m_newAction->setStatusTip(tr("Start a new scenario: empty, or with one character standing"));
    connect(m_newAction, &QAction::triggered, this, &MainWindow::onNew);

    m_saveAction = new QAction(tr("&Save"), this);
    m_saveAction->setShortcut(QKeySequence::Save);
    connect(m_saveAction, &QAction::triggered, this, &MainWindow::save);
    m_saveAsAction = new QAction(tr("Save &As…"), this);
    m_saveAsAction->setShortcut(QKeySequence::SaveAs);
    connect(m_saveAsAction, &QAction::triggered, this, &MainWindow::onSaveAs);
    m_exportPackageAction = new QAction(tr("&Package…"), this);
    m_exportPackageAction->setObjectName(QStringLiteral("exportPackage"));
    m_exportPackageAction->setStatusTip(tr("Write the scenario and every file it names into one package (.thespkg)"));
    connect(m_exportPackageAction, &QAction::triggered, this, &MainWindow::onExportPackage);
    m_exportMotionAction = new QAction(tr("&Motion (glTF or BVH)…"), this);
    m_exportMotionAction->setObjectName(QStringLiteral("exportMotion"));
    m_exportMotionAction->setStatusTip(tr("Write a character's motion as glTF (.glb, with the character) or BVH, for "
                                          "Blender, three.js and game engines"));
    connect(m_exportMotionAction, &QAction::triggered, this, &MainWindow::onExportMotion);

    m_undoGroup = new QUndoGroup(this);
    m_undoAction = m_undoGroup->createUndoAction(this, tr("&Undo"));
    m_undoAction->setShortcut(QKeySequence::Undo);
    m_undoAction->setObjectName(QStringLiteral("undo"));
    m_redoAction = m_undoGroup->createRedoAction(this, tr("&Redo"));
    m_redoAction->setShortcuts({QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z), QKeySequence::Redo});
    m_redoAction->setObjectName(QStringLiteral("redo"));

    m_openAction = new QAction(tr("&Open…"), this);
    m_openAction->setShortcut(QKeySequence::Open);
    m_openAction->setStatusTip(tr("Open a scenario file (.thespis) or a package (.thespkg)"));
    connect(m_openAction, &QAction::triggered, this, &MainWindow::onOpen);

    m_reloadAction = new QAction(tr("&Reload"), this);
    m_reloadAction->setShortcut(QKeySequence::Refresh);
    m_reloadAction->setStatusTip(tr("Read the scenario file again, e.g. after editing it elsewhere"));
    connect(m_reloadAction, &QAction::triggered, this, &MainWindow::onReload);

    m_quitAction = new QAction(tr("&Quit"), this);
    m_quitAction->setShortcut(QKeySequence::Quit);
    m_quitAction->setMenuRole(QAction::QuitRole);
    connect(m_quitAction, &QAction::triggered, this, &QWidget::close);

    // Window-wide shortcuts, so that Space plays whichever panel has the focus.
    m_playPauseAction = new QAction(tr("&Play/Pause"), this);
    m_playPauseAction->setShortcut(Qt::Key_Space);
    m_playPauseAction->setShortcutContext(Qt::WindowShortcut);
    connect(m_playPauseAction, &QAction::triggered, m_clock, &editor::PlaybackClock::togglePlayPause);
    addAction(m_playPauseAction);

    m_toStartAction = new QAction(tr("Go to &Start"), this);
    m_toStartAction->setShortcut(Qt::Key_Home);
    connect(m_toStartAction, &QAction::triggered, m_clock, [this] { m_clock->seek(0); });
    addAction(m_toStartAction);

    m_toEndAction = new QAction(tr("Go to &End"), this);
    m_toEndAction->setShortcut(Qt::Key_End);
    connect(m_toEndAction, &QAction::triggered, m_clock, [this] { m_clock->seek(m_clock->duration()); });
    addAction(m_toEndAction);

    // The arrows step frames where they mean nothing else: in the views, the transport and the
    // timeline (added there in createEditorDocks); lists and fields keep them for moving about.
    m_stepBackAction = new QAction(tr("Previous &Frame"), this);
    m_stepBackAction->setShortcut(Qt::Key_Left);
    m_stepBackAction->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    connect(m_stepBackAction, &QAction::triggered, m_clock, [this] { m_clock->step(-1); });
    m_stepForwardAction = new QAction(tr("&Next Frame"), this);
    m_stepForwardAction->setShortcut(Qt::Key_Right);
    m_stepForwardAction->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    connect(m_stepForwardAction, &QAction::triggered, m_clock, [this] { m_clock->step(1); });
    centralWidget()->addAction(m_stepBackAction);
    centralWidget()->addAction(m_stepForwardAction);

    m_loopAction = new QAction(tr("&Loop"), this);
    m_loopAction->setCheckable(true);
    m_loopAction->setShortcut(Qt::Key_L);
    connect(m_loopAction, &QAction::toggled, m_clock, &editor::PlaybackClock::setLooping);
    addAction(m_loopAction);

    m_projectionGroup = new QActionGroup(this);
    const std::pair<QString, widgets::PoseView::Projection> projections[] = {
        {tr("&Front and Side"), widgets::PoseView::Projection::FrontAndSide},
        {tr("F&ront"), widgets::PoseView::Projection::Front},
        {tr("&Side"), widgets::PoseView::Projection::Side},
    };
    for (const auto& [text, projection] : projections) {
        QAction* action = m_projectionGroup->addAction(text);
        action->setCheckable(true);
        action->setChecked(projection == m_poseView->projection());
        connect(action, &QAction::triggered, m_poseView, [this, projection = projection] { m_poseView->setProjection(projection); });
    }

    m_preferencesAction = new QAction(tr("&Preferences…"), this);
    m_preferencesAction->setObjectName(QStringLiteral("preferences"));
    m_preferencesAction->setMenuRole(QAction::PreferencesRole);
    m_preferencesAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Comma));
    connect(m_preferencesAction, &QAction::triggered, this, [this] {
        PreferencesDialog dialog(this);
        if (dialog.exec() == QDialog::Accepted)
            m_autosaver->setInterval(PreferencesDialog::storedAutosaveMinutes() * 60 * 1000);
    });

    m_aboutAction = new QAction(tr("&About Thespis Studio"), this);
    m_aboutAction->setMenuRole(QAction::AboutRole);
    connect(m_aboutAction, &QAction::triggered, this, &MainWindow::onAbout);
    m_aboutQtAction = new QAction(tr("About &Qt"), this);
    m_aboutQtAction->setMenuRole(QAction::AboutQtRole);
    connect(m_aboutQtAction, &QAction::triggered, qApp, &QApplication::aboutQt);
}

void MainWindow::createToolBar()
{
    // Icons from the desktop theme where it has them, else Qt's own.
    auto icon = [this](const char* themeName, QStyle::StandardPixmap fallback) {
        return QIcon::fromTheme(QLatin1String(themeName), style()->standardIcon(fallback));
    };
    m_newAction->setIcon(icon("document-new", QStyle::SP_FileIcon));
    m_openAction->setIcon(icon("document-open", QStyle::SP_DialogOpenButton));
    m_saveAction->setIcon(icon("document-save", QStyle::SP_DialogSaveButton));
    m_undoAction->setIcon(icon("edit-undo", QStyle::SP_ArrowBack));
    m_redoAction->setIcon(icon("edit-redo", QStyle::SP_ArrowForward));
    m_homeViewAction->setIcon(icon("go-home", QStyle::SP_DirHomeIcon));

    QToolBar* bar = addToolBar(tr("Main Toolbar"));
    bar->setObjectName(QStringLiteral("mainToolBar"));
    bar->addAction(m_newAction);
    bar->addAction(m_openAction);
    bar->addAction(m_saveAction);
    bar->addSeparator();
    bar->addAction(m_undoAction);
    bar->addAction(m_redoAction);
    bar->addSeparator();
    // Lighting of the 3D view: PRT, Phong or unlit, as in View.
    bar->addActions(m_shadingGroup->actions());
    bar->addAction(m_homeViewAction);
    bar->addSeparator();
    bar->addAction(m_content->importMotionAction());
    bar->addAction(m_content->addCharacterAction());
    bar->addAction(m_content->lightingAction());
}

void MainWindow::createMenus()
{
    QMenu* file = menuBar()->addMenu(tr("&File"));
    file->addAction(m_newAction);
    file->addAction(m_openAction);
    m_recentMenu = file->addMenu(tr("Open &Recent"));
    m_recentMenu->setObjectName(QStringLiteral("recentMenu"));
    updateRecentMenu();
    file->addAction(m_reloadAction);
    file->addSeparator();
    file->addAction(m_content->importMotionAction());
    file->addSeparator();
    file->addAction(m_saveAction);
    file->addAction(m_saveAsAction);
    QMenu* exportMenu = file->addMenu(tr("&Export"));
    exportMenu->setObjectName(QStringLiteral("exportMenu"));
    exportMenu->addAction(m_exportPackageAction);
    exportMenu->addAction(m_exportMotionAction);
    file->addSeparator();
    file->addAction(m_quitAction);

    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    edit->addAction(m_undoAction);
    edit->addAction(m_redoAction);
    edit->addSeparator();
    edit->addAction(m_timeline->copyAction());
    edit->addAction(m_timeline->pasteAction());
    edit->addAction(m_timeline->duplicateAction());
    edit->addAction(m_timeline->deleteAction());
    edit->addAction(m_timeline->rippleDeleteAction());
    edit->addAction(m_timeline->splitAction());
    edit->addSeparator();
    edit->addAction(m_timeline->snapAction());
    edit->addSeparator();
    edit->addAction(m_preferencesAction);
    for (QAction* action : {m_timeline->copyAction(), m_timeline->pasteAction(), m_timeline->duplicateAction(),
                            m_timeline->deleteAction(), m_timeline->rippleDeleteAction(), m_timeline->splitAction()})
        addAction(action);

    QMenu* character = menuBar()->addMenu(tr("&Character"));
    character->setObjectName(QStringLiteral("characterMenu"));
    m_content->fillCharacterMenu(character);
    connect(character, &QMenu::aboutToShow, m_content, &editor::ContentActions::updateEnabled);

    QMenu* playback = menuBar()->addMenu(tr("&Playback"));
    playback->addAction(m_playPauseAction);
    playback->addAction(m_toStartAction);
    playback->addAction(m_toEndAction);
    playback->addAction(m_stepBackAction);
    playback->addAction(m_stepForwardAction);
    playback->addAction(m_loopAction);

    QMenu* view = menuBar()->addMenu(tr("&View"));
    view->addSection(tr("Scene"));
    view->addActions(m_shadingGroup->actions());
    view->addAction(m_groundAction);
    view->addAction(m_content->lightingAction());
    view->addAction(m_homeViewAction);
    // A close-up of each character's face, as it is posed now (listed when the menu opens).
    QMenu* closeUp = view->addMenu(tr("&Close-up"));
    closeUp->setObjectName(QStringLiteral("closeUpMenu"));
    connect(closeUp, &QMenu::aboutToShow, this, [this, closeUp] {
        closeUp->clear();
        const editor::Document* document = m_session->document();
        const int count = document ? int(document->scenario().characters.size()) : 0;
        for (int c = 0; c < count; ++c) {
            QAction* action = closeUp->addAction(QString::fromStdString(document->scenario().characters[std::size_t(c)].name));
            action->setEnabled(m_preview != nullptr);
            connect(action, &QAction::triggered, this, [this, c] {
                if (m_preview && !m_preview->closeUp(c))
                    statusBar()->showMessage(tr("This character has no head to frame."), 4000);
            });
        }
        if (count == 0)
            closeUp->addAction(tr("No characters"))->setEnabled(false);
    });
    view->addSection(tr("Stick figures"));
    view->addActions(m_projectionGroup->actions());
    view->addSeparator();
    for (QDockWidget* dock : m_editorDocks)
        view->addAction(dock->toggleViewAction());
    view->addAction(m_outlineDock->toggleViewAction());
    view->addAction(m_messagesDock->toggleViewAction());
    if (m_scriptDock)
        view->addAction(m_scriptDock->toggleViewAction());

    QMenu* help = menuBar()->addMenu(tr("&Help"));
    help->addAction(m_aboutAction);
    help->addAction(m_aboutQtAction);
}

void MainWindow::createShadingActions()
{
    // Without a 3D view the actions exist (menus stay the same) but are disabled.
    const bool haveScene = m_preview != nullptr;
    m_shadingGroup = new QActionGroup(this);
    const std::pair<QString, core::render::Shading> shadings[] = {
        {tr("&PRT Lighting"), core::render::Shading::Prt},
        {tr("P&hong Lighting"), core::render::Shading::Phong},
        {tr("&Unlit"), core::render::Shading::Unlit},
    };
    for (const auto& [text, shading] : shadings) {
        QAction* action = m_shadingGroup->addAction(text);
        action->setCheckable(true);
        action->setChecked(shading == core::render::Shading::Prt);
        action->setObjectName(QStringLiteral("shading_") + QLatin1String(core::render::shadingName(shading)));
        if (haveScene)
            connect(action, &QAction::triggered, this, [this, shading = shading] { setShading(shading); });
    }
    m_shadingGroup->setEnabled(haveScene);
    m_shadingGroup->actions().at(0)->setStatusTip(tr("Precomputed radiance transfer: soft light and self-shadowing from the light probe"));
    m_shadingGroup->actions().at(1)->setStatusTip(tr("One directional light and ambient, for comparison with PRT"));
    m_groundAction = new QAction(tr("&Ground"), this);
    m_groundAction->setCheckable(true);
    m_groundAction->setChecked(true);
    m_groundAction->setEnabled(haveScene);
    m_homeViewAction = new QAction(tr("&Home View"), this);
    m_homeViewAction->setShortcut(Qt::Key_H);
    m_homeViewAction->setEnabled(haveScene);
    if (haveScene) {
        connect(m_groundAction, &QAction::toggled, m_preview, &editor::ScenePreview::setGroundVisible);
        connect(m_homeViewAction, &QAction::triggered, m_viewport, &widgets::OsgViewport::home);
    }
    addAction(m_homeViewAction);
}

void MainWindow::createStatusBar()
{
    m_fileLabel = new QLabel(this);
    m_fileLabel->setObjectName(QStringLiteral("fileLabel"));
    m_fpsLabel = new QLabel(this);
    m_fpsLabel->setObjectName(QStringLiteral("fpsLabel"));
    m_fpsLabel->setToolTip(tr("How often the preview is redrawn"));
    m_fpsLabel->setMinimumWidth(m_fpsLabel->fontMetrics().horizontalAdvance(tr("Preview: 000 fps")) + 8);
    statusBar()->addPermanentWidget(m_fileLabel);
    statusBar()->addPermanentWidget(m_fpsLabel);
}

void MainWindow::setDocument(std::unique_ptr<editor::Document> next)
{
    if (m_session->document())
        m_undoGroup->removeStack(m_session->document()->undoStack());
    // Every panel registered with the session follows (registerViews).
    m_session->setDocument(std::move(next));
    if (editor::Document* opened = m_session->document()) {
        m_undoGroup->addStack(opened->undoStack());
        m_undoGroup->setActiveStack(opened->undoStack());
        connect(opened, &editor::Document::modifiedChanged, this, &MainWindow::updateTitle);
        connect(opened, &editor::Document::filePathChanged, this, &MainWindow::updateTitle);
    }

    m_outline->expandAll();
    const QString sceneProblem =
        m_preview && !m_preview->problem().isEmpty() ? tr("The 3D view is empty: %1").arg(m_preview->problem()) : QString();

    const bool open = document() != nullptr;
    m_transport->setEnabled(open);
    m_reloadAction->setEnabled(open && !document()->filePath().isEmpty());
    m_saveAction->setEnabled(open);
    m_saveAsAction->setEnabled(open);
    m_exportPackageAction->setEnabled(open);
    m_exportMotionAction->setEnabled(open && !document()->scenario().characters.empty());
    m_playPauseAction->setEnabled(open);
    m_toStartAction->setEnabled(open);
    m_toEndAction->setEnabled(open);
    m_stepBackAction->setEnabled(open);
    m_stepForwardAction->setEnabled(open);
    m_loopAction->setEnabled(open);
    m_transport->setDuration(core::ticksToSeconds(m_clock->duration()));
    onTimeChanged(m_clock->time()); // the time shown everywhere, even when it did not change

    if (open) {
        m_fileLabel->setText(document()->fileName());
        m_fileLabel->setToolTip(QDir::toNativeSeparators(document()->filePath()));
        int actions = 0;
        for (const core::scenario::Character& character : document()->scenario().characters)
            for (const core::scenario::Layer& layer : character.layers)
                actions += int(layer.actions.size());
        QString summary = tr("Opened %1: %n character(s)", nullptr, int(document()->scenario().characters.size()))
                              .arg(document()->fileName()) +
                          tr(", %n action(s)", nullptr, actions) +
                          tr(", %1 s long. Press Space to play.").arg(core::ticksToSeconds(document()->previewDuration()), 0, 'f', 1);
        refreshMessages();
        if (const int warnings = m_messages->count() - (m_messages->item(0)->flags() == Qt::NoItemFlags ? 1 : 0); warnings > 0)
            summary += QLatin1Char(' ') + tr("%n warning(s): see Messages.", nullptr, warnings);
        statusBar()->showMessage(sceneProblem.isEmpty() ? summary : sceneProblem);
    } else {
        m_fileLabel->clear();
        m_fileLabel->setToolTip({});
        statusBar()->clearMessage();
    }
    onPlayingChanged(m_clock->isPlaying());
    updateTitle();
    m_content->updateEnabled();
}

void MainWindow::onAbout()
{
    QMessageBox::about(this, tr("About Thespis Studio"),
                       tr("<h3>Thespis Studio %1</h3>"
                          "<p>An authoring studio for interactive virtual humans in mixed reality: "
                          "blending schedules, speech and gestures, precomputed lighting, and AR preview.</p>"
                          "<p>Built on the MIRAnim blending engine described by Egges, Papagiannakis and "
                          "Magnenat-Thalmann, <i>Presence and interaction in mixed reality environments</i>, "
                          "The Visual Computer, 2007.</p>")
                           .arg(QStringLiteral(THESPIS_VERSION)));
}

void MainWindow::onTimeChanged(core::Tick time)
{
    // The time shown; what plays then is drawn by the Session's views at its tick.
    m_transport->setTime(core::ticksToSeconds(time));
    m_model->setTime(time);
    m_timeline->setTime(time);
    m_curves->setTime(time);
    ++m_framesSinceFps;
}

void MainWindow::onPlayingChanged(bool playing)
{
    m_transport->setPlaying(playing);
    m_playPauseAction->setText(playing ? tr("&Pause") : tr("&Play"));
    m_framesSinceFps = 0;
    m_fpsClock.start();
    if (playing)
        m_fpsTimer->start();
    else
        m_fpsTimer->stop();
    updateFps();
}

void MainWindow::updateFps()
{
    if (!document()) {
        m_fpsLabel->clear();
        return;
    }
    if (!m_clock->isPlaying()) {
        m_fpsLabel->setText(tr("Paused"));
        return;
    }
    const qint64 elapsed = m_fpsClock.restart();
    if (elapsed > 0 && m_framesSinceFps > 0)
        m_fpsLabel->setText(tr("Preview: %1 fps").arg(qRound(1000.0 * m_framesSinceFps / double(elapsed))));
    else
        m_fpsLabel->setText(tr("Playing"));
    m_framesSinceFps = 0;
}

void MainWindow::setFrameRate(double framesPerSecond)
{
    // Whole rates only: the timeline snaps to frames in exact ticks.
    const int rate = std::clamp(int(std::lround(framesPerSecond)), 1, 240);
    m_clock->setFrameRate(rate);
    m_transport->setFrameRate(rate);
    m_timeline->setFrameRate(rate);
    QSettings().setValue(kFrameRateKey, rate);
}

void MainWindow::setShading(core::render::Shading shading)
{
    if (!m_preview)
        return;
    m_preview->setShading(shading);
    for (QAction* action : m_shadingGroup->actions())
        if (action->objectName() == QStringLiteral("shading_") + QLatin1String(core::render::shadingName(shading)))
            action->setChecked(true);
    m_bake->setPrtPreview(shading == core::render::Shading::Prt);
}

void MainWindow::updateTitle()
{
    if (!document()) {
        setWindowModified(false);
        setWindowTitle(tr("Thespis Studio"));
        return;
    }
    // [*] is where Qt shows the modified mark.
    setWindowTitle(tr("%1[*] — Thespis Studio").arg(document()->scenarioName()));
    setWindowModified(document()->isModified());
    m_fileLabel->setText(document()->fileName());
    m_fileLabel->setToolTip(QDir::toNativeSeparators(document()->sourceFile()));
}

void MainWindow::onDocumentEdited()
{
    // The outline is rebuilt: the same character or layer stays selected.
    const auto location = m_model->locationOf(m_outline->currentIndex());
    m_model->setDocument(document());
    m_outline->expandAll();
    if (location)
        if (const QModelIndex index = m_model->indexOf(location->character, location->layer); index.isValid())
            m_outline->setCurrentIndex(index);
    refreshMessages();
    m_content->updateEnabled();
}

void MainWindow::closeEvent(QCloseEvent* event)
{
    if (!maybeSave()) {
        event->ignore();
        return;
    }
    QSettings settings;
    settings.setValue(kWindowGeometryKey, saveGeometry());
    settings.setValue(kWindowStateKey, saveState());
    m_autosaver->discard(); // a clean close: nothing to recover
    event->accept();
}

} // namespace thespis::studio
