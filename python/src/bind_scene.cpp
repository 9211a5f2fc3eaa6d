// Bindings of character meshes (core/scene) as the submodule thespis.scene: loading a glTF
// character in bind pose, its segments, and the receiver / occluder and PI / PD tags the
// lighting bake reads. Arrays cross as NumPy copies; segments are values (edit tags with
// apply_tags, which checks the names).

#include <optional>
#include <string>

#include "bind_common.h"
#include "errors.h"
#include "scene/character_mesh.h"
#include "scene/gltf_mesh.h"

namespace thespis::python {

using namespace pybind11::literals;
using namespace core::scene;

namespace {

template <class T>
py::array_t<T> rowsOf(std::span<const T> values, py::ssize_t columns)
{
    return toArray(values, {py::ssize_t(values.size()) / columns, columns});
}

std::span<const float> floatsOf(const std::vector<Vec3>& vectors)
{
    static_assert(sizeof(Vec3) == 3 * sizeof(float));
    return {reinterpret_cast<const float*>(vectors.data()), vectors.size() * 3};
}

} // namespace

void bindScene(py::module_& m)
{
    py::module_ s = m.def_submodule("scene", "Characters: meshes split into segments, their tags, glTF import.");

    py::enum_<SegmentRole>(s, "SegmentRole",
                           "Paper §6.1.3: a RECEIVER receives self-shadowing but casts none; an OCCLUDER casts "
                           "but is not baked; NONE does both.")
        .value("NONE", SegmentRole::None)
        .value("RECEIVER", SegmentRole::Receiver)
        .value("OCCLUDER", SegmentRole::Occluder);
    py::enum_<Posture>(s, "Posture", "Posture-independent (skull, pelvis, hands, …) or posture-dependent segment.")
        .value("INDEPENDENT", Posture::Independent)
        .value("DEPENDENT", Posture::Dependent);

    py::class_<SegmentTag>(s, "SegmentTag", "Tags for one segment, by name.")
        .def(py::init([](std::string segment, SegmentRole role, std::optional<Posture> posture) {
                 return SegmentTag{std::move(segment), role, posture};
             }),
             "segment"_a, "role"_a = SegmentRole::None, "posture"_a = std::nullopt)
        .def_readwrite("segment", &SegmentTag::segment)
        .def_readwrite("role", &SegmentTag::role)
        .def_readwrite("posture", &SegmentTag::posture, "None keeps the segment's own posture.")
        .def("__eq__", [](const SegmentTag& a, const SegmentTag& b) { return a == b; })
        .def("__repr__", [](const SegmentTag& t) {
            return "<thespis.scene.SegmentTag '" + t.segment + "' " + segmentRoleName(t.role)
                   + (t.posture ? std::string(" ") + postureName(*t.posture) : std::string()) + ">";
        });

    py::class_<Segment>(s, "Segment", "One mesh segment: its vertex and triangle ranges, bind frame and tags.")
        .def_readonly("name", &Segment::name)
        .def_readonly("joint", &Segment::joint, "The joint whose frame the segment follows ('' if none).")
        .def_readonly("first_vertex", &Segment::firstVertex)
        .def_readonly("vertex_count", &Segment::vertexCount)
        .def_readonly("first_triangle", &Segment::firstTriangle)
        .def_readonly("triangle_count", &Segment::triangleCount)
        .def_readonly("bind_rotation", &Segment::bindRotation, "World rotation (x, y, z, w) of the bind frame.")
        .def_readonly("bind_translation", &Segment::bindTranslation)
        .def_readonly("role", &Segment::role)
        .def_readonly("posture", &Segment::posture)
        .def("__repr__", [](const Segment& seg) {
            return "<thespis.scene.Segment '" + seg.name + "' " + std::to_string(seg.vertexCount) + " vertices, "
                   + segmentRoleName(seg.role) + ", " + postureName(seg.posture) + ">";
        });

    py::class_<CharacterMesh>(s, "CharacterMesh",
                              "A character's bind-pose geometry in world space (metres, y up), grouped by segment.")
        .def_property_readonly("positions", [](const CharacterMesh& mesh) { return rowsOf(floatsOf(mesh.positions), 3); },
                               "(V, 3) float32 copy.")
        .def_property_readonly("normals", [](const CharacterMesh& mesh) { return rowsOf(floatsOf(mesh.normals), 3); },
                               "(V, 3) float32 copy, unit length.")
        .def_property_readonly(
            "triangles",
            [](const CharacterMesh& mesh) { return rowsOf(std::span<const std::uint32_t>(mesh.indices), 3); },
            "(T, 3) uint32 copy of global vertex indices.")
        .def_property_readonly("segments", [](const CharacterMesh& mesh) { return mesh.segments; },
                               "The segments (a copy).")
        .def_property_readonly("vertex_count", &CharacterMesh::vertexCount)
        .def_property_readonly("triangle_count", &CharacterMesh::triangleCount)
        .def(
            "find_segment",
            [](const CharacterMesh& mesh, const std::string& name) -> std::optional<Segment> {
                const Segment* found = mesh.findSegment(name);
                return found ? std::optional<Segment>(*found) : std::nullopt;
            },
            "name"_a, "A copy of the segment called `name`, or None.")
        .def(
            "apply_tags", [](CharacterMesh& mesh, const std::vector<SegmentTag>& tags) { unwrap(applySegmentTags(mesh, tags)); },
            "tags"_a, "Sets roles and postures by segment name; an unknown name raises ValueError and changes nothing.")
        .def("validate", [](const CharacterMesh& mesh) { unwrap(mesh.validate()); },
             "Raises ValueError naming what breaks the mesh's invariants.")
        .def("__repr__", [](const CharacterMesh& mesh) {
            return "<thespis.scene.CharacterMesh " + std::to_string(mesh.vertexCount()) + " vertices, "
                   + std::to_string(mesh.triangleCount()) + " triangles, " + std::to_string(mesh.segments.size())
                   + " segments>";
        });

    s.def(
        "load_gltf_mesh",
        [](const std::filesystem::path& path, bool splitSkinnedByJoint) {
            GltfMeshOptions options;
            options.splitSkinnedByJoint = splitSkinnedByJoint;
            return unwrap(withoutGil([&] { return loadGltfMesh(path, options); }));
        },
        "path"_a, "split_skinned_by_joint"_a = true,
        "Reads a .gltf/.glb character in bind pose. Mesh nodes become segments; a skinned mesh is split by "
        "dominant joint unless split_skinned_by_joint is False. Unsupported features (Draco, meshopt, …) raise "
        "thespis.FormatError naming them.");
    s.def(
        "read_segment_tags",
        [](const std::filesystem::path& path) { return unwrap(withoutGil([&] { return readSegmentTagsFile(path); })); },
        "path"_a,
        "Reads a tags JSON file: {\"hair\": \"receiver\", …} or {\"hair\": {\"role\": \"receiver\", \"posture\": \"pi\"}}.");
    s.def("default_posture", &defaultPosture, "hanim_joint"_a,
          "The paper's posture-independent set: INDEPENDENT for skull, T1, clavicles, sacrum, pelvis, thighs, hands.");
}

} // namespace thespis::python
