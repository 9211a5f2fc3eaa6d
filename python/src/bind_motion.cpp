// thespis.motion: the paper's motion synthesis (§4.1, §4.3, §4.4) — posture vectors, the posture
// PCA and its files, the idle motion database and the idle blendable, the dependent-joint filter.
// Postures cross as NumPy arrays (one posture per row).

#include "bind_common.h"
#include "errors.h"
#include "scenario/build_idle_job.h"
#include "motion/dependent_joint_filter.h"
#include "motion/idle_motion.h"
#include "motion/posture_bases.h"
#include "scenario/posture_clip.h"
#include "scenario/train_pca_job.h"
#include "run_job.h"

namespace thespis::python {

using namespace pybind11::literals;
using namespace core::motion;
using core::scenario::PostureSource;
using core::scenario::TrainPcaJob;
using core::scenario::PostureClip;
using core::scenario::readPostureClip;
namespace anim = core::anim;

namespace {

using FloatArray = py::array_t<float, py::array::c_style | py::array::forcecast>;

// Rows of `size` numbers: a 1-D array is one posture, a 2-D array one per row.
std::span<const float> rows(const FloatArray& array, std::size_t size, const char* what)
{
    if (array.ndim() < 1 || array.ndim() > 2 || std::size_t(array.shape(array.ndim() - 1)) != size)
        throw py::value_error(std::string(what) + " must have " + std::to_string(size) + " numbers per row");
    return {array.data(), std::size_t(array.size())};
}

py::array_t<float> shaped(std::vector<float> values, const FloatArray& like, std::size_t width)
{
    if (like.ndim() == 1)
        return toArray<float>(values, {py::ssize_t(width)});
    return toArray<float>(values, {py::ssize_t(values.size() / width), py::ssize_t(width)});
}

std::vector<PostureSource> sources(const std::vector<std::filesystem::path>& files, double skip)
{
    std::vector<PostureSource> out;
    for (const auto& file : files) {
        PostureSource source;
        source.clip.file = file.string();
        source.clip.name = file.stem().string();
        source.skip = skip;
        out.push_back(std::move(source));
    }
    return out;
}

} // namespace

void bindMotion(py::module_& m)
{
    py::module_ mo = m.def_submodule("motion", "Motion synthesis (paper §4): postures, the posture PCA, idle motion, "
                                               "the dependent-joint filter.");

    py::enum_<PostureSet>(mo, "PostureSet")
        .value("whole_body", PostureSet::WholeBody)
        .value("upper_body", PostureSet::UpperBody);
    mo.def("posture_joints", [](PostureSet set) { return PostureLayout::of(set).joints; }, "set"_a,
           "The H-Anim joints of a posture set, in posture order (3 numbers each; the whole body adds the root's place).");
    mo.def("posture_size", [](PostureSet set) { return PostureLayout::of(set).size(); }, "set"_a);

    py::class_<PostureMap>(mo, "PostureMap", "A skeleton's frames as posture vectors of a set (exponential maps).")
        .def(py::init([](const anim::Skeleton& skeleton, PostureSet set) { return unwrap(PostureMap::create(skeleton, set)); }),
             "skeleton"_a, "set"_a = PostureSet::WholeBody)
        .def("to_postures",
             [](const PostureMap& map, const FloatArray& frames) {
                 const std::size_t floats = map.skeleton().frameLayout()->floatCount(), d = std::size_t(map.layout().size());
                 const auto in = rows(frames, floats, "frames");
                 std::vector<float> out(in.size() / floats * d);
                 for (std::size_t f = 0; f < in.size() / floats; ++f)
                     map.toPosture(in.subspan(f * floats, floats), std::span<float>(out).subspan(f * d, d));
                 return shaped(std::move(out), frames, d);
             },
             "frames"_a, "Postures of frames (one per row) of the skeleton.")
        .def("to_frames",
             [](const PostureMap& map, const FloatArray& postures) {
                 const std::size_t floats = map.skeleton().frameLayout()->floatCount(), d = std::size_t(map.layout().size());
                 const auto in = rows(postures, d, "postures");
                 const std::vector<float> rest = map.skeleton().restFrame();
                 std::vector<float> out;
                 for (std::size_t f = 0; f < in.size() / d; ++f) {
                     out.insert(out.end(), rest.begin(), rest.end());
                     map.toFrame(in.subspan(f * d, d), std::span<float>(out).subspan(f * floats, floats));
                 }
                 return shaped(std::move(out), postures, floats);
             },
             "postures"_a, "Frames of the skeleton (its rest where the postures say nothing).");

    py::class_<PostureBasis, std::shared_ptr<PostureBasis>>(mo, "PostureBasis",
                                                            "The PCA of a posture set: mean, eigenvalues, components.")
        .def_static(
            "train",
            [](PostureSet set, const FloatArray& postures) {
                const auto in = rows(postures, std::size_t(PostureLayout::of(set).size()), "postures");
                return unwrap(PostureBasis::train(set, in));
            },
            "set"_a, "postures"_a, "Trains on postures (one per row).")
        .def_property_readonly("set", &PostureBasis::set)
        .def_property_readonly("dimension", &PostureBasis::dimension)
        .def_property_readonly("sample_count", &PostureBasis::sampleCount)
        .def_property_readonly("mean", [](const PostureBasis& b) { return toArray<float>(b.mean()); })
        .def_property_readonly("eigenvalues", [](const PostureBasis& b) { return toArray<float>(b.eigenvalues()); })
        .def_property_readonly("components",
                               [](const PostureBasis& b) {
                                   return toArray<float>(b.components(), {b.dimension(), b.dimension()});
                               },
                               "One PC per row, largest variance first.")
        .def("explained_variance", &PostureBasis::explainedVariance, "k"_a, "The share of the variance the first k PCs hold.")
        .def(
            "project",
            [](const PostureBasis& b, const FloatArray& postures, std::optional<int> k) {
                const std::size_t d = std::size_t(b.dimension()), n = std::size_t(k.value_or(b.dimension()));
                if (n < 1 || n > d)
                    throw py::value_error("k must be between 1 and " + std::to_string(d));
                const auto in = rows(postures, d, "postures");
                std::vector<float> out(in.size() / d * n);
                for (std::size_t f = 0; f < in.size() / d; ++f)
                    b.project(in.subspan(f * d, d), std::span<float>(out).subspan(f * n, n));
                return shaped(std::move(out), postures, n);
            },
            "postures"_a, "k"_a = py::none(), "PC values of postures (the first k).")
        .def(
            "reconstruct",
            [](const PostureBasis& b, const FloatArray& pcs) {
                const std::size_t d = std::size_t(b.dimension());
                const std::size_t k = std::size_t(pcs.ndim() >= 1 ? pcs.shape(pcs.ndim() - 1) : 0);
                if (k < 1 || k > d)
                    throw py::value_error("pcs must have 1 to " + std::to_string(d) + " values per row");
                const auto in = rows(pcs, k, "pcs");
                std::vector<float> out(in.size() / k * d);
                for (std::size_t f = 0; f < in.size() / k; ++f)
                    b.reconstruct(in.subspan(f * k, k), std::span<float>(out).subspan(f * d, d));
                return shaped(std::move(out), pcs, d);
            },
            "pcs"_a, "Postures from PC values (missing higher PCs are 0).")
        .def(
            "distance",
            [](const PostureBasis& b, const FloatArray& p, const FloatArray& q, int k) {
                if (k < 1 || k > b.dimension() || p.size() < k || q.size() < k)
                    throw py::value_error("k must be between 1 and the PC vectors' length");
                return b.distance({p.data(), std::size_t(p.size())}, {q.data(), std::size_t(q.size())}, k);
            },
            "p"_a, "q"_a, "k"_a, "The paper's eq. 1 between two PC vectors over the first k PCs.");

    py::class_<PostureBases, std::shared_ptr<PostureBases>>(mo, "PostureBases", "A whole-body and an upper-body basis (.pca).")
        .def_property_readonly("whole", [](const std::shared_ptr<PostureBases>& b) { return std::shared_ptr<PostureBasis>(b, &b->whole); })
        .def_property_readonly("upper", [](const std::shared_ptr<PostureBases>& b) { return std::shared_ptr<PostureBasis>(b, &b->upper); })
        .def("save", [](const PostureBases& b, const std::filesystem::path& path) { unwrap(writePostureBasesFile(path, b)); }, "path"_a);
    mo.def("load_bases", [](const std::filesystem::path& path) { return std::make_shared<PostureBases>(unwrap(readPostureBasesFile(path))); },
           "path"_a, "Reads a .pca file (refuses damaged, newer or foreign ones, naming the field).");
    mo.def(
        "postures_of",
        [](const std::filesystem::path& file, PostureSet set, double rate, double skip, double frame_rate) {
            core::scenario::ClipAsset asset;
            asset.file = file.string();
            asset.name = file.stem().string();
            asset.frameRateOverride = frame_rate;
            const PostureClip clip = unwrap(withoutGil([&] { return readPostureClip(asset, core::scenario::Assets(".")); }));
            std::vector<float> postures = clip.postures(set, rate, skip);
            const auto d = py::ssize_t(PostureLayout::of(set).size());
            return toArray<float>(postures, {py::ssize_t(postures.size()) / d, d});
        },
        "file"_a, "set"_a = PostureSet::WholeBody, "rate"_a = 30.0, "skip"_a = 0.0, "frame_rate"_a = 0.0,
        "A clip file's postures (BVH or glTF, retargeted onto the H-Anim 25 joints), rate per second from skip on.");
    mo.def(
        "train",
        [](const std::vector<std::filesystem::path>& files, const std::filesystem::path& out, double rate, double skip,
           const py::object& progress) {
            TrainPcaJob job;
            job.sources = sources(files, skip);
            job.output = out;
            job.sampleRate = rate;
            runJob(job, progress);
            return std::make_shared<PostureBases>(std::move(job.bases));
        },
        "files"_a, "out"_a, "rate"_a = 30.0, "skip"_a = 0.0, "progress"_a = py::none(),
        "thespis-cli train-pca from Python: trains both bases on clip files and writes the .pca file; "
        "progress(done, total) is called as it reads them. Releases the GIL; Ctrl-C cancels.");

    py::class_<IdleDatabase, std::shared_ptr<IdleDatabase>>(mo, "IdleDatabase",
                                                            "Transitions between rest postures and the spread of small variations (.idle).")
        .def_property_readonly("categories", [](const IdleDatabase& d) { return d.categories; })
        .def_property_readonly("frame_rate", [](const IdleDatabase& d) { return d.frameRate; })
        .def_property_readonly("transition_count", [](const IdleDatabase& d) { return d.segments.size(); })
        .def_property_readonly("variation", [](const IdleDatabase& d) { return toArray<float>(d.variation); })
        .def_property_readonly("transitions",
                               [](const IdleDatabase& d) {
                                   py::list out;
                                   for (const IdleSegment& s : d.segments)
                                       out.append(py::dict("source"_a = s.source, "start"_a = s.sourceStart,
                                                           "frames"_a = s.count, "from_"_a = d.categories[std::size_t(s.from)],
                                                           "to"_a = d.categories[std::size_t(s.to)]));
                                   return out;
                               })
        .def("save", [](const IdleDatabase& d, const std::filesystem::path& path) { unwrap(writeIdleDatabaseFile(path, d)); }, "path"_a);
    mo.def("load_idle_database",
           [](const std::filesystem::path& path) { return std::make_shared<IdleDatabase>(unwrap(readIdleDatabaseFile(path))); },
           "path"_a);
    mo.def(
        "rest_categories",
        [](const FloatArray& postures, int categories, double frame_rate) {
            IdleRecording recording;
            const auto in = rows(postures, 78, "postures");
            recording.postures.assign(in.begin(), in.end());
            IdleBuildOptions options;
            options.categoryCount = categories;
            options.frameRate = float(frame_rate);
            const std::vector<int> labels = findRestCategories(recording, options);
            return toArray<int>(labels);
        },
        "postures"_a, "categories"_a = 3, "frame_rate"_a = 30.0,
        "Per whole-body posture (one per row, at frame_rate), its rest category: 0 weight on the left foot, 1 both, 2 right.");
    mo.def(
        "build_idle",
        [](const std::vector<std::pair<std::string, FloatArray>>& recordings, double frame_rate, int categories,
           const std::optional<std::vector<std::vector<int>>>& labels) {
            std::vector<IdleRecording> in;
            for (std::size_t i = 0; i < recordings.size(); ++i) {
                const auto postures = rows(recordings[i].second, 78, "postures");
                in.push_back({recordings[i].first, {postures.begin(), postures.end()}, labels ? labels->at(i) : std::vector<int>{}});
            }
            IdleBuildOptions options;
            options.frameRate = float(frame_rate);
            options.categoryCount = categories;
            return std::make_shared<IdleDatabase>(unwrap(buildIdleDatabase(in, options)));
        },
        "recordings"_a, "frame_rate"_a = 30.0, "categories"_a = 3, "labels"_a = py::none(),
        "An idle database from (name, whole-body postures at frame_rate) pairs; labels (per recording, per frame, "
        "-1 for none) set rest categories by hand.");

    mo.def(
        "idle",
        [](const std::shared_ptr<IdleDatabase>& database, const anim::Skeleton& skeleton, std::uint64_t seed,
           float amplitude) {
            return anim::BlendablePtr(unwrap(IdleMotion::create(database, skeleton, {.seed = seed, .amplitude = amplitude})));
        },
        "database"_a, "skeleton"_a, "seed"_a = 1, "amplitude"_a = 1.0f,
        "The paper's idle motion on a skeleton: an open-ended Blendable, the same frames whichever way time goes.");
    mo.def(
        "dependent_joint_filter",
        [](const anim::BlendablePtr& source, const anim::Skeleton& skeleton, const std::shared_ptr<PostureBasis>& upper,
           int fade_from, int mute_above) {
            return anim::BlendablePtr(unwrap(DependentJointFilter::create(source, skeleton, upper, {fade_from, mute_above})));
        },
        "source"_a, "skeleton"_a, "upper"_a, "fade_from"_a = 20, "mute_above"_a = 30,
        "A Blendable playing `source` through the dependent-joint filter of an upper-body basis.");
}

} // namespace thespis::python
