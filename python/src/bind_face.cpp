// Bindings of a character's face (core/scene/face_mapping.h, face_naming.h, face_rig.h) as the
// submodule thespis.face: face mapping tables (made, read, written, recognised, applied), a
// character's morph target names, the face channels by name, and a face frame evaluated onto the
// rest mesh. Tables are values; apply_mapping changes the character it is given.

#include <string>
#include <vector>

#include "bind_common.h"
#include "errors.h"
#include "scene/character.h"
#include "scene/face_mapping.h"
#include "scene/face_mask.h"
#include "scene/face_naming.h"
#include "scene/face_rig.h"
#include "scene/fap.h"
#include "util/text.h"

namespace thespis::python {

using namespace pybind11::literals;
using namespace core::scene;
namespace anim = core::anim;

namespace {

int channelOf(const py::object& channel)
{
    if (py::isinstance<py::str>(channel)) {
        const std::string name = channel.cast<std::string>();
        if (const std::optional<int> found = findFaceChannel(core::lowercase(name)))
            return *found;
        throw py::value_error("'" + name + "' is not a face channel (a FAP such as 'open_jaw' or 'fap3', "
                              "'viseme1' … 'viseme14', or an expression such as 'anger').");
    }
    const int index = channel.cast<int>();
    if (index < 0 || index >= kFaceChannelCount)
        throw py::value_error("Face channels go from 0 to " + std::to_string(kFaceChannelCount - 1) + ".");
    return index;
}

py::array_t<float> rows(const std::vector<Vec3>& vectors)
{
    static_assert(sizeof(Vec3) == 3 * sizeof(float));
    return toArray(std::span<const float>(reinterpret_cast<const float*>(vectors.data()), vectors.size() * 3),
                   {py::ssize_t(vectors.size()), 3});
}

} // namespace

void bindFace(py::module_& m)
{
    py::module_ f = m.def_submodule("face", "Faces: face mapping tables onto a model's own morph targets and joints.");
    f.attr("CHANNEL_COUNT") = kFaceChannelCount;

    f.def("channel_name", &faceChannelName, "channel"_a,
          "A face channel's name as tables write it: 'open_jaw', 'viseme1', 'anger'.");
    f.def("find_channel", &channelOf, "name"_a,
          "The index of a face channel ('open_jaw', 'fap3', 'viseme1', 'anger', 'expression3') in a face frame.");

    py::enum_<MorphDrive::Side>(f, "Side", "Which values of its channel move a target.")
        .value("BOTH", MorphDrive::Side::Both, "all: the weight follows the value")
        .value("POSITIVE", MorphDrive::Side::Positive, "the value's positive part only")
        .value("NEGATIVE", MorphDrive::Side::Negative, "the value's negative part only");

    py::class_<FaceMappingDrive>(f, "Drive", "A target's weight: coefficient × a face channel's value.")
        .def(py::init([](std::string target, const py::object& channel, double coefficient, MorphDrive::Side side) {
                 return FaceMappingDrive{std::move(target), channelOf(channel), coefficient, side};
             }),
             "target"_a, "channel"_a, "coefficient"_a, "side"_a = MorphDrive::Side::Both,
             "channel: a face channel's name or index.")
        .def_readwrite("target", &FaceMappingDrive::target)
        .def_readwrite("channel", &FaceMappingDrive::channel)
        .def_readwrite("coefficient", &FaceMappingDrive::coefficient)
        .def_readwrite("side", &FaceMappingDrive::side)
        .def("__eq__", [](const FaceMappingDrive& a, const FaceMappingDrive& b) { return a == b; })
        .def("__repr__", [](const FaceMappingDrive& d) {
            return "<thespis.face.Drive '" + d.target + "' ← " + faceChannelName(d.channel) + " × " +
                   std::to_string(d.coefficient) + ">";
        });

    py::class_<FaceMappingJoint>(f, "JointDrive", "A joint turned about an axis by radians_per_unit × a channel's value.")
        .def(py::init([](std::string joint, const py::object& channel, const anim::Vec3d& axis, double radiansPerUnit) {
                 return FaceMappingJoint{std::move(joint), channelOf(channel), axis, radiansPerUnit};
             }),
             "joint"_a, "channel"_a, "axis"_a, "radians_per_unit"_a,
             "axis: in the joint's rest frame (+Y up, facing +Z), unit length.")
        .def_readwrite("joint", &FaceMappingJoint::joint)
        .def_readwrite("channel", &FaceMappingJoint::channel)
        .def_readwrite("axis", &FaceMappingJoint::axis)
        .def_readwrite("radians_per_unit", &FaceMappingJoint::radiansPerUnit)
        .def("__eq__", [](const FaceMappingJoint& a, const FaceMappingJoint& b) { return a == b; })
        .def("__repr__", [](const FaceMappingJoint& j) {
            return "<thespis.face.JointDrive '" + j.joint + "' ← " + faceChannelName(j.channel) + ">";
        });

    py::class_<FaceMapping>(f, "Mapping", "A face mapping table: face channels → morph target weights and joint turns.")
        .def(py::init([](std::string name, std::vector<FaceMappingDrive> drives, std::vector<FaceMappingJoint> joints) {
                 return FaceMapping{std::move(name), std::move(drives), std::move(joints)};
             }),
             "name"_a = "", "drives"_a = std::vector<FaceMappingDrive>{}, "joints"_a = std::vector<FaceMappingJoint>{})
        .def_readwrite("name", &FaceMapping::name)
        .def_readwrite("drives", &FaceMapping::drives)
        .def_readwrite("joints", &FaceMapping::joints)
        .def("to_json", &serializeFaceMapping, "The table as the JSON text save_mapping writes.")
        .def_static(
            "from_json", [](const std::string& text) { return unwrap(parseFaceMapping(text)); }, "text"_a,
            "Reads a table from JSON text (thespis.FormatError naming the field).")
        .def("__eq__", [](const FaceMapping& a, const FaceMapping& b) { return a == b; })
        .def("__repr__", [](const FaceMapping& mapping) {
            return "<thespis.face.Mapping '" + mapping.name + "': " + std::to_string(mapping.drives.size()) +
                   " drives, " + std::to_string(mapping.joints.size()) + " joints>";
        });

    f.def(
        "load_mapping", [](const std::filesystem::path& path) { return unwrap(loadFaceMapping(path)); }, "path"_a,
        "Reads a face mapping file (thespis.FormatError naming the file and the field).");
    f.def(
        "save_mapping",
        [](const std::filesystem::path& path, const FaceMapping& mapping) { unwrap(saveFaceMapping(path, mapping)); },
        "path"_a, "mapping"_a, "Writes a face mapping file, atomically.");
    f.def("recognise_mapping", &recogniseFaceMapping, "character"_a,
          "The table the known naming schemes give the character (ARKit, Oculus visemes, expression names, "
          "eye and jaw bones); its name lists the schemes found.");
    f.def(
        "apply_mapping",
        [](Character& character, const FaceMapping& mapping) { return applyFaceMapping(mapping, character); },
        "character"_a, "mapping"_a,
          "Makes the table the character's face; returns a warning for each target or joint it lacks.");
    f.def("morph_target_names", &morphTargetNames, "character"_a, "The names of the character's morph targets.");
    f.def(
        "fap_units",
        [](const Character& character) {
            const FapUnits& u = character.face.units;
            return py::dict("IRISD"_a = u.irisd, "ES"_a = u.es, "ENS"_a = u.ens, "MNS"_a = u.mns, "MW"_a = u.mw,
                            "AU"_a = FapUnits::au);
        },
        "character"_a,
        "The character's FAP units, metres per unit (each face distance over 1024; AU is 1e-5 rad), measured on its "
        "neutral face between the MPEG-4 feature points (zero for a model that drives its targets by name).");
    f.def(
        "feature_points",
        [](const Character& character) {
            py::dict points;
            for (const FeaturePoint& point : character.face.featurePoints) {
                const Vec3& p = character.mesh.positions[point.vertex];
                points[py::str(point.name)] = py::make_tuple(p.x, p.y, p.z);
            }
            return points;
        },
        "character"_a, "The MPEG-4 feature points of the neutral face ('2.1' the chin …) → rest position (metres).");
    f.def(
        "fap",
        [](int number) {
            if (number < 1 || number > kFapCount)
                throw py::value_error("FAPs are numbered 1 to 68.");
            const FapInfo& fap = fapInfo(number);
            return py::dict("number"_a = fap.number, "name"_a = std::string(fap.name),
                            "unit"_a = std::string(fapUnitName(fap.unit)), "bidirectional"_a = fap.bidirectional,
                            "direction"_a = std::string(fap.direction), "feature_point"_a = std::string(fap.featurePoint));
        },
        "number"_a, "MPEG-4's definition of FAP `number` (1 … 68): its name, unit, direction and feature point.");
    f.def(
        "deform",
        [](const Character& character, const py::array_t<float, py::array::c_style | py::array::forcecast>& frame) {
            if (frame.size() != kFaceChannelCount)
                throw py::value_error("A face frame has " + std::to_string(kFaceChannelCount) + " values, not " +
                                      std::to_string(frame.size()) + ".");
            std::vector<Vec3> positions = character.mesh.positions, normals = character.mesh.normals;
            FaceDeformer deformer(character);
            deformer.deform(std::span<const float>(frame.data(), std::size_t(frame.size())), positions, normals);
            return py::make_tuple(rows(positions), rows(normals));
        },
        "character"_a, "frame"_a,
        "(positions, normals) of the rest mesh moved by a face frame (CHANNEL_COUNT values), vertices × 3.");

    // Face-region masks: the face's counterpart of a joint mask (paper §5.2).
    py::enum_<FaceMaskPreset>(f, "MaskPreset", "Face masks over the face's regions.")
        .value("whole_face", FaceMaskPreset::WholeFace)
        .value("speech", FaceMaskPreset::Speech)
        .value("expression", FaceMaskPreset::Expression)
        .value("eyes", FaceMaskPreset::Eyes);
    f.attr("REGIONS") = [] {
        py::list regions;
        for (std::string_view region : kFaceRegions)
            regions.append(std::string(region));
        return regions;
    }();
    f.def("mask_preset", &faceMaskPreset, "preset"_a,
          "A face mask (a JointMask naming the face's regions): speech high on the mouth, expressions on the eyes and brows.");
    f.def("is_face_mask", &isFaceMask, "mask"_a, "True when the mask names a face region or face channel.");
    f.def("mirrored_mask", &mirroredFaceMask, "mask"_a, "The face mask with left and right FAPs swapped.");
    f.def("channel_region", [](const py::object& channel) {
            const int c = channelOf(channel);
            const auto layout = anim::FrameLayout::mpeg4Face();
            return layout->group(layout->rotationCount() + layout->translationCount() + c);
        }, "channel"_a, "The face region a channel is in ('mouth', 'eyes', …); a channel by name or index.");
}

} // namespace thespis::python
