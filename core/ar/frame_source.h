#pragma once
// Where frames come from: a camera (V4L2 through OpenCV's VideoCapture), a video file, a sequence
// of pictures, or a synthetic scene with known poses (synthetic_source.h). A source is read on one
// thread at a time; LiveCapture (live_capture.h) runs one on its own thread for live previews.

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "ar/camera_file.h"
#include "ar/video_frame.h"
#include "util/error.h"

namespace thespis::core::ar {

class FrameSource {
public:
    virtual ~FrameSource() = default;
    /// What it reads, for people ("cockatoo.mp4", "camera /dev/video0 (UVC Camera)").
    virtual std::string description() const = 0;
    /// The next frame into `frame` (reusing its buffer): true, or false at the end of a file or a
    /// sequence. Errors: a frame that cannot be decoded, a camera that stopped sending frames
    /// (unplugged), each saying which source and which frame.
    virtual Result<bool> read(VideoFrame& frame) = 0;
    /// Frames per second it delivers, 0 when it cannot say.
    virtual double fps() const = 0;
    /// The frames' size (before the first frame: what the source announces; 0 when unknown).
    virtual int width() const = 0;
    virtual int height() const = 0;
    /// How many frames a file or sequence holds; −1 for a live camera.
    virtual std::int64_t frameCount() const = 0;
};

/// A video file (whatever FFmpeg, through OpenCV, decodes). Frame times are the video's own
/// timestamps. Errors: a missing file, one that is not a video.
Result<std::unique_ptr<FrameSource>> openVideoFile(const std::filesystem::path& path);

/// Pictures read one after another at `fps` (frame i at i / fps seconds). Errors: none given, a
/// file missing (named), fps not positive.
Result<std::unique_ptr<FrameSource>> openImageSequence(std::vector<std::filesystem::path> pictures, double fps);

/// Whether `camera` (called `cameraName` in the message) was calibrated at the size `source`
/// gives; a source that does not say its size yet passes. Errors: "camera.yml is for 640 × 480
/// pictures but clip.mp4 is 1280 × 720: calibrate the camera at the resolution it films at".
Result<void> checkCameraFits(const CameraIntrinsics& camera, const std::string& cameraName, const FrameSource& source);

/// One picture as a frame (index 0, time 0). Errors name the file.
Result<VideoFrame> readPicture(const std::filesystem::path& path);
/// Writes a frame as a picture (PNG, JPEG, … by extension), for overlays and tests.
Result<void> writePicture(const std::filesystem::path& path, const VideoFrame& frame);

struct CameraDevice {
    int index = 0;            ///< /dev/video<index>
    std::string path;         ///< /dev/video0
    std::string name;         ///< what the driver calls it ("Integrated Camera"), or the path
};
/// The video capture devices this machine has (none is a normal answer, not an error).
std::vector<CameraDevice> listCameras();

struct CameraRequest {
    int index = 0;
    int width = 640, height = 480; ///< asked for; the camera may choose another size
    double fps = 30;
};
/// Opens a camera. Errors: no such device ("No camera found at /dev/video1; this machine has
/// none" or the list it has), a device that cannot capture.
Result<std::unique_ptr<FrameSource>> openCamera(const CameraRequest& request);

} // namespace thespis::core::ar
