// Bindings of skeletons (core/anim/skeleton.h) and the H-Anim standard humanoid
// (core/anim/hanim.h, as the submodule thespis.hanim).

#include <optional>
#include <string>

#include "anim/hanim.h"
#include "anim/skeleton.h"
#include "bind_common.h"
#include "errors.h"

namespace thespis::python {

using namespace pybind11::literals;
using namespace core::anim;

namespace {

void checkJoint(const Skeleton& s, int joint)
{
    if (joint < 0 || joint >= s.jointCount())
        throw py::index_error("Joint index " + std::to_string(joint) + " is out of range (the skeleton has "
                              + std::to_string(s.jointCount()) + " joints).");
}

} // namespace

void bindSkeleton(py::module_& m)
{
    py::class_<Joint>(m, "Joint", "A joint of a skeleton: name, parent index, rest offset from the parent.")
        .def(py::init([](std::string name, int parent, Vec3d offset, std::string sourceName, std::string rotationOrder,
                         std::optional<Vec3d> endSite, bool translates) {
                 return Joint{std::move(name), std::move(sourceName), parent, offset, std::move(rotationOrder), endSite,
                              translates};
             }),
             "name"_a, "parent"_a = -1, "offset"_a = Vec3d{}, "source_name"_a = "", "rotation_order"_a = "ZXY",
             "end_site"_a = py::none(), "translates"_a = false)
        .def_readwrite("name", &Joint::name, "H-Anim name when mapped, else the source file's name.")
        .def_readwrite("source_name", &Joint::sourceName, "Name in the file it came from; empty if built in.")
        .def_readwrite("parent", &Joint::parent, "Index of the parent joint, -1 for the root.")
        .def_readwrite("offset", &Joint::offset, "Rest translation from the parent joint.")
        .def_readwrite("rotation_order", &Joint::rotationOrder, "Euler order used when written to BVH.")
        .def_readwrite("end_site", &Joint::endSite, "BVH End Site offset of a leaf, or None.")
        .def_readwrite("translates", &Joint::translates, "The joint's translation is animated.")
        .def("__repr__", [](const Joint& j) {
            return "<thespis.Joint '" + j.name + "' parent " + std::to_string(j.parent) + ">";
        });

    py::class_<Skeleton>(m, "Skeleton",
                         "A joint hierarchy (parents first, joint 0 the root) and its rest pose. A body frame has "
                         "one rotation per joint, then a translation for the root and every translating joint.")
        .def(py::init([](std::vector<Joint> joints) { return unwrap(Skeleton::create(std::move(joints))); }), "joints"_a,
             "ValueError unless the joints are non-empty, uniquely named, parents before children, one root.")
        .def_property_readonly("joint_count", &Skeleton::jointCount)
        .def("__len__", &Skeleton::jointCount)
        .def(
            "joint",
            [](const Skeleton& s, int index) {
                checkJoint(s, index);
                return s.joint(index);
            },
            "index"_a, "A copy of joint `index`.")
        .def_property_readonly(
            "joints", [](const Skeleton& s) { return s.joints(); }, "A copy of every joint.")
        .def_property_readonly("joint_names",
                               [](const Skeleton& s) {
                                   std::vector<std::string> names;
                                   for (const Joint& j : s.joints())
                                       names.push_back(j.name);
                                   return names;
                               })
        .def(
            "find",
            [](const Skeleton& s, std::string_view name) -> std::optional<int> {
                const int index = s.find(name);
                return index < 0 ? std::nullopt : std::optional<int>(index);
            },
            "name"_a, "Index of the joint called `name`, or None.")
        .def_property_readonly("parents", &Skeleton::parents)
        .def_property_readonly("frame_layout", &Skeleton::frameLayout)
        .def(
            "translation_element",
            [](const Skeleton& s, int joint) -> std::optional<int> {
                checkJoint(s, joint);
                const int element = s.translationElement(joint);
                return element < 0 ? std::nullopt : std::optional<int>(element);
            },
            "joint"_a, "Layout element of the joint's translation, or None when it does not translate.")
        .def("rest_frame", [](const Skeleton& s) { return toArray<float>(s.restFrame()); },
             "Identity rotations, translating joints at their rest offsets.")
        .def(
            "world_positions",
            [](const Skeleton& s, const py::array_t<float, py::array::c_style | py::array::forcecast>& frame) {
                const std::size_t floats = s.frameLayout()->floatCount();
                if (std::size_t(frame.size()) != floats)
                    throw py::value_error("The frame has " + std::to_string(frame.size()) + " values; this skeleton's "
                                          + "frames have " + std::to_string(floats) + ".");
                const std::vector<Vec3d> positions = s.worldPositions({frame.data(), floats});
                py::array_t<double> out({py::ssize_t(positions.size()), py::ssize_t(3)});
                double* values = out.mutable_data();
                for (std::size_t i = 0; i < positions.size(); ++i) {
                    values[3 * i] = positions[i].x;
                    values[3 * i + 1] = positions[i].y;
                    values[3 * i + 2] = positions[i].z;
                }
                return out;
            },
            "frame"_a, "World position of every joint for a frame, as a (joint_count, 3) float64 array.")
        .def("__repr__", [](const Skeleton& s) {
            return "<thespis.Skeleton " + std::to_string(s.jointCount()) + " joints"
                   + (s.jointCount() ? ", root '" + s.joint(0).name + "'" : std::string()) + ">";
        });

    py::module_ h = m.def_submodule("hanim", "The H-Anim 2.0 standard humanoid: joint names, hierarchy, rest pose.");
    py::enum_<hanim::Level>(h, "Level", "Levels of articulation.")
        .value("loa1", hanim::Level::Loa1, "18 joints")
        .value("loa2", hanim::Level::Loa2, "71 joints, hands with fingers")
        .value("subset25", hanim::Level::Subset25, "LOA 1 plus spine, neck and clavicles: 25 joints (the paper's)");
    h.def("skeleton", &hanim::skeleton, "level"_a = hanim::Level::Loa1, py::return_value_policy::copy,
          "The standard skeleton of a level in its rest pose (metres, +Y up, facing +Z).");
    h.def("joint_names", &hanim::jointNames, "level"_a = hanim::Level::Loa1);
    h.def("is_joint_name", &hanim::isJointName, "name"_a);
    h.def("from_hanim11", [](std::string_view name) { return std::string(hanim::fromHAnim11(name)); }, "name"_a,
          "The H-Anim 2.0 name for an H-Anim 1.1 name (other names unchanged).");
    h.def("mirror_name", &hanim::mirrorName, "name"_a, "The joint on the other side, or the name itself.");
    h.def("parent_name", [](std::string_view name) { return std::string(hanim::parentName(name)); }, "name"_a,
          "LOA 2 parent of an H-Anim joint ('' for humanoid_root or an unknown name).");
}

} // namespace thespis::python
