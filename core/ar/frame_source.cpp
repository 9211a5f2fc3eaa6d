#include "ar/frame_source.h"

#include <algorithm>
#include <fstream>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include "ar/opencv_bridge.h"
#include "util/file_io.h"

namespace thespis::core::ar {

namespace {

// Copies a decoded picture into the frame's (reused) buffer as 8-bit BGR.
void store(const cv::Mat& picture, VideoFrame& frame)
{
    frame.resize(picture.cols, picture.rows);
    cv::Mat target = bgrMat(frame);
    if (picture.channels() == 1)
        cv::cvtColor(picture, target, cv::COLOR_GRAY2BGR);
    else if (picture.channels() == 4)
        cv::cvtColor(picture, target, cv::COLOR_BGRA2BGR);
    else
        picture.copyTo(target);
    frame.captured = std::chrono::steady_clock::now();
}

class VideoCaptureSource final : public FrameSource {
public:
    VideoCaptureSource(cv::VideoCapture capture, std::string description, bool live)
        : m_capture(std::move(capture)), m_description(std::move(description)), m_live(live)
    {
    }
    std::string description() const override { return m_description; }
    double fps() const override { return m_capture.get(cv::CAP_PROP_FPS); }
    int width() const override { return int(m_capture.get(cv::CAP_PROP_FRAME_WIDTH)); }
    int height() const override { return int(m_capture.get(cv::CAP_PROP_FRAME_HEIGHT)); }
    std::int64_t frameCount() const override
    {
        return m_live ? -1 : std::int64_t(m_capture.get(cv::CAP_PROP_FRAME_COUNT));
    }

    Result<bool> read(VideoFrame& frame) override
    {
        if (!m_capture.grab()) {
            if (m_live)
                return makeError(ErrorCode::IoError, m_description + " stopped sending frames after frame " +
                                                    std::to_string(m_next) + " (unplugged or taken by another program?)");
            // A file whose first frame does not decode is broken; one that ends early simply ends
            // (containers' frame counts are estimates).
            if (m_next == 0)
                return makeError(ErrorCode::IoError, m_description + ": no frame can be decoded");
            return false;
        }
        if (!m_capture.retrieve(m_decoded) || m_decoded.empty())
            return makeError(ErrorCode::IoError, m_description + ": frame " + std::to_string(m_next) + " cannot be decoded");
        store(m_decoded, frame);
        frame.index = m_next++;
        if (m_live) {
            if (m_next == 1)
                m_start = frame.captured;
            frame.time = std::chrono::duration<double>(frame.captured - m_start).count();
        } else {
            // FFmpeg's position reads 0 at the last frames of some files: the frame rate goes on then.
            frame.time = m_capture.get(cv::CAP_PROP_POS_MSEC) / 1000.0;
            if (m_next > 1 && frame.time <= m_lastTime)
                frame.time = m_lastTime + 1.0 / (fps() > 0 ? fps() : 30.0);
            m_lastTime = frame.time;
        }
        return true;
    }

private:
    cv::VideoCapture m_capture;
    std::string m_description;
    bool m_live;
    std::int64_t m_next = 0;
    double m_lastTime = 0;
    cv::Mat m_decoded;
    std::chrono::steady_clock::time_point m_start;
};

class PictureSequence final : public FrameSource {
public:
    PictureSequence(std::vector<std::filesystem::path> pictures, double fps, cv::Size size)
        : m_pictures(std::move(pictures)), m_fps(fps), m_size(size)
    {
    }
    std::string description() const override
    {
        return std::to_string(m_pictures.size()) + " pictures from " + m_pictures.front().filename().string();
    }
    double fps() const override { return m_fps; }
    int width() const override { return m_size.width; }
    int height() const override { return m_size.height; }
    std::int64_t frameCount() const override { return std::int64_t(m_pictures.size()); }

