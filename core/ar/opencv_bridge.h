#pragma once
// core/ar's own values seen as OpenCV's, without copies. Only core/ar's .cpp files include this:
// OpenCV is private to thespis_core, so no public header may.

#include <opencv2/core.hpp>

#include "ar/camera_file.h"
#include "ar/pose.h"
#include "ar/video_frame.h"

namespace thespis::core::ar {

/// The frame's pixels as a BGR matrix (sharing the frame's buffer).
inline cv::Mat bgrMat(const VideoFrame& frame)
{
    return cv::Mat(frame.height, frame.width, CV_8UC3, const_cast<std::uint8_t*>(frame.bgr.data()));
}
inline cv::Mat bgrMat(VideoFrame& frame) { return cv::Mat(frame.height, frame.width, CV_8UC3, frame.bgr.data()); }

/// The 3 × 3 camera matrix (sharing the intrinsics' storage).
inline cv::Mat cameraMat(const CameraIntrinsics& camera)
{
    return cv::Mat(3, 3, CV_64F, const_cast<double*>(camera.matrix.data()));
}
/// The distortion coefficients as a column (sharing storage); an empty matrix for none.
inline cv::Mat distortionMat(const CameraIntrinsics& camera)
{
    if (camera.distortion.empty())
        return {};
    return cv::Mat(int(camera.distortion.size()), 1, CV_64F, const_cast<double*>(camera.distortion.data()));
}

inline cv::Vec3d rvec(const TargetPose& pose) { return {pose.rotation[0], pose.rotation[1], pose.rotation[2]}; }
inline cv::Vec3d tvec(const TargetPose& pose) { return {pose.translation[0], pose.translation[1], pose.translation[2]}; }
inline TargetPose targetPose(const cv::Vec3d& rotation, const cv::Vec3d& translation)
{
    return {{rotation[0], rotation[1], rotation[2]}, {translation[0], translation[1], translation[2]}};
}

} // namespace thespis::core::ar
