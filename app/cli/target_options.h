#pragma once
// What `track` and `play` share: the options that name what to track (--board, or --target with
// --width), read into core's TrackingTarget.

#include "ar/tracking_target.h"
#include "arguments.h"

namespace thespis::cli {

/// Appends --board, --target and --width to a command's options.
void addTargetOptions(CommandSpec& spec);
/// Reads them into `out`; prints what is wrong and returns the exit code (ExitOk when read).
int readTargetOptions(const CommandSpec& spec, const ParsedArguments& arguments, core::ar::TrackingTarget& out);

} // namespace thespis::cli
