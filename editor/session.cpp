#include "editor/session.h"

#include "editor/document.h"
#include "editor/playback_clock.h"

namespace thespis::editor {

namespace {
// Frames of each character's authored motion the stage keeps (10 s at 60 Hz): scrubbing back
// over what was just shown costs a copy per character (Stage::setFrameCache).
constexpr int kScrubCacheFrames = 600;

std::shared_ptr<core::runtime::Stage> makeStage(const Document& document)
{
    auto stage = std::make_shared<core::runtime::Stage>(document.runtime());
    stage->setFrameCache(kScrubCacheFrames);
    return stage;
}
} // namespace

Session::Session(PlaybackClock* clock, QObject* parent) : QObject(parent), m_clock(clock) {}

void Session::addView(std::function<void(Document*)> attach)
{
    attach(m_document.get());
    m_views.push_back(std::move(attach));
}

void Session::setDocument(std::unique_ptr<Document> document)
{
    m_clock->pause();
    for (const auto& view : m_views)
        view(nullptr);
    m_stage.reset();
    m_document = std::move(document);
    if (m_document) {
        m_stage = makeStage(*m_document);
        connect(m_document.get(), &Document::edited, this, &Session::onDocumentEdited);
    }
    for (const auto& view : m_views)
        view(m_document.get());
    emit documentChanged(m_document.get());
}

void Session::onDocumentEdited()
{
    // Live actions play on when the characters are the same; otherwise a stage of the new cast.
    const bool replaced = !m_stage->setRuntime(m_document->runtime());
    if (replaced)
        m_stage = makeStage(*m_document);
    emit edited(replaced);
}

} // namespace thespis::editor
