#pragma once
// JobRunner: runs one core job (util/job.h) off the GUI thread — the transfer bake, a probe
// projection, … — the studio's side of the one job model the CLI and Python share. Progress
// (stage, done, total) comes back on the GUI thread at about 20 Hz; the Cancel button calls
// cancel(), which stops the job's token. The job owns copies of its inputs, so it never touches
// a live Document (STYLE.md §6).
//
// Rules: once cancel() is called finished() reports ErrorCode::Cancelled, and what the job wrote
// is taken back (Job::discardOutput) even when it had already ended on its thread. Destroying a
// running runner cancels the job and waits for its thread; finished() is then not emitted.

#include <QObject>
#include <QString>
#include <QTimer>

#include <memory>
#include <thread>

#include "util/job.h"

namespace thespis::editor {

class JobRunner : public QObject {
    Q_OBJECT
public:
    explicit JobRunner(QObject* parent = nullptr);
    ~JobRunner() override;

    /// Validates and starts `job`. Refused (nothing started, no signal) while a job runs or when
    /// the job does not validate.
    core::Result<void> start(std::unique_ptr<core::Job> job);
    /// Asks the running job to stop; finished() follows with ErrorCode::Cancelled.
    void cancel();
    /// From start() until finished() is emitted.
    bool isRunning() const { return m_running; }
    /// The last job started: its outputs are valid once finished() reported success.
    core::Job* job() const { return m_job.get(); }
    template <class J>
    J* jobAs() const { return dynamic_cast<J*>(m_job.get()); }

signals:
    /// The job's progress, at most about 20 times a second and once at the end.
    void progress(const QString& stage, qint64 done, qint64 total);
    /// The job ended: success, or why not (ErrorCode::Cancelled when cancelled).
    void finished(const core::Result<void>& result);

private:
    void reportProgress();
    void deliver(core::Result<void> result);

    std::unique_ptr<core::Job> m_job;
    std::unique_ptr<core::JobContext> m_context;
    std::stop_source m_stop;
    std::jthread m_thread;
    QTimer m_progressTimer;
    core::JobProgress m_lastReported;
    bool m_running = false;
    bool m_cancelled = false; // cancel() was called for the running job (GUI thread)
};

} // namespace thespis::editor
