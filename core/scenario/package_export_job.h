#pragma once
// Exporting a scenario package as a job (util/job.h): the scenario and every file it names
// (package_contents.h) in one zip, the characters' lighting bakes made or refreshed first when
// asked (package_bakes.h), manifest.json first with the size and SHA-256 of every other
// entry (package_manifest.h). Written with libzip, which builds the archive beside the output
// and renames it into place when complete: a cancelled or failed export leaves the old package
// as it was. `thespis-cli export`, Python and the studio's File ▸ Export Package… run it.

#include <cstdint>
#include <filesystem>
#include <string>

#include <vector>

#include "lighting/transfer_bake.h"
#include "scenario/asset_resolver.h"
#include "scenario/package_contents.h"
#include "scenario/package_manifest.h"
#include "scenario/scenario.h"
#include "util/job.h"

namespace thespis::core::scenario {

struct ExportPackageJob final : Job {
    static constexpr const char* BakeStage = "Baking lighting"; ///< counts vertices
    static constexpr const char* ReadStage = "Reading the scenario's files";
    static constexpr const char* WriteStage = "Writing the package"; ///< counts the entries' bytes

    Scenario scenario;
    Assets assets;                              ///< where the scenario's files are found
    std::string scenarioEntry = "scenario.thespis"; ///< the scenario's name in the package
    std::filesystem::path output;               ///< the package (.thespkg)
    /// Bake every character whose bake is missing or no longer fits, into the package only.
    bool bakeLighting = false;
    lighting::BakeSettings bakeSettings;        ///< for characters that had no bake

    // After run():
    std::vector<std::string> baked;             ///< "Creon: it had none", one per bake made
    PackagePlan plan;
    PackageManifest manifest;
    std::uint64_t contentBytes = 0; ///< the entries' sizes, the manifest's included
    std::uint64_t packageBytes = 0; ///< the zip's size on disk

    std::string title() const override;
    Result<void> validate() const override;
    Result<void> run(JobContext& context) override;
    void discardOutput() override;
};

} // namespace thespis::core::scenario
