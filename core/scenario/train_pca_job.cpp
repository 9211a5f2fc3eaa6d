#include "scenario/train_pca_job.h"

#include <cmath>

#include "motion/idle_builder.h"
#include "scenario/posture_clip.h"

namespace thespis::core::scenario {

std::string TrainPcaJob::title() const
{
    return "The posture PCA of " + std::to_string(sources.size()) + (sources.size() == 1 ? " clip" : " clips");
}

Result<void> TrainPcaJob::validate() const
{
    if (sources.empty())
        return makeError(ErrorCode::InvalidArgument, "Give at least one clip to train the posture PCA on.");
    if (!(sampleRate > 0) || !std::isfinite(sampleRate))
        return makeError(ErrorCode::InvalidArgument, "The sample rate must be a positive number of frames per second.");
    for (const PostureSource& source : sources)
        if (!(source.skip >= 0) || !std::isfinite(source.skip))
            return makeError(ErrorCode::InvalidArgument,
                             "The time skipped at the start of " + source.clip.file + " must not be negative.");
    if (output.extension() != ".pca")
        return makeError(ErrorCode::InvalidArgument, "The output must be a .pca file, not " + output.string() + ".");
    return {};
}

Result<void> TrainPcaJob::run(JobContext& context)
{
    auto read = readPostureSources(sources, assets, sampleRate, context, ReadingStage, title());
    if (!read)
        return read.error();
    std::vector<float> postures;
    for (const std::vector<float>& more : *read)
        postures.insert(postures.end(), more.begin(), more.end());
    context.beginStage(AnalysingStage);
    if (context.stopRequested())
        return cancelledError(title());
    frameCount = long(postures.size() / std::size_t(motion::PostureLayout::of(motion::PostureSet::WholeBody).size()));
    auto whole = motion::PostureBasis::train(motion::PostureSet::WholeBody, postures);
    if (!whole)
        return whole.error();
    auto upper = motion::PostureBasis::train(motion::PostureSet::UpperBody, motion::upperBodyOf(postures));
    if (!upper)
        return upper.error();
    bases = {std::move(whole).value(), std::move(upper).value()};
    if (context.stopRequested())
        return cancelledError(title());
    return motion::writePostureBasesFile(output, bases);
}

void TrainPcaJob::discardOutput()
{
    std::error_code ignored;
    std::filesystem::remove(output, ignored);
}

} // namespace thespis::core::scenario
