#pragma once
// Private to core/scenario (and its tests): the upgrade steps that migrate older scenario
// documents to the current version before they are parsed (STYLE.md §7). Each step takes the
// JSON of version N to version N + 1; they run in order, so a file of any older version reaches
// format::Current. Raising format::Current means adding a step in the same change.

#include <span>

#include <nlohmann/json.hpp>

#include "util/error.h"

namespace thespis::core::scenario::detail {

struct UpgradeStep {
    int from = 0;             ///< upgrades a document of this version to version from + 1
    const char* name = "";    ///< what changed, for error messages ("joint mask weights")
    Result<void> (*apply)(nlohmann::json& document) = nullptr;
};

/// The steps this build knows, ordered by `from`.
std::span<const UpgradeStep> upgradeSteps();

/// Runs the steps taking `document` from `fromVersion` to `toVersion`, in order, writing the
/// new "version" after each. Errors: a missing step (Internal), a failing step (CorruptData,
/// naming the step). Exceptions thrown by a step's JSON access are turned into errors.
Result<void> runUpgradeSteps(nlohmann::json& document, int fromVersion, int toVersion,
                             std::span<const UpgradeStep> steps);

} // namespace thespis::core::scenario::detail
