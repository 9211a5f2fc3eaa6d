// Exporting a scenario package (package_export_job.h).

#include "scenario/package_export_job.h"

#include <memory>
#include <vector>

#include "scenario/package_bakes.h"
#include "scenario/package_zip.h"
#include "scenario/scenario_io.h"
#include "util/file_io.h"
#include "util/sha256.h"

namespace thespis::core::scenario {

namespace {

/// What libzip's progress and cancel callbacks see while zip_close() writes.
struct Writing {
    JobContext* context = nullptr;
    std::uint64_t bytes = 0; ///< the stage's total: libzip reports a fraction of it
};

} // namespace

std::string ExportPackageJob::title() const
{
    return "The package " + output.filename().string();
}

Result<void> ExportPackageJob::validate() const
{
    if (output.empty())
        return makeError(ErrorCode::InvalidArgument, "The package's output file is not set.");
    if (auto allowed = checkEntryName(scenarioEntry); !allowed)
        return makeError(ErrorCode::InvalidArgument, "The scenario's name in the package: " + allowed.error().message);
    return {};
}

Result<void> ExportPackageJob::run(JobContext& context)
{
    baked.clear();
    std::vector<PackageBake> bakes;
    if (bakeLighting) {
        auto made = makePackageBakes(scenario, assets, bakeSettings, context, BakeStage);
        if (!made)
            return made.error().code == ErrorCode::Cancelled ? cancelledError(title()) : made.error();
        bakes = std::move(made).value();
    }
    Scenario packed = scenario;
    for (const PackageBake& bake : bakes)
        packed.characters[bake.character].bake.clear(); // the old one stays out
    auto planned = planPackage(packed, assets, scenarioEntry);
    if (!planned)
        return planned.error();
    plan = std::move(planned).value();
    for (PackageBake& bake : bakes) {
        Character& character = plan.scenario.characters[bake.character];
        character.bake = addMadeFile(plan, "bakes/" + character.name + ".prt", "characters[" + character.name + "].bake",
                                     std::move(bake.bytes));
        baked.push_back(character.name + ": " + bake.reason);
    }

    // Every entry's bytes are read once, hashed and handed to libzip as they are: what the
    // manifest says is what the package holds, even if a file changes meanwhile.
    context.beginStage(ReadStage, plan.files.size() + 1);
    std::vector<std::string> contents;
    contents.reserve(plan.files.size() + 2);
    const std::string document = serializeScenario(plan.scenario);
    if (auto check = parseScenario(document); !check)
        return makeError(ErrorCode::InvalidArgument, "The scenario cannot be exported: " + check.error().message);
    manifest = {};
    manifest.writer = std::string("Thespis ") + THESPIS_VERSION;
    manifest.scenario = plan.scenarioEntry;
    contents.push_back(document);
    manifest.entries.push_back({plan.scenarioEntry, document.size(), sha256Hex(document)});
    context.setDone(1);
    for (const PackageFile& file : plan.files) {
        if (context.stopRequested())
            return cancelledError(title());
        auto bytes = file.source.empty() ? Result<std::string>(file.content) : readTextFile(file.source);
        if (!bytes)
            return makeError(bytes.error().code, file.usedBy + ": " + bytes.error().message, bytes.error().detail);
        manifest.entries.push_back({file.name, bytes->size(), sha256Hex(*bytes)});
        contents.push_back(std::move(bytes).value());
        context.setDone(contents.size());
    }
    const std::string manifestText = serializeManifest(manifest);

    int openError = 0;
    detail::ZipArchive archive(zip_open(output.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &openError));
    if (!archive) {
        return makeError(ErrorCode::IoError,
                         "Cannot write the package " + output.string() + ": " + detail::zipOpenError(openError) + ".");
    }
    const auto failed = [&](const std::string& what) {
        return makeError(ErrorCode::IoError, "Writing the package " + output.string() + " failed at " + what + ": "
                                                 + zip_error_strerror(zip_get_error(archive.get())) + ".");
    };
    const auto addEntry = [&](const std::string& name, const std::string& bytes) -> Result<void> {
        zip_source_t* source = zip_source_buffer(archive.get(), bytes.data(), bytes.size(), 0);
        if (!source)
            return failed(name);
        const zip_int64_t index = zip_file_add(archive.get(), name.c_str(), source, ZIP_FL_ENC_UTF_8);
        if (index < 0) {
            zip_source_free(source);
            return failed(name);
        }
        return {};
    };
    if (auto added = addEntry(std::string(kManifestName), manifestText); !added)
        return added.error();
    for (std::size_t i = 0; i < contents.size(); ++i)
        if (auto added = addEntry(manifest.entries[i].name, contents[i]); !added)
            return added.error();

    contentBytes = manifestText.size();
    for (const PackageEntry& entry : manifest.entries)
        contentBytes += entry.size;
    context.beginStage(WriteStage, contentBytes);
    Writing writing{&context, contentBytes};
    zip_register_progress_callback_with_state(
        archive.get(), 0.001,
        [](zip_t*, double done, void* state) {
            auto* w = static_cast<Writing*>(state);
            w->context->setDone(std::uint64_t(done * double(w->bytes)));
        },
        nullptr, &writing);
    zip_register_cancel_callback_with_state(
        archive.get(), [](zip_t*, void* state) { return static_cast<Writing*>(state)->context->stopRequested() ? 1 : 0; },
        nullptr, &writing);
    if (zip_close(archive.get()) != 0) {
        if (context.stopRequested())
            return cancelledError(title());
        return failed("the end");
    }
    (void)archive.release(); // zip_close freed it
    std::error_code error;
    packageBytes = std::filesystem::file_size(output, error);
    return {};
}

void ExportPackageJob::discardOutput()
{
    std::error_code error;
    std::filesystem::remove(output, error);
}

} // namespace thespis::core::scenario
