#pragma once
// FarmBakeJob: the transfer bake of `thespis-cli bake --scheduler`, run on a running Dask cluster
// by thespis.farm in the embedded interpreter (interpreter.h). It is a core job like
// TransferBakeJob, so a front end runs it the same way (progress, Ctrl-C) and gets the same
// result: the bake, equal bit for bit to the local one, written atomically with the same writer
// at the very end (a cancelled or failed bake leaves no file). Progress is baked vertices as the
// cluster's tasks finish; a cancel cancels every task on the cluster.

#include <filesystem>
#include <optional>
#include <string>

#include "lighting/transfer_bake.h"
#include "scenario/bake_character.h"
#include "util/job.h"

namespace thespis::script {

struct FarmBakeJob final : core::Job {
    std::string scheduler;                       ///< "tcp://HOST:PORT" of a running scheduler
    core::scenario::BakeCharacter character;     ///< each worker loads it itself, at the same path
    core::lighting::BakeSettings settings;       ///< threads: bake threads per task (0 → 1)
    std::filesystem::path output;                ///< the bake file to write; empty keeps it in memory

    std::optional<core::lighting::TransferBake> bake; ///< after run()
    core::lighting::BakeStatistics statistics;        ///< after run(): vertices, rays, seconds

    std::string title() const override;
    /// The settings (validateBakeSettings) and a scheduler address.
    core::Result<void> validate() const override;
    core::Result<void> run(core::JobContext& context) override;
    void discardOutput() override;
};

} // namespace thespis::script
