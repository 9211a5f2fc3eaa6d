#pragma once
// Private to the scenario bindings (bind_scenario.cpp, bind_package.cpp): where a scenario's
// files are found, as Python says it. Defined in bind_package.cpp.

#include "bind_common.h"
#include "scenario/asset_resolver.h"

namespace thespis::python {

/// A folder (str or path: the scenario file's) or an open thespis.Package.
core::scenario::Assets assetsArgument(const py::handle& where);
/// thespis.Package, open_package, export_package.
void bindPackages(py::module_& m);

} // namespace thespis::python
