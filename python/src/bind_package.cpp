// thespis.open_package, thespis.export_package and thespis.Package: scenario packages from
// Python, through the same core code as `thespis-cli export / import / validate`.

#include "bind_package.h"

#include "errors.h"
#include "run_job.h"
#include "scenario/package_export_job.h"
#include "scenario/package_resolver.h"
#include "scenario/scenario_io.h"

namespace thespis::python {

namespace {

using namespace pybind11::literals;
using namespace core::scenario;

struct ExportResult {
    std::vector<PackageEntry> entries;
    std::uint64_t packageBytes = 0;
    std::uint64_t contentBytes = 0;
    std::vector<std::string> baked;
};

} // namespace

Assets assetsArgument(const py::handle& where)
{
    if (py::isinstance<OpenedPackage>(where))
        return where.cast<const OpenedPackage&>().assets;
    return Assets(where.cast<std::filesystem::path>());
}

void bindPackages(py::module_& m)
{
    m.attr("PACKAGE_EXTENSION") = std::string(kPackageExtension);
    py::class_<PackageEntry>(m, "PackageEntry", "One entry of a package's manifest.")
        .def_readonly("name", &PackageEntry::name)
        .def_readonly("size", &PackageEntry::size, "Bytes, uncompressed.")
        .def_readonly("sha256", &PackageEntry::sha256)
        .def("__repr__", [](const PackageEntry& e) {
            return "<thespis.PackageEntry '" + e.name + "' " + std::to_string(e.size) + " bytes>";
        });

    py::class_<OpenedPackage>(m, "Package",
                              "An open scenario package, every check passed. Pass it as base_dir to build_runtime, "
                              "validate_scenario or bake_motion: its scenario plays straight from it.")
        .def_property_readonly("file", [](const OpenedPackage& p) { return p.package->file(); })
        .def_property_readonly("writer", [](const OpenedPackage& p) { return p.package->manifest().writer; })
        .def_property_readonly("scenario_entry", [](const OpenedPackage& p) { return p.package->manifest().scenario; })
        .def_property_readonly("entries", [](const OpenedPackage& p) { return p.package->manifest().entries; },
                               "The manifest's entries (the manifest itself not among them).")
        .def_readonly("scenario", &OpenedPackage::scenario, "The package's scenario (a copy).")
        .def(
            "read",
            [](const OpenedPackage& p, const std::string& name) {
                auto bytes = withoutGil([&] { return p.package->read(name); });
                return py::bytes(unwrap(std::move(bytes)));
            },
            "name"_a, "An entry's bytes, checked against the manifest.")
        .def(
            "extract_to",
            [](const OpenedPackage& p, const std::filesystem::path& folder) {
                return unwrap(withoutGil([&] { return p.package->extractTo(folder); }));
            },
            "folder"_a,
            "Imports the package: writes every entry under folder (made if missing) and returns the scenario's "
            "path there. A file already there must be the same.")
        .def("__repr__", [](const OpenedPackage& p) {
            return "<thespis.Package '" + p.package->file().string() + "' " + std::to_string(p.package->manifest().entries.size())
                   + " entries>";
        });

    m.def(
        "open_package",
        [](const std::filesystem::path& file) { return unwrap(withoutGil([&] { return openPackage(file); })); },
        "file"_a,
        "Opens a .thespkg, refusing what is unsafe or damaged (a path out of the package, a link, a name twice, a "
        "zip bomb, an entry whose SHA-256 is not the manifest's, a newer format) with thespis.FormatError naming "
        "the entry.");

    py::class_<ExportResult>(m, "PackageExport", "What export_package wrote.")
        .def_readonly("entries", &ExportResult::entries, "The manifest's entries.")
        .def_readonly("package_bytes", &ExportResult::packageBytes, "The package's size on disk.")
        .def_readonly("content_bytes", &ExportResult::contentBytes, "The entries' sizes, uncompressed.")
        .def_readonly("baked", &ExportResult::baked, "The bakes made first (bake=True): \"Creon: it had none\" …");
    m.def(
        "export_package",
        [](const py::object& scenario, const std::filesystem::path& out, const py::object& baseDir,
           const std::string& scenarioEntry, const py::object& progress, bool bake, int rays) {
            ExportPackageJob job;
            job.bakeLighting = bake;
            job.bakeSettings.raysPerVertex = rays;
            if (py::isinstance<Scenario>(scenario)) {
                job.scenario = scenario.cast<Scenario>();
                job.assets = assetsArgument(baseDir.is_none() ? py::str(".") : baseDir);
                job.scenarioEntry = scenarioEntry;
            } else {
                const auto path = scenario.cast<std::filesystem::path>();
                job.scenario = unwrap(withoutGil([&] { return loadScenario(path); }));
                job.assets = baseDir.is_none() ? Assets::besideFile(path) : assetsArgument(baseDir);
                job.scenarioEntry = path.filename().string();
            }
            job.output = out;
            runJob(job, progress);
            return ExportResult{job.manifest.entries, job.packageBytes, job.contentBytes, job.baked};
        },
        "scenario"_a, "out"_a, py::kw_only(), "base_dir"_a = py::none(), "scenario_entry"_a = "scenario.thespis",
        "progress"_a = py::none(), "bake"_a = false, "rays"_a = 1024,
        "Writes a package of a scenario (a .thespis path, or a Scenario whose files base_dir finds) and every file "
        "it names, as `thespis-cli export` does (the same job). A missing file raises FileNotFoundError naming "
        "the field; progress(done, total); Ctrl-C stops it and the old package stays. With bake, characters whose "
        "lighting bake is missing or no longer fits are baked first (rays per vertex for those that had none), "
        "into the package only.");
}

} // namespace thespis::python
