#include "ar/pose_fit.h"

#include <algorithm>
#include <cmath>

#include <opencv2/calib3d.hpp>

#include "ar/opencv_bridge.h"

namespace thespis::core::ar {

namespace {

// A clearly better fit wins over nearness to the last pose: the ratio of RMS errors beyond which
// the worse of IPPE's two poses is the mirror image, not noise.
constexpr double ClearlyBetterFit = 3.0;
// The pixel noise assumed at least: a close fit of few points hides some. The marker edges place
// sharp corners to about 0.03 px (issue 29), so a higher floor would make the filter trust its
// prediction over a sharp frame, and carry a smeared frame's error into the sharp ones after it.
constexpr double MinimumPixelNoise = 0.05;
// How far, as a share of a smear's length, its points may be off along it: fitting the markers'
// patterns leaves about a hundredth of the smear, the edges alone about a tenth, more on small or
// slanted markers (issue 29).
constexpr double ModelledSmearShare = 0.02;
constexpr double EdgeSmearShare = 0.25;

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

// JᵀWJ of the reprojection, W the inverse of each point's 2 × 2 pixel covariance, for a
// perturbation R·exp([δθ]) and t + δt: a point X of the plane is seen at P = R X + t, so
// ∂P/∂t = I and ∂P/∂δθ = −R [X]×; then the pinhole's ∂(u, v)/∂P. (Lens distortion changes the
// Jacobian only slightly and is left out.)
cv::Matx66d information(const std::vector<cv::Point3f>& objectPoints, const CameraIntrinsics& camera,
                        const cv::Vec3d& rotation, const cv::Vec3d& translation, const cv::Matx22d& pixelCovariance)
{
    cv::Matx33d r;
    cv::Rodrigues(rotation, r);
    const cv::Matx22d weight = pixelCovariance.inv();
    cv::Matx66d jtwj = cv::Matx66d::zeros();
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
        jtwj += j.t() * weight * j;
    }
    return jtwj;
}

// A point's pixel covariance: the noise left after the fit each way, and along the smear a share
// of its length. A smear biases the edges it crosses by a fraction of a pixel the same way all
// over the board (the black squares look wider along it), which the residuals hardly show; the
// markers' smeared patterns, fitted, much less.
cv::Matx22d pixelCovariance(double noise, const MotionBlur& blur)
{
    const double share = blur.modelled ? ModelledSmearShare : EdgeSmearShare;
    const double along = share * blur.length, dx = std::cos(blur.angle), dy = std::sin(blur.angle);
    return cv::Matx22d(noise * noise, 0, 0, noise * noise) +
           cv::Matx22d(dx * dx, dx * dy, dx * dy, dy * dy) * (along * along);
}

// IPPE's two poses of a planar target differ by a turn about an axis in its plane; when they fit
// nearly alike, the chosen one's rotation about that axis is known less than its Jacobian says.
// The information along that axis is scaled by (ratio / 3)² (a congruence, so it stays positive).
void discountAmbiguity(cv::Matx66d& info, const cv::Vec3d& chosen, const cv::Vec3d& other, double ratio)
{
    if (!(ratio < ClearlyBetterFit))
        return;
    cv::Matx33d a, b;
    cv::Rodrigues(chosen, a);
    cv::Rodrigues(other, b);
    // The tilt that takes one pose's plane normal to the other's: an axis in the target's plane
    // (their relative rotation would also hold their in-plane turn, which the picture does show).
    const cv::Vec3d normal(a(0, 2), a(1, 2), a(2, 2)), otherNormal(b(0, 2), b(1, 2), b(2, 2));
    cv::Vec3d axis = a.t() * normal.cross(otherNormal); // in the target's frame, as the information's rotation is
    const double length = cv::norm(axis);
    if (length < 1e-9)
        return;
    axis /= length;
    const double keep = std::max(ratio, 1.0) / ClearlyBetterFit;
    cv::Matx66d scale = cv::Matx66d::eye();
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            scale(3 + i, 3 + j) -= (1 - keep) * axis[i] * axis[j];
    info = scale * info * scale;
}

} // namespace

std::optional<TrackerEstimate> fitPlanarPose(const std::vector<cv::Point3f>& objectPoints,
                                             const std::vector<cv::Point2f>& imagePoints, const CameraIntrinsics& camera,
                                             const std::optional<TargetPose>& previous, const MotionBlur& blur)
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
    estimate.blur = blur;
    // The noise left after the fit, per coordinate, with 6 degrees of freedom taken by the pose.
    const double n = double(objectPoints.size());
    const double noise = std::max(MinimumPixelNoise, estimate.reprojectionError * std::sqrt(n / std::max(1.0, 2 * n - 6)));
    cv::Matx66d info = information(objectPoints, camera, rotation, translation, pixelCovariance(noise, blur));
    if (rotations.size() == 2) {
        estimate.ambiguity = errors[0] > 0 ? errors[1] / errors[0] : ClearlyBetterFit * 1e3;
        discountAmbiguity(info, rotation, cv::Vec3d(rotations[1 - chosen]), estimate.ambiguity);
    }
    std::copy(info.val, info.val + 36, estimate.information.begin());
    return estimate;
}

} // namespace thespis::core::ar
