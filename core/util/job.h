#pragma once
// The job model: every long piece of work (transfer bake, motion bake, frame-sequence render,
// probe projection) is a Job that checks its inputs in validate() and does the work in
// run(context). The context carries the one cancel mechanism — a std::stop_token — and the
// progress: a stage name and a done / total count. Front ends run jobs the same way: the CLI and
// Python through runJobWatched (Ctrl-C and KeyboardInterrupt stop the token), the studio through
// editor::JobRunner (the Cancel button stops it).
//
// Rules every job keeps: a stopped job returns ErrorCode::Cancelled and leaves no file behind
// (files are written atomically, at the end); a job never touches live editor state, it owns
// copies of its inputs; outputs are members of the job, read after run() succeeded.

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <stop_token>
#include <string>

#include "util/error.h"

namespace thespis::core {

struct JobProgress {
    std::string stage;       ///< what the job does now, for people ("Tracing rays")
    std::uint64_t done = 0;  ///< units of the stage finished
    std::uint64_t total = 0; ///< units of the stage; 0 when unknown
};

/// What a running job reads (its stop token) and writes (its progress). Progress may be reported
/// from any thread, as often as the job likes: reporting is cheap (an atomic store) except when a
/// stage begins.
class JobContext {
public:
    explicit JobContext(std::stop_token stop = {}) : m_stop(std::move(stop)) {}
    JobContext(const JobContext&) = delete;
    JobContext& operator=(const JobContext&) = delete;

    const std::stop_token& stopToken() const { return m_stop; }
    bool stopRequested() const { return m_stop.stop_requested(); }

    /// Begins a stage: its name and how many units it has (done is 0 again).
    void beginStage(std::string name, std::uint64_t total = 0);
    void setDone(std::uint64_t done);
    /// A copy of the latest progress.
    JobProgress progress() const;
    /// Waits until progress is reported or `timeout` passes; for watchers.
    void waitForProgress(std::chrono::milliseconds timeout) const;

private:
    void notify();

    std::stop_token m_stop;
    mutable std::mutex m_mutex;
    mutable std::condition_variable m_changed;
    std::string m_stage;
    std::atomic<std::uint64_t> m_done{0}, m_total{0};
    std::atomic<std::uint64_t> m_reports{0};
};

class Job {
public:
    virtual ~Job() = default;
    /// What the job makes, as the subject of a sentence ("The transfer bake of hero.glb").
    virtual std::string title() const = 0;
    /// Checks the inputs: every rule the job depends on, in a message naming the field.
    virtual Result<void> validate() const = 0;
    /// Does the work; ErrorCode::Cancelled when the context's token was stopped.
    virtual Result<void> run(JobContext& context) = 0;
    /// Takes back what a completed run wrote (its files), for a cancel that came too late: the
    /// user asked to stop, so nothing of the job may stay. By default there is nothing to take back.
    virtual void discardOutput() {}
};

/// The error a job returns when stopped: "<what> was cancelled; nothing was written."
Error cancelledError(const std::string& what);

/// Called on the calling thread of runJobWatched with the latest progress; returns false to stop
/// the job.
using JobWatcher = std::function<bool(const JobProgress&)>;

/// Validates `job`, then runs it on a worker thread while the calling thread keeps control: it
/// wakes on every progress report, and at least every `interval`, to call `watch`, so a front end
/// can draw progress and notice Ctrl-C on its own thread. `watch` returning false stops the job
/// (ErrorCode::Cancelled; a job that had already finished is discarded). `watch` is called once
/// more when the job has ended, with its last progress.
Result<void> runJobWatched(Job& job, std::chrono::milliseconds interval, const JobWatcher& watch);

} // namespace thespis::core
