#include "editor/session.h"

#include "editor/document.h"
#include "editor/playback_clock.h"

namespace thespis::editor {

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
        m_stage = std::make_shared<core::runtime::Stage>(m_document->runtime());
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
        m_stage = std::make_shared<core::runtime::Stage>(m_document->runtime());
    emit edited(replaced);
}

} // namespace thespis::editor
