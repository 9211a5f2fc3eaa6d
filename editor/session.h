#pragma once
// Session: the studio's open scenario as one object the window hands to its views once — the
// document (or none), the playback clock, and the Stage every view plays. The session owns the
// tick: at each new time of the clock it lets scripts see the time (aboutToTick), evaluates the
// stage once into one PoseSet and publishes it — posesChanged for the views on the GUI thread
// (3D view, stick figures, posture chart), the mailbox for the AR preview's renderer. No view
// evaluates a schedule of its own.
//
// Views register once (addView); opening another scenario detaches every view from the old
// document before it goes and attaches them to the new one, in registration order. Only the
// session gives the stage a new runtime after an edit (live actions play on; only the characters
// the edit touched were rebuilt by the Document); a stage that cannot follow (characters added,
// removed or given another skeleton) is made anew. Views then follow (edited), and one tick
// shows the edit. The stage keeps a cache of recent frames, so scrubbing back over them is cheap.

#include <QObject>
#include <QPointer>

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "runtime/pose_mailbox.h"
#include "runtime/stage.h"

namespace thespis::editor {

class Document;
class PlaybackClock;

class Session : public QObject {
    Q_OBJECT
public:
    /// The owner closes the document (setDocument(nullptr)) while its views still live: a view
    /// may be gone by the time the session is.
    explicit Session(PlaybackClock* clock, QObject* parent = nullptr);

    Document* document() const { return m_document.get(); }
    PlaybackClock* clock() const { return m_clock; }
    /// The stage of the document's runtime; null without a document.
    const std::shared_ptr<core::runtime::Stage>& stage() const { return m_stage; }
    /// The poses of the last tick (the stage's character order); empty without a document.
    const core::runtime::PoseSet& poses() const { return m_poses; }
    /// The same poses, published once per tick for views that draw on threads of their own.
    const std::shared_ptr<core::runtime::PoseMailbox>& mailbox() const { return m_mailbox; }
    /// Every character's authored motion over the whole timeline (runtime::sampleTimeline),
    /// made once per runtime: what views frame themselves on. Empty without a document.
    const std::vector<core::runtime::PoseSet>& timelineSamples();
    /// How many times the session evaluated the stage: once per tick.
    std::uint64_t evaluations() const { return m_evaluations; }
    /// How many times it gave the stage a runtime (a new document, an edit).
    std::uint64_t runtimesSet() const { return m_runtimesSet; }

    /// A view of the document: called with each new document, and with nullptr before the one it
    /// shows goes. Called at once with the current document. With an `owner`, the view goes when
    /// the owner does.
    void addView(std::function<void(Document*)> attach, QObject* owner = nullptr);
    /// addView for a panel with setDocument(Document*).
    template <class Panel>
    void addPanel(Panel* panel)
    {
        addView([panel](Document* document) { panel->setDocument(document); }, panel);
    }

    /// Closes the current document (views detached first), opens `document` (may be null), sets
    /// the clock's length to it and plays it from the start.
    void setDocument(std::unique_ptr<Document> document);

public slots:
    /// Evaluates the stage once at the clock's time and publishes the poses: what every new time
    /// of the clock does; call it when something else changed what plays now (a live action
    /// started or stopped while the clock is paused).
    void tick();

signals:
    /// After setDocument: every view shows `document` (null: none).
    void documentChanged(Document* document);
    /// After an edit of the document, once the stage plays its new runtime and before the tick
    /// that shows it; `stageReplaced` when the stage had to be made anew.
    void edited(bool stageReplaced);
    /// Before the stage is evaluated at `time`: a script waiting for that time acts first.
    void aboutToTick(core::Tick time);
    /// After each evaluation: the poses every view draws.
    void posesChanged(const core::runtime::PoseSet& poses);

private:
    void onDocumentEdited();
    void makeStage();

    PlaybackClock* m_clock = nullptr;
    std::unique_ptr<Document> m_document;
    std::shared_ptr<core::runtime::Stage> m_stage;
    core::runtime::PoseSet m_poses;
    std::shared_ptr<core::runtime::PoseMailbox> m_mailbox = std::make_shared<core::runtime::PoseMailbox>();
    std::optional<std::vector<core::runtime::PoseSet>> m_samples;
    struct View {
        std::function<void(Document*)> attach;
        QPointer<QObject> owner;
        bool owned = false;
    };
    void attachViews(Document* document);
    std::vector<View> m_views;
    std::uint64_t m_evaluations = 0, m_runtimesSet = 0;
};

} // namespace thespis::editor
