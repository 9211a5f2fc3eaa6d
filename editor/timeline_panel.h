#pragma once
// TimelinePanel: the timeline editor. Shows one track per character and layer with its actions
// as clips (widgets::TimelineView), the markers and the playhead, and turns the view's intents
// (move in time and to another layer of the character, trim, fade, drop a clip from the library,
// mute / solo / lock, markers, scrub) into undoable edits of the document; a drag is one undo step. Also owns the edit actions that work
// on the timeline selection: delete, ripple delete, copy, paste, duplicate, split at the playhead.

#include <QWidget>

#include <optional>
#include <utility>
#include <vector>

#include "edit/document_edits.h"
#include "util/tick.h"

class QAction;
class QToolButton;

namespace thespis::widgets {
class TimelineView;
}

namespace thespis::editor {

class Document;

class TimelinePanel : public QWidget {
    Q_OBJECT
public:
    explicit TimelinePanel(QWidget* parent = nullptr);

    void setDocument(Document* document);
    /// The playback time shown by the playhead (seconds); the lanes scroll to keep it in view.
    void setTime(core::Tick time);
    /// Whole frames per second of snapping, trimming and the ruler (default 30).
    void setFrameRate(int framesPerSecond);
    /// The idle motion database (absolute path) an "Idle" dropped from the clip library plays.
    void setIdleDatabase(const QString& path) { m_idleDatabase = path; }

    widgets::TimelineView* view() const { return m_view; }
    /// The actions selected on the timeline, in timeline order.
    std::vector<core::edit::ActionPath> selectedActions() const;
    /// The first of them, or none.
    std::optional<core::edit::ActionPath> currentAction() const;
    void selectActions(const std::vector<core::edit::ActionPath>& actions);
    /// The clip id the view shows for an action (tests drive the view with it), or -1.
    int clipId(const core::edit::ActionPath& action) const;

    QAction* deleteAction() const { return m_delete; }
    QAction* rippleDeleteAction() const { return m_rippleDelete; }
    QAction* copyAction() const { return m_copy; }
    QAction* pasteAction() const { return m_paste; }
    QAction* duplicateAction() const { return m_duplicate; }
    QAction* splitAction() const { return m_split; }
    QAction* snapAction() const { return m_snap; }

signals:
    void seekRequested(core::Tick time);
    /// The first selected action (the curve editor shows it), or none.
    void currentActionChanged(std::optional<core::edit::ActionPath> action);
    void actionActivated(core::edit::ActionPath action);
    /// Files from the file manager dropped on a layer's track at `time`: to import into its
    /// character, the first playing there.
    void filesDropped(core::edit::LayerPath layer, core::Tick time, const QStringList& files);
    void problem(const QString& message);

private:
    void refresh();
    void report(const core::Result<void>& result);
    // Pushes `edit`, which adds an action at the end of `layer`, and selects that action.
    void addActionAtEnd(const core::edit::LayerPath& layer, core::Result<core::edit::Edit> edit, const QString& text);
    std::vector<core::edit::ActionPath> pathsOf(const QList<int>& ids) const;
    void onMoveRequested(const QList<int>& ids, qint64 delta, int trackDelta, bool finished);
    void onDelete(bool ripple);
    void onCopy();
    void onPaste();
    void onDuplicate();
    void onSplit();

    Document* m_document = nullptr;
    widgets::TimelineView* m_view = nullptr;
    std::vector<core::edit::LayerPath> m_tracks;     // per view track
    std::vector<core::edit::ActionPath> m_clipPaths; // per view clip id
    // A clip move drag in progress: the document at its start and the actions it moves. Each step
    // is made again from that start (a step to another layer changes the actions' paths, and the
    // view's clip ids with them) and pushed as the step from the last one, merging into one command.
    struct MoveDrag {
        core::scenario::Scenario start;
        std::vector<core::edit::ActionPath> actions;
        core::edit::Edit applied; // what the drag has done to `start` so far
        int appliedLayers = 0;    // its layer offset
    };
    std::optional<MoveDrag> m_moveDrag;
    core::Tick m_playhead = 0;
    int m_frameRate = 30;
    // Copied actions with their layer, start times relative to the earliest.
    std::vector<std::pair<core::edit::LayerPath, core::scenario::ActionSpec>> m_clipboard;

    QAction* m_delete = nullptr;
    QAction* m_rippleDelete = nullptr;
    QAction* m_copy = nullptr;
    QAction* m_paste = nullptr;
    QAction* m_duplicate = nullptr;
    QAction* m_split = nullptr;
    QAction* m_snap = nullptr;
    QString m_idleDatabase;
};

} // namespace thespis::editor
