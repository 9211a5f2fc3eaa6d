#pragma once
// Shared by every binding file: pybind11 includes, the casters that let core's value types and
// `shared_ptr<const T>` cross into Python, and the per-area bind functions module.cpp calls.
// Every binding translation unit includes this header, so all of them see the same casters.

#include <memory>
#include <span>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "anim/quat.h"
#include "motion/gaze_target.h"

namespace pybind11::detail {

// Core shares immutable objects as shared_ptr<const T> (layouts, blendables, masks). Python
// objects are held by shared_ptr<T>; const-ness is kept by binding no mutating method of
// those types. Loading accepts any instance of a bound T (or None → null).
template <typename T>
class type_caster<std::shared_ptr<const T>> {
    using Base = copyable_holder_caster<T, std::shared_ptr<T>>;

public:
    PYBIND11_TYPE_CASTER(std::shared_ptr<const T>, Base::name);

    bool load(handle src, bool convert)
    {
        Base base;
        if (!base.load(src, convert))
            return false;
        value = static_cast<std::shared_ptr<T>&>(base);
        return true;
    }

    static handle cast(const std::shared_ptr<const T>& src, return_value_policy policy, handle parent)
    {
        return Base::cast(std::const_pointer_cast<T>(src), policy, parent);
    }
};

// Vectors and quaternions travel as tuples (and load from any sequence of numbers, NumPy arrays
// included): (x, y, z) and (x, y, z, w).
template <typename T>
struct type_caster<thespis::core::anim::Vec3T<T>> {
    PYBIND11_TYPE_CASTER(thespis::core::anim::Vec3T<T>, const_name("tuple[float, float, float]"));

    bool load(handle src, bool convert)
    {
        T components[3];
        if (!loadSequence(src, convert, components, 3))
            return false;
        value = {components[0], components[1], components[2]};
        return true;
    }
    static handle cast(const thespis::core::anim::Vec3T<T>& v, return_value_policy, handle)
    {
        return make_tuple(v.x, v.y, v.z).release();
    }

    static bool loadSequence(handle src, bool convert, T* out, std::size_t n)
    {
        if (!isinstance<sequence>(src) || isinstance<str>(src) || isinstance<bytes>(src))
            return false;
        const auto seq = reinterpret_borrow<sequence>(src);
        if (seq.size() != n)
            return false;
        for (std::size_t i = 0; i < n; ++i) {
            make_caster<T> component;
            if (!component.load(seq[i], convert))
                return false;
            out[i] = cast_op<T>(component);
        }
        return true;
    }
};

template <typename T>
struct type_caster<thespis::core::anim::QuatT<T>> {
    PYBIND11_TYPE_CASTER(thespis::core::anim::QuatT<T>, const_name("tuple[float, float, float, float]"));

    bool load(handle src, bool convert)
    {
        T components[4];
        if (!type_caster<thespis::core::anim::Vec3T<T>>::loadSequence(src, convert, components, 4))
            return false;
        value = {components[0], components[1], components[2], components[3]};
        return true;
    }
    static handle cast(const thespis::core::anim::QuatT<T>& q, return_value_policy, handle)
    {
        return make_tuple(q.x, q.y, q.z, q.w).release();
    }
};

} // namespace pybind11::detail

namespace thespis::python {

namespace py = pybind11;

/// A new NumPy array holding a copy of `values`, shaped `shape` (C order).
template <class T>
py::array_t<T> toArray(std::span<const T> values, std::vector<py::ssize_t> shape = {})
{
    if (shape.empty())
        shape.push_back(py::ssize_t(values.size()));
    py::array_t<T> array(shape);
    std::copy(values.begin(), values.end(), array.mutable_data());
    return array;
}

/// Runs `work` with the GIL released (file reading, clip loading, projection may take a while)
/// and returns its value; Results are unwrapped afterwards, with the GIL held again.
template <class Work>
auto withoutGil(Work&& work)
{
    py::gil_scoped_release release;
    return work();
}

/// Fills the `_thespis` module (module.cpp's extension and the embedded one).
void defineModule(py::module_& m);

/// A gaze target from Python: "camera", "Antigone", "Antigone:l_radiocarpal", or three numbers (bind_runtime.cpp).
core::motion::GazeTarget gazeTarget(const py::object& target);

void bindErrors(py::module_& m);
void bindFrames(py::module_& m); // FrameLayout, TimeDomain, Blendable (bind_anim.cpp)
void bindAnim(py::module_& m);   // curves, masks, clips, modifiers, schedules
void bindSkeleton(py::module_& m);
void bindBvh(py::module_& m);
void bindScenario(py::module_& m);
void bindScene(py::module_& m);    // thespis.scene: character meshes, segments, tags, glTF
void bindFace(py::module_& m);     // thespis.face: face mapping tables, morph targets, face frames
void bindLighting(py::module_& m); // thespis.lighting: SH, probes, the transfer bake
void bindRender(py::module_& m);   // thespis.render: headless pictures of scenarios
void bindEdit(py::module_& m);     // thespis.edit: the studio's undoable scenario edits
void bindRuntime(py::module_& m);  // thespis.runtime: clocks, the Stage, the animation service
void bindMotion(py::module_& m);   // thespis.motion: postures, the posture PCA, idle motion, the filter
void bindSpeech(py::module_& m);   // thespis.speech: tagged text, espeak-ng speech, visemes, Insert
void bindBml(py::module_& m);      // thespis.bml: BML blocks read and realised on the Stage
void bindDialogue(py::module_& m); // thespis.dialogue: AIML bots, conversations, listening, the interaction service

} // namespace thespis::python
