// The `_thespis` module's contents. Each area binds itself in its own file; the order matters
// only where default arguments use another area's types.

#include "bind_common.h"

namespace thespis::python {

void bindAr(py::module_& m); // thespis.ar: boards, calibration, tracking, capture (bind_ar.cpp)

void defineModule(py::module_& m)
{
    m.doc() = "Thespis core bindings (use the `thespis` package, which re-exports these).";
    m.attr("__version__") = THESPIS_VERSION;
    bindErrors(m);
    bindFrames(m);
    bindSkeleton(m);
    bindAnim(m);
    bindBvh(m);
    bindScene(m);
    bindFace(m);
    bindScenario(m);
    bindLighting(m);
    bindRender(m);
    bindEdit(m);
    bindRuntime(m);
    bindMotion(m);
    bindSpeech(m);
    bindBml(m);
    bindDialogue(m);
    bindAr(m);
}

} // namespace thespis::python
