#include "editor/content_actions.h"

#include <QAction>
#include <QDir>
#include <QFileDialog>
#include <QInputDialog>
#include <QMenu>
#include <QSettings>

#include "edit/content_edits.h"
#include "edit/document_edits.h"
#include "edit/gaze_edits.h"
#include "editor/character_dialog.h"
#include "editor/document.h"
#include "editor/playback_clock.h"
#include "editor/import_motion_dialog.h"
#include "editor/lighting_dialog.h"
#include "editor/qt_conversions.h"
#include "editor/session.h"

namespace thespis::editor {

ContentActions::ContentActions(Session* session, QWidget* window, ContentSelection selection)
    : QObject(window), m_session(session), m_window(window), m_selection(std::move(selection))
{
    auto make = [this](const QString& text, const QString& name, const QString& tip) {
        auto* action = new QAction(text, this);
        action->setObjectName(name);
        action->setStatusTip(tip);
        return action;
    };
    m_importMotion = make(tr("&Import Motion…"), QStringLiteral("importMotion"),
                          tr("Add BVH motion capture or glTF animations as clips of a character"));
    m_importMotion->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_I));
    m_addCharacter = make(tr("&Add Character…"), QStringLiteral("addCharacter"),
                          tr("Add a character on the built-in humanoid or a glTF model"));
    m_duplicateCharacter = make(tr("&Duplicate Character"), QStringLiteral("duplicateCharacter"),
                                tr("A copy of the current character, a metre to its right"));
    m_renameCharacter = make(tr("Re&name Character…"), QStringLiteral("renameCharacter"), {});
    m_removeCharacter = make(tr("&Remove Character"), QStringLiteral("removeCharacter"), {});
    m_addBodyLayer = make(tr("Add &Body Layer"), QStringLiteral("addBodyLayer"),
                          tr("A layer of body actions on top of the current character's"));
    m_addFaceLayer = make(tr("Add &Face Layer"), QStringLiteral("addFaceLayer"),
                          tr("A layer of facial animation (MPEG-4 FAPs)"));
    m_addGaze = make(tr("Add &Gaze at Playhead"), QStringLiteral("addGaze"),
                     tr("The current character looks at the camera (or at the other character) for two seconds "
                        "from the playhead; pick what it looks at in Properties"));
    m_renameLayer = make(tr("Rena&me Layer…"), QStringLiteral("renameLayer"), {});
    m_moveLayerUp = make(tr("Move Layer &Up"), QStringLiteral("moveLayerUp"), {});
    m_moveLayerDown = make(tr("Move Layer Do&wn"), QStringLiteral("moveLayerDown"), {});
    m_removeLayer = make(tr("Remove &Layer"), QStringLiteral("removeLayer"), {});
    m_lighting = make(tr("&Lighting…"), QStringLiteral("lighting"),
                      tr("Choose the light probe, turn it and set its intensity"));

    connect(m_importMotion, &QAction::triggered, this, &ContentActions::onImportMotion);
    connect(m_addCharacter, &QAction::triggered, this, &ContentActions::onAddCharacter);
    connect(m_renameCharacter, &QAction::triggered, this, &ContentActions::onRenameCharacter);
    connect(m_renameLayer, &QAction::triggered, this, &ContentActions::onRenameLayer);
    connect(m_lighting, &QAction::triggered, this, &ContentActions::onLighting);
    connect(m_duplicateCharacter, &QAction::triggered, this, [this] {
        if (auto* d = document())
            push(core::edit::duplicateCharacter(d->scenario(), m_selection.character()), tr("Duplicate Character"));
    });
    connect(m_removeCharacter, &QAction::triggered, this, [this] {
        if (auto* d = document())
            push(core::edit::removeCharacter(d->scenario(), m_selection.character()), tr("Remove Character"));
    });
    const auto addLayer = [this](core::scenario::LayerKind kind, const QString& text) {
        if (auto* d = document())
            push(core::edit::addLayer(d->scenario(), m_selection.character(), {}, kind), text);
    };
    connect(m_addBodyLayer, &QAction::triggered, this, [=] { addLayer(core::scenario::LayerKind::Body, tr("Add Body Layer")); });
    connect(m_addFaceLayer, &QAction::triggered, this, [=] { addLayer(core::scenario::LayerKind::Face, tr("Add Face Layer")); });
    connect(m_addGaze, &QAction::triggered, this, [this] {
        auto* d = document();
        const int c = m_selection.character();
        if (!d || c < 0 || std::size_t(c) >= d->scenario().characters.size())
            return;
        // With two characters each looks at the other by default; otherwise at the viewer.
        core::scenario::GazeSpec gaze;
        const auto& characters = d->scenario().characters;
        if (characters.size() == 2)
            gaze.target = characters[std::size_t(1 - c)].name;
        push(core::edit::addGaze(d->scenario(), c, std::move(gaze), m_session->clock()->time(), 2.0), tr("Add Gaze"));
    });
    const auto moveLayer = [this](int delta) {
        auto* d = document();
        const auto layer = m_selection.layer();
        if (d && layer)
            push(core::edit::moveLayer(d->scenario(), *layer, delta), delta < 0 ? tr("Move Layer Up") : tr("Move Layer Down"));
    };
    connect(m_moveLayerUp, &QAction::triggered, this, [=] { moveLayer(-1); });
    connect(m_moveLayerDown, &QAction::triggered, this, [=] { moveLayer(1); });
    connect(m_removeLayer, &QAction::triggered, this, [this] {
        auto* d = document();
        if (const auto layer = m_selection.layer(); d && layer)
            push(core::edit::removeLayer(d->scenario(), *layer), tr("Remove Layer"));
    });
    updateEnabled();
}

