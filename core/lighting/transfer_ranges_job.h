#pragma once
// Part of a transfer bake as a job (util/job.h): the vertex ranges a farm worker was handed
// (thespis.farm through thespis.lighting.bake_ranges). Their floats stay in memory for the caller,
// who places them into the bake's plan (placeTransferRange); nothing is written.

#include <vector>

#include "lighting/transfer_bake.h"
#include "scene/character_mesh.h"
#include "util/job.h"

namespace thespis::core::lighting {

struct TransferRangesJob final : Job {
    scene::CharacterMesh mesh;
    BakeSettings settings;
    std::vector<VertexRange> ranges;

    std::vector<float> transfer; ///< after run(): order² floats per vertex, range after range
    BakeStatistics statistics;   ///< after run()

    std::string title() const override;
    /// The settings (validateBakeSettings), the mesh (it must validate) and at least one range
    /// (each range is checked against the mesh's segments when the bake starts).
    Result<void> validate() const override;
    Result<void> run(JobContext& context) override;
};

} // namespace thespis::core::lighting
