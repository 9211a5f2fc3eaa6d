#include "job_progress.h"

#include <chrono>
#include <cstdio>
#include <optional>

#include "cancel.h"
#include "commands.h"
#include "exit_codes.h"
#include "progress.h"

namespace thespis::cli {

core::Result<void> runJobWithProgress(const std::string& command, core::Job& job, const JobBar& bar, bool quiet,
                                      const std::string& afterCancel)
{
    installInterruptHandlers();
    std::optional<ProgressReporter> progress; // once the counted stage begins
    const auto done = core::runJobWatched(job, std::chrono::milliseconds(50), [&](const core::JobProgress& p) {
        if (bar.stage.empty() || p.stage == bar.stage) {
            if (!progress) {
                if (bar.onStageBegins)
                    bar.onStageBegins();
                progress.emplace(stderr, command, bar.unit, bar.total > 0 ? bar.total : long(p.total), quiet);
            }
            progress->update(long(p.done));
        }
        return !interrupted();
    });
    if (!done) {
        if (progress)
            progress->abandon();
        if (done.error().code == core::ErrorCode::Cancelled)
            std::fprintf(stderr, "thespis-cli %s: cancelled; %s.\n", command.c_str(), afterCancel.c_str());
        return done;
    }
    if (progress)
        progress->finish();
    return done;
}

int reportJobFailure(const std::string& command, const core::Error& error)
{
    if (error.code == core::ErrorCode::Cancelled)
        return ExitCancelled;
    printError(command, error);
    return error.code == core::ErrorCode::IoError ? ExitFailure : ExitInvalidInput;
}

} // namespace thespis::cli
