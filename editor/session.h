#pragma once
// Session: the studio's open scenario as one object the window hands to its panels once — the
// document (or none), the playback clock, and the Stage every view plays: the 3D view draws its
// poses, the skeleton view reads them, scripts activate actions on it. Panels register once
// (addView); opening another scenario detaches every view from the old document before it goes
// and attaches them to the new one, in registration order. An edit updates the stage in place
// (live actions play on, only the characters the edit touched were rebuilt by the Document); a
// stage that cannot follow (characters added, removed or given another skeleton) is made anew.
// The stage keeps a cache of recent frames, so scrubbing back over them is cheap.

#include <QObject>

#include <functional>
#include <memory>
#include <vector>

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

    /// A view of the document: called with each new document, and with nullptr before the one it
    /// shows goes. Called at once with the current document.
    void addView(std::function<void(Document*)> attach);
    /// addView for a panel with setDocument(Document*).
    template <class Panel>
    void addPanel(Panel* panel)
    {
        addView([panel](Document* document) { panel->setDocument(document); });
    }

    /// Closes the current document (views detached first) and opens `document` (may be null).
    void setDocument(std::unique_ptr<Document> document);

signals:
    /// After setDocument: every view shows `document` (null: none).
    void documentChanged(Document* document);
    /// After an edit of the document, once the stage plays its new runtime; `stageReplaced` when
    /// the stage had to be made anew.
    void edited(bool stageReplaced);

private:
    void onDocumentEdited();

    PlaybackClock* m_clock = nullptr;
    std::unique_ptr<Document> m_document;
    std::shared_ptr<core::runtime::Stage> m_stage;
    std::vector<std::function<void(Document*)>> m_views;
};

} // namespace thespis::editor
