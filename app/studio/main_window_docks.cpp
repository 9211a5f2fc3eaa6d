// MainWindow's docks: the scenario outline, the editors around the timeline, and the Messages
// list, with what picking in them selects. The rest of the window is in main_window.cpp.

#include "main_window.h"

#include <QCheckBox>
#include <QCoreApplication>
#include <QDir>
#include <QDockWidget>
#include <QHeaderView>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QStatusBar>
#include <QTreeView>
#include <QTreeWidget>

#include "editor/content_actions.h"
#include "startup.h"
#include "editor/ar_preview_panel.h"
#include "editor/bake_panel.h"
#include "editor/clip_library_panel.h"
#include "editor/conversation_panel.h"
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
#include "editor/qt_conversions.h"
#include "editor/scenario_tree_model.h"
#include "editor/script_trust.h"
#include "editor/segment_panel.h"
#include "editor/speech_panel.h"
#include "editor/timeline_panel.h"

namespace thespis::studio {

void MainWindow::createOutlineDock()
{
    m_outlineDock = new QDockWidget(tr("Scenario"), this);
    m_outlineDock->setObjectName(QStringLiteral("outlineDock"));
    m_outlineDock->setAllowedAreas(Qt::LeftDockWidgetArea | Qt::RightDockWidgetArea);
    m_outline = new QTreeView(m_outlineDock);
    m_outline->setObjectName(QStringLiteral("outlineView"));
    m_outline->setModel(m_model);
    m_outline->setAlternatingRowColors(true);
    m_outline->setUniformRowHeights(true);
    m_outline->setAllColumnsShowFocus(true);
    m_outline->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_outline->header()->setStretchLastSection(false);
    m_outline->header()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_outlineDock->toggleViewAction()->setText(tr("Scenario &Outline"));
    m_outlineDock->setWidget(m_outline);
    addDockWidget(Qt::LeftDockWidgetArea, m_outlineDock);
    // A character (or one of its layers) picked in the outline shows in Properties and is what
    // the Character menu acts on.
    connect(m_outline->selectionModel(), &QItemSelectionModel::currentChanged, this, [this](const QModelIndex& index) {
        const auto location = m_model->locationOf(index);
        if (location && location->kind != editor::ScenarioTreeModel::NodeKind::Action) {
            m_properties->setAction(std::nullopt);
            m_properties->setCharacter(location->character);
        }
        m_content->updateEnabled();
    });
    m_outline->setContextMenuPolicy(Qt::CustomContextMenu);
    connect(m_outline, &QWidget::customContextMenuRequested, this, [this](const QPoint& at) {
        QMenu menu(this);
        m_content->updateEnabled();
        m_content->fillCharacterMenu(&menu);
        menu.exec(m_outline->viewport()->mapToGlobal(at));
    });
}

void MainWindow::createMessagesDock()
{
    m_messages = new editor::MessagesPanel(this);
    m_messagesDock = new QDockWidget(tr("Messages"), this);
    m_messagesDock->setObjectName(QStringLiteral("messagesDock"));
    m_messagesDock->setWidget(m_messages);
    addDockWidget(Qt::BottomDockWidgetArea, m_messagesDock);
    tabifyDockWidget(m_editorDocks.front(), m_messagesDock);
    m_editorDocks.front()->raise();
    connect(m_messages, &editor::MessagesPanel::showRequested, this, [this](int character, const QString& clip) {
        if (!document() || character < 0)
            return;
        const QString name = editor::fromUtf8(document()->scenario().characters.at(std::size_t(character)).name);
        if (QTreeWidgetItem* item = clip.isEmpty() ? nullptr : m_library->clipItem(name, clip)) {
            m_library->setCurrentItem(item);
            if (auto* dock = qobject_cast<QDockWidget*>(m_library->parentWidget()))
                dock->raise();
            m_library->setFocus();
            return;
        }
        selectCharacter(character);
    });
}

void MainWindow::createScriptDock()
{
#ifdef THESPIS_WITH_PYTHON
    m_script = new editor::ScriptPanel(this);
    m_scriptDock = new QDockWidget(tr("Script"), this);
    m_scriptDock->setObjectName(QStringLiteral("scriptDock"));
    m_scriptDock->setWidget(m_script);
    addDockWidget(Qt::BottomDockWidgetArea, m_scriptDock);
    tabifyDockWidget(m_messagesDock, m_scriptDock);
    m_editorDocks.front()->raise();
    connect(m_script, &editor::ScriptPanel::playRequested, this, [this] {
        if (!m_clock->isPlaying())
            m_clock->play();
    });
    connect(m_script, &editor::ScriptPanel::pauseRequested, m_clock, &editor::PlaybackClock::pause);
    m_script->setSession(m_session);
    m_script->setAudio(m_audio);
    m_script->setTrustCheck([this] { return confirmScriptTrust(); });
    connect(m_script, &editor::ScriptPanel::finished, this, [this](const QString& message) {
        statusBar()->showMessage(message.isEmpty() ? tr("The script ran to its end.") : tr("Script: %1").arg(message), 8000);
        // A script that hands a character to a conversation (the demo's act ends so) goes on in
        // the Conversation dock, where the visitor types or speaks.
        if (m_conversation->takeOver(m_script->interactionService()))
            if (auto* dock = qobject_cast<QDockWidget*>(m_conversation->parentWidget())) {
                dock->show();
                dock->raise();
            }
    });
#endif
}

bool MainWindow::confirmScriptTrust()
{
    // A scenario never saved holds only what the user made here; one opened from a package is the
    // package's until saved.
    if (!document() || document()->sourceFile().isEmpty() || editor::ScriptTrust::isTrusted(document()->sourceFile()))
        return true;
    QMessageBox box(QMessageBox::Warning, tr("Run Scripts From This File?"),
                    tr("“%1” keeps Python scripts. A script can do anything your user account can: read, change "
                       "and delete files, or use the network.\n\nRun the scenario's scripts only if you trust where "
                       "this file came from. Your answer is remembered for this file as it is now.")
                        .arg(document()->fileName()),
                    QMessageBox::Cancel, this);
    QPushButton* trust = box.addButton(tr("Trust This File and Run"), QMessageBox::AcceptRole);
    box.setDefaultButton(QMessageBox::Cancel);
    box.exec();
    if (box.clickedButton() != trust)
        return false;
    editor::ScriptTrust::trust(document()->sourceFile());
    return true;
}

void MainWindow::refreshMessages()
{
    QList<editor::MessagesPanel::Entry> entries;
    if (document()) {
        for (const editor::Document::Message& message : document()->messages())
            entries.push_back({message.text, message.character, message.clip});
        // The 3D view's (a model's joints without H-Anim names, a bake left out) start with the
        // character's name.
        if (m_preview)
            for (const QString& warning : m_preview->warnings()) {
                int character = -1;
                const auto& characters = document()->scenario().characters;
                for (std::size_t c = 0; c < characters.size(); ++c)
                    if (warning.startsWith(editor::fromUtf8(characters[c].name) + QLatin1Char(':')))
                        character = int(c);
                entries.push_back({warning, character, {}});
            }
    }
    m_messages->setMessages(entries);
    m_messagesDock->setWindowTitle(entries.isEmpty() ? tr("Messages") : tr("Messages (%1)").arg(entries.size()));
}

int MainWindow::currentCharacter() const
{
    if (!document() || document()->scenario().characters.empty())
        return -1;
    if (const auto location = m_model->locationOf(m_outline->currentIndex()))
        return location->character;
    if (const auto action = m_timeline->currentAction())
        return action->character;
    return 0;
}

std::optional<core::edit::LayerPath> MainWindow::currentLayer() const
{
    if (!document())
        return std::nullopt;
    if (const auto location = m_model->locationOf(m_outline->currentIndex()); location && location->layer >= 0)
        return core::edit::LayerPath{location->character, location->layer};
    if (const auto action = m_timeline->currentAction())
        return action->layerPath();
    return std::nullopt;
}

void MainWindow::selectCharacter(int character)
{
    const QModelIndex index = m_model->indexOf(character);
    if (!index.isValid())
        return;
    m_outlineDock->raise();
    m_outline->setCurrentIndex(index);
    m_outline->scrollTo(index);
}

void MainWindow::createEditorDocks()
{
    auto dock = [this](const QString& title, const QString& name, QWidget* content, Qt::DockWidgetArea area) {
        auto* d = new QDockWidget(title, this);
        d->setObjectName(name);
        d->setWidget(content);
        addDockWidget(area, d);
        m_editorDocks.push_back(d);
        return d;
    };
    m_timeline = new editor::TimelinePanel(this);
    m_curves = new editor::CurvePanel(this);
    m_masks = new editor::JointMaskPanel(this);
    m_library = new editor::ClipLibraryPanel(this);
    const QString idleDatabase = shippedResource(QCoreApplication::applicationDirPath(), QStringLiteral("motion/cmu_standing.idle"));
    m_library->setIdleDatabase(idleDatabase);
    m_timeline->setIdleDatabase(idleDatabase);
    m_properties = new editor::PropertiesPanel(this);
    m_gesticon = new editor::GesticonPanel(this);
    m_gesticon->setSession(m_session);
    m_facePose = new editor::FacePosePanel(this);
    m_facePose->setSession(m_session);
    connect(m_facePose, &editor::FacePosePanel::closeUpRequested, this, [this](int character) {
        if (m_preview && character >= 0)
            m_preview->closeUp(character);
    });
    m_speech = new editor::SpeechPanel(this);
    m_speech->setSession(m_session, m_audio);
    connect(m_speech, &editor::SpeechPanel::closeUpRequested, this, [this](int character) {
        if (m_preview && character >= 0)
            m_preview->closeUp(character);
    });
    connect(m_speech, &editor::SpeechPanel::playRequested, this, [this] {
        if (!m_clock->isPlaying())
            m_clock->play();
    });
    // The visitor talks to a character (paper §5.3); the demo's bot is offered when shipped.
    m_conversation = new editor::ConversationPanel(this);
    m_conversation->setSession(m_session, m_audio);
    m_conversation->setDefaultBot(shippedResource(QCoreApplication::applicationDirPath(), QStringLiteral("dialogue/antigone")));
    connect(m_conversation, &editor::ConversationPanel::playRequested, this, [this] {
        if (!m_clock->isPlaying())
            m_clock->play();
    });
    m_segments = new editor::SegmentPanel(this);
    m_bake = new editor::BakePanel(this);
    m_postureChart = new editor::PostureChartPanel(this);
    m_postureChart->setSession(m_session);
    m_postureChart->setDefaultBases(shippedResource(QCoreApplication::applicationDirPath(), QStringLiteral("motion/cmu_postures.pca")));
    m_bake->prtPreviewCheck()->setEnabled(m_preview != nullptr);
    connect(m_bake, &editor::BakePanel::prtPreviewToggled, this,
            [this](bool prt) { setShading(prt ? core::render::Shading::Prt : core::render::Shading::Phong); });
    if (m_preview)
        m_segments->setScenePreview(m_preview);
    m_timeline->addAction(m_stepBackAction);
    m_timeline->addAction(m_stepForwardAction);
    QDockWidget* timelineDock = dock(tr("Timeline"), QStringLiteral("timelineDock"), m_timeline, Qt::BottomDockWidgetArea);
    QDockWidget* curveDock = dock(tr("Curve Editor"), QStringLiteral("curveDock"), m_curves, Qt::BottomDockWidgetArea);
    tabifyDockWidget(timelineDock, curveDock);
    QDockWidget* postureDock = dock(tr("Posture PCs"), QStringLiteral("postureChartDock"), m_postureChart, Qt::BottomDockWidgetArea);
    tabifyDockWidget(curveDock, postureDock);
    // The AR preview: wide at the bottom (video beside its controls), or floated as a window.
    m_arPreview = new editor::ArPreviewPanel(this);
    m_arPreview->setSession(m_session);
    QDockWidget* arDock = dock(tr("AR Preview"), QStringLiteral("arPreviewDock"), m_arPreview, Qt::BottomDockWidgetArea);
    tabifyDockWidget(postureDock, arDock);
    timelineDock->raise();
    QDockWidget* propertiesDock = dock(tr("Properties"), QStringLiteral("propertiesDock"), m_properties, Qt::RightDockWidgetArea);
    QDockWidget* maskDock = dock(tr("Masks"), QStringLiteral("maskDock"), m_masks, Qt::RightDockWidgetArea);
    tabifyDockWidget(propertiesDock, maskDock);
    QDockWidget* segmentsDock = dock(tr("Segments"), QStringLiteral("segmentsDock"), m_segments, Qt::RightDockWidgetArea);
    tabifyDockWidget(maskDock, segmentsDock);
    QDockWidget* bakeDock = dock(tr("Bake"), QStringLiteral("bakeDock"), m_bake, Qt::RightDockWidgetArea);
    tabifyDockWidget(segmentsDock, bakeDock);
    QDockWidget* faceDock = dock(tr("Face Pose"), QStringLiteral("facePoseDock"), m_facePose, Qt::RightDockWidgetArea);
    tabifyDockWidget(bakeDock, faceDock);
    QDockWidget* speechDock = dock(tr("Speech"), QStringLiteral("speechDock"), m_speech, Qt::RightDockWidgetArea);
    tabifyDockWidget(faceDock, speechDock);
    QDockWidget* conversationDock = dock(tr("Conversation"), QStringLiteral("conversationDock"), m_conversation, Qt::RightDockWidgetArea);
    tabifyDockWidget(speechDock, conversationDock);
    propertiesDock->raise();
    QDockWidget* libraryDock = dock(tr("Clip Library"), QStringLiteral("clipLibraryDock"), m_library, Qt::LeftDockWidgetArea);
    tabifyDockWidget(m_outlineDock, libraryDock);
    QDockWidget* gesticonDock = dock(tr("Gesticon"), QStringLiteral("gesticonDock"), m_gesticon, Qt::LeftDockWidgetArea);
    tabifyDockWidget(libraryDock, gesticonDock);
    m_outlineDock->raise();

    connect(m_timeline, &editor::TimelinePanel::problem, this, [this](const QString& m) { statusBar()->showMessage(m, 8000); });
    connect(m_curves, &editor::CurvePanel::problem, this, [this](const QString& m) { statusBar()->showMessage(m, 8000); });
    connect(m_masks, &editor::JointMaskPanel::problem, this, [this](const QString& m) { statusBar()->showMessage(m, 8000); });
    connect(m_properties, &editor::PropertiesPanel::problem, this, [this](const QString& m) { statusBar()->showMessage(m, 8000); });
    connect(m_timeline, &editor::TimelinePanel::seekRequested, m_clock, [this](core::Tick time) { m_clock->seek(time); });
    connect(m_timeline, &editor::TimelinePanel::currentActionChanged, this,
            [this](std::optional<core::edit::ActionPath> action) {
                m_curves->setAction(action);
                m_properties->setAction(action);
                if (action && document()) {
                    const auto& spec = document()->scenario().characters[std::size_t(action->character)]
                                           .layers[std::size_t(action->layer)].actions[std::size_t(action->action)];
                    if (!spec.mask.empty())
                        m_masks->showMask(QString::fromStdString(spec.mask));
                }
            });
    connect(m_timeline, &editor::TimelinePanel::actionActivated, this, [curveDock] { curveDock->raise(); });
    // Motion files dropped from the file manager: imported into the character they land on.
    connect(m_timeline, &editor::TimelinePanel::filesDropped, this,
            [this](core::edit::LayerPath layer, core::Tick time, const QStringList& files) {
                m_content->importFiles(files, layer.character, layer, time);
            });
    connect(m_library, &editor::ClipLibraryPanel::filesDropped, this, [this](const QStringList& files, int character) {
        m_content->importFiles(files, character >= 0 ? character : currentCharacter());
    });
}

} // namespace thespis::studio
