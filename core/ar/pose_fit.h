#pragma once
// The pose of a planar target from its points on the plane and where they are seen, shared by
// the marker and the planar trackers: IPPE's two candidate poses (cv::solvePnPGeneric), the
// mirror-image one rejected, then refined by Levenberg–Marquardt, with the RMS error left and the
// pose's information matrix. Private to core/ar.

#include <optional>
#include <vector>

#include <opencv2/core.hpp>

#include "ar/camera_file.h"
#include "ar/tracker.h"

namespace thespis::core::ar {

/// At least 4 points, on the plane z = 0. `previous`, when the target was seen lately, chooses
/// between IPPE's two poses when the picture alone cannot (a small or distant target seen nearly
/// face-on): the one nearer to it wins. Without it, or when one pose fits clearly better, the
/// better fit wins. `blur`, the frame's motion blur, makes the information matrix trust each point
/// less along the smear. Empty when OpenCV finds no pose.
std::optional<TrackerEstimate> fitPlanarPose(const std::vector<cv::Point3f>& objectPoints,
                                             const std::vector<cv::Point2f>& imagePoints, const CameraIntrinsics& camera,
                                             const std::optional<TargetPose>& previous, const MotionBlur& blur = {});

} // namespace thespis::core::ar
