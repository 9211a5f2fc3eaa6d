#pragma once
// Exit codes of thespis-cli, distinct so that scripts and farms can tell what went wrong.

namespace thespis::cli {

enum ExitCode : int {
    ExitOk = 0,
    ExitUsage = 2,        ///< bad command line: unknown command or option, missing argument
    ExitInvalidInput = 3, ///< a file is missing, malformed or invalid (the message says where)
    ExitFailure = 4,      ///< the work itself failed (e.g. the output could not be written)
    ExitCancelled = 130,  ///< stopped by Ctrl-C (SIGINT) or SIGTERM; nothing half-written is left
};

} // namespace thespis::cli
