#include "lighting/transfer_ranges_job.h"

namespace thespis::core::lighting {

std::string TransferRangesJob::title() const
{
    return "The transfer bake of " + std::to_string(ranges.size()) + " vertex range" + (ranges.size() == 1 ? "" : "s");
}

Result<void> TransferRangesJob::validate() const
{
    if (ranges.empty())
        return makeError(ErrorCode::InvalidArgument, "A partial transfer bake needs at least one vertex range.");
    if (auto valid = validateBakeSettings(settings); !valid)
        return valid;
    return mesh.validate();
}

Result<void> TransferRangesJob::run(JobContext& context)
{
    transfer.clear();
    std::uint64_t vertices = 0;
    for (const VertexRange& range : ranges)
        vertices += range.vertexCount;
    context.beginStage("Baking transfer", vertices);
    auto baked = bakeTransferRanges(
        mesh, settings, ranges, context.stopToken(),
        [&context](const BakeProgress& progress) { context.setDone(progress.verticesDone); }, &statistics);
    if (!baked)
        return baked.error().code == ErrorCode::Cancelled ? cancelledError(title()) : baked.error();
    transfer = std::move(baked).value();
    return {};
}

} // namespace thespis::core::lighting
