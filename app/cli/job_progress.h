#pragma once
// Running a core job (util/job.h) from a command: on a worker thread, with Ctrl-C as its cancel
// and a progress bar (progress.h) on stderr. Every long command runs its job through here.

#include <functional>
#include <string>

#include "util/job.h"

namespace thespis::cli {

struct JobBar {
    std::string stage;  ///< the stage the bar counts; empty: every stage
    std::string unit;   ///< what it counts ("frames")
    long total = 0;     ///< 0: the stage's own total
    /// Called once, when the counted stage begins (before the bar is drawn).
    std::function<void()> onStageBegins;
};

/// Runs `job` for `command`. A cancel prints "thespis-cli COMMAND: cancelled; <afterCancel>." and
/// returns ErrorCode::Cancelled; other errors are returned for the command to print.
core::Result<void> runJobWithProgress(const std::string& command, core::Job& job, const JobBar& bar, bool quiet,
                                      const std::string& afterCancel);

/// The exit code for a job that failed (exit_codes.h), after printing its error (a cancel was
/// printed already): cancelled → ExitCancelled, a write that failed → ExitFailure, anything
/// else wrong with the inputs → ExitInvalidInput.
int reportJobFailure(const std::string& command, const core::Error& error);

} // namespace thespis::cli
