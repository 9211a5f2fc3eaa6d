// PYBIND11_MODULE(_thespis): the compiled half of the `thespis` package, as an extension module
// for python3 (the same module is built into the studio and the CLI by thespis_script).

#include "bind_common.h"

PYBIND11_MODULE(_thespis, m)
{
    thespis::python::defineModule(m);
}
