// The planar pose fit's account of how well a frame knows its pose (core/ar/pose_fit.h, issue
// 29): a small target seen nearly face-on, where IPPE's two tilts fit almost alike, says so
// (ambiguity below 3); a large oblique board does not. The picture is OpenCV's own projection of the corners, with a little noise.

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include <opencv2/calib3d.hpp>

#include "ar/pose.h"
#include "ar/pose_fit.h"

using namespace thespis::core::ar;

namespace {

CameraIntrinsics camera()
{
    CameraIntrinsics c;
    c.width = 640;
    c.height = 480;
    c.matrix = {600, 0, 319.5, 0, 600, 239.5, 0, 0, 1};
    return c;
}

// The corners of a square of `side` metres, turned by `tilt` radians about x, `distance` m away.
struct View {
    std::vector<cv::Point3f> object;
    std::vector<cv::Point2f> image;
};

// The corners of a square of `side` metres at the pose `rotation` (Rodrigues), `translation`, as
// OpenCV projects them, with Gaussian noise of `noise` pixels.
View square(double side, const cv::Vec3d& rotation, const cv::Vec3d& translation, double noise, unsigned seed)
{
    View view;
    const float h = float(side / 2);
    view.object = {{-h, -h, 0}, {h, -h, 0}, {h, h, 0}, {-h, h, 0}};
    const CameraIntrinsics c = camera();
    const cv::Matx33d k(c.matrix.data());
    cv::projectPoints(view.object, rotation, translation, k, cv::noArray(), view.image);
    std::mt19937 random(seed);
    std::normal_distribution<float> jitter(0, float(noise));
    for (cv::Point2f& p : view.image)
        p += cv::Point2f(jitter(random), jitter(random));
    return view;
}

// A square turned by `tilt` radians about x, `distance` m away, near the picture's middle.
View square(double side, double tilt, double distance, double noise, unsigned seed)
{
    return square(side, cv::Vec3d(tilt, 0, 0), cv::Vec3d(0.01, -0.005, distance), noise, seed);
}

} // namespace

TEST(PoseFit, ASmallFaceOnTargetSaysItsTiltIsUnsure)
{
    // A 3 cm marker at 1 m, tilted 3°: 18 px across, its two tilts a few tenths of a pixel apart.
    int unsure = 0;
    for (unsigned seed = 1; seed <= 20; ++seed) {
        const View view = square(0.03, 0.05, 1.0, 0.3, seed);
        const auto estimate = fitPlanarPose(view.object, view.image, camera(), std::nullopt);
        ASSERT_TRUE(estimate);
        EXPECT_GT(estimate->ambiguity, 0);
        unsure += estimate->ambiguity < 3;
    }
    EXPECT_GE(unsure, 10); // most of these views cannot tell the two tilts apart

    // A 20 cm board at 0.5 m tilted 35°: the picture tells, and the tilt is well known.
    const View clear = square(0.2, 0.6, 0.5, 0.3, 7);
    const auto sure = fitPlanarPose(clear.object, clear.image, camera(), std::nullopt);
    ASSERT_TRUE(sure);
    EXPECT_GT(sure->ambiguity, 3);
}

namespace {

// The information matrix a frame's points give, computed here from OpenCV's own projection by
// central differences (the reference the fit's analytic Jacobian must match): the pose perturbed
// as R·exp([δθ]×), t + δt, each image coordinate weighted 1 / σ².
cv::Matx66d referenceInformation(const View& view, const TargetPose& pose, double sigma)
{
    const CameraIntrinsics c = camera();
    const cv::Matx33d k(c.matrix.data());
    cv::Matx33d r;
    cv::Rodrigues(cv::Vec3d(pose.rotation[0], pose.rotation[1], pose.rotation[2]), r);
    const cv::Vec3d t(pose.translation[0], pose.translation[1], pose.translation[2]);
    const std::vector<cv::Point3d> object(view.object.begin(), view.object.end());
    const auto project = [&](const cv::Vec6d& delta) {
        cv::Matx33d turn;
        cv::Rodrigues(cv::Vec3d(delta[3], delta[4], delta[5]), turn);
        cv::Vec3d rotation;
        cv::Rodrigues(r * turn, rotation);
        std::vector<cv::Point2d> image;
        cv::projectPoints(object, rotation, t + cv::Vec3d(delta[0], delta[1], delta[2]), k, cv::noArray(), image);
        return image;
    };
    constexpr double Step = 1e-6;
    cv::Mat jacobian(int(2 * view.object.size()), 6, CV_64F);
    for (int p = 0; p < 6; ++p) {
        cv::Vec6d plus, minus;
        plus[p] = Step, minus[p] = -Step;
        const std::vector<cv::Point2d> a = project(plus), b = project(minus);
        for (std::size_t i = 0; i < a.size(); ++i) {
            jacobian.at<double>(int(2 * i), p) = (a[i].x - b[i].x) / (2 * Step);
            jacobian.at<double>(int(2 * i + 1), p) = (a[i].y - b[i].y) / (2 * Step);
        }
    }
    cv::Mat info;
    cv::mulTransposed(jacobian, info, true);
    return cv::Matx66d(info) * (1 / (sigma * sigma));
}

double rotationInformation(const cv::Matx66d& info, const cv::Vec3d& axis)
{
    double sum = 0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            sum += axis[i] * info(3 + i, 3 + j) * axis[j];
    return sum;
}

} // namespace

