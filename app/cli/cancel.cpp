#include "cancel.h"

#include <csignal>

namespace thespis::cli {
namespace {

// sig_atomic_t: the only type a signal handler may portably write.
volatile std::sig_atomic_t g_signal = 0;

extern "C" void onInterrupt(int signal)
{
    g_signal = signal;
}

} // namespace

void installInterruptHandlers()
{
    struct sigaction action {};
    action.sa_handler = onInterrupt;
    sigemptyset(&action.sa_mask);
    // SA_RESETHAND: the handler runs once; a second Ctrl-C gets the default action (terminate).
    action.sa_flags = SA_RESETHAND;
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
}

bool interrupted()
{
    return g_signal != 0;
}

int interruptSignal()
{
    return g_signal;
}

} // namespace thespis::cli