void ContentActions::fillCharacterMenu(QMenu* menu) const
{
    menu->addAction(m_addCharacter);
    menu->addAction(m_duplicateCharacter);
    menu->addAction(m_renameCharacter);
    menu->addAction(m_removeCharacter);
    menu->addSeparator();
    menu->addAction(m_addBodyLayer);
    menu->addAction(m_addFaceLayer);
    menu->addAction(m_addGaze);
    menu->addAction(m_renameLayer);
    menu->addAction(m_moveLayerUp);
    menu->addAction(m_moveLayerDown);
    menu->addAction(m_removeLayer);
}

void ContentActions::updateEnabled()
{
    const Document* d = document();
    const bool open = d != nullptr;
    const bool anyCharacter = open && !d->scenario().characters.empty();
    const bool anyLayer = anyCharacter && m_selection.layer().has_value();
    m_importMotion->setEnabled(anyCharacter);
    m_addCharacter->setEnabled(open);
    m_lighting->setEnabled(open);
    for (QAction* action : {m_duplicateCharacter, m_renameCharacter, m_removeCharacter, m_addBodyLayer, m_addFaceLayer,
                             m_addGaze})
        action->setEnabled(anyCharacter);
    for (QAction* action : {m_renameLayer, m_moveLayerUp, m_moveLayerDown, m_removeLayer})
        action->setEnabled(anyLayer);
}

bool ContentActions::push(core::Result<core::edit::Edit> edit, const QString& text)
{
    Document* d = document();
    if (!d)
        return false;
    if (auto done = d->edit(std::move(edit), text); !done) {
        emit message(tr("%1: %2").arg(text, fromUtf8(done.error().message)));
        return false;
    }
    return true;
}

void ContentActions::onImportMotion()
{
    Document* d = document();
    if (!d)
        return;
    // A dialog object rather than the static helper, so that tests can drive it.
    QFileDialog dialog(m_window, tr("Import Motion"), importFolder(),
                       tr("Motion (*.bvh *.gltf *.glb);;BVH motion capture (*.bvh);;glTF (*.gltf *.glb);;All files (*)"));
    dialog.setObjectName(QStringLiteral("importFileDialog"));
    dialog.setFileMode(QFileDialog::ExistingFiles);
    dialog.setOption(QFileDialog::DontUseNativeDialog);
    if (dialog.exec() != QDialog::Accepted || dialog.selectedFiles().isEmpty())
        return;
    QSettings().setValue(QStringLiteral("import/lastFolder"), dialog.directory().absolutePath());
    importFiles(dialog.selectedFiles(), m_selection.character());
}

