// Bindings of characters (core/scene) as the submodule thespis.scene: meshes split into segments
// with the receiver / occluder and PI / PD tags the lighting bake reads, whole characters
// (skeleton, skin, clips) from glTF or the built-in humanoid, and skinning them into a pose.
// Arrays cross as NumPy copies; segments are values (edit tags with apply_tags, which checks the
// names).

#include <map>
#include <optional>
#include <span>
#include <string>

#include "bind_common.h"
#include "errors.h"
#include "anim/hanim.h"
#include "scene/character.h"
#include "scene/character_mesh.h"
#include "scene/default_humanoid.h"
#include "scene/gltf_character.h"
#include "scene/gltf_mesh.h"
#include "scene/skinning.h"

namespace thespis::python {

using namespace pybind11::literals;
using namespace core::scene;
namespace anim = core::anim;

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

    py::class_<SegmentTag>(s, "SegmentTag", "Tags for one segment, by name.")
        .def(py::init([](std::string segment, SegmentRole role) { return SegmentTag{std::move(segment), role}; }),
             "segment"_a, "role"_a = SegmentRole::None)
        .def_readwrite("segment", &SegmentTag::segment)
        .def_readwrite("role", &SegmentTag::role)
        .def("__eq__", [](const SegmentTag& a, const SegmentTag& b) { return a == b; })
        .def("__repr__", [](const SegmentTag& t) {
            return "<thespis.scene.SegmentTag '" + t.segment + "' " + segmentRoleName(t.role) + ">";
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
        .def("__repr__", [](const Segment& seg) {
            return "<thespis.scene.Segment '" + seg.name + "' " + std::to_string(seg.vertexCount) + " vertices, "
                   + segmentRoleName(seg.role) + ">";
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
            "tags"_a, "Sets roles by segment name; an unknown name raises ValueError and changes nothing.")
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
    py::enum_<SkinningMethod>(s, "SkinningMethod", "How skin weights blend the joints' motions.")
        .value("LBS", SkinningMethod::Linear, "linear blend skinning")
        .value("DQS", SkinningMethod::DualQuaternion, "dual-quaternion skinning (keeps volume at twists)");

    py::class_<Character>(s, "Character",
                          "A skeleton, a skinned mesh split into segments, materials and clips, all in the "
                          "world-aligned rest pose (identity rotations = rest, as H-Anim and BVH).")
        .def_readonly("name", &Character::name)
        .def_readonly("skeleton", &Character::skeleton)
        .def_property_readonly("mesh", [](const Character& c) { return c.mesh; }, "The rest-pose mesh (a copy).")
        .def_readonly("clips", &Character::clips, "The file's animations, on the character's skeleton.")
        .def_readonly("warnings", &Character::warnings, "What the importer could not map or dropped.")
        .def_property_readonly("influences", [](const Character& c) { return c.skin.influences; },
                               "Joint influences per vertex (0: segments follow their joints rigidly).")
        .def_property_readonly(
            "skin_joints",
            [](const Character& c) {
                return toArray<std::uint16_t>(c.skin.joints, {py::ssize_t(c.mesh.vertexCount()), py::ssize_t(c.skin.influences)});
            },
            "vertices × influences skeleton joint indices")
        .def_property_readonly(
            "skin_weights",
            [](const Character& c) {
                return toArray<float>(c.skin.weights, {py::ssize_t(c.mesh.vertexCount()), py::ssize_t(c.skin.influences)});
            },
            "vertices × influences weights, summing to 1 per vertex")
        .def("apply_tags",
             [](Character& c, const std::vector<SegmentTag>& tags) { unwrap(applySegmentTags(c.mesh, tags)); }, "tags"_a,
             "Sets the roles of the mesh's segments by name (ValueError on an unknown name).")
        .def(
            "skin",
            [](const Character& c, const py::array_t<float, py::array::c_style | py::array::forcecast>& frame,
               SkinningMethod method) {
                const std::size_t floats = c.skeleton.frameLayout()->floatCount();
                if (std::size_t(frame.size()) != floats)
                    throw py::value_error("The frame has " + std::to_string(frame.size()) + " values; the skeleton needs " +
                                          std::to_string(floats) + ".");
                const std::size_t joints = std::size_t(c.skeleton.jointCount());
                std::vector<anim::Vec3d> rest = c.skeleton.worldPositions(c.skeleton.restFrame());
                std::vector<anim::Vec3d> positions(joints);
                std::vector<anim::Quatd> orientations(joints);
                std::vector<RigidTransform> transforms(joints);
                computeSkinningTransforms(c.skeleton, std::span<const float>(frame.data(), floats), rest, positions,
                                          orientations, transforms);
                std::vector<Vec3> posed(c.mesh.vertexCount()), normals(c.mesh.vertexCount());
                SkinningWorkers(1).skin(c, transforms, method, posed, normals);
                return py::make_tuple(rowsOf(floatsOf(posed), 3), rowsOf(floatsOf(normals), 3));
            },
            "frame"_a, "method"_a = SkinningMethod::Linear,
            "(positions, normals) of the mesh posed by a frame of the skeleton's layout, as vertices × 3 arrays.")
        .def("validate", [](const Character& c) { unwrap(c.validate()); })
        .def("__repr__", [](const Character& c) {
            return "<thespis.scene.Character '" + c.name + "': " + std::to_string(c.skeleton.jointCount()) + " joints, " +
                   std::to_string(c.mesh.vertexCount()) + " vertices, " + std::to_string(c.mesh.segments.size()) +
                   " segments, " + std::to_string(c.clips.size()) + " clips>";
        });

    s.def(
        "default_humanoid",
        [](anim::hanim::Level level, double detail) { return unwrap(makeDefaultHumanoid({.level = level, .detail = detail})); },
        "level"_a = anim::hanim::Level::Subset25, "detail"_a = 1.0,
        "The built-in procedural humanoid (about 23k triangles at detail 1, a hair segment over the skull) on the "
        "H-Anim skeleton of `level`.");
    s.def(
        "load_gltf_character",
        [](const std::filesystem::path& path, const std::map<std::string, std::string>& jointMapping,
           bool automaticMapping, double clipFrameRate, const std::optional<FaceMapping>& faceMapping) {
            GltfCharacterOptions options;
            options.jointMapping = jointMapping;
            options.automaticMapping = automaticMapping;
            options.clipFrameRate = clipFrameRate;
            options.faceMapping = faceMapping;
            return unwrap(withoutGil([&] { return loadGltfCharacter(path, options); }));
        },
        "path"_a, "joint_mapping"_a = std::map<std::string, std::string>{}, "automatic_mapping"_a = true,
        "clip_frame_rate"_a = 30.0, "face_mapping"_a = py::none(),
        "Reads a .gltf/.glb character: skeleton (joints mapped onto H-Anim names where known, or by joint_mapping "
        "{source name: H-Anim name}), skin, segments, materials and animations as clips, and its morph targets "
        "driven by face_mapping (a thespis.face.Mapping), or by the table thespis.face.recognise_mapping gives.");
    s.def("automatic_hanim_name", &automaticHAnimName, "source_name"_a,
          "The H-Anim name the automatic mapping gives a joint name ('' when it knows none).");
}

} // namespace thespis::python
