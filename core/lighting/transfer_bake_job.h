#pragma once
// The PRT transfer bake as a job (util/job.h): the CLI's `bake`, Python's thespis.lighting.bake
// and the studio's Bake panel all run this one. The bake itself spreads over settings.threads
// workers; progress is vertices baked. With an output path the bake file is written atomically
// at the very end, so a cancelled or failed bake leaves no file. The bake stays in `bake` for the
// caller either way.

#include <filesystem>
#include <optional>

#include "lighting/transfer_bake.h"
#include "scene/character_mesh.h"
#include "util/job.h"

namespace thespis::core::lighting {

struct TransferBakeJob final : Job {
    scene::CharacterMesh mesh;
    BakeSettings settings;
    std::filesystem::path output; ///< the bake file to write; empty keeps the bake in memory

    std::optional<TransferBake> bake; ///< after run()
    BakeStatistics statistics;        ///< after run()

    std::string title() const override;
    /// The settings (validateBakeSettings) and the mesh (it must validate).
    Result<void> validate() const override;
    Result<void> run(JobContext& context) override;
    void discardOutput() override;
};

} // namespace thespis::core::lighting
