#pragma once
// Python runs core jobs (util/job.h) the way the CLI does: on a worker thread without the GIL,
// while the calling thread wakes every 100 ms to call the user's `progress(done, total)` and to
// check for Ctrl-C. KeyboardInterrupt, or an exception the callback raises, stops the job and is
// raised once the job has stopped; other failures raise the job's error.

#include "bind_common.h"
#include "util/job.h"

namespace thespis::python {

void runJob(core::Job& job, const py::object& progress);

} // namespace thespis::python
