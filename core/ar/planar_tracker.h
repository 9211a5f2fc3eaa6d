#pragma once
// A planar markerless target (paper §7.2, like the paper's paper maquette): any textured picture,
// printed at a known width, found in frames by its features. PlanarTracker detects the picture with
// AKAZE features, k-NN matching with Lowe's ratio test and a MAGSAC++ (RANSAC-family) homography,
// follows corners on it between detections with KLT optical flow (forward-backward checked, the
// homography refitted each frame), detects again when too few points survive, the fit degenerates,
// or every RedetectionInterval frames against drift, and turns the correspondences into a pose with
// OpenCV's IPPE. It owns the picture's features and every per-frame buffer (grey image, pyramids,
// point lists), which it reuses from frame to frame.
//
// The target's frame: origin at the picture's top-left corner, x along its width to the right,
// y down, z = 0 on the plane (into the picture), metres; the picture's height follows its aspect.
// This is OpenCV's solvePnP convention, as for ArUco boards.
//
// Also here, without a camera: finding a picture in another (findPlanarHomography), reading
// homography files (readHomographyFile), and drawing the target as a camera sees it
// (renderPlanarTarget), which the tests and the synthetic video source use.

#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

#include "ar/camera_file.h"
#include "ar/pose.h"
#include "ar/tracker.h"
#include "ar/video_frame.h"
#include "util/error.h"

namespace thespis::core::ar {

/// A 3 × 3 homography, row by row, mapping a reference picture's pixels (x, y, 1) to a frame's.
using Homography = std::array<double, 9>;
/// A point in a frame, pixels (x right, y down; OpenCV's pixel centres).
using PixelPoint = std::array<double, 2>;

class PlanarTracker final : public Tracker {
public:
    /// Fewer features than this in the reference picture and it is refused: it is too plain to
    /// be found again.
    static constexpr int MinimumReferenceFeatures = 40;
    /// Frames tracked by KLT before the picture is detected again anyway, so that drift never
    /// builds up for long (half a second at 30 frames per second; 30 frames doubled the mean pose
    /// error on the tests' hand-held sweep).
    static constexpr int RedetectionInterval = 15;

    /// Errors: the width is not a positive number of metres (InvalidArgument); the picture is
    /// missing (FileNotFound) or not one OpenCV reads (NotOurFormat), naming the file; it has fewer
    /// than MinimumReferenceFeatures features (InvalidArgument, saying how many it has).
    static Result<std::unique_ptr<PlanarTracker>> create(const std::filesystem::path& picture, double widthMetres,
                                                         const CameraIntrinsics& camera);
    ~PlanarTracker() override;

    std::string description() const override;
    TrackerEstimate estimate(const VideoFrame& frame) override;
    void reset() override;
    TargetGeometry geometry() const override
    {
        return {{m_width / 2, m_height / 2, 0}, {m_width, m_height}, -1}; // y down the picture: its face looks along −z
    }

    double widthMetres() const { return m_width; }
    double heightMetres() const { return m_height; }
    int pictureWidth() const { return m_pictureWidth; }
    int pictureHeight() const { return m_pictureHeight; }
    int referenceFeatures() const { return m_referenceFeatures; }

    /// Reference picture → the last frame, when the last estimate found the target. With a
    /// distorting lens, → the frame as an ideal pinhole camera would see it (undistorted pixels).
    const Homography& homography() const { return m_homography; }
    /// The target's corners in the last frame (top-left, top-right, bottom-right, bottom-left of
    /// the picture), from the pose and the camera's distortion; when the last estimate found it.
    const std::array<PixelPoint, 4>& corners() const { return m_corners; }
    /// Whether the last estimate found the target by a full feature detection (false: by KLT
    /// tracking, or not found).
    bool lastWasDetection() const { return m_lastWasDetection; }
    /// Frames estimated by detection and by KLT tracking since creation or reset().
    int detections() const { return m_detections; }
    int trackedFrames() const { return m_trackedFrames; }

private:
    struct State; // OpenCV's side: features, matcher, buffers (planar_tracker.cpp)
    PlanarTracker(std::unique_ptr<State> state, std::string name, double width, double height, int pictureWidth,
                  int pictureHeight, int referenceFeatures);
    TrackerEstimate estimateFrame(const VideoFrame& frame);

    std::unique_ptr<State> m_state;
    std::string m_name;
    double m_width = 0, m_height = 0;
    int m_pictureWidth = 0, m_pictureHeight = 0;
    int m_referenceFeatures = 0;
    Homography m_homography{};
    std::array<PixelPoint, 4> m_corners{};
    bool m_lastWasDetection = false;
    int m_detections = 0, m_trackedFrames = 0;
};

/// What findPlanarMatch found: the homography and how well it is supported.
struct PlanarMatch {
    Homography homography{};
    int matches = 0; ///< feature matches that passed the ratio test
    int inliers = 0; ///< of them, those that agree with the homography
};

/// Finds `reference` in `scene` by features alone (no camera): AKAZE, ratio test, MAGSAC++.
/// Errors: either picture cannot be read (naming it); too few features in the reference; the
/// reference is not found in the scene (too few inliers, or a homography that folds the picture).
Result<PlanarMatch> findPlanarMatch(const std::filesystem::path& reference, const std::filesystem::path& scene);
/// The homography of findPlanarMatch alone.
Result<Homography> findPlanarHomography(const std::filesystem::path& reference, const std::filesystem::path& scene);

/// Reads a 3 × 3 homography: an OpenCV storage file (XML, YAML or JSON, the first matrix in it;
/// OpenCV's H1to3p.xml) or plain text of three rows of three numbers (the Oxford data set's
/// H1to3p). Errors name the file and the line of what is wrong.
Result<Homography> readHomographyFile(const std::filesystem::path& path);

/// Maps a point through a homography (pixels to pixels).
PixelPoint applyHomography(const Homography& homography, const PixelPoint& point);

/// Draws `picture` (a frame, as readPicture in frame_source.h gives), printed `widthMetres` wide,
/// as `camera` sees it from `pose` (the target frame above), into `frame`, which keeps its size
/// (camera.width × camera.height when empty), index and time. The camera's distortion is applied; pixels off the target, or behind the camera, are
/// `background` grey. The picture is smoothed before it is shrunk, as a lens would, so small views
/// of it do not alias.
void renderPlanarTarget(const VideoFrame& picture, double widthMetres, const CameraIntrinsics& camera,
                        const TargetPose& pose, VideoFrame& frame, std::uint8_t background = 128);
/// The same from a picture file, into a new frameWidth × frameHeight frame (index 0).
/// Errors: the picture cannot be read; the width or the frame size is not positive.
Result<VideoFrame> warpTargetIntoFrame(const std::filesystem::path& reference, double widthMetres,
                                       const CameraIntrinsics& camera, const TargetPose& pose, int frameWidth,
                                       int frameHeight);

} // namespace thespis::core::ar
