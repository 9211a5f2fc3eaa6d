#pragma once
// ContentActions: the studio's commands that bring the user's own content into a scenario —
// File ▸ Import Motion… (also files dropped from the file manager on the clip library or a
// track), the Character menu (add on the built-in humanoid or a glTF model, duplicate, rename,
// remove; add, rename, move and remove layers) and Scene ▸ Lighting…. Each opens its dialog
// over the window and pushes one undoable edit (core/edit/content_edits.h) on the Session's
// document. The window tells it which character and layer are current (the outline's selection,
// else the timeline's) through a ContentSelection.

#include <QObject>
#include <QStringList>

#include <functional>
#include <optional>

#include "edit/scenario_edit.h"
#include "util/tick.h"

class QAction;
class QMenu;
class QWidget;

namespace thespis::editor {

class Document;
class Session;

/// What the window knows of the user's selection.
struct ContentSelection {
    std::function<int()> character;                              ///< -1 without characters
    std::function<std::optional<core::edit::LayerPath>()> layer;
    std::function<void(int)> selectCharacter;                    ///< shows a character just added
};

class ContentActions : public QObject {
    Q_OBJECT
public:
    /// Dialogs open over `window`, which also owns the actions.
    ContentActions(Session* session, QWidget* window, ContentSelection selection);

    QAction* importMotionAction() const { return m_importMotion; }
    QAction* addCharacterAction() const { return m_addCharacter; }
    QAction* lightingAction() const { return m_lighting; }
    /// Fills the Character menu.
    void fillCharacterMenu(QMenu* menu) const;
    /// Enables what the open document allows.
    void updateEnabled();
    /// Where the import file dialog opens (the last folder imported from, else the scenario's).
    QString importFolder() const;

    /// Opens the import dialog for `files` into `character`; with `track`, the first clip
    /// imported also plays there from `time`, in the same undo step. False when nothing was
    /// imported (cancelled, or no file could be read).
    bool importFiles(const QStringList& files, int character, std::optional<core::edit::LayerPath> track = {},
                     core::Tick time = 0);

signals:
    /// Something to tell in the status bar.
    void message(const QString& text);

private:
    void onImportMotion();
    void onAddCharacter();
    void onRenameCharacter();
    void onRenameLayer();
    void onLighting();
    // Pushes `edit` as one command named `text`; a refusal is told in the status bar.
    bool push(core::Result<core::edit::Edit> edit, const QString& text);

    Document* document() const;

    Session* m_session;
    QWidget* m_window;
    ContentSelection m_selection;
    QAction* m_importMotion = nullptr;
    QAction* m_addCharacter = nullptr;
    QAction* m_duplicateCharacter = nullptr;
    QAction* m_renameCharacter = nullptr;
    QAction* m_removeCharacter = nullptr;
    QAction* m_addBodyLayer = nullptr;
    QAction* m_addFaceLayer = nullptr;
    QAction* m_addGaze = nullptr;
    QAction* m_renameLayer = nullptr;
    QAction* m_moveLayerUp = nullptr;
    QAction* m_moveLayerDown = nullptr;
    QAction* m_removeLayer = nullptr;
    QAction* m_lighting = nullptr;
};

} // namespace thespis::editor
