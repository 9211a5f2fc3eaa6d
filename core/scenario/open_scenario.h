#pragma once
// Opening what users open: a scenario file (.thespis, whose files are found beside it) or a
// package (.thespkg: checked, played straight from the zip, names it does not hold found beside
// it). The CLI, the studio's Document and Python open scenarios through this one function.

#include <filesystem>
#include <memory>

#include "scenario/asset_resolver.h"
#include "scenario/package.h"
#include "scenario/scenario.h"
#include "util/error.h"

namespace thespis::core::scenario {

struct OpenedScenario {
    Scenario scenario;
    Assets assets;
    std::shared_ptr<const Package> package; ///< the package, when a package was opened
};

/// True for a package's file name (.thespkg).
bool isPackagePath(const std::filesystem::path& path);

/// Opens a scenario file or a package. Errors name the file (and, for a package, the entry).
Result<OpenedScenario> openScenario(const std::filesystem::path& path);

} // namespace thespis::core::scenario
