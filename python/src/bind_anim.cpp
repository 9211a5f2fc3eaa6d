// Bindings of core/anim: frame layouts, blendables, curves, joint masks, blending parameters,
// keyframe clips, modifiers, the frame cache and blending schedules. Frames cross as NumPy
// float32 arrays laid out as in core (rotations x y z w, then translations, then scalars).
// Evaluation keeps the GIL: a schedule is evaluated by one thread at a time, and the GIL is
// what guarantees that when several Python threads share one.

#include <cmath>
#include <optional>
#include <sstream>
#include <string>

#include "anim/blendable.h"
#include "anim/blending_params.h"
#include "anim/blending_schedule.h"
#include "anim/curve.h"
#include "anim/frame.h"
#include "anim/frame_blender.h"
#include "anim/frame_cache.h"
#include "anim/joint_mask.h"
#include "anim/keyframe_clip.h"
#include "anim/modifiers.h"
#include "anim/skeleton.h"
#include "bind_common.h"
#include "errors.h"

namespace thespis::python {

using namespace pybind11::literals;
using namespace core::anim;

namespace {

using FloatArray = py::array_t<float, py::array::c_style | py::array::forcecast>;
using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

void checkIndex(int index, int count, const char* what)
{
    if (index < 0 || index >= count)
        throw py::index_error(std::string(what) + " index " + std::to_string(index) + " is out of range (0 to "
                              + std::to_string(count - 1) + ").");
}

std::string formatNumber(double value)
{
    std::ostringstream text;
    text << value;
    return text.str();
}

// `frames` as a flat vector of whole frames of `floats` values: a 2-D array must have `floats`
// columns; a 1-D array is taken as frames one after the other.
std::vector<float> framesFromArray(const FloatArray& frames, std::size_t floats, const char* what)
{
    if (frames.ndim() != 1 && frames.ndim() != 2)
        throw py::value_error(std::string(what) + " must be a 1-D or 2-D array (frames × values), not "
                              + std::to_string(frames.ndim()) + "-D.");
    if (frames.ndim() == 2 && std::size_t(frames.shape(1)) != floats)
        throw py::value_error(std::string(what) + " has " + std::to_string(frames.shape(1))
                              + " values per frame; the layout needs " + std::to_string(floats) + ".");
    return std::vector<float>(frames.data(), frames.data() + frames.size());
}

// A frame the caller gives for `layout`; empty when `frame` is None.
std::vector<float> optionalFrame(const std::optional<FloatArray>& frame, const FrameLayout& layout, const char* what)
{
    if (!frame)
        return {};
    if (std::size_t(frame->size()) != layout.floatCount())
        throw py::value_error(std::string(what) + " has " + std::to_string(frame->size()) + " values; the layout needs "
                              + std::to_string(layout.floatCount()) + ".");
    return std::vector<float>(frame->data(), frame->data() + frame->size());
}

// Parent indices for mask inheritance: one per rotation, each -1 or an earlier rotation (core
// reads them as indices, so a bad one would read out of bounds).
void checkParents(const std::vector<int>& parents, const FrameLayout& layout)
{
    if (parents.empty())
        return;
    if (parents.size() != std::size_t(layout.rotationCount()))
        throw py::value_error("parents has " + std::to_string(parents.size()) + " entries; the layout has "
                              + std::to_string(layout.rotationCount()) + " rotations.");
    for (std::size_t i = 0; i < parents.size(); ++i)
        if (parents[i] < -1 || parents[i] >= int(i))
            throw py::value_error("parents[" + std::to_string(i) + "] is " + std::to_string(parents[i])
                                  + "; it must be -1 or the index of an earlier rotation.");
}

std::shared_ptr<const JointMask> sharedMask(const std::optional<JointMask>& mask)
{
    return mask ? std::make_shared<const JointMask>(*mask) : nullptr;
}

std::optional<JointMask> maskCopy(const std::shared_ptr<const JointMask>& mask)
{
    return mask ? std::optional<JointMask>(*mask) : std::nullopt;
}

std::string curveRepr(const Curve& c)
{
    const EnvelopeParams& e = c.envelope();
    switch (c.kind()) {
    case CurveKind::Constant:
        return "Curve.constant(" + formatNumber(e.peak) + ")";
    case CurveKind::LinearFade:
    case CurveKind::CubicFade:
        return std::string(c.kind() == CurveKind::LinearFade ? "Curve.linear_fade(" : "Curve.cubic_fade(")
               + formatNumber(e.attack) + ", " + formatNumber(e.release) + ", peak=" + formatNumber(e.peak) + ")";
    case CurveKind::LinearAdsr:
    case CurveKind::CubicAdsr:
        return std::string(c.kind() == CurveKind::LinearAdsr ? "Curve.linear_adsr(" : "Curve.cubic_adsr(")
               + formatNumber(e.attack) + ", " + formatNumber(e.decay) + ", " + formatNumber(e.sustain) + ", "
               + formatNumber(e.release) + ", peak=" + formatNumber(e.peak) + ")";
    case CurveKind::Keyframed:
        return "Curve.keyframed(<" + std::to_string(c.keys().size()) + " keys>)";
    case CurveKind::Dominance:
        return "Curve.dominance(" + formatNumber(e.alpha) + ", peak=" + formatNumber(e.peak) + ")";
    }
    return "Curve()";
}

void bindCurves(py::module_& m)
{
    py::enum_<CurveKind>(m, "CurveKind", "The shape family of a Curve.")
        .value("constant", CurveKind::Constant)
        .value("linear_fade", CurveKind::LinearFade)
        .value("cubic_fade", CurveKind::CubicFade)
        .value("linear_adsr", CurveKind::LinearAdsr)
        .value("cubic_adsr", CurveKind::CubicAdsr)
        .value("keyframed", CurveKind::Keyframed)
        .value("dominance", CurveKind::Dominance);

    py::enum_<TangentMode>(m, "TangentMode", "How a keyframed curve leaves and enters a key.")
        .value("auto_clamped", TangentMode::AutoClamped, "smooth, flattened at extrema (never overshoots)")
        .value("linear", TangentMode::Linear, "straight towards the neighbouring keys")
        .value("constant", TangentMode::Constant, "step: hold the key's value until the next key")
        .value("free", TangentMode::Free, "user slope (in_slope), the same on both sides")
        .value("broken", TangentMode::Broken, "independent in_slope and out_slope");

    py::class_<CurveKey>(m, "CurveKey", "A key of a keyframed curve: time (s), value, tangent mode and slopes.")
        .def(py::init([](double time, double value, TangentMode mode, double inSlope, double outSlope) {
                 return CurveKey{time, value, mode, inSlope, outSlope};
             }),
             "time"_a, "value"_a, "mode"_a = TangentMode::AutoClamped, "in_slope"_a = 0.0, "out_slope"_a = 0.0)
        .def_readwrite("time", &CurveKey::time)
        .def_readwrite("value", &CurveKey::value)
        .def_readwrite("mode", &CurveKey::mode)
        .def_readwrite("in_slope", &CurveKey::inSlope)
        .def_readwrite("out_slope", &CurveKey::outSlope)
        .def("__eq__", [](const CurveKey& a, const CurveKey& b) { return a == b; })
        .def("__repr__", [](const CurveKey& k) {
            return "CurveKey(" + formatNumber(k.time) + ", " + formatNumber(k.value) + ", "
                   + py::repr(py::cast(k.mode)).cast<std::string>() + ")";
        });

    py::class_<EnvelopeParams>(m, "EnvelopeParams", "Parameters of a fade, ADSR or dominance curve (read only).")
        .def_readonly("attack", &EnvelopeParams::attack)
        .def_readonly("decay", &EnvelopeParams::decay)
        .def_readonly("sustain", &EnvelopeParams::sustain)
        .def_readonly("release", &EnvelopeParams::release)
        .def_readonly("peak", &EnvelopeParams::peak)
        .def_readonly("alpha", &EnvelopeParams::alpha, "The dominance curve's α (0 for the other kinds).")
        .def("__eq__", [](const EnvelopeParams& a, const EnvelopeParams& b) { return a == b; });

    py::class_<Curve>(m, "Curve",
                      "A weight or scale curve over an action's local time (paper Fig. 3). Fades and ADSR "
                      "envelopes are relative to the action's duration: the fade-out/release ends at the "
                      "duration passed to evaluate(). Curves are values: copy freely.")
        .def(py::init<>(), "The constant 1.")
        .def_readonly_static("INFINITE", &Curve::Infinite)
        .def_static("constant", &Curve::constant, "value"_a)
        .def_static("linear_fade", &Curve::linearFade, "fade_in"_a, "fade_out"_a, "peak"_a = 1.0)
        .def_static("cubic_fade", &Curve::cubicFade, "fade_in"_a, "fade_out"_a, "peak"_a = 1.0)
        .def_static("linear_adsr", &Curve::linearAdsr, "attack"_a, "decay"_a, "sustain"_a, "release"_a,
                    "peak"_a = 1.0)
        .def_static("cubic_adsr", &Curve::cubicAdsr, "attack"_a, "decay"_a, "sustain"_a, "release"_a,
                    "peak"_a = 1.0)
        .def_static("dominance", &Curve::dominance, "alpha"_a, "peak"_a = 1.0,
                    "The coarticulation dominance (paper eq. 3) over the action's duration, times peak: 0 "
                    "at both ends, peak in the middle; a larger alpha (> 0) peaks more sharply. An "
                    "open-ended action holds the peak.")
        .def_static(
            "keyframed", [](std::vector<CurveKey> keys) { return unwrap(Curve::keyframed(std::move(keys))); },
            "keys"_a, "A cubic Hermite curve through the keys (sorted by time). ValueError for no keys, "
                      "two keys at one time or a non-finite value.")
        .def("validate", [](const Curve& c) { unwrap(c.validate()); },
             "Raises ValueError when a parameter is not finite, a time is negative, sustain is outside [0, 1] "
             "or a dominance curve's alpha is not above 0.")
        .def_property_readonly("kind", &Curve::kind)
        .def_property_readonly("envelope", [](const Curve& c) { return c.envelope(); })
        .def_property_readonly("constant_value", &Curve::constantValue)
        .def_property_readonly("keys", [](const Curve& c) { return c.keys(); })
        .def_property_readonly("is_identity", &Curve::isIdentity)
        .def("evaluate", py::vectorize(&Curve::evaluate), "t"_a, "duration"_a = Curve::Infinite,
             "Value at local time t (a number or an array of times) of an action lasting `duration` seconds.")
        .def("__eq__", [](const Curve& a, const Curve& b) { return a == b; })
        .def("__repr__", &curveRepr);

    m.def("smooth_step", &smoothStep, "u"_a, "3u² − 2u³ on [0, 1] (clamped): the cubic fade shape.");
    m.def("dominance", py::vectorize(&dominance), "alpha"_a, "x"_a,
          "The paper's eq. 3 at x in [0, 1] (a number or an array): e^(−α·2|x−0.5|) − 2|x−0.5|·e^(−α); "
          "0 outside [0, 1]. Curve.dominance is this over an action's duration.");
}

void bindMasks(py::module_& m)
{
    py::enum_<MaskPreset>(m, "MaskPreset", "Built-in joint masks over H-Anim joint names.")
        .value("full_body", MaskPreset::FullBody)
        .value("upper_body", MaskPreset::UpperBody)
        .value("lower_body", MaskPreset::LowerBody)
        .value("left_arm", MaskPreset::LeftArm)
        .value("right_arm", MaskPreset::RightArm)
        .value("head_and_neck", MaskPreset::HeadAndNeck)
        .value("spine", MaskPreset::Spine);

    py::class_<JointMask>(m, "JointMask",
                          "A weight in [0, 1] per joint. Joints the mask does not name inherit their nearest "
                          "named ancestor's weight when the hierarchy is known, else take default_weight.")
        .def(py::init<std::map<std::string, float>, float>(), "weights"_a = std::map<std::string, float>{},
             "default_weight"_a = 0.0f)
        .def_static("preset", &JointMask::preset, "preset"_a)
        .def_property_readonly("weights", [](const JointMask& mask) { return mask.weights(); },
                               "A copy of the named weights (joint name → weight).")
        .def_property("default_weight", &JointMask::defaultWeight, &JointMask::setDefaultWeight)
        .def(
            "weight",
            [](const JointMask& mask, const std::string& joint) -> std::optional<float> {
                const float w = mask.weight(joint);
                return w < 0 ? std::nullopt : std::optional<float>(w);
            },
            "joint"_a, "The weight the mask names for `joint`, or None when it does not name it.")
        .def("set_weight", &JointMask::setWeight, "joint"_a, "weight"_a)
        .def("mirrored", &JointMask::mirrored, "Left and right swapped.")
        .def("inverted", &JointMask::inverted, "1 − w for every named weight and the default.")
        .def("validate", [](const JointMask& mask) { unwrap(mask.validate()); },
             "Raises ValueError naming the joint whose weight is outside [0, 1] or not finite.")
        .def(
            "resolve",
            [](const JointMask& mask, const FrameLayout& layout, std::vector<int> parents) {
                checkParents(parents, layout);
                const std::vector<float> weights = mask.resolve(layout, parents);
                return toArray<float>(weights);
            },
            "layout"_a, "parents"_a = std::vector<int>{},
            "One weight per layout element (float32 array); `parents` gives each rotation's parent rotation.")
        .def("__eq__", [](const JointMask& a, const JointMask& b) { return a == b; })
        .def("__repr__", [](const JointMask& mask) {
            return "<thespis.JointMask " + std::to_string(mask.weights().size()) + " joints, default "
                   + formatNumber(mask.defaultWeight()) + ">";
        });
}

void bindParams(py::module_& m)
{
    py::enum_<BlendMode>(m, "BlendMode", "How an action combines with the others.")
        .value("normalized", BlendMode::Normalized, "the paper's weighted blend, normalized per element")
        .value("additive", BlendMode::Additive, "adds its difference to a reference pose, scaled by the weight")
        .value("override", BlendMode::Override, "moves the result towards this action by the weight");

    py::enum_<AdditiveReference>(m, "AdditiveReference", "The pose an additive action is relative to.")
        .value("first_frame", AdditiveReference::FirstFrame)
        .value("rest_pose", AdditiveReference::RestPose);

    py::class_<BlendingParams>(m, "BlendingParams",
                               "How an action takes part in a blend: weight and scale curves, an optional joint "
                               "mask (multiplexed with the weight), and the blend mode. The mask is stored by "
                               "value: assign a changed mask back to take effect.")
        .def(py::init([](Curve weight, Curve scale, std::optional<JointMask> mask, BlendMode mode,
                         AdditiveReference reference) {
                 BlendingParams params;
                 params.weight = std::move(weight);
                 params.scale = std::move(scale);
                 params.mask = sharedMask(mask);
                 params.mode = mode;
                 params.additiveReference = reference;
                 return params;
             }),
             "weight"_a = Curve(), "scale"_a = Curve(), "mask"_a = py::none(), "mode"_a = BlendMode::Normalized,
             "additive_reference"_a = AdditiveReference::FirstFrame)
        .def_readwrite("weight", &BlendingParams::weight)
        .def_readwrite("scale", &BlendingParams::scale)
        .def_property(
            "mask", [](const BlendingParams& p) { return maskCopy(p.mask); },
            [](BlendingParams& p, const std::optional<JointMask>& mask) { p.mask = sharedMask(mask); })
        .def_readwrite("mode", &BlendingParams::mode)
        .def_readwrite("additive_reference", &BlendingParams::additiveReference);
}

void bindClipsAndModifiers(py::module_& m)
{
    py::class_<KeyframeClip, BlendableObject, std::shared_ptr<KeyframeClip>>(
        m, "KeyframeClip",
        "Frames sampled at a fixed rate, evaluated at any time (slerp for rotations, linear otherwise).")
        .def(py::init([](FrameLayoutPtr layout, double frameRate, const FloatArray& frames, std::string name) {
                 std::vector<float> values = framesFromArray(frames, layout->floatCount(), "frames");
                 return unwrap(KeyframeClip::create(std::move(layout), frameRate, std::move(values), std::move(name)));
             }),
             "layout"_a.none(false), "frame_rate"_a, "frames"_a, "name"_a = "",
             "A clip from a (frame_count, layout.float_count) array. Rotations are normalized. ValueError for a "
             "frame rate ≤ 0, no frames, a non-finite value or a zero rotation.")
        .def_property_readonly("name", &KeyframeClip::name)
        .def_property_readonly("frame_rate", &KeyframeClip::frameRate)
        .def_property_readonly("frame_count", &KeyframeClip::frameCount)
        .def(
            "frame",
            [](const KeyframeClip& clip, int index) {
                checkIndex(index, clip.frameCount(), "Frame");
                return toArray<float>(clip.frame(index));
            },
            "index"_a, "A copy of key `index` (rotations may have flipped sign: the same rotation).")
        .def_property_readonly(
            "frames",
            [](py::object self) {
                const auto& clip = self.cast<const KeyframeClip&>();
                const auto floats = py::ssize_t(clip.layout()->floatCount());
                // A read-only view of the clip's storage; the array keeps the clip alive.
                py::array_t<float> view({py::ssize_t(clip.frameCount()), floats},
                                        {floats * py::ssize_t(sizeof(float)), py::ssize_t(sizeof(float))},
                                        clip.data().data(), self);
                py::detail::array_proxy(view.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
                return view;
            },
            "Every key as a read-only (frame_count, float_count) float32 array.")
        .def("__repr__", [](const KeyframeClip& clip) {
            return "<thespis.KeyframeClip '" + clip.name() + "' " + std::to_string(clip.frameCount()) + " frames at "
                   + formatNumber(clip.frameRate()) + " fps>";
        });

    m.def(
        "remap_clip",
        [](const KeyframeClip& clip, FrameLayoutPtr target, const FloatArray& rest) {
            std::vector<std::string> dropped;
            const std::span<const float> restValues(rest.data(), std::size_t(rest.size()));
            auto remapped = unwrap(remapClip(clip, std::move(target), restValues, &dropped));
            return py::make_tuple(std::const_pointer_cast<KeyframeClip>(std::shared_ptr<const KeyframeClip>(remapped)),
                                  dropped);
        },
        "clip"_a, "target"_a.none(false), "rest"_a,
        "Copies a clip onto another layout (elements matched by name and kind; missing ones from `rest`). "
        "Returns (clip, names of the clip's elements the target lacks).");

    py::class_<Modifier, BlendableObject, std::shared_ptr<Modifier>>(
        m, "Modifier", "A blendable wrapping another blendable (its `source`).")
        .def_property_readonly("source", &Modifier::source);

    py::class_<TimeStretch, Modifier, std::shared_ptr<TimeStretch>>(
        m, "TimeStretch", "Plays the source `factor` times slower (2 = twice as long).")
        .def(py::init([](BlendablePtr source, double factor) {
                 return unwrap(TimeStretch::create(std::move(source), factor));
             }),
             "source"_a.none(false), "factor"_a)
        .def_property_readonly("factor", &TimeStretch::factor);

    py::class_<TimeWarp, Modifier, std::shared_ptr<TimeWarp>>(
        m, "TimeWarp", "Remaps time through a curve: local time u plays the source at source start + warp(u).")
        .def(py::init([](BlendablePtr source, Curve warp, double duration) {
                 return unwrap(TimeWarp::create(std::move(source), std::move(warp), duration));
             }),
             "source"_a.none(false), "warp"_a, "duration"_a)
        .def_property_readonly("warp", &TimeWarp::warp);

    py::class_<Loop, Modifier, std::shared_ptr<Loop>>(m, "Loop",
                                                       "Repeats the source `count` times, or forever when count = 0.")
        .def(py::init([](BlendablePtr source, int count) { return unwrap(Loop::create(std::move(source), count)); }),
             "source"_a.none(false), "count"_a = 0)
        .def_property_readonly("count", &Loop::count);

    py::class_<Mirror, Modifier, std::shared_ptr<Mirror>>(
        m, "Mirror", "Left/right flip across the plane normal to `axis` (0 = x, the H-Anim sagittal plane).")
        .def(py::init([](BlendablePtr source, int axis) { return unwrap(Mirror::create(std::move(source), axis)); }),
             "source"_a.none(false), "axis"_a = 0)
        .def_property_readonly("axis", &Mirror::axis);

    py::class_<GlobalTransform, Modifier, std::shared_ptr<GlobalTransform>>(
        m, "GlobalTransform", "Moves the whole animation: root rotation R·q, root translation R·t + T.")
        .def(py::init([](BlendablePtr source, Quat rotation, Vec3 translation) {
                 return unwrap(GlobalTransform::create(std::move(source), rotation, translation));
             }),
             "source"_a.none(false), "rotation"_a = Quat{}, "translation"_a = Vec3{})
        .def_property_readonly("rotation", &GlobalTransform::rotation)
        .def_property_readonly("translation", &GlobalTransform::translation);

    py::class_<TimeOffset, Modifier, std::shared_ptr<TimeOffset>>(
        m, "TimeOffset", "Shifts the source in time: the frame at t is the source's at t − offset.")
        .def(py::init<BlendablePtr, double>(), "source"_a.none(false), "offset"_a)
        .def_property_readonly("offset", &TimeOffset::offset);

    py::class_<Trim, Modifier, std::shared_ptr<Trim>>(
        m, "Trim", "The part of the source between `start` and `end` (source times), in the source's time.")
        .def(py::init([](BlendablePtr source, double start, double end) {
                 return unwrap(Trim::create(std::move(source), start, end));
             }),
             "source"_a.none(false), "start"_a, "end"_a);

    m.def(
        "split",
        [](BlendablePtr source, double at) {
            auto parts = unwrap(split(std::move(source), at));
            return py::make_tuple(parts.first, parts.second);
        },
        "source"_a.none(false), "at"_a, "Splits a blendable with a fixed domain at `at`: (before, after).");

    py::class_<CachedBlendable, BlendableObject, std::shared_ptr<CachedBlendable>>(
        m, "CachedBlendable",
        "A bounded cache of rendered frames in front of a blendable, dropped when the source is edited.")
        .def(py::init<BlendablePtr, int>(), "source"_a.none(false), "capacity"_a = 256)
        .def_property_readonly("capacity", &CachedBlendable::capacity)
        .def_property_readonly("hits", &CachedBlendable::hits)
        .def_property_readonly("misses", &CachedBlendable::misses)
        .def_property_readonly("size", &CachedBlendable::size);
}

void bindSchedule(py::module_& m)
{
    py::class_<BlendingAction>(m, "BlendingAction",
                               "A blendable with its blending parameters, start time (s) and whether it keeps "
                               "rendering outside its source's domain.")
        .def(py::init([](BlendablePtr source, BlendingParams params, double start, std::string name,
                         bool renderOutside) {
                 return BlendingAction{std::move(name), std::move(source), std::move(params), start, renderOutside};
             }),
             "source"_a = py::none(), "params"_a = BlendingParams(), "start"_a = 0.0, "name"_a = "",
             "render_outside_domain"_a = false)
        .def_readwrite("name", &BlendingAction::name)
        .def_property(
            "source", [](const BlendingAction& a) { return a.source; },
            [](BlendingAction& a, BlendablePtr source) { a.source = std::move(source); })
        .def_readwrite("params", &BlendingAction::params)
        .def_readwrite("start", &BlendingAction::start)
        .def_readwrite("render_outside_domain", &BlendingAction::renderOutsideDomain)
        .def("__repr__", [](const BlendingAction& a) {
            return "<thespis.BlendingAction '" + a.name + "' at " + formatNumber(a.start) + " s>";
        });

    py::class_<FrameBlender, std::shared_ptr<FrameBlender>>(m, "FrameBlender", "Combines frames (abstract).");
    py::class_<QuaternionBlender, FrameBlender, std::shared_ptr<QuaternionBlender>>(
        m, "QuaternionBlender", "The default: rotations hemisphere-aligned and normalized, the rest linear.")
        .def(py::init<>());
    py::class_<LinearBlender, FrameBlender, std::shared_ptr<LinearBlender>>(
        m, "LinearBlender", "Blends every float linearly (the paper's default blender).")
        .def(py::init<>());
    m.def("default_blender", &defaultBlender);

    py::class_<BlendingSchedule, BlendableObject, std::shared_ptr<BlendingSchedule>>(
        m, "BlendingSchedule",
        "Actions keyed by start time, blended into one frame per time (paper §4.2). A schedule is itself a "
        "blendable, so schedules nest. Actions may be added, cut off and removed while it plays.")
        .def(py::init([](FrameLayoutPtr layout, const std::optional<FloatArray>& rest, std::vector<int> parents) {
                 checkParents(parents, *layout);
                 std::vector<float> restFrame = optionalFrame(rest, *layout, "rest");
                 return std::make_shared<BlendingSchedule>(std::move(layout), std::move(restFrame), std::move(parents));
             }),
             "layout"_a.none(false), "rest"_a = py::none(), "parents"_a = std::vector<int>{},
             "A schedule on a layout; `rest` is the pose of elements nobody drives (default: neutral).")
        .def(py::init<const Skeleton&>(), "skeleton"_a, "A body schedule with the skeleton's layout, rest pose and hierarchy.")
        .def("add_action", [](BlendingSchedule& s, BlendingAction action) { return unwrap(s.addAction(std::move(action))); },
             "action"_a, "Adds an action; returns its id. ValueError for no source, another layout, invalid curves or mask.")
        .def(
            "add_action",
            [](BlendingSchedule& s, BlendablePtr source, double start, Curve weight, Curve scale,
               std::optional<JointMask> mask, BlendMode mode, std::string name, bool renderOutside) {
                BlendingAction action{std::move(name), std::move(source), {}, start, renderOutside};
                action.params.weight = std::move(weight);
                action.params.scale = std::move(scale);
                action.params.mask = sharedMask(mask);
                action.params.mode = mode;
                return unwrap(s.addAction(std::move(action)));
            },
            "source"_a.none(false), py::kw_only(), "start"_a = 0.0, "weight"_a = Curve(), "scale"_a = Curve(),
            "mask"_a = py::none(), "mode"_a = BlendMode::Normalized, "name"_a = "", "render_outside_domain"_a = false,
            "Adds an action playing `source` from `start`; returns its id.")
        .def("remove_action", &BlendingSchedule::removeAction, "id"_a, "Removes an action now; False when there is none.")
        .def("cut_off_action", &BlendingSchedule::cutOffAction, "id"_a, "at"_a, "fade_duration"_a,
             "Fades the action out over `fade_duration` s from time `at`, after which it is finished.")
        .def("set_action_start", [](BlendingSchedule& s, ActionId id, double start) { unwrap(s.setActionStart(id, start)); },
             "id"_a, "start"_a)
        .def("set_action_params",
             [](BlendingSchedule& s, ActionId id, BlendingParams params) { unwrap(s.setActionParams(id, std::move(params))); },
             "id"_a, "params"_a)
        .def("set_action_source",
             [](BlendingSchedule& s, ActionId id, BlendablePtr source) { unwrap(s.setActionSource(id, std::move(source))); },
             "id"_a, "source"_a.none(false))
        .def("remove_finished_actions", &BlendingSchedule::removeFinishedActions, "t"_a)
        .def("clear", &BlendingSchedule::clear)
        .def("is_finished", &BlendingSchedule::isFinished, "id"_a, "t"_a,
             "True when the action no longer contributes at time t, or does not exist.")
        .def("end_time", &BlendingSchedule::endTime, "id"_a,
             "When the action ends (inf when open-ended), NaN when it does not exist.")
        .def(
            "action",
            [](const BlendingSchedule& s, ActionId id) -> std::optional<BlendingAction> {
                const BlendingAction* action = s.action(id);
                return action ? std::optional<BlendingAction>(*action) : std::nullopt;
            },
            "id"_a, "A copy of the action, or None.")
        .def_property_readonly("action_ids", &BlendingSchedule::actionIds, "Ids in evaluation order.")
        .def_property_readonly("action_count", &BlendingSchedule::actionCount)
        .def("__len__", &BlendingSchedule::actionCount)
        .def(
            "find_action",
            [](const BlendingSchedule& s, const std::string& name) -> std::optional<ActionId> {
                const ActionId id = s.findAction(name);
                return id ? std::optional<ActionId>(id) : std::nullopt;
            },
            "name"_a, "The id of the first action with this name, or None.")
        .def("set_blender", &BlendingSchedule::setBlender, "blender"_a.none(false))
        .def_property_readonly("rest_pose", [](const BlendingSchedule& s) { return toArray<float>(s.restPose()); })
        .def("__repr__", [](const BlendingSchedule& s) {
            const TimeDomain d = s.domain();
            return "<thespis.BlendingSchedule " + std::to_string(s.actionCount()) + " actions over ["
                   + formatNumber(d.start) + ", " + formatNumber(d.end) + "] s>";
        });
}

} // namespace

void bindFrames(py::module_& m)
{
    py::enum_<ElementKind>(m, "ElementKind", "Kind of a frame element: 4, 3 or 1 floats.")
        .value("rotation", ElementKind::Rotation)
        .value("translation", ElementKind::Translation)
        .value("scalar", ElementKind::Scalar);

    py::class_<FrameLayout, std::shared_ptr<FrameLayout>>(
        m, "FrameLayout",
        "Names and kinds of a frame's elements. A frame is one flat float32 array: every rotation quaternion "
        "(x y z w), then every translation (x y z), then every scalar.")
        .def(py::init([](std::vector<std::string> rotations, std::vector<std::string> translations,
                         std::vector<std::string> scalars) {
                 return std::const_pointer_cast<FrameLayout>(
                     FrameLayout::create(std::move(rotations), std::move(translations), std::move(scalars)));
             }),
             "rotations"_a, "translations"_a = std::vector<std::string>{}, "scalars"_a = std::vector<std::string>{})
        .def_static("mpeg4_face", &FrameLayout::mpeg4Face, "The 68 MPEG-4 FAPs as scalars fap1 … fap68.")
        .def_property_readonly("rotation_count", &FrameLayout::rotationCount)
        .def_property_readonly("translation_count", &FrameLayout::translationCount)
        .def_property_readonly("scalar_count", &FrameLayout::scalarCount)
        .def_property_readonly("element_count", &FrameLayout::elementCount)
        .def_property_readonly("float_count", &FrameLayout::floatCount)
        .def_property_readonly("translation_offset", &FrameLayout::translationOffset)
        .def_property_readonly("scalar_offset", &FrameLayout::scalarOffset)
        .def_property_readonly("rotation_names", &FrameLayout::rotationNames)
        .def_property_readonly("translation_names", &FrameLayout::translationNames)
        .def_property_readonly("scalar_names", &FrameLayout::scalarNames)
        .def(
            "kind",
            [](const FrameLayout& l, int element) {
                checkIndex(element, l.elementCount(), "Element");
                return l.kind(element);
            },
            "element"_a)
        .def(
            "name",
            [](const FrameLayout& l, int element) {
                checkIndex(element, l.elementCount(), "Element");
                return l.name(element);
            },
            "element"_a)
        .def(
            "float_offset",
            [](const FrameLayout& l, int element) {
                checkIndex(element, l.elementCount(), "Element");
                return l.floatOffset(element);
            },
            "element"_a)
        .def(
            "find",
            [](const FrameLayout& l, std::string_view name, ElementKind kind) -> std::optional<int> {
                const int element = l.find(name, kind);
                return element < 0 ? std::nullopt : std::optional<int>(element);
            },
            "name"_a, "kind"_a = ElementKind::Rotation, "Element index of `name` among elements of `kind`, or None.")
        .def("neutral_frame", [](const FrameLayout& l) { return toArray<float>(neutralFrame(l)); },
             "Identity rotations, zero translations and scalars.")
        .def("__eq__", [](const FrameLayout& a, const FrameLayout& b) { return a == b; })
        .def("__repr__", [](const FrameLayout& l) {
            return "<thespis.FrameLayout " + std::to_string(l.rotationCount()) + " rotations, "
                   + std::to_string(l.translationCount()) + " translations, " + std::to_string(l.scalarCount())
                   + " scalars>";
        });

    py::class_<TimeDomain>(m, "TimeDomain", "The time span [start, end] of a blendable; end is inf when open-ended.")
        .def(py::init([](double start, double end) { return TimeDomain{start, end}; }), "start"_a = 0.0,
             "end"_a = Curve::Infinite)
        .def_readwrite("start", &TimeDomain::start)
        .def_readwrite("end", &TimeDomain::end)
        .def_property_readonly("open_ended", &TimeDomain::openEnded)
        .def_property_readonly("duration", &TimeDomain::duration)
        .def("contains", &TimeDomain::contains, "t"_a)
        .def("__eq__", [](const TimeDomain& a, const TimeDomain& b) { return a == b; })
        .def("__repr__", [](const TimeDomain& d) {
            return "TimeDomain(" + formatNumber(d.start) + ", " + formatNumber(d.end) + ")";
        });

    py::class_<BlendableObject, std::shared_ptr<BlendableObject>>(
        m, "Blendable", "An animation A: t → frame over a time domain (paper §4.2); base of clips, modifiers, schedules.")
        .def_property_readonly("layout", &BlendableObject::layout)
        .def_property_readonly("domain", &BlendableObject::domain)
        .def_property_readonly("revision", &BlendableObject::revision,
                               "Changes whenever an edit changes what evaluate() returns.")
        .def(
            "evaluate",
            [](const BlendableObject& b, double t) {
                py::array_t<float> frame(py::ssize_t(b.layout()->floatCount()));
                b.evaluate(t, std::span<float>(frame.mutable_data(), std::size_t(frame.size())));
                return frame;
            },
            "t"_a, "The frame at time t (seconds) as a new float32 array of layout.float_count values.")
        .def(
            "evaluate_into",
            [](const BlendableObject& b, double t, py::array_t<float, py::array::c_style> out) {
                if (std::size_t(out.size()) != b.layout()->floatCount())
                    throw py::value_error("out has " + std::to_string(out.size()) + " values; a frame has "
                                          + std::to_string(b.layout()->floatCount()) + ".");
                b.evaluate(t, std::span<float>(out.mutable_data(), std::size_t(out.size())));
            },
            "t"_a, "out"_a.noconvert(), "Writes the frame at time t into `out` (a contiguous float32 array).")
        .def(
            "sample",
            [](const BlendableObject& b, const DoubleArray& times) {
                if (times.ndim() != 1)
                    throw py::value_error("times must be a 1-D array of seconds, not "
                                          + std::to_string(times.ndim()) + "-D.");
                const auto floats = py::ssize_t(b.layout()->floatCount());
                py::array_t<float> frames({times.shape(0), floats});
                float* out = frames.mutable_data();
                for (py::ssize_t i = 0; i < times.shape(0); ++i)
                    b.evaluate(times.data()[i], std::span<float>(out + i * floats, std::size_t(floats)));
                return frames;
            },
            "times"_a, "Frames at each of `times` as a (len(times), float_count) float32 array.");

    m.def("neutral_frame", [](const FrameLayout& l) { return toArray<float>(neutralFrame(l)); }, "layout"_a);
}

void bindAnim(py::module_& m)
{
    bindCurves(m);
    bindMasks(m);
    bindParams(m);
    bindClipsAndModifiers(m);
    bindSchedule(m);
}

} // namespace thespis::python
