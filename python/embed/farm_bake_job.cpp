// pybind11's embed header must come before anything that may include Qt (its `slots` macro).
#include <pybind11/embed.h>

#include "farm_bake_job.h"

#include <chrono>
#include <system_error>

#include "bind_common.h"
#include "interpreter.h"

namespace thespis::script {

namespace py = pybind11;
using namespace pybind11::literals;

namespace {

py::object optionalPath(const std::filesystem::path& path)
{
    return path.empty() ? py::none() : py::object(py::str(path.string()));
}

/// The core error of a Python exception thespis.farm raised: thespis's own errors keep their
/// code (errors.cpp sets `code`); other failures (the cluster, the network) are I/O errors.
core::Error errorOf(py::error_already_set& error)
{
    std::string message = py::str(error.value());
    if (message.empty())
        message = py::str(error.type().attr("__name__"));
    if (py::hasattr(error.value(), "code")) {
        try {
            return core::makeError(error.value().attr("code").cast<core::ErrorCode>(), message);
        } catch (const py::cast_error&) {
            // an exception's own `code` attribute (OSError's errno has another name): fall through
        }
    }
    if (error.matches(PyExc_FileNotFoundError))
        return core::makeError(core::ErrorCode::FileNotFound, message);
    if (error.matches(PyExc_ValueError))
        return core::makeError(core::ErrorCode::InvalidArgument, message);
    return core::makeError(core::ErrorCode::IoError, "The farm bake failed: " + message,
                           py::str(error.type().attr("__name__")).cast<std::string>());
}

} // namespace

std::string FarmBakeJob::title() const
{
    return output.empty() ? "The farm bake on " + scheduler : "The farm bake into " + output.string();
}

core::Result<void> FarmBakeJob::validate() const
{
    if (scheduler.empty())
        return core::makeError(core::ErrorCode::InvalidArgument, "A farm bake needs the address of a Dask scheduler.");
    return core::lighting::validateBakeSettings(settings);
}

core::Result<void> FarmBakeJob::run(core::JobContext& context)
{
    bake.reset();
    const auto started = std::chrono::steady_clock::now();
    ensurePython();
    GilHolder gil;
    try {
        py::module_ farm = py::module_::import("thespis.farm");
        py::object source = farm.attr("Character")(
            "file"_a = character.file.string(), "character"_a = character.character,
            "tags"_a = optionalPath(character.tagsFile), "tags_scenario"_a = optionalPath(character.tagsScenario),
            "split_skinned_by_joint"_a = character.splitSkinnedByJoint);
        bool begun = false;
        auto progress = py::cpp_function([&](std::uint64_t done, std::uint64_t total) {
            if (!begun) {
                context.beginStage("Baking transfer", total);
                begun = true;
            }
            context.setDone(done);
        });
        // Polled by thespis.farm between tasks (every 0.1 s): Ctrl-C cancels the cluster's tasks.
        auto stop = py::cpp_function([&] { return context.stopRequested(); });
        py::object result = farm.attr("bake")(
            source, "scheduler"_a = scheduler, "order"_a = settings.order, "rays"_a = settings.raysPerVertex,
            "transfer"_a = core::lighting::transferKindName(settings.transfer),
            "backend"_a = core::lighting::occlusionBackendName(settings.backend), "epsilon"_a = settings.epsilon,
            "seed"_a = settings.seed, "threads_per_task"_a = settings.threads > 0 ? settings.threads : 1,
            "progress"_a = progress, "stop"_a = stop);
        bake = result.cast<core::lighting::TransferBake>();
    } catch (py::error_already_set& error) {
        if (error.matches(PyExc_KeyboardInterrupt) || context.stopRequested())
            return core::cancelledError(title());
        return errorOf(error);
    }
    std::uint64_t vertices = 0;
    for (const core::lighting::BakedSegment& segment : bake->segments)
        vertices += segment.baked ? segment.vertexCount : 0;
    statistics.vertices = vertices;
    statistics.rays = vertices * std::uint64_t(settings.raysPerVertex);
    statistics.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    if (context.stopRequested())
        return core::cancelledError(title());
    if (!output.empty())
        if (auto written = core::lighting::writeBakeFile(output, *bake); !written)
            return written; // written atomically: nothing is left behind
    return {};
}

void FarmBakeJob::discardOutput()
{
    bake.reset();
    if (!output.empty()) {
        std::error_code ignored;
        std::filesystem::remove(output, ignored);
    }
}

} // namespace thespis::script
