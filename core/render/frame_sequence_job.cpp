#include "render/frame_sequence_job.h"

#include <cmath>
#include <system_error>

namespace thespis::core::render {

std::string FrameSequenceJob::title() const
{
    return "The rendering of frames " + std::to_string(first) + " to " + std::to_string(last) + " into "
           + folder.string();
}

Result<void> FrameSequenceJob::validate() const
{
    if (first < 0 || last < first)
        return makeError(ErrorCode::InvalidArgument, "The frames must be FIRST:LAST with 0 ≤ FIRST ≤ LAST, not "
                                                         + std::to_string(first) + ":" + std::to_string(last) + ".");
    if (!(fps > 0) || !std::isfinite(fps))
        return makeError(ErrorCode::InvalidArgument, "fps must be a positive number.");
    if (folder.empty())
        return makeError(ErrorCode::InvalidArgument, "The frames have no folder to go into.");
    return {};
}

Result<void> FrameSequenceJob::run(JobContext& context)
{
    m_written.clear();
    context.beginStage(PreparingStage);
    if (std::error_code ec; !std::filesystem::is_directory(folder, ec) && !std::filesystem::create_directories(folder, ec))
        return makeError(ErrorCode::IoError, "Cannot create the folder " + folder.string() + ": " + ec.message() + ".");
    auto made = ScenarioPicture::create(scenario, assets, picture);
    if (!made)
        return made.error();
    ScenarioPicture& scene = **made;
    warnings = scene.scene().warnings();
    glDescription = scene.glDescription();

    context.beginStage(FramesStage, std::uint64_t(last - first + 1));
    for (long frame = first; frame <= last; ++frame) {
        if (context.stopRequested()) {
            discardOutput();
            return cancelledError(title());
        }
        scene.playAt(secondsToTicks(double(frame) / fps));
        const std::filesystem::path file = folder / frameFileName(frame);
        if (auto written = scene.writePng(file); !written) {
            discardOutput();
            return written;
        }
        m_written.push_back(file);
        context.setDone(std::uint64_t(frame - first + 1));
    }
    return {};
}

void FrameSequenceJob::discardOutput()
{
    for (const std::filesystem::path& file : m_written) {
        std::error_code ignored;
        std::filesystem::remove(file, ignored);
    }
    m_written.clear();
}

} // namespace thespis::core::render