// Where IPPE's two tilts fit nearly alike, the fit trusts its rotation less about the one axis
// that turns one tilt into the other (the axis between the two poses' plane normals, in the
// target's frame) by (ratio / 3)², and keeps every other direction as the points give it.
TEST(PoseFit, AnUnsureTiltIsDiscountedAboutTheAxisBetweenIppesTwoPoses)
{
    const CameraIntrinsics c = camera();
    const cv::Matx33d k(c.matrix.data());
    int checked = 0;
    for (unsigned seed = 1; seed <= 20; ++seed) {
        // Off to the side, turned in its plane and tilted about a slanted axis: IPPE's two poses
        // then differ by an in-plane turn too, which the picture does show.
        const View view = square(0.03, cv::Vec3d(0.04, 0.03, 0.7), cv::Vec3d(0.12, -0.09, 1.0), 0.3, seed);
        const auto estimate = fitPlanarPose(view.object, view.image, c, std::nullopt);
        ASSERT_TRUE(estimate);
        if (!(estimate->ambiguity < 3))
            continue;
        ++checked;
        const double n = double(view.object.size());
        const double sigma = std::max(0.05, estimate->reprojectionError * std::sqrt(n / (2 * n - 6)));
        const cv::Matx66d reference = referenceInformation(view, estimate->pose, sigma);
        const cv::Matx66d info(estimate->information.data());

        // The axis from the fitted pose's plane normal to that of OpenCV's other IPPE pose (the
        // one farther from it).
        std::vector<cv::Mat> rotations, translations;
        ASSERT_EQ(cv::solvePnPGeneric(view.object, view.image, k, cv::noArray(), rotations, translations, false,
                                      cv::SOLVEPNP_IPPE),
                  2);
        const TargetPose first = {{rotations[0].at<double>(0), rotations[0].at<double>(1), rotations[0].at<double>(2)}, {}};
        const TargetPose second = {{rotations[1].at<double>(0), rotations[1].at<double>(1), rotations[1].at<double>(2)}, {}};
        const bool otherIsSecond =
            rotationDifference(first, estimate->pose) < rotationDifference(second, estimate->pose);
        cv::Matx33d chosen, other;
        cv::Rodrigues(cv::Vec3d(estimate->pose.rotation[0], estimate->pose.rotation[1], estimate->pose.rotation[2]),
                      chosen);
        cv::Rodrigues(rotations[otherIsSecond ? 1 : 0], other);
        const cv::Vec3d normal(chosen(0, 2), chosen(1, 2), chosen(2, 2)), otherNormal(other(0, 2), other(1, 2), other(2, 2));
        cv::Vec3d axis = chosen.t() * normal.cross(otherNormal);
        axis /= cv::norm(axis);
        EXPECT_LT(std::abs(axis[2]), 0.05) << "the turn between two tilts lies in the target's plane";
        const cv::Vec3d across = cv::Vec3d(0, 0, 1).cross(axis);

        const double keep = std::max(estimate->ambiguity, 1.0) / 3;
        EXPECT_NEAR(rotationInformation(info, axis), keep * keep * rotationInformation(reference, axis),
                    0.02 * rotationInformation(reference, axis));
        EXPECT_NEAR(rotationInformation(info, across), rotationInformation(reference, across),
                    0.02 * rotationInformation(reference, across));
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                EXPECT_NEAR(info(i, j), reference(i, j), 0.02 * std::abs(reference(i, i)) + 1e-9)
                    << "translation's information is the points' own";
    }
    EXPECT_GE(checked, 10);
}