    Result<bool> read(VideoFrame& frame) override
    {
        if (m_next >= m_pictures.size())
            return false;
        const cv::Mat picture = cv::imread(m_pictures[m_next].string(), cv::IMREAD_COLOR);
        if (picture.empty())
            return makeError(ErrorCode::IoError, m_pictures[m_next].string() + ": not a picture OpenCV can read");
        store(picture, frame);
        frame.index = std::int64_t(m_next);
        frame.time = double(m_next) / m_fps;
        ++m_next;
        return true;
    }

private:
    std::vector<std::filesystem::path> m_pictures;
    double m_fps;
    cv::Size m_size;
    std::size_t m_next = 0;
};

std::string deviceName(int index)
{
    std::ifstream file("/sys/class/video4linux/video" + std::to_string(index) + "/name");
    std::string name;
    std::getline(file, name);
    return name;
}

} // namespace

Result<std::unique_ptr<FrameSource>> openVideoFile(const std::filesystem::path& path)
{
    if (!std::filesystem::is_regular_file(path))
        return makeError(ErrorCode::FileNotFound, path.string() + ": no such video file");
    cv::VideoCapture capture;
    try {
        capture.open(path.string(), cv::CAP_FFMPEG);
    } catch (const cv::Exception&) {
    }
    if (!capture.isOpened())
        return makeError(ErrorCode::NotOurFormat, path.string() + ": not a video this build can decode");
    return std::unique_ptr<FrameSource>(new VideoCaptureSource(std::move(capture), path.filename().string(), false));
}

Result<std::unique_ptr<FrameSource>> openImageSequence(std::vector<std::filesystem::path> pictures, double fps)
{
    if (pictures.empty())
        return makeError(ErrorCode::InvalidArgument, "An image sequence needs at least one picture");
    if (!(fps > 0))
        return makeError(ErrorCode::InvalidArgument, "An image sequence's frame rate must be positive");
    for (const std::filesystem::path& picture : pictures)
        if (!std::filesystem::is_regular_file(picture))
            return makeError(ErrorCode::FileNotFound, picture.string() + ": no such picture");
    const cv::Mat first = cv::imread(pictures.front().string(), cv::IMREAD_COLOR);
    if (first.empty())
        return makeError(ErrorCode::InvalidArgument, pictures.front().string() + ": not a picture OpenCV can read");
    return std::unique_ptr<FrameSource>(new PictureSequence(std::move(pictures), fps, first.size()));
}

Result<void> checkCameraFits(const CameraIntrinsics& camera, const std::string& cameraName, const FrameSource& source)
{
    if (source.width() <= 0 || (source.width() == camera.width && source.height() == camera.height))
        return {};
    return makeError(ErrorCode::InvalidArgument,
                     cameraName + " is for " + std::to_string(camera.width) + " × " + std::to_string(camera.height) +
                         " pictures but " + source.description() + " is " + std::to_string(source.width()) + " × " +
                         std::to_string(source.height()) + ": calibrate the camera at the resolution it films at");
}

Result<VideoFrame> readPicture(const std::filesystem::path& path)
{
    const cv::Mat picture = cv::imread(path.string(), cv::IMREAD_COLOR);
    if (picture.empty())
        return makeError(std::filesystem::exists(path) ? ErrorCode::NotOurFormat : ErrorCode::FileNotFound,
                         path.string() + (std::filesystem::exists(path) ? ": not a picture OpenCV can read"
                                                                         : ": no such picture"));
    VideoFrame frame;
    store(picture, frame);
    frame.index = 0;
    return frame;
}

Result<void> writePicture(const std::filesystem::path& path, const VideoFrame& frame)
{
    std::vector<std::uint8_t> encoded;
    try {
        if (!cv::imencode(path.extension().string(), bgrMat(frame), encoded))
            return makeError(ErrorCode::InvalidArgument, path.string() + ": cannot encode a picture of that kind");
    } catch (const cv::Exception&) {
        return makeError(ErrorCode::InvalidArgument,
                         path.string() + ": \"" + path.extension().string() + "\" is not a picture format OpenCV writes");
    }
    return writeFileAtomically(path, std::string(encoded.begin(), encoded.end()));
}

std::vector<CameraDevice> listCameras()
{
    std::vector<CameraDevice> cameras;
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator("/dev", error)) {
        const std::string name = entry.path().filename().string();
        if (!name.starts_with("video") || name.size() == 5)
            continue;
        try {
            const int index = std::stoi(name.substr(5));
            const std::string driverName = deviceName(index);
            cameras.push_back({index, entry.path().string(), driverName.empty() ? entry.path().string() : driverName});
        } catch (const std::exception&) {
        }
    }
    std::sort(cameras.begin(), cameras.end(), [](const auto& a, const auto& b) { return a.index < b.index; });
    return cameras;
}

Result<std::unique_ptr<FrameSource>> openCamera(const CameraRequest& request)
{
    const std::string path = "/dev/video" + std::to_string(request.index);
    if (!std::filesystem::exists(path)) {
        const std::vector<CameraDevice> cameras = listCameras();
        std::string known = cameras.empty() ? "this machine has none" : "it has";
        for (const CameraDevice& camera : cameras)
            known += " " + camera.path + " (" + camera.name + ")";
        return makeError(ErrorCode::NotFound, "No camera found at " + path + "; " + known);
    }
    cv::VideoCapture capture;
    try {
        capture.open(request.index, cv::CAP_V4L2);
    } catch (const cv::Exception&) {
    }
    if (!capture.isOpened())
        return makeError(ErrorCode::IoError, path + " cannot capture (busy, or not a camera)");
    capture.set(cv::CAP_PROP_FRAME_WIDTH, request.width);
    capture.set(cv::CAP_PROP_FRAME_HEIGHT, request.height);
    capture.set(cv::CAP_PROP_FPS, request.fps);
    const std::string name = deviceName(request.index);
    return std::unique_ptr<FrameSource>(
        new VideoCaptureSource(std::move(capture), "camera " + path + (name.empty() ? "" : " (" + name + ")"), true));
}

} // namespace thespis::core::ar
