#pragma once
// Ctrl-C handling for long commands: the first SIGINT (or SIGTERM) only raises a flag that the
// work loop polls, so the command can stop cleanly and leave no half-written file; a second
// Ctrl-C terminates at once, as users expect when a program does not react.

namespace thespis::cli {

/// Installs the handlers (idempotent).
void installInterruptHandlers();
/// True once SIGINT or SIGTERM has arrived.
bool interrupted();
/// The signal that interrupted (SIGINT or SIGTERM), or 0.
int interruptSignal();

} // namespace thespis::cli
