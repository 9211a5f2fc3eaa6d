#pragma once
// What goes into a scenario package: every file the scenario names (characters' models and bakes,
// clips' motion files, idle motion databases, the light probe, the posture bases, phantom
// occluders' models; a .gltf's buffers and images with it), each under the name the package's
// scenario will use. A relative name inside the scenario's folder stays as it is; any other
// (absolute, or reaching out with "..") moves to assets/<file name>. Scripts and the gesticon are
// part of the scenario document itself; the sounds and dialogue files a script names by a string
// literal (a voice's .wav, an AIML set) come along, and the script is rewritten to their entries.

#include <filesystem>
#include <string>
#include <vector>

#include "scenario/asset_resolver.h"
#include "scenario/scenario.h"
#include "util/error.h"

namespace thespis::core::scenario {

struct PackageFile {
    std::string name;             ///< its entry in the package
    std::filesystem::path source; ///< where it is read from; empty when made for the package
    std::string usedBy;           ///< the first field naming it ("characters[Creon].model")
    std::string content;          ///< the bytes of a file made for the package (a fresh bake)
};

/// The extensions of the files a script's string literals bring into a package.
bool isScriptMediaFile(const std::filesystem::path& file);

struct PackagePlan {
    Scenario scenario;               ///< with every file named as in the package
    std::string scenarioEntry;       ///< the scenario's own entry
    std::vector<PackageFile> files;  ///< the scenario's files, each once, in the order named
};

/// The package of `scenario`, whose files `assets` finds; its document goes in as `scenarioEntry`.
/// Errors: NotFound naming the field and the file for a file that is missing; CorruptData for a
/// .gltf that cannot be read or names a file outside its folder; InvalidArgument for a
/// scenarioEntry that checkEntryName refuses.
Result<PackagePlan> planPackage(const Scenario& scenario, const Assets& assets, const std::string& scenarioEntry);

/// Adds a file made for the package (`content`) as `preferred`, or a free name beside it; returns
/// the entry.
std::string addMadeFile(PackagePlan& plan, const std::string& preferred, const std::string& usedBy, std::string content);

} // namespace thespis::core::scenario
