// PYBIND11_MODULE(_thespis): the compiled half of the `thespis` package. Each area binds itself
// in its own file; the order matters only where default arguments use another area's types.

#include "bind_common.h"

PYBIND11_MODULE(_thespis, m)
{
    m.doc() = "Thespis core bindings (use the `thespis` package, which re-exports these).";
    m.attr("__version__") = THESPIS_VERSION;
    thespis::python::bindErrors(m);
    thespis::python::bindFrames(m);
    thespis::python::bindSkeleton(m);
    thespis::python::bindAnim(m);
    thespis::python::bindBvh(m);
    thespis::python::bindScene(m);
    thespis::python::bindScenario(m);
    thespis::python::bindLighting(m);
    thespis::python::bindRender(m);
    thespis::python::bindEdit(m);
    thespis::python::bindRuntime(m);
}
