// pybind11's embed header must come before anything that may include Qt (its `slots` macro).
#include <pybind11/embed.h>

#include "interpreter.h"

#include <filesystem>
#include <mutex>

#include "bind_common.h"

PYBIND11_EMBEDDED_MODULE(_thespis, m)
{
    thespis::python::defineModule(m);
}

namespace thespis::script {

namespace py = pybind11;

void ensurePython()
{
    static std::once_flag started;
    std::call_once(started, [] {
        py::initialize_interpreter(false);
        {
            py::module_ sys = py::module_::import("sys");
            const std::filesystem::path buildTree = THESPIS_PYTHON_BUILD_DIR;
            if (std::filesystem::exists(buildTree / "thespis" / "__init__.py"))
                sys.attr("path").attr("insert")(0, buildTree.string());
            sys.attr("argv") = py::make_tuple("thespis");
        }
        py::detail::get_internals(); // made here, with the GIL, not first in a worker thread
        PyEval_SaveThread(); // held by no one until a script runs; never taken back (Python lives on)
    });
}

} // namespace thespis::script
