#include "editor/session.h"

#include "editor/document.h"
#include "editor/playback_clock.h"
#include "runtime/timeline_samples.h"

namespace thespis::editor {

namespace {
// Frames of each character's authored motion the stage keeps (10 s at 60 Hz): scrubbing back
// over what was just shown costs a copy per character (Stage::setFrameCache).
constexpr int kScrubCacheFrames = 600;
} // namespace

Session::Session(PlaybackClock* clock, QObject* parent) : QObject(parent), m_clock(clock)
{
    connect(m_clock, &PlaybackClock::timeChanged, this, &Session::tick);
}

void Session::addView(std::function<void(Document*)> attach, QObject* owner)
{
    attach(m_document.get());
    m_views.push_back({std::move(attach), owner, owner != nullptr});
}

void Session::attachViews(Document* document)
{
    std::erase_if(m_views, [](const View& view) { return view.owned && !view.owner; });
    for (const View& view : m_views)
        view.attach(document);
}

void Session::makeStage()
{
    m_stage = std::make_shared<core::runtime::Stage>(m_document->runtime());
    m_stage->setFrameCache(kScrubCacheFrames);
    m_poses = m_stage->makePoseSet();
    ++m_runtimesSet;
}

void Session::setDocument(std::unique_ptr<Document> document)
{
    m_clock->pause();
    attachViews(nullptr);
    m_stage.reset();
    m_poses = {};
    m_samples.reset();
    m_document = std::move(document);
    if (m_document) {
        makeStage();
        connect(m_document.get(), &Document::edited, this, &Session::onDocumentEdited);
    }
    attachViews(m_document.get());
    emit documentChanged(m_document.get());
    // From the start; a clock already there says nothing, so the first poses are made here.
    m_clock->setDuration(m_document ? m_document->previewDuration() : 0);
    const core::Tick before = m_clock->time();
    m_clock->seek(0);
    if (m_clock->time() == before)
        tick();
}

void Session::onDocumentEdited()
{
    // Live actions play on when the characters are the same; otherwise a stage of the new cast.
    const bool replaced = !m_stage->setRuntime(m_document->runtime());
    if (replaced)
        makeStage();
    else
        ++m_runtimesSet;
    // Paused, an edit shows settled: gaze and pointing move with time, which a paused clock does
    // not give them; evaluated a tick back first, they settle at once, as on a seek back.
    if (!replaced && !m_clock->isPlaying())
        m_stage->evaluate(m_clock->time() - 1, m_poses);
    m_samples.reset();
    emit edited(replaced);
    const core::Tick before = m_clock->time();
    m_clock->setDuration(m_document->previewDuration());
    if (m_clock->time() == before) // else the clamped time ticked already
        tick();
}

void Session::tick()
{
    if (!m_stage)
        return;
    const core::Tick now = m_clock->time();
    emit aboutToTick(now);
    m_stage->evaluate(now, m_poses);
    ++m_evaluations;
    m_mailbox->publish(m_poses);
    emit posesChanged(m_poses);
}

const std::vector<core::runtime::PoseSet>& Session::timelineSamples()
{
    if (!m_samples)
        m_samples = m_stage ? core::runtime::sampleTimeline(m_stage->runtime()) : std::vector<core::runtime::PoseSet>{};
    return *m_samples;
}

} // namespace thespis::editor
