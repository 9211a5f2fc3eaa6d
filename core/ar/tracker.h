#pragma once
// What finds a target in a frame: a marker board (marker_tracker.h) or a planar picture
// (planar_tracker.h). A tracker estimates each frame on its own, but may use what it saw last to
// search faster or to choose between ambiguous poses; TrackingSession (tracking_session.h) adds
// the temporal filter, the lost / recovered events and the latency.

#include <array>
#include <string>

#include "ar/pose.h"
#include "ar/video_frame.h"

namespace thespis::core::ar {

/// The motion blur a frame shows on the target's edges (marker boards only; zero elsewhere).
struct MotionBlur {
    double length = 0; ///< pixels a point of the picture was smeared over; 0 when sharp
    double angle = 0;  ///< the smear's direction, radians from the picture's x towards its y, in [0, π)
    /// Every point was placed by a model of the smeared picture (not by edges the smear biases).
    bool modelled = false;
};

struct TrackerEstimate {
    bool found = false;
    TargetPose pose;               ///< when found
    int features = 0;              ///< markers, ChArUco corners or matched points used
    double reprojectionError = -1; ///< RMS, pixels, of the pose against what was found
    /// How well the pose is known: its information matrix (the inverse covariance) over
    /// [translation (m), rotation (rad) about the target's own axes], row-major, as the
    /// reprojection's Jacobian and the pixel noise left give it. The temporal filter weighs the
    /// frame by it: one small marker seen edge-on counts for less than a whole board face-on.
    std::array<double, 36> information{};
    MotionBlur blur; ///< the frame's blur, which `information` already discounts
    /// The worse of IPPE's two poses' RMS error over the better one's (0: only one pose). Below
    /// about 3 the picture hardly tells a planar target's two tilts apart, and `information`
    /// trusts the rotation between them less.
    double ambiguity = 0;
};

/// The target's shape in its own frame, for placing a scene on it.
struct TargetGeometry {
    std::array<double, 3> centre{};  ///< the middle of the printed area (metres)
    std::array<double, 2> size{};    ///< its extent along the target's x and y (metres)
    /// Which way the printed side faces along the target's z: +1 or −1 (OpenCV 4.6's ArUco grid
    /// has y up and +z out of the print; a picture target has y down and −z out of it).
    double faceNormal = 1;
};

class Tracker {
public:
    virtual ~Tracker() = default;
    /// What it tracks, for people ("ArUco grid 4 × 3 of DICT_4X4_50", "graf1.png, 0.30 m wide").
    virtual std::string description() const = 0;
    virtual TrackerEstimate estimate(const VideoFrame& frame) = 0;
    /// Forgets what it saw (a new video, a jump).
    virtual void reset() = 0;
    virtual TargetGeometry geometry() const = 0;
};

} // namespace thespis::core::ar
