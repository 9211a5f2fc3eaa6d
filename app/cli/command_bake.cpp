// thespis-cli bake: the PRT transfer bake of a glTF character or of a scenario's character (its
// model or the built-in humanoid; paper §6) from a .thespis file or a .thespkg package, written as
// a bake file. Segment tags come from a tags file or from a scenario's character
// (core/scenario/bake_character.h). The bake runs on worker threads — or, with --scheduler, on a
// Dask cluster through thespis.farm in the embedded interpreter — while this thread draws the
// progress bar and watches for Ctrl-C, which cancels the bake: nothing is written then (the bake
// file is written atomically at the very end). Both give the same file, byte for byte.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>

#include "commands.h"
#include "exit_codes.h"
#include "lighting/probe.h"
#include "lighting/probe_projection_job.h"
#include "lighting/transfer_bake.h"
#include "lighting/transfer_bake_job.h"
#include "job_progress.h"
#include "scenario/bake_character.h"

#ifdef THESPIS_WITH_PYTHON
#include "farm_bake_job.h"
#endif

namespace thespis::cli {
namespace {

namespace lighting = core::lighting;

} // namespace

CommandSpec bakeSpec()
{
    CommandSpec spec;
    spec.name = "bake";
    spec.summary = "Bake per-vertex PRT transfer (DU, DS or DSM) of a glTF character or a scenario's character.";
    spec.positionals = {"CHARACTER"};
    spec.options = {
        {"out", "FILE", "the bake file to write; an existing file is replaced atomically", true},
        {"order", "N", "SH order: bands 0 … N−1, N² coefficients per vertex (default 5, 1 to 11)"},
        {"rays", "N", "rays per vertex (default 1024)"},
        {"transfer", "du|ds|dsm", "diffuse unshadowed, shadowed (own segment) or shadowed merged (default dsm)"},
        {"backend", "embree|grid", "ray tracer: Embree or the paper's uniform grid (default embree)"},
        {"epsilon", "METRES", "ignore ray hits nearer than this (default 1.71e-4, the H-Anim segment gap)"},
        {"seed", "N", "random seed of the ray directions (default 1)"},
        {"threads", "N", "worker threads (default: all cores); the result does not depend on it"},
        {"tags", "FILE.json", "segment tags: {\"hair\": \"receiver\", \"coat\": {\"role\": \"occluder\"}}"},
        {"scenario", "FILE.thespis", "take the segment tags from this scenario's character instead"},
        {"character", "NAME", "the scenario's character (needed when it has several)"},
        {"probe", "FILE", "also light the bake with this HDR probe (.exr or .hdr) and print the radiance range"},
        {"layout", "NAME", "the probe's layout: angular, latlong, mirrorball or cross (default latlong)"},
        {"no-split", "", "keep a skinned mesh as one segment instead of one per dominant joint"},
        {"scheduler", "tcp://HOST:PORT", "bake on this running Dask cluster (thespis.farm); its workers load CHARACTER"},
        {"quiet", "", "no progress and no summary"},
    };
    spec.description =
        "CHARACTER is a .gltf/.glb file, a .thespis scenario or a .thespkg package: then its character's body\n"
        "(its model, or the built-in humanoid) is baked with the scenario's tags, ready for 'thespis-cli render'.\n"
        "Segments are the glTF's mesh nodes, and a skinned mesh is split by dominant joint. With DSM a\n"
        "segment tagged receiver is transparent to rays and an occluder is not baked (paper §6.1.3).\n"
        "The summary gives vertices, rays, seconds and Mrays/s. Ctrl-C stops the bake without writing.\n"
        "With --scheduler the bake is split into vertex ranges that the cluster's workers bake (each loads\n"
        "CHARACTER, and the tags file, from the same path: use a shared folder; they need the thespis Python\n"
        "package); a worker that dies has its ranges baked by another. The file is the local bake's, byte\n"
        "for byte. --threads is then the bake threads of each task (default 1: Dask runs a task per thread).\n"
        "Exit status: 0 written, 2 bad command line, 3 unreadable character, tags or probe,\n"
        "4 the bake or the file failed, 130 cancelled.";
    return spec;
}

int runBake(const CommandSpec& spec, const ParsedArguments& arguments)
{
    const std::filesystem::path characterPath = arguments.positionals[0];
    const std::filesystem::path outPath = *arguments.value("out");
    const bool quiet = arguments.has("quiet");
    const std::optional<std::string> scheduler = arguments.value("scheduler");
#ifndef THESPIS_WITH_PYTHON
    if (scheduler)
        return usageError(spec, "--scheduler runs thespis.farm in Python, and this thespis-cli was built without it");
#endif

    int exitCode = ExitOk;
    lighting::BakeSettings settings;
    settings.order = int(integerOption(spec, arguments, "order", 1, 11, exitCode).value_or(settings.order));
    settings.raysPerVertex = int(integerOption(spec, arguments, "rays", 1, 1 << 20, exitCode).value_or(settings.raysPerVertex));
    settings.seed = std::uint64_t(integerOption(spec, arguments, "seed", 0, 1L << 52, exitCode).value_or(long(settings.seed)));
    settings.threads = int(integerOption(spec, arguments, "threads", 0, 1024, exitCode).value_or(settings.threads));
    const auto transfer = choiceOption(spec, arguments, "transfer", settings.transfer, lighting::parseTransferKind, exitCode);
    const auto backend = choiceOption(spec, arguments, "backend", settings.backend, lighting::parseOcclusionBackend, exitCode);
    const auto layout = choiceOption(spec, arguments, "layout", lighting::ProbeLayout::LatLong, lighting::parseProbeLayout, exitCode);
    if (const auto epsilonText = arguments.value("epsilon")) {
        const auto epsilon = parseNumber(*epsilonText);
        if (!epsilon || *epsilon < 0)
            return usageError(spec, "--epsilon must be a distance in metres (0 or more), not '" + *epsilonText + "'");
        settings.epsilon = float(*epsilon);
    }
    if (exitCode != ExitOk)
        return exitCode;
    settings.transfer = *transfer;
    settings.backend = *backend;
    if (arguments.has("tags") && arguments.has("scenario"))
        return usageError(spec, "give the segment tags either with --tags or with --scenario, not both");
    if (arguments.has("character") && !arguments.has("scenario") && characterPath.extension() != ".thespis")
        return usageError(spec, "--character needs --scenario or a scenario CHARACTER");
    if (arguments.has("layout") && !arguments.has("probe"))
        return usageError(spec, "--layout needs --probe");
    if (auto valid = lighting::validateBakeSettings(settings); !valid)
        return usageError(spec, valid.error().message);
    const std::filesystem::path outDir = outPath.parent_path().empty() ? "." : outPath.parent_path();
    if (std::error_code ec; !std::filesystem::is_directory(outDir, ec)) {
        printError(spec.name, "cannot write " + outPath.string() + ": the folder " + outDir.string() + " does not exist.");
        return ExitInvalidInput;
    }

    const bool fromScenario = core::scenario::isScenarioFile(characterPath);
    if (fromScenario && (arguments.has("scenario") || arguments.has("no-split")))
        return usageError(spec, "a scenario CHARACTER brings its own tags and segments: leave out --scenario and --no-split");
    const core::scenario::BakeCharacter source{characterPath, arguments.value("character").value_or(""),
                                               arguments.value("tags").value_or(""),
                                               arguments.value("scenario").value_or(""), !arguments.has("no-split")};
    auto mesh = core::scenario::loadBakeCharacter(source);
    if (!mesh) {
        printError(spec.name, mesh.error());
        return ExitInvalidInput;
    }
    std::optional<lighting::ShRgb> light;
    if (const auto probePath = arguments.value("probe")) {
        auto projected = lighting::projectProbeFile(*probePath, *layout, settings.order);
        if (!projected) {
            printError(spec.name, projected.error());
            return ExitInvalidInput;
        }
        light = *projected;
    }

    // The local bake, or the same bake on a Dask cluster: one job or the other, the same file.
    lighting::TransferBakeJob localJob;
    localJob.mesh = *mesh;
    localJob.settings = settings;
    localJob.output = outPath;
    core::Job* job = &localJob;
    const std::optional<lighting::TransferBake>* bake = &localJob.bake;
    const lighting::BakeStatistics* statistics = &localJob.statistics;
#ifdef THESPIS_WITH_PYTHON
    script::FarmBakeJob farmJob;
    if (scheduler) {
        farmJob.scheduler = *scheduler;
        farmJob.character = source;
        farmJob.settings = settings;
        farmJob.output = outPath;
        job = &farmJob;
        bake = &farmJob.bake;
        statistics = &farmJob.statistics;
    }
#endif
    const auto baked = runJobWithProgress(spec.name, *job, {"", "vertices", long(mesh->vertexCount())}, quiet,
                                          outPath.string() + " was not written");
    if (!baked) {
        if (baked.error().code == core::ErrorCode::Cancelled)
            return ExitCancelled;
        printError(spec.name, baked.error());
        return baked.error().code == core::ErrorCode::FileNotFound ? ExitInvalidInput : ExitFailure;
    }
    if (quiet)
        return ExitOk;

    std::size_t segmentsBaked = 0;
    for (const auto& segment : (*bake)->segments)
        segmentsBaked += segment.baked ? 1 : 0;
    std::printf("Baked %s transfer of %s: %zu vertices, %zu triangles, %zu of %zu segments, order %d (%d coefficients).\n",
                lighting::transferKindName(settings.transfer), characterPath.filename().string().c_str(),
                mesh->vertexCount(), mesh->triangleCount(), segmentsBaked, (*bake)->segments.size(), settings.order,
                settings.order * settings.order);
    const double mrays = statistics->seconds > 0 ? double(statistics->rays) / statistics->seconds / 1e6 : 0.0;
    std::printf("%llu rays (%d per vertex, %s%s) in %.2f s: %.1f Mrays/s. Written to %s.\n",
                static_cast<unsigned long long>(statistics->rays), settings.raysPerVertex,
                lighting::occlusionBackendName(settings.backend),
                scheduler ? (", on the Dask cluster at " + *scheduler).c_str() : "", statistics->seconds, mrays,
                outPath.string().c_str());
    if (light) {
        // The luminance of every baked vertex in the bind pose under the probe: a quick check
        // that the bake and the light fit (no negative or absurd values).
        double least = HUGE_VAL, most = -HUGE_VAL, sum = 0;
        std::size_t count = 0;
        for (const auto& segment : mesh->segments)
            for (std::uint32_t v = segment.firstVertex; v < segment.firstVertex + segment.vertexCount; ++v) {
                if ((*bake)->vertexTransfer(v).empty())
                    continue;
                const auto rgb = lighting::shadeVertex(**bake, *mesh, v, *light, segment.bindRotation);
                const double luminance = 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2];
                least = std::min(least, luminance);
                most = std::max(most, luminance);
                sum += luminance;
                ++count;
            }
        if (count > 0)
            std::printf("Under %s: vertex luminance %.4g to %.4g, mean %.4g.\n",
                        std::filesystem::path(*arguments.value("probe")).filename().string().c_str(), least, most,
                        sum / double(count));
    }
    return ExitOk;
}

} // namespace thespis::cli
