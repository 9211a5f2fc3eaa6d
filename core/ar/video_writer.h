#pragma once
// Frames written as a video file (FFmpeg through OpenCV's VideoWriter): H.264 in .mp4 when the
// system's FFmpeg has an encoder for it, else MPEG-4 part 2; Motion JPEG in .avi. The file is
// written beside its final name and renamed when finished, so a crash or a cancel leaves no
// half-written video behind.

#include <filesystem>
#include <memory>

#include "ar/video_frame.h"
#include "util/error.h"

namespace thespis::core::ar {

class VideoWriter {
public:
    /// Errors: an extension other than .mp4 / .avi, a folder that cannot be written, sizes or
    /// a frame rate that are not positive.
    static Result<std::unique_ptr<VideoWriter>> create(const std::filesystem::path& path, int width, int height,
                                                       double fps);
    /// Removes the unfinished file unless finish() succeeded.
    ~VideoWriter();

    /// Errors: a frame of another size.
    Result<void> write(const VideoFrame& frame);
    /// Closes the file and gives it its name.
    Result<void> finish();

    const std::filesystem::path& path() const { return m_path; }
    std::int64_t frames() const { return m_frames; }

private:
    struct State;
    VideoWriter(std::unique_ptr<State> state, std::filesystem::path path);
    std::unique_ptr<State> m_state;
    std::filesystem::path m_path;
    std::int64_t m_frames = 0;
};

} // namespace thespis::core::ar
