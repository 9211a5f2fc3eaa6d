#pragma once
// Reading a light probe and projecting it onto spherical harmonics, as a job (util/job.h): the
// studio's Lighting dialog runs it off the GUI thread, the scenario scene and the CLI run it in
// place, Python through thespis.lighting.project_probe. Writes no file.

#include <filesystem>
#include <optional>

#include "lighting/probe.h"
#include "util/job.h"

namespace thespis::core::lighting {

struct ProbeProjectionJob final : Job {
    std::filesystem::path path;
    ProbeLayout layout = ProbeLayout::LatLong;
    int order = 3;
    int threads = 0; ///< ProbeProjector::project's

    std::optional<LightProbe> probe; ///< after run(): the probe as read
    ShRgb light;                     ///< after run(): its radiance coefficients

    std::string title() const override;
    /// The order (1 to kMaxShOrder) and a path.
    Result<void> validate() const override;
    Result<void> run(JobContext& context) override;
};

/// One-shot, on this thread: read a probe file and project it.
Result<ShRgb> projectProbeFile(const std::filesystem::path& path, ProbeLayout layout, int order);

} // namespace thespis::core::lighting
