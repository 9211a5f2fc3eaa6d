#include "editor/job_runner.h"

#include <QMetaObject>

#include "editor/qt_conversions.h"

namespace thespis::editor {

namespace {
// Progress reaches the GUI at most this often (STYLE.md §6: about 20 Hz).
constexpr int kProgressIntervalMs = 50;
} // namespace

JobRunner::JobRunner(QObject* parent) : QObject(parent)
{
    m_progressTimer.setInterval(kProgressIntervalMs);
    connect(&m_progressTimer, &QTimer::timeout, this, &JobRunner::reportProgress);
}

JobRunner::~JobRunner()
{
    // The thread posts to this object: it must be gone before the QObject is. A result it posted
    // and that was not delivered dies with the object.
    m_stop.request_stop();
    if (m_thread.joinable())
        m_thread.join();
}

core::Result<void> JobRunner::start(std::unique_ptr<core::Job> job)
{
    if (m_running)
        return core::makeError(core::ErrorCode::InvalidArgument,
                               "A job is already running: cancel it or wait for it to finish.");
    if (auto valid = job->validate(); !valid)
        return valid;
    if (m_thread.joinable())
        m_thread.join(); // the previous job's thread: it has delivered its result, so it is ending

    m_job = std::move(job);
    m_stop = std::stop_source();
    m_context = std::make_unique<core::JobContext>(m_stop.get_token());
    m_lastReported = {};
    m_running = true;
    m_cancelled = false;
    m_thread = std::jthread([this, job = m_job.get(), context = m_context.get()] {
        core::Result<void> result = job->run(*context);
        QMetaObject::invokeMethod(this, [this, result] { deliver(result); }, Qt::QueuedConnection);
    });
    m_progressTimer.start();
    return {};
}

void JobRunner::cancel()
{
    if (!m_running)
        return;
    m_cancelled = true;
    m_stop.request_stop();
}

void JobRunner::reportProgress()
{
    if (!m_running)
        return;
    const core::JobProgress now = m_context->progress();
    if (now.stage == m_lastReported.stage && now.done == m_lastReported.done && now.total == m_lastReported.total)
        return;
    m_lastReported = now;
    emit progress(fromUtf8(now.stage), qint64(now.done), qint64(now.total));
}

void JobRunner::deliver(core::Result<void> result)
{
    if (!m_running)
        return;
    m_progressTimer.stop();
    if (m_thread.joinable())
        m_thread.join(); // its last act was posting this result
    if (m_cancelled) {
        if (result)
            m_job->discardOutput(); // cancelled after the job had ended on its thread: take it back
        if (result || result.error().code != core::ErrorCode::Cancelled)
            result = core::cancelledError(m_job->title());
    }
    m_running = false;
    if (result) {
        const core::JobProgress last = m_context->progress();
        emit progress(fromUtf8(last.stage), qint64(last.total), qint64(last.total));
    }
    emit finished(result);
}

} // namespace thespis::editor
