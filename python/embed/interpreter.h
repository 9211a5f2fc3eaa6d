#pragma once
// The embedded interpreter every in-process Python user shares (ScriptRunner, FarmBakeJob): the
// `thespis` module built in, Python started once per process, the GIL taken by any thread.
// Include <pybind11/embed.h> before this header's users include anything that may include Qt.

#include <pybind11/pybind11.h>

namespace thespis::script {

/// Starts Python once for the whole process, then lets go of the GIL so that any thread can
/// take it. Python's own signal handlers are not installed: the program keeps its Ctrl-C.
void ensurePython();

/// Holds the GIL in any thread, with Python's own per-thread state (threads the program made
/// get one the first time).
class GilHolder {
public:
    GilHolder() : m_state(PyGILState_Ensure()) {}
    ~GilHolder() { PyGILState_Release(m_state); }
    GilHolder(const GilHolder&) = delete;
    GilHolder& operator=(const GilHolder&) = delete;

private:
    PyGILState_STATE m_state;
};

} // namespace thespis::script
