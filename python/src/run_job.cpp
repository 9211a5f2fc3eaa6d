#include "run_job.h"

#include <chrono>
#include <optional>

#include "errors.h"

namespace thespis::python {

void runJob(core::Job& job, const py::object& progress)
{
    std::optional<py::error_already_set> pythonError;
    auto result = withoutGil([&] {
        return core::runJobWatched(job, std::chrono::milliseconds(100), [&](const core::JobProgress& p) {
            py::gil_scoped_acquire gil;
            if (pythonError)
                return false;
            try {
                if (PyErr_CheckSignals() != 0)
                    throw py::error_already_set();
                if (!progress.is_none())
                    progress(p.done, p.total);
                return true;
            } catch (py::error_already_set& error) {
                pythonError.emplace(std::move(error));
                return false;
            }
        });
    });
    if (pythonError)
        throw std::move(*pythonError);
    unwrap(std::move(result));
}

} // namespace thespis::python
