#include "ar/pose_fit.h"

#include <cmath>

#include <opencv2/calib3d.hpp>

#include "ar/opencv_bridge.h"

namespace thespis::core::ar {

namespace {

// A clearly better fit wins over nearness to the last pose: the ratio of RMS errors beyond which
// the worse of IPPE's two poses is the mirror image, not noise.
constexpr double ClearlyBetterFit = 3.0;
// The pixel noise assumed at least: corners found in a picture are off by a tenth or two of a
// pixel in ways that change slowly from frame to frame, which a close fit of few points hides.
constexpr double MinimumPixelNoise = 0.2;

double rmsError(const std::vector<cv::Point3f>& objectPoints, const std::vector<cv::Point2f>& imagePoints,
                const CameraIntrinsics& camera, const cv::Vec3d& rotation, const cv::Vec3d& translation)
{
    std::vector<cv::Point2f> projected;
    cv::projectPoints(objectPoints, rotation, translation, cameraMat(camera), distortionMat(camera), projected);
    double sum = 0;
    for (std::size_t i = 0; i < projected.size(); ++i) {
        const cv::Point2f d = projected[i] - imagePoints[i];
        sum += d.dot(d);
    }
    return std::sqrt(sum / double(projected.size()));
}

// JᵀJ / σ² of the reprojection, for a perturbation R·exp([δθ]) and t + δt: a point X of the plane
// is seen at P = R X + t, so ∂P/∂t = I and ∂P/∂δθ = −R [X]×; then the pinhole's ∂(u, v)/∂P.
// (Lens distortion changes the Jacobian only slightly and is left out.)
std::array<double, 36> information(const std::vector<cv::Point3f>& objectPoints, const CameraIntrinsics& camera,
                                   const cv::Vec3d& rotation, const cv::Vec3d& translation, double pixelNoise)
{
    cv::Matx33d r;
    cv::Rodrigues(rotation, r);
    cv::Matx66d jtj = cv::Matx66d::zeros();
    for (const cv::Point3f& point : objectPoints) {
        const cv::Vec3d x(point.x, point.y, point.z);
        const cv::Vec3d p = r * x + translation;
        const double iz = 1.0 / p[2];
        const cv::Matx23d projection(camera.fx() * iz, 0, -camera.fx() * p[0] * iz * iz,
                                     0, camera.fy() * iz, -camera.fy() * p[1] * iz * iz);
        const cv::Matx33d skew(0, -x[2], x[1], x[2], 0, -x[0], -x[1], x[0], 0);
        const cv::Matx23d dt = projection;
        const cv::Matx23d dtheta = projection * (-(r * skew));
        cv::Matx<double, 2, 6> j;
        for (int row = 0; row < 2; ++row)
            for (int c = 0; c < 3; ++c) {
                j(row, c) = dt(row, c);
                j(row, 3 + c) = dtheta(row, c);
            }
        jtj += j.t() * j;
    }
    std::array<double, 36> result;
    const double weight = 1.0 / (pixelNoise * pixelNoise);
    for (int i = 0; i < 36; ++i)
        result[std::size_t(i)] = jtj.val[i] * weight;
    return result;
}

} // namespace

std::optional<TrackerEstimate> fitPlanarPose(const std::vector<cv::Point3f>& objectPoints,
                                             const std::vector<cv::Point2f>& imagePoints, const CameraIntrinsics& camera,
                                             const std::optional<TargetPose>& previous)
{
    if (objectPoints.size() < 4 || objectPoints.size() != imagePoints.size())
        return std::nullopt;
    std::vector<cv::Mat> rotations, translations;
    std::vector<double> errors;
    try {
        if (cv::solvePnPGeneric(objectPoints, imagePoints, cameraMat(camera), distortionMat(camera), rotations,
                                translations, false, cv::SOLVEPNP_IPPE, cv::noArray(), cv::noArray(), errors) == 0)
            return std::nullopt;
    } catch (const cv::Exception&) {
        return std::nullopt; // degenerate points (all on a line)
    }
    std::size_t chosen = 0;
    if (rotations.size() == 2 && previous && errors[1] < ClearlyBetterFit * errors[0]) {
        const auto distance = [&](std::size_t i) {
            return rotationDifference(targetPose(cv::Vec3d(rotations[i]), cv::Vec3d(translations[i])), *previous);
        };
        chosen = distance(1) < distance(0) ? 1 : 0;
    }
    cv::Vec3d rotation(rotations[chosen]), translation(translations[chosen]);
    cv::solvePnPRefineLM(objectPoints, imagePoints, cameraMat(camera), distortionMat(camera), rotation, translation);
    if (translation[2] <= 0)
        return std::nullopt; // behind the camera: no real view gives that
    TrackerEstimate estimate;
    estimate.found = true;
    estimate.pose = targetPose(rotation, translation);
    estimate.features = int(objectPoints.size());
    estimate.reprojectionError = rmsError(objectPoints, imagePoints, camera, rotation, translation);
    // The noise left after the fit, per coordinate, with 6 degrees of freedom taken by the pose.
    const double n = double(objectPoints.size());
    const double noise = std::max(MinimumPixelNoise, estimate.reprojectionError * std::sqrt(n / std::max(1.0, 2 * n - 6)));
    estimate.information = information(objectPoints, camera, rotation, translation, noise);
    return estimate;
}

} // namespace thespis::core::ar
