// Bindings of BVH import/export (core/anim/bvh.h) as the submodule thespis.bvh. Reading and
// writing files release the GIL: they touch only their own arguments.

#include <optional>
#include <string>

#include "anim/bvh.h"
#include "bind_common.h"
#include "errors.h"

namespace thespis::python {

using namespace pybind11::literals;
using namespace core::anim;

namespace {

bvh::ImportOptions importOptions(bool mapToHAnim, std::optional<bvh::JointMapping> mapping,
                                 std::optional<double> frameRate)
{
    bvh::ImportOptions options;
    options.mapToHAnim = mapToHAnim;
    options.mapping = std::move(mapping);
    options.frameRate = frameRate;
    return options;
}

// The writer indexes the clip's frames by the skeleton's layout: refuse a mismatch here rather
// than read out of bounds.
void checkSameLayout(const Skeleton& skeleton, const KeyframeClip& clip)
{
    if (!(*clip.layout() == *skeleton.frameLayout()))
        throw py::value_error("The clip's layout is not the skeleton's frame layout; remap it first "
                              "(thespis.remap_clip).");
}

} // namespace

void bindBvh(py::module_& m)
{
    py::module_ b = m.def_submodule("bvh", "BVH motion capture: import onto H-Anim joint names, and export.");

    py::class_<bvh::ImportReport>(b, "ImportReport", "What the importer found in a BVH file.")
        .def_readonly("convention", &bvh::ImportReport::convention,
                      "Detected joint naming ('cmu', 'cmu-3dsmax', 'daz', 'makehuman', …, or 'none').")
        .def_readonly("is_body", &bvh::ImportReport::isBody, "A humanoid body was recognised and mapped.")
        .def_readonly("joint_count", &bvh::ImportReport::jointCount, "ROOT and JOINT entries (End Sites excluded).")
        .def_readonly("channel_count", &bvh::ImportReport::channelCount)
        .def_readonly("frame_count", &bvh::ImportReport::frameCount, "'Frames:' of the header.")
        .def_readonly("frame_time", &bvh::ImportReport::frameTime, "'Frame Time:' of the header, seconds.")
        .def_readonly("unmapped", &bvh::ImportReport::unmapped, "File joint names that kept their own name.")
        .def("__repr__", [](const bvh::ImportReport& r) {
            return "<thespis.bvh.ImportReport " + r.convention + ", " + std::to_string(r.jointCount) + " joints, "
                   + std::to_string(r.frameCount) + " frames, " + std::to_string(r.unmapped.size()) + " unmapped>";
        });

    py::class_<bvh::ImportedClip>(b, "ImportedClip",
                                  "An imported BVH file: skeleton, clip (on skeleton.frame_layout) and report. "
                                  "Unpacks as `skeleton, clip, report = thespis.bvh.load(path)`.")
        .def_readonly("skeleton", &bvh::ImportedClip::skeleton)
        .def_property_readonly("clip", [](const bvh::ImportedClip& c) { return c.clip; })
        .def_readonly("report", &bvh::ImportedClip::report)
        .def("__iter__", [](py::object self) {
            return py::iter(py::make_tuple(self.attr("skeleton"), self.attr("clip"), self.attr("report")));
        });

    b.def(
        "load",
        [](const std::filesystem::path& path, bool mapToHAnim, std::optional<bvh::JointMapping> mapping,
           std::optional<double> frameRate) {
            const bvh::ImportOptions options = importOptions(mapToHAnim, std::move(mapping), frameRate);
            core::Result<bvh::ImportedClip> result = [&] {
                py::gil_scoped_release release;
                return bvh::load(path, options);
            }();
            return unwrap(std::move(result));
        },
        "path"_a, py::kw_only(), "map_to_hanim"_a = true, "mapping"_a = py::none(), "frame_rate"_a = py::none(),
        "Loads a BVH file. `mapping` (file joint → H-Anim name) replaces the built-in tables; `frame_rate` "
        "overrides the header's Frame Time. FileNotFoundError, or thespis.FormatError naming the line.");
    b.def(
        "parse",
        [](const std::string& text, bool mapToHAnim, std::optional<bvh::JointMapping> mapping,
           std::optional<double> frameRate, const std::string& clipName) {
            const bvh::ImportOptions options = importOptions(mapToHAnim, std::move(mapping), frameRate);
            core::Result<bvh::ImportedClip> result = [&] {
                py::gil_scoped_release release;
                return bvh::parse(text, options, clipName);
            }();
            return unwrap(std::move(result));
        },
        "text"_a, py::kw_only(), "map_to_hanim"_a = true, "mapping"_a = py::none(), "frame_rate"_a = py::none(),
        "clip_name"_a = "", "Parses BVH text (see load).");
    b.def(
        "write",
        [](const Skeleton& skeleton, const KeyframeClip& clip) {
            checkSameLayout(skeleton, clip);
            return bvh::write(skeleton, clip);
        },
        "skeleton"_a, "clip"_a,
          "The clip (on the skeleton's layout) as BVH text: file joint names, rotation orders, End Sites.");
    b.def(
        "save",
        [](const std::filesystem::path& path, const Skeleton& skeleton, const KeyframeClip& clip) {
            checkSameLayout(skeleton, clip);
            core::Result<void> result = [&] {
                py::gil_scoped_release release;
                return bvh::save(path, skeleton, clip);
            }();
            unwrap(std::move(result));
        },
        "path"_a, "skeleton"_a, "clip"_a, "Writes a BVH file atomically (temporary file, then rename).");
    b.def("load_mapping", [](const std::filesystem::path& path) { return unwrap(bvh::loadMapping(path)); }, "path"_a,
          "Reads a joint mapping file: 'file_joint  hanim_name' per line, '#' comments.");
    b.def("parse_mapping", [](std::string_view text) { return unwrap(bvh::parseMapping(text)); }, "text"_a);
}

} // namespace thespis::python
