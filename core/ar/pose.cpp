#include "ar/pose.h"

#include <algorithm>
#include <cmath>

#include <opencv2/calib3d.hpp>

#include "ar/opencv_bridge.h"

namespace thespis::core::ar {

namespace {
cv::Matx33d matrixOf(const TargetPose& pose)
{
    cv::Matx33d r;
    cv::Rodrigues(rvec(pose), r);
    return r;
}
} // namespace

std::array<double, 9> rotationMatrix(const TargetPose& pose)
{
    const cv::Matx33d r = matrixOf(pose);
    std::array<double, 9> out;
    std::copy(r.val, r.val + 9, out.begin());
    return out;
}

std::array<double, 3> toCamera(const TargetPose& pose, const std::array<double, 3>& point)
{
    const cv::Vec3d p = matrixOf(pose) * cv::Vec3d(point[0], point[1], point[2]) + tvec(pose);
    return {p[0], p[1], p[2]};
}

double rotationDifference(const TargetPose& a, const TargetPose& b)
{
    const cv::Matx33d relative = matrixOf(a).t() * matrixOf(b);
    const double cosine = std::clamp((cv::trace(relative) - 1.0) / 2.0, -1.0, 1.0);
    return std::acos(cosine);
}

double translationDifference(const TargetPose& a, const TargetPose& b)
{
    return cv::norm(tvec(a) - tvec(b));
}

} // namespace thespis::core::ar
