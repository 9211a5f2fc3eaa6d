// thespis-cli bake: the PRT transfer bake of a glTF character or of a scenario's character (its
// model or the built-in humanoid; paper §6), written as a bake file. Segment tags come from a
// tags file or from a scenario's character. The bake runs on worker
// threads while this thread draws the progress bar and watches for Ctrl-C, which cancels the
// bake: nothing is written then (the bake file is written atomically at the very end).

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
#include "scenario/scenario_character.h"
#include "scene/gltf_mesh.h"

namespace thespis::cli {
namespace {

namespace lighting = core::lighting;
namespace scene = core::scene;

/// The scenario's character named by --character, or its only one; prints the problem and
/// returns nothing when there is no such character.
const core::scenario::Character* chooseCharacter(const CommandSpec& spec, const ParsedArguments& arguments,
                                                 const core::scenario::Scenario& document)
{
    const auto characterName = arguments.value("character");
    const core::scenario::Character* character = nullptr;
    if (characterName) {
        character = document.findCharacter(*characterName);
    } else if (document.characters.size() == 1) {
        character = &document.characters.front();
    }
    if (!character) {
        std::vector<std::string> names;
        for (const auto& c : document.characters)
            names.push_back(c.name);
        printError(spec.name, (characterName ? "the scenario has no character named '" + *characterName + "'"
                                             : std::string("the scenario has several characters; name one with --character"))
                                  + " (its characters: " + joinNames(names) + ").");
    }
    return character;
}

/// Tags from --tags FILE, or from the scenario character's segment tags.
std::optional<std::vector<scene::SegmentTag>> loadTags(const CommandSpec& spec, const ParsedArguments& arguments,
                                                       int& exitCode)
{
    if (const auto tagsFile = arguments.value("tags")) {
        auto tags = scene::readSegmentTagsFile(*tagsFile);
        if (!tags) {
            printError(spec.name, tags.error());
            exitCode = ExitInvalidInput;
            return std::nullopt;
        }
        return std::move(tags).value();
    }
    const auto scenarioFile = arguments.value("scenario");
    if (!scenarioFile)
        return std::vector<scene::SegmentTag>{};
    const auto document = loadScenarioReporting(spec.name, *scenarioFile);
    const core::scenario::Character* character = document ? chooseCharacter(spec, arguments, *document) : nullptr;
    if (!character) {
        exitCode = ExitInvalidInput;
        return std::nullopt;
    }
    return character->segmentTags;
}

/// The mesh to bake, or nothing (the problem printed): a glTF file's mesh, or the body of a
/// scenario's character (its glTF model or the built-in humanoid, with the scenario's tags) —
/// the very mesh `thespis-cli render` and the studio draw, so the bake fits them.
std::optional<scene::CharacterMesh> loadCharacterMesh(const CommandSpec& spec, const ParsedArguments& arguments,
                                                      const std::filesystem::path& path)
{
    if (path.extension() != ".thespis") {
        scene::GltfMeshOptions meshOptions;
        meshOptions.splitSkinnedByJoint = !arguments.has("no-split");
        auto mesh = scene::loadGltfMesh(path, meshOptions);
        if (!mesh) {
            printError(spec.name, mesh.error());
            return std::nullopt;
        }
        return std::move(mesh).value();
    }
    const auto document = loadScenarioReporting(spec.name, path);
    const core::scenario::Character* character = document ? chooseCharacter(spec, arguments, *document) : nullptr;
    if (!character)
        return std::nullopt;
    auto body = core::scenario::loadCharacterBody(*document, std::size_t(character - document->characters.data()),
                                                  core::scenario::Assets::besideFile(path));
    if (!body) {
        printError(spec.name, body.error());
        return std::nullopt;
    }
    return std::move(body->mesh);
}

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
        {"quiet", "", "no progress and no summary"},
    };
    spec.description =
        "CHARACTER is a .gltf/.glb file or a .thespis scenario: then its character's body (its model, or the\n"
        "built-in humanoid) is baked with the scenario's tags, ready for 'thespis-cli render --bake'.\n"
        "Segments are the glTF's mesh nodes, and a skinned mesh is split by dominant joint. With DSM a\n"
        "segment tagged receiver is transparent to rays and an occluder is not baked (paper §6.1.3).\n"
        "The summary gives vertices, rays, seconds and Mrays/s. Ctrl-C stops the bake without writing.\n"
        "Exit status: 0 written, 2 bad command line, 3 unreadable character, tags or probe,\n"
        "4 the bake or the file failed, 130 cancelled.";
    return spec;
}

int runBake(const CommandSpec& spec, const ParsedArguments& arguments)
{
    const std::filesystem::path characterPath = arguments.positionals[0];
    const std::filesystem::path outPath = *arguments.value("out");
    const bool quiet = arguments.has("quiet");

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

    const bool fromScenario = characterPath.extension() == ".thespis";
    if (fromScenario && (arguments.has("scenario") || arguments.has("no-split")))
        return usageError(spec, "a scenario CHARACTER brings its own tags and segments: leave out --scenario and --no-split");
    auto mesh = loadCharacterMesh(spec, arguments, characterPath);
    if (!mesh)
        return ExitInvalidInput;
    const auto tags = loadTags(spec, arguments, exitCode);
    if (!tags)
        return exitCode;
    if (auto applied = scene::applySegmentTags(*mesh, *tags); !applied) {
        printError(spec.name, applied.error());
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

    lighting::TransferBakeJob job;
    job.mesh = *mesh;
    job.settings = settings;
    job.output = outPath;
    const auto baked = runJobWithProgress(spec.name, job, {"", "vertices", long(mesh->vertexCount())}, quiet,
                                          outPath.string() + " was not written");
    if (!baked) {
        if (baked.error().code == core::ErrorCode::Cancelled)
            return ExitCancelled;
        printError(spec.name, baked.error());
        return ExitFailure;
    }
    const lighting::TransferBake* bake = &*job.bake;
    const lighting::BakeStatistics& statistics = job.statistics;
    if (quiet)
        return ExitOk;

    std::size_t segmentsBaked = 0;
    for (const auto& segment : bake->segments)
        segmentsBaked += segment.baked ? 1 : 0;
    std::printf("Baked %s transfer of %s: %zu vertices, %zu triangles, %zu of %zu segments, order %d (%d coefficients).\n",
                lighting::transferKindName(settings.transfer), characterPath.filename().string().c_str(),
                mesh->vertexCount(), mesh->triangleCount(), segmentsBaked, bake->segments.size(), settings.order,
                settings.order * settings.order);
    const double mrays = statistics.seconds > 0 ? double(statistics.rays) / statistics.seconds / 1e6 : 0.0;
    std::printf("%llu rays (%d per vertex, %s) in %.2f s: %.1f Mrays/s. Written to %s.\n",
                static_cast<unsigned long long>(statistics.rays), settings.raysPerVertex,
                lighting::occlusionBackendName(settings.backend), statistics.seconds, mrays, outPath.string().c_str());
    if (light) {
        // The luminance of every baked vertex in the bind pose under the probe: a quick check
        // that the bake and the light fit (no negative or absurd values).
        double least = HUGE_VAL, most = -HUGE_VAL, sum = 0;
        std::size_t count = 0;
        for (const auto& segment : mesh->segments)
            for (std::uint32_t v = segment.firstVertex; v < segment.firstVertex + segment.vertexCount; ++v) {
                if (bake->vertexTransfer(v).empty())
                    continue;
                const auto rgb = lighting::shadeVertex(*bake, *mesh, v, *light, segment.bindRotation);
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
