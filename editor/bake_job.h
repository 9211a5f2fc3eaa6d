#pragma once
// BakeJob: runs one PRT transfer bake (core::lighting::bakeTransfer) off the GUI thread and
// writes its bake file. It owns the thread that runs the bake (the bake itself spreads over
// settings.threads workers) and a copy of the mesh, so it never touches a live Document
// (STYLE.md §6). Progress and the result come back on the thread that owns the job (the GUI
// thread), progress throttled to about 20 Hz.
//
// Rules: the bake file is written atomically (a temporary file beside it, then renamed) and only
// when the bake completes; once cancel() is called — or the bake fails — no file is left behind
// and finished() reports an error (ErrorCode::Cancelled, its message says "cancelled"), even
// when the bake had already ended on its thread. Destroying a running job cancels it and waits
// for its thread; finished() is then not emitted.

#include <QObject>
#include <QString>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <thread>

#include "lighting/transfer_bake.h"
#include "scene/character_mesh.h"
#include "util/error.h"

namespace thespis::editor {

class BakeJob : public QObject {
    Q_OBJECT
public:
    explicit BakeJob(QObject* parent = nullptr);
    /// Cancels a running bake and waits for its thread.
    ~BakeJob() override;

    /// Starts baking `mesh` with `settings` into `outputPath`. Refused (nothing started, no
    /// signal) while a bake runs, for settings validateBakeSettings refuses, or for an empty path.
    core::Result<void> start(core::scene::CharacterMesh mesh, const core::lighting::BakeSettings& settings,
                             const QString& outputPath);
    /// Asks a running bake to stop; finished() follows with a "cancelled" error. Does nothing
    /// when no bake runs.
    void cancel();
    /// From start() until finished() is emitted.
    bool isRunning() const { return m_running; }

    /// The settings and path of the last bake started.
    const core::lighting::BakeSettings& settings() const { return m_settings; }
    QString outputPath() const { return m_outputPath; }
    /// Numbers of the last bake that completed (vertices, rays, seconds).
    const core::lighting::BakeStatistics& statistics() const { return m_statistics; }

signals:
    /// Vertices baked so far of `total` (at most about 20 times a second, and once at the end).
    void progress(qint64 done, qint64 total);
    /// The bake ended: the written file's path, or why there is none (ErrorCode::Cancelled when
    /// cancelled).
    void finished(const core::Result<QString>& path);

private:
    // State shared with the bake's thread; outlives neither the job nor the thread.
    struct Shared {
        std::atomic<std::uint64_t> done{0}, total{0};
        std::atomic<bool> progressPosted{false};
        std::atomic<std::int64_t> lastPostNs{0};
    };
    void postProgress();
    void deliver(core::Result<QString> result, core::lighting::BakeStatistics statistics);

    std::jthread m_thread;
    std::shared_ptr<Shared> m_shared;
    core::lighting::BakeSettings m_settings;
    core::lighting::BakeStatistics m_statistics;
    QString m_outputPath;
    bool m_running = false;
    bool m_cancelled = false; // cancel() was called for the running bake (GUI thread)
};

} // namespace thespis::editor
