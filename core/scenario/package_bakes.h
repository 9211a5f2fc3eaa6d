#pragma once
// Lighting bakes made or refreshed for a package (ExportPackageJob::bakeLighting): every character
// whose bake is missing, unreadable or no longer fits its body (its tags or model changed since)
// is baked again — with the settings of the bake it replaces, else the ones given — so that the
// package lights every character as the studio would after a fresh bake. The bakes go into the
// package only; the scenario's own folder is not touched.

#include <cstdint>
#include <string>
#include <vector>

#include "lighting/transfer_bake.h"
#include "scenario/asset_resolver.h"
#include "scenario/scenario.h"
#include "util/job.h"

namespace thespis::core::scenario {

struct PackageBake {
    std::size_t character = 0; ///< index in the scenario
    std::string bytes;         ///< the bake file
    std::string reason;        ///< why it was baked: "it had none", "its bake no longer fits: …"
};

/// Bakes what needs it, reporting vertices under `stage`; stops with Cancelled when asked.
/// Errors: a character's body cannot be loaded (naming it), invalid settings.
Result<std::vector<PackageBake>> makePackageBakes(const Scenario& scenario, const Assets& assets,
                                                  const lighting::BakeSettings& settings, JobContext& context,
                                                  const char* stage);

} // namespace thespis::core::scenario
