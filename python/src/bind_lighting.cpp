// Bindings of core/lighting as the submodule thespis.lighting: spherical harmonics (evaluate,
// rotate, irradiance), HDR probes and their projection, and the PRT transfer bake — whole, or in
// vertex ranges for farm bakes (thespis.farm: plan_bake, split_bake, bake_ranges, place_range).
//
// Coefficients are NumPy float64 arrays whose last axis has order² entries (index l(l+1)+m);
// an RGB light is shaped (3, order²). The bake runs on worker threads with the GIL released; the
// calling thread wakes every 100 ms to deliver progress to the Python callback and to notice
// Ctrl-C, which cancels the bake (KeyboardInterrupt is raised once the workers have stopped).

#include <chrono>
#include <cmath>
#include <optional>
#include <string>

#include "bind_common.h"
#include "errors.h"
#include "lighting/probe.h"
#include "lighting/probe_projection_job.h"
#include "lighting/sh.h"
#include "lighting/sh_rotation.h"
#include "lighting/transfer_bake.h"
#include "lighting/transfer_bake_job.h"
#include "lighting/transfer_ranges_job.h"
#include "run_job.h"
#include "scenario/bake_character.h"

namespace thespis::python {

using namespace pybind11::literals;
using namespace core::lighting;
namespace anim = core::anim;
namespace scene = core::scene;

namespace {

using Coefficients = py::array_t<double, py::array::c_style | py::array::forcecast>;

int checkedOrder(int order)
{
    if (order < 1 || order > kMaxShOrder)
        throw py::value_error("order must be between 1 and " + std::to_string(kMaxShOrder) + " (bands 0 … order−1), not "
                              + std::to_string(order) + ".");
    return order;
}

/// The order n of an array whose last axis holds n² coefficients.
int orderOfLastAxis(const Coefficients& coefficients)
{
    if (coefficients.ndim() < 1)
        throw py::value_error("SH coefficients must be an array whose last axis has order² entries.");
    const auto count = coefficients.shape(coefficients.ndim() - 1);
    for (int order = 1; order <= kMaxShOrder; ++order)
        if (order * order == count)
            return order;
    throw py::value_error("the last axis has " + std::to_string(count)
                          + " entries, which is not order² for an order from 1 to " + std::to_string(kMaxShOrder) + ".");
}

Vec3d unitDirection(const Vec3d& d)
{
    const double length = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
    if (!(length > 0) || !std::isfinite(length))
        throw py::value_error("a direction must be a finite, non-zero vector.");
    return d * (1.0 / length);
}

py::array_t<double> shRgbToArray(const ShRgb& light)
{
    const int count = light.order * light.order;
    py::array_t<double> out({py::ssize_t(3), py::ssize_t(count)});
    for (int c = 0; c < 3; ++c)
        std::copy_n(light[c].data(), count, out.mutable_data(c, 0));
    return out;
}

ShRgb shRgbFromArray(const Coefficients& array)
{
    if (array.ndim() != 2 || array.shape(0) != 3)
        throw py::value_error("an RGB light must be shaped (3, order²).");
    ShRgb light;
    light.order = orderOfLastAxis(array);
    for (int c = 0; c < 3; ++c)
        std::copy_n(array.data(c, 0), light.order * light.order, light[c].data());
    return light;
}

HdrImage imageFromArray(const py::array_t<float, py::array::c_style | py::array::forcecast>& pixels)
{
    if (pixels.ndim() != 3 || pixels.shape(2) != 3)
        throw py::value_error("an HDR image must be shaped (height, width, 3).");
    HdrImage image;
    image.height = int(pixels.shape(0));
    image.width = int(pixels.shape(1));
    image.rgb.assign(pixels.data(), pixels.data() + pixels.size());
    return image;
}

py::array_t<float> imageToArray(const HdrImage& image)
{
    return toArray(std::span<const float>(image.rgb), {image.height, image.width, 3});
}

void bindSphericalHarmonics(py::module_& l)
{
    l.attr("MAX_ORDER") = kMaxShOrder;
    l.def(
        "sh_index", [](int band, int m) { return shIndex(band, m); }, "l"_a, "m"_a, "Coefficient index l(l+1)+m.");
    l.def(
        "sh_evaluate",
        [](int order, const py::array_t<double, py::array::c_style | py::array::forcecast>& directions) {
            checkedOrder(order);
            if (directions.ndim() < 1 || directions.shape(directions.ndim() - 1) != 3)
                throw py::value_error("directions must be shaped (3,) or (N, 3).");
            const py::ssize_t count = directions.size() / 3;
            const int n = order * order;
            py::array_t<double> out(directions.ndim() == 1 ? std::vector<py::ssize_t>{n}
                                                           : std::vector<py::ssize_t>{count, n});
            const double* d = directions.data();
            double* values = out.mutable_data();
            for (py::ssize_t i = 0; i < count; ++i)
                evaluateSh(order, unitDirection({d[3 * i], d[3 * i + 1], d[3 * i + 2]}),
                           std::span<double>(values + i * n, std::size_t(n)));
            return out;
        },
        "order"_a, "directions"_a,
        "Every real SH basis function of bands 0 … order−1 at unit direction(s) (normalised here): shape "
        "(order²,) or (N, order²). No Condon–Shortley phase: Y1,-1 ∝ y, Y1,0 ∝ z, Y1,1 ∝ x.");
    l.def("clamped_cosine_kernel", &clampedCosineKernel, "l"_a,
          "Â_l of the clamped cosine: π, 2π/3, π/4, 0, −π/24, … (irradiance E_lm = Â_l·L_lm).");
    l.def(
        "irradiance_from_radiance",
        [](const Coefficients& radiance) {
            const int order = orderOfLastAxis(radiance);
            py::array_t<double> out(std::vector<py::ssize_t>(radiance.shape(), radiance.shape() + radiance.ndim()));
            std::copy_n(radiance.data(), radiance.size(), out.mutable_data());
            const py::ssize_t n = order * order;
            for (py::ssize_t offset = 0; offset < out.size(); offset += n)
                irradianceFromRadiance(order, std::span<double>(out.mutable_data() + offset, std::size_t(n)));
            return out;
        },
        "radiance"_a, "Irradiance coefficients (Â_l·L_lm) from radiance coefficients, along the last axis.");

    l.def("rotation_matrix", &rotationMatrix, "quaternion"_a, "Row-major 3×3 matrix of a unit quaternion (x, y, z, w).");
    py::class_<ShRotation>(l, "ShRotation",
                           "Rotation of SH coefficients (Ivanic & Ruedenberg recursion, any order). If f' is f "
                           "turned by the rotation, apply(coefficients of f) gives the coefficients of f'.")
        .def(py::init([](int order, const anim::Quatd& rotation) { return ShRotation(checkedOrder(order), rotation); }),
             "order"_a, "quaternion"_a)
        .def_static(
            "from_matrix",
            [](int order, const py::array_t<double, py::array::c_style | py::array::forcecast>& matrix) {
                if (matrix.ndim() != 2 || matrix.shape(0) != 3 || matrix.shape(1) != 3)
                    throw py::value_error("the rotation matrix must be 3×3.");
                Matrix3d m;
                std::copy_n(matrix.data(), 9, m.begin());
                return ShRotation(checkedOrder(order), m);
            },
            "order"_a, "matrix"_a)
        .def_property_readonly("order", &ShRotation::order)
        .def(
            "band",
            [](const ShRotation& rotation, int band) {
                if (band < 0 || band >= rotation.order())
                    throw py::value_error("band must be between 0 and " + std::to_string(rotation.order() - 1) + ".");
                return toArray(rotation.band(band), {2 * band + 1, 2 * band + 1});
            },
            "l"_a, "The (2l+1)×(2l+1) matrix of band l.")
        .def(
            "apply",
            [](const ShRotation& rotation, const Coefficients& coefficients) {
                const int order = orderOfLastAxis(coefficients);
                if (order != rotation.order())
                    throw py::value_error("the coefficients are of order " + std::to_string(order)
                                          + " but the rotation of order " + std::to_string(rotation.order()) + ".");
                py::array_t<double> out(
                    std::vector<py::ssize_t>(coefficients.shape(), coefficients.shape() + coefficients.ndim()));
                const std::size_t n = std::size_t(order) * std::size_t(order);
                for (std::size_t offset = 0; offset < std::size_t(out.size()); offset += n)
                    rotation.apply(std::span<const double>(coefficients.data() + offset, n),
                                   std::span<double>(out.mutable_data() + offset, n));
                return out;
            },
            "coefficients"_a, "Rotated coefficients, along the last axis (e.g. a (3, order²) RGB light).");
}

void bindProbes(py::module_& l)
{
    py::enum_<ProbeLayout>(l, "ProbeLayout", "How an environment map's pixels map to directions (see probe.h).")
        .value("ANGULAR", ProbeLayout::Angular)
        .value("LATLONG", ProbeLayout::LatLong)
        .value("MIRRORBALL", ProbeLayout::MirrorBall)
        .value("CROSS", ProbeLayout::VerticalCross);
    l.def(
        "parse_probe_layout", [](const std::string& name) { return unwrap(parseProbeLayout(name)); }, "name"_a,
        "'angular', 'latlong', 'mirrorball' or 'cross'.");
    l.def(
        "read_hdr",
        [](const std::filesystem::path& path) { return imageToArray(unwrap(withoutGil([&] { return readHdrImage(path); }))); },
        "path"_a, "Reads an OpenEXR or Radiance .hdr image as a (height, width, 3) float32 array of linear RGB.");
    l.def(
        "write_hdr",
        [](const std::filesystem::path& path, const py::array_t<float, py::array::c_style | py::array::forcecast>& pixels) {
            const HdrImage image = imageFromArray(pixels);
            unwrap(withoutGil([&] { return writeRadianceHdr(path, image); }));
        },
        "path"_a, "pixels"_a, "Writes a (height, width, 3) array as a Radiance .hdr file (atomically).");
    l.def(
        "project_probe",
        [](const std::filesystem::path& path, ProbeLayout layout, int order, const py::object& progress) {
            checkedOrder(order);
            ProbeProjectionJob job;
            job.path = path;
            job.layout = layout;
            job.order = order;
            runJob(job, progress);
            return shRgbToArray(job.light);
        },
        "path"_a, "layout"_a = ProbeLayout::LatLong, "order"_a = 3, "progress"_a = py::none(),
        "Reads a probe file and projects it: a (3, order²) float64 array of radiance coefficients. "
        "Releases the GIL; Ctrl-C cancels and raises KeyboardInterrupt.");
    l.def(
        "project_image",
        [](const py::array_t<float, py::array::c_style | py::array::forcecast>& pixels, ProbeLayout layout, int order) {
            checkedOrder(order);
            const HdrImage image = imageFromArray(pixels);
            return shRgbToArray(unwrap(withoutGil([&]() -> core::Result<ShRgb> {
                auto projector = ProbeProjector::create(layout, image.width, image.height, order);
                if (!projector)
                    return projector.error();
                return projector->project(image);
            })));
        },
        "pixels"_a, "layout"_a = ProbeLayout::LatLong, "order"_a = 3,
        "Projects a (height, width, 3) image in the given layout: a (3, order²) array.");

    py::class_<LightProbe>(l, "LightProbe", "An environment map in a layout, looked up by direction.")
        .def_static(
            "load",
            [](const std::filesystem::path& path, ProbeLayout layout) {
                return unwrap(withoutGil([&] { return LightProbe::load(path, layout); }));
            },
            "path"_a, "layout"_a = ProbeLayout::LatLong)
        .def_property_readonly("layout", &LightProbe::layout)
        .def_property_readonly("pixels", [](const LightProbe& probe) { return imageToArray(probe.image()); })
        .def(
            "radiance", [](const LightProbe& probe, const Vec3d& d) { return probe.radiance(unitDirection(d)); },
            "direction"_a, "RGB radiance arriving from a world direction (bilinear).");
}

BakeSettings makeBakeSettings(int order, int rays, const std::string& transfer, const std::string& backend,
                              float epsilon, std::uint64_t seed, int threads)
{
    BakeSettings settings;
    settings.order = order;
    settings.raysPerVertex = rays;
    settings.transfer = unwrap(parseTransferKind(transfer));
    settings.backend = unwrap(parseOcclusionBackend(backend));
    settings.epsilon = epsilon;
    settings.seed = seed;
    settings.threads = threads;
    return settings;
}

using RangeTuple = std::pair<std::uint32_t, std::uint32_t>; // (first vertex, vertex count)

/// A bake in vertex ranges, for thespis.farm: the settings as an object, the plan, its ranges,
/// a range's floats and their place in the plan (transfer_bake.h, "A bake in pieces").
void bindBakePieces(py::module_& l)
{
    py::class_<BakeSettings>(l, "BakeSettings", "The settings of a transfer bake (the keywords of thespis.lighting.bake).")
        .def(py::init(&makeBakeSettings), py::kw_only(), "order"_a = 5, "rays"_a = 1024, "transfer"_a = "dsm",
             "backend"_a = "embree", "epsilon"_a = 1.71e-4f, "seed"_a = 1, "threads"_a = 0)
        .def_readonly("order", &BakeSettings::order)
        .def_readonly("rays", &BakeSettings::raysPerVertex)
        .def_property_readonly("transfer", [](const BakeSettings& s) { return transferKindName(s.transfer); })
        .def_property_readonly("backend", [](const BakeSettings& s) { return occlusionBackendName(s.backend); })
        .def_readonly("epsilon", &BakeSettings::epsilon)
        .def_readonly("seed", &BakeSettings::seed)
        .def_readonly("threads", &BakeSettings::threads);

    l.def(
        "load_bake_character",
        [](const std::filesystem::path& file, const std::string& character, const std::optional<std::filesystem::path>& tags,
           const std::optional<std::filesystem::path>& tagsScenario, bool splitSkinnedByJoint) {
            core::scenario::BakeCharacter source{file, character, tags.value_or(""), tagsScenario.value_or(""),
                                                 splitSkinnedByJoint};
            return unwrap(withoutGil([&] { return core::scenario::loadBakeCharacter(source); }));
        },
        "file"_a, py::kw_only(), "character"_a = "", "tags"_a = py::none(), "tags_scenario"_a = py::none(),
        "split_skinned_by_joint"_a = true,
        "The mesh `thespis-cli bake` bakes: a .gltf/.glb file, or a scenario's character (.thespis or .thespkg; "
        "`character` names it when there are several) with its tags; then a tags file's tags, or (glTF only) "
        "those of tags_scenario's character. Errors name the file, field or character.");
    l.def("geometry_hash", &meshGeometryHash, "mesh"_a,
          "The hash a bake records of the mesh's shape (TransferBake.geometry_hash).");
    l.def(
        "plan_bake",
        [](const scene::CharacterMesh& mesh, const BakeSettings& settings) { return unwrap(planTransferBake(mesh, settings)); },
        "mesh"_a, "settings"_a,
        "The bake of mesh with every field but the transfer filled in (it is zero): place ranges into it.");
    l.def(
        "split_bake",
        [](const TransferBake& plan, std::uint32_t maxVertices) {
            if (maxVertices < 1)
                throw py::value_error("max_vertices must be at least 1.");
            std::vector<RangeTuple> ranges;
            for (const VertexRange& range : splitTransferBake(plan, maxVertices))
                ranges.emplace_back(range.firstVertex, range.vertexCount);
            return ranges;
        },
        "plan"_a, "max_vertices"_a,
        "Every baked segment cut into (first_vertex, vertex_count) ranges of at most max_vertices, in the order "
        "of the transfer.");
    l.def(
        "bake_ranges",
        [](const scene::CharacterMesh& mesh, const BakeSettings& settings, const std::vector<RangeTuple>& ranges,
           const py::object& progress) {
            TransferRangesJob job;
            job.mesh = mesh;
            job.settings = settings;
            for (const auto& [first, count] : ranges)
                job.ranges.push_back({first, count});
            runJob(job, progress);
            return toArray(std::span<const float>(job.transfer));
        },
        "mesh"_a, "settings"_a, "ranges"_a, py::kw_only(), "progress"_a = py::none(),
        "Bakes only the (first_vertex, vertex_count) ranges (each inside one baked segment): a flat float32 array, "
        "order² floats per vertex, range after range, equal bit for bit to those vertices of the whole bake. "
        "Releases the GIL; progress(done, total); Ctrl-C cancels and raises KeyboardInterrupt.");
}

void bindBake(py::module_& l)
{
    py::class_<BakedSegment>(l, "BakedSegment", "A segment's entry in a bake.")
        .def_readonly("name", &BakedSegment::name)
        .def_readonly("first_vertex", &BakedSegment::firstVertex)
        .def_readonly("vertex_count", &BakedSegment::vertexCount)
        .def_readonly("baked", &BakedSegment::baked, "False for occluder segments (no transfer stored).")
        .def_readonly("role", &BakedSegment::role)
        .def("__repr__", [](const BakedSegment& s) {
            return "<thespis.lighting.BakedSegment '" + s.name + "' " + std::to_string(s.vertexCount) + " vertices"
                   + (s.baked ? "" : ", not baked") + ">";
        });

    py::class_<TransferBake>(l, "TransferBake",
                             "Per-vertex transfer vectors (order² floats, in each segment's bind frame).")
        .def_readonly("order", &TransferBake::order)
        .def_property_readonly("transfer_kind", [](const TransferBake& b) { return transferKindName(b.transferKind); })
        .def_readonly("rays_per_vertex", &TransferBake::raysPerVertex)
        .def_readonly("epsilon", &TransferBake::epsilon)
        .def_readonly("seed", &TransferBake::seed)
        .def_readonly("vertex_count", &TransferBake::vertexCount)
        .def_readonly("geometry_hash", &TransferBake::geometryHash,
                      "A hash of the baked mesh's shape (0: not recorded, bake files of format 1).")
        .def_readonly("segments", &TransferBake::segments)
        .def_property_readonly(
            "transfer",
            [](const TransferBake& b) {
                const py::ssize_t n = py::ssize_t(b.order) * b.order;
                return toArray(std::span<const float>(b.transfer), {py::ssize_t(b.transfer.size()) / n, n});
            },
            "(baked vertices, order²) float32 copy, segment after segment.")
        .def(
            "vertex_transfer",
            [](const TransferBake& b, std::uint32_t vertex) -> std::optional<py::array_t<float>> {
                if (vertex >= b.vertexCount)
                    throw py::index_error("vertex " + std::to_string(vertex) + " is out of range (the bake has "
                                          + std::to_string(b.vertexCount) + ").");
                const auto t = b.vertexTransfer(vertex);
                if (t.empty())
                    return std::nullopt;
                return toArray(t);
            },
            "vertex"_a, "The vertex's transfer vector, or None for vertices of unbaked (occluder) segments.")
        .def("save", [](const TransferBake& b, const std::filesystem::path& path) {
                unwrap(withoutGil([&] { return writeBakeFile(path, b); }));
            }, "path"_a, "Writes the bake file atomically.")
        .def_static(
            "load", [](const std::filesystem::path& path) { return unwrap(withoutGil([&] { return readBakeFile(path); })); },
            "path"_a, "Reads a bake file; corrupt or newer files raise thespis.FormatError naming the field.")
        .def(
            "check_matches", [](const TransferBake& b, const scene::CharacterMesh& mesh) { unwrap(checkBakeMatchesMesh(b, mesh)); },
            "mesh"_a, "Raises ValueError saying how the bake and the mesh differ.")
        .def(
            "shade",
            [](const TransferBake& b, const scene::CharacterMesh& mesh, const Coefficients& lightArray) {
                unwrap(checkBakeMatchesMesh(b, mesh));
                const ShRgb light = shRgbFromArray(lightArray);
                if (light.order != b.order)
                    throw py::value_error("the light is of order " + std::to_string(light.order)
                                          + " but the bake of order " + std::to_string(b.order) + ".");
                py::array_t<double> out({py::ssize_t(mesh.vertexCount()), py::ssize_t(3)});
                double* rgb = out.mutable_data();
                for (const scene::Segment& segment : mesh.segments)
                    for (std::uint32_t v = segment.firstVertex; v < segment.firstVertex + segment.vertexCount; ++v) {
                        const auto radiance = shadeVertex(b, mesh, v, light, segment.bindRotation);
                        std::copy(radiance.begin(), radiance.end(), rgb + 3 * std::size_t(v));
                    }
                return out;
            },
            "mesh"_a, "light"_a, "Exit radiance (V, 3) of every vertex in the bind pose under an RGB light (3, order²).")
        .def(
            "place_range",
            [](TransferBake& b, std::uint32_t first, std::uint32_t count,
               const py::array_t<float, py::array::c_style>& transfer) {
                unwrap(placeTransferRange(b, {first, count}, std::span<const float>(transfer.data(), std::size_t(transfer.size()))));
            },
            "first_vertex"_a, "vertex_count"_a, "transfer"_a,
            "Copies a range's float32 transfer (bake_ranges' result) into this bake (a plan_bake); ValueError when the "
            "range is not inside one baked segment or the count does not fit.")
        .def("__eq__", [](const TransferBake& a, const TransferBake& b) { return a == b; })
        .def("__repr__", [](const TransferBake& b) {
            return std::string("<thespis.lighting.TransferBake ") + transferKindName(b.transferKind) + " order "
                   + std::to_string(b.order) + ", " + std::to_string(b.vertexCount) + " vertices, "
                   + std::to_string(b.raysPerVertex) + " rays>";
        });

    l.def(
        "bake",
        [](const scene::CharacterMesh& mesh, int order, int rays, const std::string& transfer, const std::string& backend,
           float epsilon, std::uint64_t seed, int threads, const py::object& progress) {
            TransferBakeJob job;
            job.mesh = mesh;
            job.settings = makeBakeSettings(order, rays, transfer, backend, epsilon, seed, threads);
            runJob(job, progress);
            return std::move(*job.bake);
        },
        "mesh"_a, py::kw_only(), "order"_a = 5, "rays"_a = 1024, "transfer"_a = "dsm", "backend"_a = "embree",
        "epsilon"_a = 1.71e-4f, "seed"_a = 1, "threads"_a = 0, "progress"_a = py::none(),
        "Bakes per-vertex transfer: transfer 'du', 'ds' or 'dsm' (paper §6.1.1), backend 'embree' or 'grid', "
        "epsilon the relaxation distance in metres. Releases the GIL; progress(done, total) is called on this "
        "thread; Ctrl-C cancels the bake and raises KeyboardInterrupt. The result does not depend on threads.");
}

} // namespace

void bindLighting(py::module_& m)
{
    py::module_ l = m.def_submodule("lighting", "Spherical harmonics, HDR light probes and the PRT transfer bake (paper §6).");
    bindSphericalHarmonics(l);
    bindProbes(l);
    bindBake(l);
    bindBakePieces(l);
}

} // namespace thespis::python
