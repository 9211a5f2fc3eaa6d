#include "editor/bake_job.h"

#include <QMetaObject>

#include <filesystem>
#include <system_error>

#include "editor/qt_conversions.h"

namespace thespis::editor {

namespace {

namespace lighting = core::lighting;

// Progress reaches the GUI at most this often (STYLE.md §6: about 20 Hz).
constexpr std::chrono::milliseconds kProgressInterval(50);

core::Error cancelledError(const QString& path)
{
    return core::makeError(core::ErrorCode::Cancelled, "The bake was cancelled; nothing was written.",
                           "output " + path.toStdString());
}

std::int64_t nowNs()
{
    return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

} // namespace

BakeJob::BakeJob(QObject* parent) : QObject(parent) {}

BakeJob::~BakeJob()
{
    // The thread posts to this object: it must be gone before the QObject is. Events it posted
    // and that were not delivered die with the object.
    if (m_thread.joinable()) {
        m_thread.request_stop();
        m_thread.join();
    }
}

core::Result<void> BakeJob::start(core::scene::CharacterMesh mesh, const lighting::BakeSettings& settings,
                                  const QString& outputPath)
{
    if (m_running)
        return core::makeError(core::ErrorCode::InvalidArgument,
                               "A bake is already running: cancel it or wait for it to finish.");
    if (auto valid = lighting::validateBakeSettings(settings); !valid)
        return valid.error();
    if (outputPath.isEmpty())
        return core::makeError(core::ErrorCode::InvalidArgument, "The bake has no file to be written to.");
    if (m_thread.joinable())
        m_thread.join(); // the previous bake's thread: it has delivered its result, so it is ending

    m_settings = settings;
    m_outputPath = outputPath;
    m_running = true;
    m_cancelled = false;
    m_shared = std::make_shared<Shared>();
    m_shared->total = mesh.vertexCount();
    m_thread = std::jthread([this, shared = m_shared, mesh = std::move(mesh), settings, outputPath,
                             path = toFsPath(outputPath)](std::stop_token stop) {
        lighting::BakeStatistics statistics;
        auto bake = lighting::bakeTransfer(
            mesh, settings, stop,
            [this, &shared](const lighting::BakeProgress& p) {
                shared->done = p.verticesDone;
                shared->total = p.verticesTotal;
                const std::int64_t now = nowNs();
                const bool last = p.verticesDone >= p.verticesTotal;
                if (!last && now - shared->lastPostNs < std::chrono::nanoseconds(kProgressInterval).count())
                    return;
                // One report in flight is enough: it reads the latest numbers when it arrives.
                if (shared->progressPosted.exchange(true))
                    return;
                shared->lastPostNs = now;
                QMetaObject::invokeMethod(this, [this] { postProgress(); }, Qt::QueuedConnection);
            },
            &statistics);
        core::Result<QString> result = outputPath;
        if (!bake)
            result = bake.error().code == core::ErrorCode::Cancelled ? cancelledError(outputPath) : bake.error();
        else if (stop.stop_requested())
            result = cancelledError(outputPath);
        else if (auto written = lighting::writeBakeFile(path, *bake); !written)
            result = written.error(); // written atomically: nothing is left behind
        QMetaObject::invokeMethod(
            this, [this, result, statistics] { deliver(result, statistics); }, Qt::QueuedConnection);
    });
    return {};
}

void BakeJob::cancel()
{
    if (!m_running)
        return;
    m_cancelled = true;
    m_thread.request_stop();
}

void BakeJob::postProgress()
{
    if (!m_shared || !m_running)
        return;
    m_shared->progressPosted = false; // before reading, so that a newer report is not lost
    emit progress(qint64(m_shared->done.load()), qint64(m_shared->total.load()));
}

void BakeJob::deliver(core::Result<QString> result, lighting::BakeStatistics statistics)
{
    if (!m_running)
        return;
    if (result && m_cancelled) {
        // Cancelled after the bake had ended on its thread: take the file back.
        std::error_code ec;
        std::filesystem::remove(toFsPath(*result), ec);
        result = cancelledError(m_outputPath);
    }
    if (m_thread.joinable())
        m_thread.join(); // its last act was posting this result
    m_running = false;
    if (result) {
        m_statistics = statistics;
        const auto total = qint64(m_shared->total.load());
        emit progress(total, total);
    }
    emit finished(result);
}

} // namespace thespis::editor
