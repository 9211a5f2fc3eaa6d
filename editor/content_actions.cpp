#include "content_actions.h"

#include <QAction>
#include <QFileDialog>
#include <QInputDialog>
#include <QMenu>

#include "edit/content_edits.h"
#include "edit/document_edits.h"
#include "editor/character_dialog.h"
#include "editor/document.h"
#include "editor/import_motion_dialog.h"
#include "editor/lighting_dialog.h"
#include "editor/qt_conversions.h"
#include "main_window.h"

namespace thespis::studio {

ContentActions::ContentActions(MainWindow& window) : QObject(&window), m_window(window)
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
        if (auto* d = m_window.document())
            push(core::edit::duplicateCharacter(d->scenario(), m_window.currentCharacter()), tr("Duplicate Character"));
    });
    connect(m_removeCharacter, &QAction::triggered, this, [this] {
        if (auto* d = m_window.document())
            push(core::edit::removeCharacter(d->scenario(), m_window.currentCharacter()), tr("Remove Character"));
    });
    const auto addLayer = [this](core::scenario::LayerKind kind, const QString& text) {
        if (auto* d = m_window.document())
            push(core::edit::addLayer(d->scenario(), m_window.currentCharacter(), {}, kind), text);
    };
    connect(m_addBodyLayer, &QAction::triggered, this, [=] { addLayer(core::scenario::LayerKind::Body, tr("Add Body Layer")); });
    connect(m_addFaceLayer, &QAction::triggered, this, [=] { addLayer(core::scenario::LayerKind::Face, tr("Add Face Layer")); });
    const auto moveLayer = [this](int delta) {
        auto* d = m_window.document();
        const auto layer = m_window.currentLayer();
        if (d && layer)
            push(core::edit::moveLayer(d->scenario(), *layer, delta), delta < 0 ? tr("Move Layer Up") : tr("Move Layer Down"));
    };
    connect(m_moveLayerUp, &QAction::triggered, this, [=] { moveLayer(-1); });
    connect(m_moveLayerDown, &QAction::triggered, this, [=] { moveLayer(1); });
    connect(m_removeLayer, &QAction::triggered, this, [this] {
        auto* d = m_window.document();
        if (const auto layer = m_window.currentLayer(); d && layer)
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
    menu->addAction(m_renameLayer);
    menu->addAction(m_moveLayerUp);
    menu->addAction(m_moveLayerDown);
    menu->addAction(m_removeLayer);
}

void ContentActions::updateEnabled()
{
    const editor::Document* d = m_window.document();
    const bool open = d != nullptr;
    const bool anyCharacter = open && !d->scenario().characters.empty();
    const bool anyLayer = anyCharacter && m_window.currentLayer().has_value();
    m_importMotion->setEnabled(anyCharacter);
    m_addCharacter->setEnabled(open);
    m_lighting->setEnabled(open);
    for (QAction* action : {m_duplicateCharacter, m_renameCharacter, m_removeCharacter, m_addBodyLayer, m_addFaceLayer})
        action->setEnabled(anyCharacter);
    for (QAction* action : {m_renameLayer, m_moveLayerUp, m_moveLayerDown, m_removeLayer})
        action->setEnabled(anyLayer);
}

bool ContentActions::push(core::Result<core::edit::Edit> edit, const QString& text)
{
    editor::Document* d = m_window.document();
    if (!d)
        return false;
    if (auto done = d->edit(std::move(edit), text); !done) {
        emit message(tr("%1: %2").arg(text, editor::fromUtf8(done.error().message)));
        return false;
    }
    return true;
}

void ContentActions::onImportMotion()
{
    editor::Document* d = m_window.document();
    if (!d)
        return;
    // A dialog object rather than the static helper, so that tests can drive it.
    QFileDialog dialog(&m_window, tr("Import Motion"), m_window.importFolder(),
                       tr("Motion (*.bvh *.gltf *.glb);;BVH motion capture (*.bvh);;glTF (*.gltf *.glb);;All files (*)"));
    dialog.setObjectName(QStringLiteral("importFileDialog"));
    dialog.setFileMode(QFileDialog::ExistingFiles);
    dialog.setOption(QFileDialog::DontUseNativeDialog);
    if (dialog.exec() != QDialog::Accepted || dialog.selectedFiles().isEmpty())
        return;
    m_window.setImportFolder(dialog.directory().absolutePath());
    importFiles(dialog.selectedFiles(), m_window.currentCharacter());
}

bool ContentActions::importFiles(const QStringList& files, int character, std::optional<core::edit::LayerPath> track,
                                 core::Tick time)
{
    editor::Document* d = m_window.document();
    if (!d || files.isEmpty())
        return false;
    editor::ImportMotionDialog dialog(*d, files, character, &m_window);
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
                          editor::fromUtf8(d->scenario().characters[std::size_t(dialog.character())].name)));
    return true;
}

void ContentActions::onAddCharacter()
{
    editor::Document* d = m_window.document();
    if (!d)
        return;
    editor::CharacterDialog dialog(d->baseDir(), tr("Actor"), &m_window);
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
        m_window.selectCharacter(int(d->scenario().characters.size()) - 1);
}

void ContentActions::onRenameCharacter()
{
    editor::Document* d = m_window.document();
    const int c = m_window.currentCharacter();
    if (!d || c < 0 || std::size_t(c) >= d->scenario().characters.size())
        return;
    bool ok = false;
    const QString name = QInputDialog::getText(&m_window, tr("Rename Character"), tr("New name:"), QLineEdit::Normal,
                                               editor::fromUtf8(d->scenario().characters[std::size_t(c)].name), &ok);
    if (ok)
        push(core::edit::renameCharacter(d->scenario(), c, name.trimmed().toStdString()), tr("Rename Character"));
}

void ContentActions::onRenameLayer()
{
    editor::Document* d = m_window.document();
    const auto layer = m_window.currentLayer();
    if (!d || !layer)
        return;
    bool ok = false;
    const auto& current = d->scenario().characters[std::size_t(layer->character)].layers[std::size_t(layer->layer)];
    const QString name = QInputDialog::getText(&m_window, tr("Rename Layer"), tr("New name:"), QLineEdit::Normal,
                                               editor::fromUtf8(current.name), &ok);
    if (ok)
        push(core::edit::renameLayer(d->scenario(), *layer, name.trimmed().toStdString()), tr("Rename Layer"));
}

void ContentActions::onLighting()
{
    editor::Document* d = m_window.document();
    if (!d)
        return;
    editor::LightingDialog dialog(d->baseDir(), d->scenario().lighting, &m_window);
    if (dialog.exec() == QDialog::Accepted)
        push(core::edit::setLighting(d->scenario(), dialog.lighting()), tr("Change Lighting"));
}

} // namespace thespis::studio
