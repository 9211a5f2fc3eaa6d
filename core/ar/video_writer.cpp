#include "ar/video_writer.h"

#include <opencv2/videoio.hpp>

#include "ar/opencv_bridge.h"

namespace thespis::core::ar {

struct VideoWriter::State {
    cv::VideoWriter writer;
    std::filesystem::path partial;
    int width = 0, height = 0;
    bool finished = false;
};

VideoWriter::VideoWriter(std::unique_ptr<State> state, std::filesystem::path path)
    : m_state(std::move(state)), m_path(std::move(path))
{
}

VideoWriter::~VideoWriter()
{
    if (!m_state->finished) {
        m_state->writer.release();
        std::error_code ignored;
        std::filesystem::remove(m_state->partial, ignored);
    }
}

Result<std::unique_ptr<VideoWriter>> VideoWriter::create(const std::filesystem::path& path, int width, int height,
                                                         double fps)
{
    const std::string extension = path.extension().string();
    if (extension != ".mp4" && extension != ".avi")
        return makeError(ErrorCode::InvalidArgument, path.string() + ": videos are written as .mp4 or .avi");
    if (width <= 0 || height <= 0 || !(fps > 0))
        return makeError(ErrorCode::InvalidArgument, path.string() + ": a video needs a size and a frame rate");
    auto state = std::make_unique<State>();
    state->partial = path;
    state->partial.replace_filename(path.stem().string() + ".partial" + extension);
    state->width = width;
    state->height = height;
    const cv::Size size(width, height);
    try {
        if (extension == ".avi") {
            state->writer.open(state->partial.string(), cv::CAP_FFMPEG, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), fps, size);
        } else {
            state->writer.open(state->partial.string(), cv::CAP_FFMPEG, cv::VideoWriter::fourcc('a', 'v', 'c', '1'), fps, size);
            if (!state->writer.isOpened())
                state->writer.open(state->partial.string(), cv::CAP_FFMPEG, cv::VideoWriter::fourcc('m', 'p', '4', 'v'), fps,
                                   size);
        }
    } catch (const cv::Exception&) {
    }
    if (!state->writer.isOpened())
        return makeError(ErrorCode::IoError, path.string() + ": cannot be written (is the folder there and writable?)");
    return std::unique_ptr<VideoWriter>(new VideoWriter(std::move(state), path));
}

Result<void> VideoWriter::write(const VideoFrame& frame)
{
    if (frame.width != m_state->width || frame.height != m_state->height)
        return makeError(ErrorCode::InvalidArgument, m_path.string() + ": a " + std::to_string(frame.width) + " × " +
                                                         std::to_string(frame.height) + " frame in a " +
                                                         std::to_string(m_state->width) + " × " +
                                                         std::to_string(m_state->height) + " video");
    m_state->writer.write(bgrMat(frame));
    ++m_frames;
    return {};
}

Result<void> VideoWriter::finish()
{
    m_state->writer.release();
    std::error_code error;
    std::filesystem::rename(m_state->partial, m_path, error);
    if (error)
        return makeError(ErrorCode::IoError, m_path.string() + ": " + error.message());
    m_state->finished = true;
    return {};
}

} // namespace thespis::core::ar
