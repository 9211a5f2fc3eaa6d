#include "scenario/build_idle_job.h"

#include <cmath>

#include "scenario/posture_clip.h"

namespace thespis::core::scenario {

std::string BuildIdleJob::title() const
{
    return "The idle motion database " + output.filename().string();
}

Result<void> BuildIdleJob::validate() const
{
    if (sources.empty())
        return makeError(ErrorCode::InvalidArgument, "Give at least one standing recording to build an idle database from.");
    for (const PostureSource& source : sources)
        if (!(source.skip >= 0) || !std::isfinite(source.skip))
            return makeError(ErrorCode::InvalidArgument,
                             "The time skipped at the start of " + source.clip.file + " must not be negative.");
    if (output.extension() != ".idle")
        return makeError(ErrorCode::InvalidArgument, "The output must be an .idle file, not " + output.string() + ".");
    return {};
}

Result<void> BuildIdleJob::run(JobContext& context)
{
    if (!basesFile.empty()) {
        auto bases = motion::readPostureBasesFile(basesFile);
        if (!bases)
            return bases.error();
        options.bases = std::move(bases).value();
    }
    auto postures = readPostureSources(sources, assets, options.frameRate, context, ReadingStage, title());
    if (!postures)
        return postures.error();
    std::vector<motion::IdleRecording> recordings;
    for (std::size_t i = 0; i < sources.size(); ++i)
        recordings.push_back({std::filesystem::path(sources[i].clip.file).filename().string(), std::move((*postures)[i]), {}});
    context.beginStage(BuildingStage);
    auto built = motion::buildIdleDatabase(recordings, options, &report);
    if (!built)
        return built.error();
    database = std::move(built).value();
    if (context.stopRequested())
        return cancelledError(title());
    return motion::writeIdleDatabaseFile(output, database);
}

void BuildIdleJob::discardOutput()
{
    std::error_code ignored;
    std::filesystem::remove(output, ignored);
}

} // namespace thespis::core::scenario
