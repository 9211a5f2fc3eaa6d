#include "lighting/transfer_bake_job.h"

#include <system_error>

namespace thespis::core::lighting {

std::string TransferBakeJob::title() const
{
    return output.empty() ? std::string("The transfer bake") : "The transfer bake into " + output.string();
}

Result<void> TransferBakeJob::validate() const
{
    if (auto valid = validateBakeSettings(settings); !valid)
        return valid;
    return mesh.validate();
}

Result<void> TransferBakeJob::run(JobContext& context)
{
    bake.reset();
    context.beginStage("Baking transfer", mesh.vertexCount());
    auto baked = bakeTransfer(
        mesh, settings, context.stopToken(),
        [&context](const BakeProgress& progress) { context.setDone(progress.verticesDone); }, &statistics);
    if (!baked)
        return baked.error().code == ErrorCode::Cancelled ? cancelledError(title()) : baked.error();
    if (context.stopRequested())
        return cancelledError(title());
    if (!output.empty())
        if (auto written = writeBakeFile(output, *baked); !written)
            return written; // written atomically: nothing is left behind
    bake = std::move(baked).value();
    return {};
}

void TransferBakeJob::discardOutput()
{
    bake.reset();
    if (!output.empty()) {
        std::error_code ignored;
        std::filesystem::remove(output, ignored);
    }
}

} // namespace thespis::core::lighting
