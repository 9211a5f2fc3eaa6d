#include "lighting/probe_projection_job.h"

namespace thespis::core::lighting {

std::string ProbeProjectionJob::title() const
{
    return "The projection of the probe " + path.filename().string();
}

Result<void> ProbeProjectionJob::validate() const
{
    if (order < 1 || order > kMaxShOrder)
        return makeError(ErrorCode::InvalidArgument, "order must be 1 to " + std::to_string(kMaxShOrder) + ", not "
                                                         + std::to_string(order) + ".");
    if (path.empty())
        return makeError(ErrorCode::InvalidArgument, "The probe projection has no file to read.");
    return {};
}

Result<void> ProbeProjectionJob::run(JobContext& context)
{
    probe.reset();
    context.beginStage("Reading the probe", 1);
    auto read = LightProbe::load(path, layout);
    if (!read)
        return read.error();
    if (context.stopRequested())
        return cancelledError(title());
    context.beginStage("Projecting onto spherical harmonics", 1);
    auto projector = ProbeProjector::create(layout, read->image().width, read->image().height, order);
    if (!projector)
        return projector.error();
    auto projected = projector->project(read->image(), context.stopToken(), threads);
    if (!projected)
        return projected.error().code == ErrorCode::Cancelled ? cancelledError(title()) : projected.error();
    light = *projected;
    probe = std::move(read).value();
    context.setDone(1);
    return {};
}

Result<ShRgb> projectProbeFile(const std::filesystem::path& path, ProbeLayout layout, int order)
{
    ProbeProjectionJob job;
    job.path = path;
    job.layout = layout;
    job.order = order;
    if (auto valid = job.validate(); !valid)
        return valid.error();
    JobContext context;
    if (auto done = job.run(context); !done)
        return done.error();
    return job.light;
}

} // namespace thespis::core::lighting