bool ContentActions::importFiles(const QStringList& files, int character, std::optional<core::edit::LayerPath> track,
                                 core::Tick time)
{
    Document* d = document();
    if (!d || files.isEmpty())
        return false;
    ImportMotionDialog dialog(*d, files, character, m_window);
    if (dialog.exec() != QDialog::Accepted)
        return false;
    auto edit = dialog.edit();
    if (!edit)
        return false;
    const QStringList names = dialog.clipNames();
    if (track && !names.isEmpty()) {
        // Dropped on a track of that character: its first clip plays there, in the same step.
        core::scenario::Scenario after = d->scenario();
        if (edit->apply(after))
            if (auto action = core::edit::actionFromClip(after, *track, names.front().toStdString(), time))
                if (auto insert = core::edit::insertActions(after, *track, {*action}))
                    edit->append(std::move(insert).value());
    }
    if (!push(std::move(*edit), tr("Import %n Clip(s)", nullptr, int(names.size()))))
        return false;
    emit message(tr("Imported %1 into %2.")
                     .arg(names.join(QStringLiteral(", ")),
                          fromUtf8(d->scenario().characters[std::size_t(dialog.character())].name)));
    return true;
}

void ContentActions::onAddCharacter()
{
    Document* d = document();
    if (!d)
        return;
    CharacterDialog dialog(d->baseDir(), tr("Actor"), m_window);
    if (dialog.exec() != QDialog::Accepted)
        return;
    auto edit = core::edit::addCharacter(d->scenario(), dialog.character());
    const std::vector<core::scenario::ClipAsset> clips = dialog.clips();
    if (edit && !clips.empty()) {
        core::scenario::Scenario after = d->scenario();
        if (edit->apply(after))
            if (auto added = core::edit::addClips(after, int(after.characters.size()) - 1, clips))
                edit->append(std::move(added).value());
    }
    if (push(std::move(edit), tr("Add Character")))
        m_selection.selectCharacter(int(d->scenario().characters.size()) - 1);
}

void ContentActions::onRenameCharacter()
{
    Document* d = document();
    const int c = m_selection.character();
    if (!d || c < 0 || std::size_t(c) >= d->scenario().characters.size())
        return;
    bool ok = false;
    const QString name = QInputDialog::getText(m_window, tr("Rename Character"), tr("New name:"), QLineEdit::Normal,
                                               fromUtf8(d->scenario().characters[std::size_t(c)].name), &ok);
    if (ok)
        push(core::edit::renameCharacter(d->scenario(), c, name.trimmed().toStdString()), tr("Rename Character"));
}

void ContentActions::onRenameLayer()
{
    Document* d = document();
    const auto layer = m_selection.layer();
    if (!d || !layer)
        return;
    bool ok = false;
    const auto& current = d->scenario().characters[std::size_t(layer->character)].layers[std::size_t(layer->layer)];
    const QString name = QInputDialog::getText(m_window, tr("Rename Layer"), tr("New name:"), QLineEdit::Normal,
                                               fromUtf8(current.name), &ok);
    if (ok)
        push(core::edit::renameLayer(d->scenario(), *layer, name.trimmed().toStdString()), tr("Rename Layer"));
}

void ContentActions::onLighting()
{
    Document* d = document();
    if (!d)
        return;
    LightingDialog dialog(d->baseDir(), d->scenario().lighting, m_window);
    if (dialog.exec() == QDialog::Accepted)
        push(core::edit::setLighting(d->scenario(), dialog.lighting()), tr("Change Lighting"));
}

Document* ContentActions::document() const
{
    return m_session->document();
}

QString ContentActions::importFolder() const
{
    const QString stored = QSettings().value(QStringLiteral("import/lastFolder")).toString();
    if (!stored.isEmpty())
        return stored;
    return document() ? document()->baseDir() : QDir::homePath();
}

} // namespace thespis::editor
